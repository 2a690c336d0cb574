// Finite-strain von Mises plasticity (J2Plasticity under NLGEOM): the tangent
// dS/dE against central differences at random elastic and plastic states,
// exactness against the small-strain return in logarithmic strains for
// loading on fixed principal axes, the small-strain limit, and the refusals.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <random>

#include "material_fixtures.hpp"
#include "support/error_message.hpp"
#include "tether/materials/j2_plasticity.hpp"

using namespace tether;
using namespace tether::test;

namespace {

constexpr double kE = 200000, kNu = 0.3;
using State = std::vector<double>;

/// Isotropic: (p, y) = (0, 200), (0.01, 300), (0.05, 350), flat beyond.
J2Plasticity steel() {
  return {kE, kNu, HardeningCurve({0, 0.01, 0.05}, {200, 300, 350}), J2Plasticity::Hardening::Isotropic};
}

MaterialResponse respond(const J2Plasticity& m, const Eigen::Matrix3d& C, const State& old, State* next = nullptr) {
  State scratch(old.size());
  MaterialResponse r;
  Eigen::Matrix3d c = C;
  m.update_finite_strain(c, false, old, next ? *next : scratch, {}, r);
  return r;
}

/// C = F^T F along F(s) = I + s (F_end - I), committed in `steps` increments from `state`.
State strain_path(const J2Plasticity& m, const Eigen::Matrix3d& F_start, const Eigen::Matrix3d& F_end, int steps,
                  State state) {
  for (int k = 1; k <= steps; ++k) {
    const Eigen::Matrix3d F = F_start + (F_end - F_start) * (static_cast<double>(k) / steps);
    State next(state.size());
    respond(m, F.transpose() * F, state, &next);
    state = next;
  }
  return state;
}

/// Largest entry of |D - D_fd| relative to the largest entry of D, central differences in E.
double tangent_error(const J2Plasticity& m, const Eigen::Matrix3d& C, const State& old) {
  const MaterialResponse r = respond(m, C, old);
  const Vec6 E = green_lagrange_of(C);
  const double h = 1e-7;
  Mat6 fd;
  for (int j = 0; j < 6; ++j) {
    Vec6 e = E;
    e(j) += h;
    const Vec6 sp = respond(m, cauchy_green_of(e), old).stress;
    e(j) -= 2 * h;
    const Vec6 sm = respond(m, cauchy_green_of(e), old).stress;
    fd.col(j) = (sp - sm) / (2 * h);
  }
  return (fd - r.tangent).cwiseAbs().maxCoeff() / r.tangent.cwiseAbs().maxCoeff();
}

}  // namespace

TEST(J2FiniteStrain, TangentMatchesFiniteDifferencesOnBothBranches) {
  const J2Plasticity m = steel();
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> d(-1, 1);
  int plastic = 0, elastic = 0;
  double worst = 0;
  for (bool plane : {true, false})
    for (const Eigen::Matrix3d& F1 : random_deformations(6, 0.25, plane, 5)) {
      // A committed plastic state at F1, then a trial at F1 plus a random
      // increment (mostly plastic) or minus a part of the last one (elastic unloading).
      const State committed = strain_path(m, Eigen::Matrix3d::Identity(), F1, 8, State(J2Plasticity::kStateSize, 0.0));
      ASSERT_GT(committed[12], 0.01);
      Eigen::Matrix3d dF = Eigen::Matrix3d::Zero();
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          if (!plane || (i < 2 && j < 2) || (i == 2 && j == 2)) dF(i, j) = 0.01 * d(gen);
      for (const Eigen::Matrix3d& F2 : {Eigen::Matrix3d(F1 + dF), Eigen::Matrix3d(F1 - 0.002 * (F1 - Eigen::Matrix3d::Identity()))}) {
        State next(committed.size());
        respond(m, F2.transpose() * F2, committed, &next);
        (next[12] > committed[12] ? plastic : elastic) += 1;
        const double err = tangent_error(m, F2.transpose() * F2, committed);
        worst = std::max(worst, err);
        EXPECT_LT(err, 1e-6) << (next[12] > committed[12] ? "plastic" : "elastic");
      }
    }
  std::printf("finite-strain J2 tangent: %d plastic, %d elastic points, worst relative error %.2e\n", plastic,
              elastic, worst);
  EXPECT_GE(plastic, 8);
  EXPECT_GE(elastic, 4);
  // The virgin point (C = I, repeated eigenvalues) and an equibiaxial stretch (two equal ones).
  EXPECT_LT(tangent_error(m, Eigen::Matrix3d::Identity(), State(J2Plasticity::kStateSize, 0.0)), 1e-6);
  const Eigen::Matrix3d biaxial = Eigen::Vector3d(1.2, 1.2, 1 / 1.44).asDiagonal();
  EXPECT_LT(tangent_error(m, biaxial * biaxial, State(J2Plasticity::kStateSize, 0.0)), 1e-6);
}

