/* Test UMAT (tests/analysis/user_material_test.cpp): a rate-dependent
 * material, linear elasticity in series with a linear dashpot on the whole
 * strain (Maxwell), integrated by backward Euler. PROPS = E, nu, relaxation
 * time tau; STATEV = the viscous strain (NTENS components). At a held strain
 * the stress decays by 1 / (1 + DTIME / tau) per increment, so the routine's
 * answer depends on the time even when the strain does not change. */
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
  (void)sse, (void)spd, (void)scd, (void)rpl, (void)ddsddt, (void)drplde, (void)drpldt, (void)time, (void)temp;
  (void)dtemp, (void)predef, (void)dpred, (void)cmname, (void)ndi, (void)nshr, (void)nstatv, (void)nprops;
  (void)coords, (void)drot, (void)pnewdt, (void)celent, (void)dfgrd0, (void)dfgrd1, (void)noel, (void)npt;
  (void)layer, (void)kspt, (void)kstep, (void)kinc, (void)cmname_length;
  const double E = props[0], nu = props[1], tau = props[2];
  const double lam = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const double keep = 1 / (1 + *dtime / tau);  /* elastic share of a strain change */
  double C[16] = {0}, elastic[4];
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) C[i + 4 * j] = lam;
    C[i + 4 * i] += 2 * mu;
  }
  C[15] = mu;
  for (int k = 0; k < 4; ++k) {
    const double strain = stran[k] + dstran[k];
    statev[k] = keep * statev[k] + (1 - keep) * strain;
    elastic[k] = strain - statev[k];
  }
  for (int i = 0; i < *ntens; ++i) {
    stress[i] = 0;
    for (int j = 0; j < *ntens; ++j) {
      stress[i] += C[i + 4 * j] * elastic[j];
      ddsdde[i + *ntens * j] = keep * C[i + 4 * j];
    }
  }
}
