/* Test UMAT (tests/analysis/user_material_test.cpp): linear elasticity with a
 * thermal expansion whose secant coefficient varies linearly with the
 * temperature, alpha(T) = a0 + a1 T about the reference temperature T0,
 * integrated incrementally as ABAQUS asks of a UMAT: the thermal strain
 * increment is alpha(T1) (T1 - T0) - alpha(T) (T - T0) with T = TEMP (start
 * of the increment) and T1 = TEMP + DTEMP (its end). The increments add up to
 * the total secant thermal strain only when both TEMP and DTEMP are right.
 * PROPS = E, nu, a0, a1, T0; no state variables. Plane strain and
 * axisymmetry only (NTENS = 4). */
#include <stddef.h>

#include "tether/materials/user_material.h"

static double secant_strain(const double* props, double t) { return (props[2] + props[3] * t) * (t - props[4]); }

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
  (void)time, (void)dtime, (void)predef, (void)dpred, (void)cmname, (void)nshr, (void)nstatv, (void)nprops;
  (void)coords, (void)drot, (void)pnewdt, (void)celent, (void)dfgrd0, (void)dfgrd1, (void)noel, (void)npt;
  (void)layer, (void)kspt, (void)kstep, (void)kinc, (void)cmname_length;
  const double E = props[0], nu = props[1];
  const double lam = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const double dthermal = secant_strain(props, *temp + *dtemp) - secant_strain(props, *temp);
  const int n = *ntens;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) ddsdde[i + n * j] = (i < *ndi && j < *ndi ? lam : 0) + (i == j ? (i < *ndi ? 2 * mu : mu) : 0);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) stress[i] += ddsdde[i + n * j] * (dstran[j] - (j < *ndi ? dthermal : 0));
}
