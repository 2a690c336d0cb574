/*
 * A worked user material: small-strain von Mises plasticity with linear
 * isotropic hardening, written as an ABAQUS UMAT in C (see
 * tether/materials/user_material.h). It is the same model as
 *
 *   *ELASTIC
 *   E, nu
 *   *PLASTIC
 *   sy0, 0.
 *   sy0 + H, 1.
 *
 * (for PEEQ below 1) and tether's tests check that both give the same answer
 * to 1e-10.
 *
 *   *USER MATERIAL, CONSTANTS=4, LIBRARY=build/libj2_umat.so
 *   E, nu, sy0, H
 *   *DEPVAR
 *   5
 *
 * PROPS: E, nu, initial yield stress sy0, hardening modulus H = d sy / d PEEQ.
 * STATEV: plastic strain (11, 22, 33, engineering 12), PEEQ.
 * Plane strain and axisymmetric elements only (NTENS = 4): for plane stress it
 * returns NaN, which tether reports naming the element and the point.
 */
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
  (void)scd, (void)rpl, (void)ddsddt, (void)drplde, (void)drpldt, (void)temp, (void)dtemp;
  (void)predef, (void)dpred, (void)cmname, (void)ndi, (void)nshr, (void)nprops, (void)coords, (void)drot;
  (void)pnewdt, (void)celent, (void)dfgrd0, (void)dfgrd1, (void)noel, (void)npt, (void)layer, (void)kspt;
  (void)kstep, (void)kinc, (void)cmname_length;
  const int n = *ntens;
  if (n != 4 || *nstatv < 5) {
    for (int i = 0; i < n; ++i) stress[i] = NAN;
    return;
  }
  const double E = props[0], nu = props[1], sy0 = props[2], H = props[3];
  const double mu = E / (2 * (1 + nu)), kappa = E / (3 * (1 - 2 * nu));
  const double p_old = statev[4];

  /* Elastic trial: elastic strain, its deviator (tensor shear), trial stress. */
  double ee[4], e[4], s[4];
  for (int i = 0; i < 4; ++i) ee[i] = stran[i] + dstran[i] - statev[i];
  const double vol = ee[0] + ee[1] + ee[2];
  for (int i = 0; i < 3; ++i) e[i] = ee[i] - vol / 3;
  e[3] = 0.5 * ee[3];
  for (int i = 0; i < 4; ++i) s[i] = 2 * mu * e[i];
  const double norm = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2] + 2 * s[3] * s[3]);
  const double q = sqrt(1.5) * norm, k = sy0 + H * p_old;

  double dp = 0, theta = 1, theta_bar = 0, nrm[4] = {0, 0, 0, 0};
  if (q - k > 1e-12 * k) { /* plastic: radial return, closed form for linear hardening */
    dp = (q - k) / (3 * mu + H);
    for (int i = 0; i < 4; ++i) nrm[i] = s[i] / norm;
    theta = 1 - 3 * mu * dp / q;
    theta_bar = 1 / (1 + H / (3 * mu)) - (1 - theta);
    const double shrink = 2 * mu * sqrt(1.5) * dp;
    for (int i = 0; i < 4; ++i) s[i] -= shrink * nrm[i];
    for (int i = 0; i < 3; ++i) statev[i] += sqrt(1.5) * dp * nrm[i];
    statev[3] += 2 * sqrt(1.5) * dp * nrm[3]; /* engineering shear */
    statev[4] = p_old + dp;
  } else if (time[0] > 1e-9 * (time[0] + *dtime) && q - k > -1e-6 * k) {
    /* On the yield surface in an increment that continues a step (a point
     * that yielded in the last one, at its first iteration): the loading
     * tangent, the plastic one at dp = 0, as *PLASTIC gives it there. */
    for (int i = 0; i < 4; ++i) nrm[i] = s[i] / norm;
    theta_bar = 1 / (1 + H / (3 * mu));
  }
  for (int i = 0; i < 3; ++i) stress[i] = s[i] + kappa * vol;
  stress[3] = s[3];

  /* DDSDDE(i,j) = ddsdde[i + 4 j]: kappa 1x1 + 2 mu theta I_dev - 2 mu theta_bar n x n. */
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      double dev = 0;
      if (i < 3 && j < 3) dev = (i == j ? 1.0 : 0.0) - 1.0 / 3;
      if (i == 3 && j == 3) dev = 0.5;
      ddsdde[i + 4 * j] = (i < 3 && j < 3 ? kappa : 0) + 2 * mu * theta * dev - 2 * mu * theta_bar * nrm[i] * nrm[j];
    }

  /* Energies: elastic energy 1/2 sigma : eps_e; plastic work of the increment (trapezoid, exact here). */
  double we = 0;
  for (int i = 0; i < 4; ++i) we += stress[i] * (stran[i] + dstran[i] - statev[i]);
  *sse = 0.5 * we;
  *spd += dp * (k + 0.5 * H * dp);
}
