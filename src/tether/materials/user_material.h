/*
 * tether user-material interface (C, C++ and Fortran): ABAQUS's user
 * subroutine UMAT, called unchanged.
 *
 * A user material is a routine you write, compile into a shared library and
 * name in the deck; tether loads it at run time (dlopen), no recompiling:
 *
 *   *MATERIAL, NAME=MY_STEEL
 *   *USER MATERIAL, CONSTANTS=4, LIBRARY=build/libj2_umat.so[, SYMBOL=umat_]
 *   200000., 0.3, 250., 1000.          <- PROPS(1..NPROPS), 8 per line
 *   *DEPVAR
 *   5                                  <- NSTATV
 *
 * The routine has exactly the argument list of ABAQUS/Standard's UMAT, passed
 * the way Fortran passes it: every argument by address, and the length of the
 * CHARACTER*80 CMNAME as a hidden trailing argument (size_t, gfortran >= 8).
 * So a Fortran UMAT compiled with
 *
 *   gfortran -shared -fPIC -O2 umat.f -o libumat.so
 *
 * works as it is: gfortran names SUBROUTINE UMAT `umat_` (lower case, one
 * trailing underscore), which is tether's default SYMBOL. A routine written in
 * C or C++ defines `umat_` with C linkage and the prototype below (or another
 * name given with SYMBOL=). Intel Fortran on Linux also appends one
 * underscore; compilers that do not (e.g. with -fno-underscoring) need
 * SYMBOL=umat.
 *
 * Arrays are Fortran arrays: column-major, 1-based in Fortran, 0-based here
 * (DDSDDE(I,J) is ddsdde[(I-1) + ntens*(J-1)]). Components are in ABAQUS's
 * order, direct then shear, shear strains engineering (gamma = 2 eps):
 *
 *   plane strain, axisymmetric: NDI = 3, NSHR = 1, NTENS = 4: 11, 22, 33, 12
 *                               (axisymmetric: rr, zz, theta-theta, rz)
 *   plane stress:               NDI = 2, NSHR = 1, NTENS = 3: 11, 22, 12
 *
 * What tether passes and expects. Small strain first; in an NLGEOM step
 * (finite strain) the routine is called as ABAQUS/Standard calls it, a
 * Jaumann-rate integration, but in the frame of the polar rotation R of
 * F = R U rather than the global one: every tensor below is then expressed
 * in that frame (docs/theory/user_material.md has the kinematics):
 *
 *   STRESS(NTENS)   in: stress at the start of the increment; out: at its end.
 *                   NLGEOM: Cauchy stress (R^T sigma R), on entry already
 *                   rotated by DROT, as ABAQUS does
 *   STATEV(NSTATV)  in: state variables at the start; out: at the end
 *   DDSDDE(NTENS,NTENS) out: the Jacobian d(delta stress)/d(delta strain)
 *                   (NLGEOM: of the returned Cauchy stress with respect to
 *                   DSTRAN at the rotated start stress; tether adds the
 *                   rotation and geometric terms itself).
 *                   tether makes no assumption of symmetry (it solves with an
 *                   unsymmetric factorization). Newton's convergence depends
 *                   on its accuracy.
 *   SSE, SPD, SCD   in: specific elastic strain energy, plastic dissipation,
 *                   creep dissipation at the start; out: at the end (per unit
 *                   volume; NLGEOM: integrated over the reference volume). SSE is the element's elastic energy, the increase
 *                   of SPD its plastic dissipation (ALLPD).
 *   RPL, DDSDDT, DRPLDE, DRPLDT  zeroed, ignored (no thermal coupling)
 *   STRAN(NTENS)    total strain at the start of the increment (NLGEOM: the
 *                   sum of the DSTRANs, rotated by DROT: the logarithmic
 *                   strain ln U to the Hughes-Winget error)
 *   DSTRAN(NTENS)   strain increment (plane stress: the in-plane components).
 *                   NLGEOM: sym A with A = (U1 - U0) ((U0 + U1)/2)^-1, the
 *                   midpoint (Hughes-Winget) approximation of the increment
 *                   of the logarithmic strain
 *   TIME(2)         step time and total time at the start of the increment
 *   DTIME           time increment
 *   TEMP            temperature of the point at the start of the increment
 *                   (the shape-function interpolation of the nodal values of
 *                   *INITIAL CONDITIONS, TYPE=TEMPERATURE and *TEMPERATURE;
 *                   0 without them)
 *   DTEMP           its increment over the increment (TEMP + DTEMP: at the end)
 *   PREDEF(1), DPRED(1)  0 (no field variables)
 *   CMNAME          the material name, upper case, blank-padded to 80 characters
 *   NDI, NSHR, NTENS, NSTATV, PROPS(NPROPS), NPROPS  as above
 *   COORDS(3)       reference coordinates of the integration point (z = 0)
 *   DROT(3,3)       identity (small strain); NLGEOM: the Hughes-Winget
 *                   rotation (I - W/2)^-1 (I + W/2), W = skew A, relative to R
 *   PNEWDT          in: a large value; out: a value < 1 rejects the increment:
 *                   tether cuts it back (by its usual cut-back factor, not by
 *                   PNEWDT) and tries again
 *   CELENT          0 (not known)
 *   DFGRD0, DFGRD1(3,3)  NLGEOM: U at the start and end of the increment
 *                   (R^T F, the deformation gradient in the rotated frame);
 *                   small strain: I + eps at the start and end (the
 *                   symmetric small-strain approximation)
 *   NOEL, NPT       element label, integration point (1-based)
 *   LAYER, KSPT     1
 *   KSTEP, KINC     0 (not known to the material; as in the user-MPC interface)
 *
 * tether calls the routine at every Newton iteration from the state of the
 * last accepted increment and keeps what it returns only once the increment
 * is accepted, so the routine need not undo anything; it may be called
 * concurrently for different points (OpenMP assembly), so it must not keep
 * writable global state. A NaN or infinite output is an error naming the
 * element and the point (the increment is cut back). Once, when the model is
 * built, tether calls it at zero strain (NOEL = NPT = 0, DTIME = 0) to read
 * the initial shear stiffness DDSDDE(4,4) (plane: the last shear term).
 *
 * A plane-stress routine must return sigma_33 = 0 itself (ABAQUS's
 * convention); tether does not know the thickness strain of a user material
 * and reports eps_33 = 0. For the same reason plane-stress elements of a
 * user material are refused in NLGEOM steps (use CPE or CAX).
 */
