/* Test UMAT (tests/analysis/user_material_nlgeom_test.cpp): hypoelastic
 * isotropic linear elasticity, STRESS += DDSDDE . DSTRAN, the textbook UMAT
 * ABAQUS users run under NLGEOM (a Jaumann-rate hypoelastic material there).
 * PROPS = E, nu, and optionally a strain-increment limit: a |DSTRAN(k)|
 * above it sets PNEWDT = 0.5. STATEV(1) = STRAN(1) + DSTRAN(1) (the
 * accumulated 11 strain, to check that state variables are carried);
 * SSE = 1/2 STRESS . (STRAN + DSTRAN). */
#include <math.h>
#include <stddef.h>

#include "tether/materials/user_material.h"

TETHER_UMAT_EXPORT void umat_(double* stress, double* statev, double* ddsdde, double* sse, double* spd,
                              double* scd, double* rpl, double* ddsddt, double* drplde, double* drpldt,
                              const double* stran, const double* dstran, const double* time, const double* dtime,
                              const double* temp, const double* dtemp, const double* predef, const double* dpred,
                              const char* cmname, const int* ndi, const int* nshr, const int* ntens,
                              const int* nstatv, const double* props, const int* nprops, const double* coords,
                              const double* drot, double* pnewdt, const double* celent, const double* dfgrd0,
                              const double* dfgrd1, const int* noel, const int* npt, const int* layer,
                              const int* kspt, const int* kstep, const int* kinc, size_t cmname_length) {
  (void)spd, (void)scd, (void)rpl, (void)ddsddt, (void)drplde, (void)drpldt, (void)time, (void)dtime, (void)temp;
  (void)dtemp, (void)predef, (void)dpred, (void)cmname, (void)nshr, (void)coords, (void)drot, (void)celent;
  (void)dfgrd0, (void)dfgrd1, (void)noel, (void)npt, (void)layer, (void)kspt, (void)kstep, (void)kinc;
  (void)cmname_length;
  const double E = props[0], nu = props[1];
  const double lam = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const int n = *ntens;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) ddsdde[i + n * j] = (i < *ndi && j < *ndi ? lam : 0) + (i == j ? (i < *ndi ? 2 * mu : mu) : 0);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) stress[i] += ddsdde[i + n * j] * dstran[j];
  *sse = 0;
  for (int i = 0; i < n; ++i) *sse += 0.5 * stress[i] * (stran[i] + dstran[i]);
  if (*nstatv > 0) statev[0] = stran[0] + dstran[0];
  if (*nprops > 2)
    for (int k = 0; k < n; ++k)
      if (fabs(dstran[k]) > props[2]) *pnewdt = 0.5;
}
