// Plane-stress condensation and closed-form uniaxial neo-Hookean responses.
#include <gtest/gtest.h>

#include <cmath>

#include "material_fixtures.hpp"
#include "tether/materials/plane_stress.hpp"

using namespace tether;
using namespace tether::test;

namespace {

constexpr int kInPlane[3] = {0, 1, 3};

/// Cauchy stress of the ABAQUS neo-Hookean solid for F = diag(l1, l2, l3):
/// sigma_i = mu J^(-5/3) (l_i^2 - I1/3) + K (J - 1).
Eigen::Vector3d neo_hooke_cauchy(double mu, double K, double l1, double l2, double l3) {
  const double J = l1 * l2 * l3, I1 = l1 * l1 + l2 * l2 + l3 * l3;
  const double a = mu * std::pow(J, -5.0 / 3.0);
  return {a * (l1 * l1 - I1 / 3) + K * (J - 1), a * (l2 * l2 - I1 / 3) + K * (J - 1),
          a * (l3 * l3 - I1 / 3) + K * (J - 1)};
}

/// Cauchy stress sigma_11 of a PK2 S for F = diag(l1, l2, l3).
double cauchy_11(const Vec6& S, double l1, double l2, double l3) { return l1 * l1 * S(0) / (l1 * l2 * l3); }

}  // namespace

TEST(PlaneStress, SmallStrainLinearElasticMatchesClosedForm) {
  const double E = 200, nu = 0.3;
  const LinearElastic m(E, nu);
  Vec6 eps = Vec6::Zero(), sigma;
  Mat6 D;
  eps(0) = 1e-3;
  eps(1) = -2e-4;
  eps(3) = 5e-4;
  plane_stress_small_strain(m, eps, sigma, D);
  EXPECT_NEAR(sigma(2), 0.0, 1e-14);
  EXPECT_NEAR(eps(2), -nu / (1 - nu) * (1e-3 - 2e-4), 1e-15);
  EXPECT_NEAR(sigma(0), E / (1 - nu * nu) * (1e-3 + nu * -2e-4), 1e-12);
  EXPECT_NEAR(D(0, 0), E / (1 - nu * nu), 1e-10);
  EXPECT_NEAR(D(0, 1), E * nu / (1 - nu * nu), 1e-10);
  EXPECT_NEAR(D(3, 3), E / (2 * (1 + nu)), 1e-10);
  EXPECT_EQ(D.row(2).norm() + D.col(2).norm(), 0.0);
}

TEST(PlaneStress, CondensedTangentsMatchFiniteDifferences) {
  const double h = 1e-6;
  for (const auto& m : all_models()) {
    for (const auto& F : random_deformations(5, 0.3, true)) {
      // Finite strain: in-plane C varied, C33 re-solved each time.
      Eigen::Matrix3d C = F.transpose() * F;
      C(2, 2) = 1;
      Vec6 S, Sp, Sm;
      Mat6 D, Dd;
      Eigen::Matrix3d Cs = C;
      plane_stress_finite_strain(*m, Cs, S, D);
      EXPECT_LT(std::abs(S(2)), 1e-10 * S.norm()) << m->describe();
      const Vec6 E = green_lagrange_of(Cs);
      for (int k : kInPlane) {
        Vec6 e = E;
        e(k) += h;
        Eigen::Matrix3d Cp = cauchy_green_of(e);
        plane_stress_finite_strain(*m, Cp, Sp, Dd);
        e(k) -= 2 * h;
        Eigen::Matrix3d Cm = cauchy_green_of(e);
        plane_stress_finite_strain(*m, Cm, Sm, Dd);
        const Vec6 fd = (Sp - Sm) / (2 * h);
        for (int i : kInPlane) EXPECT_NEAR(fd(i), D(i, k), 1e-6 * D.norm()) << m->describe() << " " << i << k;
      }
      // Small strain, same in-plane components scaled down.
      Vec6 eps = 0.01 * E;
      eps(2) = 0;
      Vec6 sigma, sp, sm;
      plane_stress_small_strain(*m, eps, sigma, D);
      EXPECT_LT(std::abs(sigma(2)), 1e-12 * sigma.norm());
      for (int k : kInPlane) {
        Vec6 e = eps;
        e(k) += h;
        plane_stress_small_strain(*m, e, sp, Dd);
        e = eps;
        e(k) -= h;
        plane_stress_small_strain(*m, e, sm, Dd);
        for (int i : kInPlane) EXPECT_NEAR((sp(i) - sm(i)) / (2 * h), D(i, k), 1e-6 * D.norm());
      }
    }
  }
}

TEST(NeoHookeUniaxial, PlaneStrainStretchMatchesClosedForm) {
  const double c10 = 0.5, d1 = 0.1, mu = 1.0, K = 20.0;
  const NeoHooke m(c10, d1);
  for (double l : {0.6, 0.9, 1.5, 2.5}) {
    Eigen::Matrix3d C = Eigen::Matrix3d::Identity();
    C(0, 0) = l * l;  // F = diag(l, 1, 1): stretch in x, y and z held
    Vec6 S;
    Mat6 D;
    m.finite_strain(C, S, D);
    const Eigen::Vector3d sigma = neo_hooke_cauchy(mu, K, l, 1, 1);
    EXPECT_NEAR(cauchy_11(S, l, 1, 1), sigma(0), 1e-12 * (1 + std::abs(sigma(0))));
    EXPECT_NEAR(S(1) / l, sigma(1), 1e-12 * (1 + std::abs(sigma(1))));  // sigma_22 = S22 / J
    EXPECT_NEAR(S(2) / l, sigma(2), 1e-12 * (1 + std::abs(sigma(2))));
  }
}

TEST(NeoHookeUniaxial, PlaneStressStretchMatchesClosedForm) {
  const double c10 = 0.5, d1 = 0.1, mu = 1.0, K = 20.0;
  const NeoHooke m(c10, d1);
  for (double l : {0.6, 0.9, 1.5, 2.5}) {
    // Closed form: lateral stretch l2 = l3 from sigma_22 = 0, found by bisection.
    double lo = 0.05, hi = 3.0;
    for (int it = 0; it < 200; ++it) {
      const double mid = 0.5 * (lo + hi);
      (neo_hooke_cauchy(mu, K, l, mid, mid)(1) > 0 ? hi : lo) = mid;
    }
    const double l2 = 0.5 * (lo + hi);
    const double sigma11 = neo_hooke_cauchy(mu, K, l, l2, l2)(0);

    // tether: in-plane C = diag(l^2, l2^2), S22 = 0 by symmetry of the solution, S33 = 0 solved.
    Eigen::Matrix3d C = Eigen::Matrix3d::Identity();
    C(0, 0) = l * l;
    C(1, 1) = l2 * l2;
    Vec6 S;
    Mat6 D;
    plane_stress_finite_strain(m, C, S, D);
    EXPECT_NEAR(std::sqrt(C(2, 2)), l2, 1e-10);
    EXPECT_NEAR(S(1), 0.0, 1e-9);
    EXPECT_NEAR(cauchy_11(S, l, l2, l2), sigma11, 1e-9 * (1 + std::abs(sigma11)));
  }
}