TEST(J2FiniteStrain, FixedPrincipalAxesGiveTheSmallStrainReturnInLogarithmicStrains) {
  // On fixed principal axes the exponential map adds logarithmic strains
  // exactly: the Kirchhoff stress of every increment equals the small-strain
  // stress at eps = ln(stretch), and the PEEQ is the same.
  const J2Plasticity m = steel();
  const Eigen::Matrix3d axes = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  State finite(J2Plasticity::kStateSize, 0.0), small(J2Plasticity::kStateSize, 0.0);
  double worst = 0;
  for (int k = 1; k <= 40; ++k) {
    const double s = 0.25 * std::sin(0.1 * k);  // load, unload, reverse
    const Eigen::Vector3d log_stretch(s, -0.3 * s + 0.01 * std::cos(0.3 * k), 0.02 * s);
    const Eigen::Matrix3d U = axes * log_stretch.array().exp().matrix().asDiagonal() * axes.transpose();
    State next_f(finite.size()), next_s(small.size());
    const MaterialResponse rf = respond(m, U * U, finite, &next_f);
    Vec6 eps = to_voigt_strain(axes * log_stretch.asDiagonal() * axes.transpose());
    MaterialResponse rs;
    m.update_small_strain(eps, false, small, next_s, {}, rs);
    const Eigen::Matrix3d tau = U * from_voigt_stress(rf.stress) * U;  // F = U: tau = F S F^T
    worst = std::max(worst, (tau - from_voigt_stress(rs.stress)).cwiseAbs().maxCoeff() / 200);
    EXPECT_NEAR(next_f[12], next_s[12], 1e-12) << k;
    finite = next_f, small = next_s;
  }
  EXPECT_GT(small[12], 0.1);
  EXPECT_LT(worst, 1e-10);
}

TEST(J2FiniteStrain, SmallStrainsGiveTheSmallStrainAnswer) {
  // Proportional path in 10 increments past yield, at two strain levels: the
  // stress and PEEQ differences vanish with the strain (at least linearly).
  const J2Plasticity m = steel();
  Vec6 E;
  E << 1.3, -0.4, -0.2, 0.9, 0.3, -0.5;
  double stress_error[2], peeq_error[2];
  for (int level = 0; level < 2; ++level) {
    const double scale = level == 0 ? 6e-3 : 2e-3;
    State finite(J2Plasticity::kStateSize, 0.0), small(J2Plasticity::kStateSize, 0.0);
    MaterialResponse rf, rs;
    for (int k = 1; k <= 10; ++k) {
      const Vec6 e = E * (scale * k / 10);
      State nf(finite.size()), ns(small.size());
      rf = respond(m, cauchy_green_of(e), finite, &nf);
      Vec6 eps = e;
      m.update_small_strain(eps, false, small, ns, {}, rs);
      finite = nf, small = ns;
    }
    ASSERT_GT(small[12], 0);
    stress_error[level] = (rf.stress - rs.stress).cwiseAbs().maxCoeff() / rs.stress.cwiseAbs().maxCoeff();
    peeq_error[level] = std::abs(finite[12] - small[12]) / scale;  // relative to the strain
  }
  std::printf("finite against small strain: stress %.2e -> %.2e, PEEQ %.2e -> %.2e (relative to the strain)\n", stress_error[0],
              stress_error[1], peeq_error[0], peeq_error[1]);
  EXPECT_LT(stress_error[0], 0.05);
  EXPECT_LT(peeq_error[0], 0.05);
  EXPECT_LT(stress_error[1], stress_error[0] / 2.5);
  EXPECT_LT(peeq_error[1], peeq_error[0] / 2);
}

TEST(J2FiniteStrain, PlaneStressAndKinematicHardeningAreRefused) {
  const J2Plasticity iso = steel();
  const J2Plasticity kin{kE, kNu, HardeningCurve({0, 1}, {200, 10200}), J2Plasticity::Hardening::Kinematic};
  State old(J2Plasticity::kStateSize, 0.0), next(old.size());
  MaterialResponse r;
  Eigen::Matrix3d C = Eigen::Matrix3d::Identity();
  const std::string plane = tether::testing::model_error_of([&] { iso.update_finite_strain(C, true, old, next, {}, r); });
  EXPECT_NE(plane.find("not available for plane stress"), std::string::npos) << plane;
  const std::string kinematic =
      tether::testing::model_error_of([&] { kin.update_finite_strain(C, false, old, next, {}, r); });
  EXPECT_NE(kinematic.find("HARDENING=KINEMATIC or COMBINED under NLGEOM"), std::string::npos) << kinematic;
}
