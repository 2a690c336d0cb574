C     Linear elastic UMAT in fixed-form Fortran (plane strain and
C     axisymmetric, NTENS = 4), for tests/analysis/user_material_test.cpp:
C     PROPS = E, NU. It checks that CMNAME arrives as 'FORTRAN' (the hidden
C     length argument) and returns NaN otherwise.
      SUBROUTINE UMAT(STRESS,STATEV,DDSDDE,SSE,SPD,SCD,RPL,DDSDDT,
     1 DRPLDE,DRPLDT,STRAN,DSTRAN,TIME,DTIME,TEMP,DTEMP,PREDEF,DPRED,
     2 CMNAME,NDI,NSHR,NTENS,NSTATV,PROPS,NPROPS,COORDS,DROT,PNEWDT,
     3 CELENT,DFGRD0,DFGRD1,NOEL,NPT,LAYER,KSPT,KSTEP,KINC)
      IMPLICIT DOUBLE PRECISION (A-H,O-Z)
      CHARACTER*80 CMNAME
      DIMENSION STRESS(NTENS),STATEV(*),DDSDDE(NTENS,NTENS),
     1 DDSDDT(NTENS),DRPLDE(NTENS),STRAN(NTENS),DSTRAN(NTENS),
     2 TIME(2),PREDEF(1),DPRED(1),PROPS(NPROPS),COORDS(3),DROT(3,3),
     3 DFGRD0(3,3),DFGRD1(3,3)
      E = PROPS(1)
      ANU = PROPS(2)
      ALAM = E*ANU/((1.D0+ANU)*(1.D0-2.D0*ANU))
      AMU = E/(2.D0*(1.D0+ANU))
      DO I = 1, NTENS
        DO J = 1, NTENS
          DDSDDE(I,J) = 0.D0
        END DO
      END DO
      DO I = 1, NDI
        DO J = 1, NDI
          DDSDDE(I,J) = ALAM
        END DO
        DDSDDE(I,I) = ALAM + 2.D0*AMU
      END DO
      DDSDDE(NTENS,NTENS) = AMU
      DO I = 1, NTENS
        DO J = 1, NTENS
          STRESS(I) = STRESS(I) + DDSDDE(I,J)*DSTRAN(J)
        END DO
      END DO
      SSE = 0.D0
      DO I = 1, NTENS
        SSE = SSE + 0.5D0*STRESS(I)*(STRAN(I)+DSTRAN(I))
      END DO
      IF (CMNAME .NE. 'FORTRAN' .OR. LEN(CMNAME) .NE. 80) THEN
        ZERO = 0.D0
        DO I = 1, NTENS
          STRESS(I) = ZERO/ZERO
        END DO
      END IF
      RETURN
      END
