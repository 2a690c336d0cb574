/* Test UMAT (tests/analysis/user_material_test.cpp): linear elastic, NTENS = 4,
 * PROPS = E, nu, limit. Asks for a smaller increment (PNEWDT = 0.5) whenever a
 * strain increment component exceeds `limit`. */
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
  (void)statev, (void)sse, (void)spd, (void)scd, (void)rpl, (void)ddsddt, (void)drplde, (void)drpldt, (void)stran;
  (void)time, (void)dtime, (void)temp, (void)dtemp, (void)predef, (void)dpred, (void)cmname, (void)ndi, (void)nshr;
  (void)nstatv, (void)nprops, (void)coords, (void)drot, (void)celent, (void)dfgrd0, (void)dfgrd1, (void)noel;
  (void)npt, (void)layer, (void)kspt, (void)kstep, (void)kinc, (void)cmname_length;
  const double E = props[0], nu = props[1], limit = props[2];
  const double lam = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  for (int i = 0; i < 16; ++i) ddsdde[i] = 0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) ddsdde[i + 4 * j] = lam;
    ddsdde[i + 4 * i] += 2 * mu;
  }
  ddsdde[15] = mu;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) stress[i] += ddsdde[i + 4 * j] * dstran[j];
  for (int i = 0; i < *ntens; ++i)
    if (fabs(dstran[i]) > limit) *pnewdt = 0.5;
}