#ifndef TETHER_MATERIALS_USER_MATERIAL_H
#define TETHER_MATERIALS_USER_MATERIAL_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Symbol tether looks up when the deck gives no SYMBOL= (gfortran's name of SUBROUTINE UMAT). */
#define TETHER_UMAT_DEFAULT_SYMBOL "umat_"

/* Marks the routine as exported from the shared library. */
#if defined(__GNUC__) || defined(__clang__)
#define TETHER_UMAT_EXPORT __attribute__((visibility("default")))
#else
#define TETHER_UMAT_EXPORT
#endif

/* ABAQUS's UMAT argument list, in order, by address; cmname_length is the
 * hidden length of CMNAME (80). */
typedef void (*tether_umat_fn)(double* stress, double* statev, double* ddsdde, double* sse, double* spd,
                               double* scd, double* rpl, double* ddsddt, double* drplde, double* drpldt,
                               const double* stran, const double* dstran, const double* time, const double* dtime,
                               const double* temp, const double* dtemp, const double* predef, const double* dpred,
                               const char* cmname, const int* ndi, const int* nshr, const int* ntens,
                               const int* nstatv, const double* props, const int* nprops, const double* coords,
                               const double* drot, double* pnewdt, const double* celent, const double* dfgrd0,
                               const double* dfgrd1, const int* noel, const int* npt, const int* layer,
                               const int* kspt, const int* kstep, const int* kinc, size_t cmname_length);

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* TETHER_MATERIALS_USER_MATERIAL_H */
