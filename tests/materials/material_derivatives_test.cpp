// Finite-difference checks of every constitutive model: stress = dW/dstrain,
// tangent = dstress/dstrain, in small and finite strain, at several random states.
#include <gtest/gtest.h>

#include "material_fixtures.hpp"

using namespace tether;
using namespace tether::test;

namespace {

constexpr double kStep = 1e-6;
constexpr double kRelTol = 1e-6;  // relative to the largest entry

}  // namespace

TEST(MaterialDerivatives, SmallStrainStressIsEnergyGradientAndTangentIsStressGradient) {
  for (const auto& m : all_models())
    for (const auto& F : random_deformations(5, 0.02, false)) {
      const Vec6 eps = to_voigt_strain(0.5 * (F + F.transpose()) - Eigen::Matrix3d::Identity());
      Vec6 sigma, sp, sm;
      Mat6 D, Dd, fd;
      m->small_strain(eps, sigma, D);
      Vec6 grad;
      for (int k = 0; k < 6; ++k) {
        Vec6 e = eps;
        e(k) += kStep;
        const double wp = m->small_strain_energy(e);
        m->small_strain(e, sp, Dd);
        e(k) -= 2 * kStep;
        const double wm = m->small_strain_energy(e);
        m->small_strain(e, sm, Dd);
        grad(k) = (wp - wm) / (2 * kStep);
        fd.col(k) = (sp - sm) / (2 * kStep);
      }
      EXPECT_LT((grad - sigma).norm(), kRelTol * sigma.norm() + 1e-10) << m->describe();
      EXPECT_LT((fd - D).norm(), kRelTol * D.norm()) << m->describe();
    }
}

TEST(MaterialDerivatives, FiniteStrainStressIsEnergyGradientAndTangentIsStressGradient) {
  for (const auto& m : all_models())
    for (const auto& F : random_deformations(6, 0.35, false)) {
      const Eigen::Matrix3d C = F.transpose() * F;
      const Vec6 E = green_lagrange_of(C);
      Vec6 S, sp, sm, grad;
      Mat6 D, Dd, fd;
      m->finite_strain(C, S, D);
      for (int k = 0; k < 6; ++k) {
        Vec6 e = E;
        e(k) += kStep;
        const double wp = m->finite_strain_energy(cauchy_green_of(e));
        m->finite_strain(cauchy_green_of(e), sp, Dd);
        e(k) -= 2 * kStep;
        const double wm = m->finite_strain_energy(cauchy_green_of(e));
        m->finite_strain(cauchy_green_of(e), sm, Dd);
        grad(k) = (wp - wm) / (2 * kStep);
        fd.col(k) = (sp - sm) / (2 * kStep);
      }
      EXPECT_LT((grad - S).norm(), kRelTol * S.norm()) << m->describe();
      EXPECT_LT((fd - D).norm(), kRelTol * D.norm()) << m->describe();
      EXPECT_LT((D - D.transpose()).norm(), 1e-12 * D.norm()) << m->describe();
    }
}

TEST(MaterialDerivatives, FiniteStrainReducesToLinearElasticityAtSmallStrain) {
  for (const auto& m : all_models()) {
    const Vec6 zero = Vec6::Zero();
    Vec6 sigma, S;
    Mat6 D_small, D_finite;
    m->small_strain(zero, sigma, D_small);
    m->finite_strain(Eigen::Matrix3d::Identity(), S, D_finite);
    EXPECT_LT(S.norm(), 1e-12 * D_small.norm()) << m->describe();
    EXPECT_LT((D_finite - D_small).norm(), 1e-12 * D_small.norm()) << m->describe();
    // Stress agrees to second order in the strain.
    for (double scale : {1e-3, 1e-4}) {
      Vec6 E;
      E << 0.3, -0.7, 0.2, 0.5, -0.1, 0.4;
      E *= scale;
      m->finite_strain(cauchy_green_of(E), S, D_finite);
      m->small_strain(E, sigma, D_small);
      EXPECT_LT((S - sigma).norm(), 10 * scale * sigma.norm()) << m->describe();
    }
  }
}

TEST(MaterialDerivatives, LinearElasticIsotropicConstants) {
  const LinearElastic m(100.0, 0.25);
  EXPECT_DOUBLE_EQ(m.mu(), 40.0);
  EXPECT_DOUBLE_EQ(m.lambda(), 40.0);
  Vec6 eps = Vec6::Zero(), sigma;
  Mat6 D;
  eps(0) = 1e-3;  // uniaxial strain: sigma11 = (lambda + 2 mu) eps, sigma22 = lambda eps
  m.small_strain(eps, sigma, D);
  EXPECT_NEAR(sigma(0), 0.12, 1e-14);
  EXPECT_NEAR(sigma(1), 0.04, 1e-14);
  eps.setZero();
  eps(3) = 2e-3;  // engineering shear
  m.small_strain(eps, sigma, D);
  EXPECT_NEAR(sigma(3), 0.08, 1e-14);
}
