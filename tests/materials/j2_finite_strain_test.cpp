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
/// Kinematic: back stress from (0, 200), (0.01, 300), (0.05, 350), flat beyond; yield stress 200.
J2Plasticity kinematic_steel() {
  return {kE, kNu, HardeningCurve({0, 0.01, 0.05}, {200, 300, 350}), J2Plasticity::Hardening::Kinematic};
}
/// Combined: back stress as kinematic_steel, yield stress (0, 200), (0.02, 260), (1, 400).
J2Plasticity combined_steel() {
  return {kE, kNu, HardeningCurve({0, 0.01, 0.05}, {200, 300, 350}), J2Plasticity::Hardening::Combined,
          HardeningCurve({0, 0.02, 1}, {200, 260, 400})};
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
  const double scale = r.tangent.cwiseAbs().maxCoeff();
  if (m.symmetric_tangent(true))
    EXPECT_LT((r.tangent - r.tangent.transpose()).cwiseAbs().maxCoeff(), 1e-12 * scale) << "the tangent is symmetric";
  return (fd - r.tangent).cwiseAbs().maxCoeff() / scale;
}

}  // namespace

TEST(J2FiniteStrain, TangentMatchesFiniteDifferencesOnBothBranches) {
  for (const J2Plasticity& m : {steel(), kinematic_steel(), combined_steel()}) {
  SCOPED_TRACE(m.describe());
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
}

TEST(J2FiniteStrain, FixedPrincipalAxesGiveTheSmallStrainReturnInLogarithmicStrains) {
  // On fixed principal axes the exponential map adds logarithmic strains
  // exactly: the Kirchhoff stress of every increment equals the small-strain
  // stress at eps = ln(stretch), and the PEEQ is the same.
  for (const J2Plasticity& m : {steel(), kinematic_steel(), combined_steel()}) {
  SCOPED_TRACE(m.describe());
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
  for (int i = 6; i < 12; ++i) EXPECT_NEAR(finite[i], small[i], 1e-9 * 200) << "back stress " << i;
  }
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

namespace {

/// Plane stress update at the in-plane C (C33 solved by the model from the guess 1).
MaterialResponse respond_plane_stress(const J2Plasticity& m, Eigen::Matrix3d C, const State& old, State* next = nullptr,
                                      double* C33 = nullptr) {
  State scratch(old.size());
  MaterialResponse r;
  C(2, 2) = 1;
  m.update_finite_strain(C, true, old, next ? *next : scratch, {}, r);
  if (C33) *C33 = C(2, 2);
  return r;
}

/// The in-plane right Cauchy-Green tensor of F (2x2 block; C33 = 1 as a guess).
Eigen::Matrix3d in_plane_C(const Eigen::Matrix3d& F) {
  Eigen::Matrix3d C = Eigen::Matrix3d::Identity();
  C.topLeftCorner<2, 2>() = (F.transpose() * F).topLeftCorner<2, 2>();
  return C;
}

}  // namespace

TEST(J2FiniteStrain, PlaneStressKeepsS33ZeroAndItsTangentMatchesFiniteDifferences) {
  // Plane stress under NLGEOM: a local Newton iteration on C33 gives S33 = 0
  // to round-off; the condensed tangent (in-plane E11, E22, 2 E12) against
  // central differences, elastic and plastic branches, every hardening kind.
  constexpr int kIn[3] = {0, 1, 3};
  for (const J2Plasticity& m : {steel(), kinematic_steel(), combined_steel()}) {
    SCOPED_TRACE(m.describe());
    int plastic = 0, elastic = 0;
    double worst = 0, worst_s33 = 0;
    std::mt19937 gen(5);
    std::uniform_real_distribution<double> d(-1, 1);
    for (const Eigen::Matrix3d& F1 : random_deformations(8, 0.2, true, 9)) {
      State state(J2Plasticity::kStateSize, 0.0);
      for (int k = 1; k <= 8; ++k) {
        State next(state.size());
        const Eigen::Matrix3d F = Eigen::Matrix3d::Identity() + (F1 - Eigen::Matrix3d::Identity()) * (k / 8.0);
        respond_plane_stress(m, in_plane_C(F), state, &next);
        state = next;
      }
      ASSERT_GT(state[12], 0.005);
      Eigen::Matrix3d dF = Eigen::Matrix3d::Zero();
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) dF(i, j) = 0.01 * d(gen);
      for (const Eigen::Matrix3d& F2 : {Eigen::Matrix3d(F1 + dF), Eigen::Matrix3d(F1 - 0.003 * (F1 - Eigen::Matrix3d::Identity()))}) {
        const Eigen::Matrix3d C = in_plane_C(F2);
        State next(state.size());
        const MaterialResponse r = respond_plane_stress(m, C, state, &next);
        (next[12] > state[12] ? plastic : elastic) += 1;
        worst_s33 = std::max(worst_s33, std::abs(r.stress(2)) / r.stress.cwiseAbs().maxCoeff());
        Mat6 fd = Mat6::Zero();
        const double h = 1e-7;
        for (int j : kIn) {
          Eigen::Matrix3d dE = Eigen::Matrix3d::Zero();
          if (j == 3) dE(0, 1) = dE(1, 0) = 0.5;
          else dE(j, j) = 1;
          fd.col(j) = (respond_plane_stress(m, C + 2 * h * dE, state).stress -
                       respond_plane_stress(m, C - 2 * h * dE, state).stress) / (2 * h);
        }
        double err = 0;  // the in-plane block (the condensation leaves the unused 23, 13 rows alone)
        for (int a : kIn)
          for (int b : kIn) err = std::max(err, std::abs(fd(a, b) - r.tangent(a, b)));
        err /= r.tangent.cwiseAbs().maxCoeff();
        EXPECT_TRUE(r.tangent.row(2).isZero() && r.tangent.col(2).isZero());
        worst = std::max(worst, err);
        EXPECT_LT(err, 1e-6) << (next[12] > state[12] ? "plastic" : "elastic");
      }
    }
    std::printf("plane stress finite-strain J2 tangent: %d plastic, %d elastic, worst %.2e, |S33|/|S| %.1e\n",
                plastic, elastic, worst, worst_s33);
    EXPECT_GE(plastic, 4);
    EXPECT_GE(elastic, 4);
    EXPECT_LT(worst_s33, 1e-12);
  }
}

TEST(J2FiniteStrain, UniaxialKinematicLoadUnloadReverseMatchesTheLogarithmicClosedForm) {
  // Uniaxial stress on fixed axes, linear kinematic hardening y = s0 + Hk p,
  // Kirchhoff stress tau against the axial log strain e:
  //   loading:   tau (1 + Hk/E) = s0 + Hk e;
  //   unloading: tau = E (e - ep1), elastic down to tau = Hk ep1 - s0;
  //   reverse:   tau (1 + Hk/E) = Hk e - s0;
  // plastic strain ep = e - tau/E, lateral log strain -nu tau/E - ep/2,
  // J = exp((1 - 2 nu) tau / E), Cauchy stress tau / J. Driven in plane stress
  // (the model solves C33) with the axial and in-plane lateral stretches of the
  // closed form: S22 and S33 must vanish and C33 must be the closed form's.
  const double s0 = 200, Hk = 10000;
  const J2Plasticity m{kE, kNu, HardeningCurve({0, 1}, {s0, s0 + Hk}), J2Plasticity::Hardening::Kinematic};
  const double e_peak = 0.2, e_end = -0.15;
  const double ep1 = e_peak - (s0 + Hk * e_peak) / (1 + Hk / kE) / kE;
  const auto closed_form = [&](int leg, double e) {
    if (leg == 0) return e <= s0 / kE ? kE * e : (s0 + Hk * e) / (1 + Hk / kE);
    const double elastic = kE * (e - ep1);
    return elastic >= Hk * ep1 - s0 ? elastic : (Hk * e - s0) / (1 + Hk / kE);
  };
  State state(J2Plasticity::kStateSize, 0.0);
  double worst = 0, worst_lateral = 0, worst_thickness = 0;
  const int n = 100;  // increments per leg
  for (int leg = 0; leg < 2; ++leg)
    for (int k = 1; k <= n; ++k) {
      const double e = leg == 0 ? e_peak * k / n : e_peak + (e_end - e_peak) * k / n;
      const double tau = closed_form(leg, e), ep = e - tau / kE;
      const double lateral = -kNu * tau / kE - ep / 2;
      Eigen::Matrix3d C = Eigen::Vector3d(std::exp(2 * e), std::exp(2 * lateral), 1).asDiagonal();
      State next(state.size());
      double C33 = 0;
      const MaterialResponse r = respond_plane_stress(m, C, state, &next, &C33);
      const double J = std::exp((1 - 2 * kNu) * tau / kE);
      const double cauchy = std::exp(2 * e) * r.stress(0) / J;  // sigma = F S F^T / J
      worst = std::max(worst, std::abs(cauchy - tau / J) / s0);
      worst_lateral = std::max(worst_lateral, std::abs(r.stress(1)) / s0);
      worst_thickness = std::max(worst_thickness, std::abs(0.5 * std::log(C33) - lateral));
      state = next;
    }
  std::printf("uniaxial kinematic, log strain 0.2 -> -0.15: stress %.1e, lateral stress %.1e (of s0), thickness "
              "log strain %.1e; PEEQ %.4f\n", worst, worst_lateral, worst_thickness, state[12]);
  EXPECT_NEAR(state[12], ep1 + (ep1 - (e_end - closed_form(1, e_end) / kE)), 1e-10);
  EXPECT_LT(worst, 1e-8);
  EXPECT_LT(worst_lateral, 1e-8);
  EXPECT_LT(worst_thickness, 1e-10);
}

TEST(J2FiniteStrain, SimpleShearWithKinematicHardeningDoesNotOscillate) {
  // Simple shear to gamma = 8 with linear kinematic hardening (H = 1000, to
  // PEEQ 20): the back stress turns with the material rotation R of F = R U,
  // so the shear stress rises monotonically (a back stress carried by the
  // Jaumann rate would make it oscillate, Nagtegaal and de Jong 1982). Also
  // tau11 = -tau22 and the sign pattern of simple shear.
  const J2Plasticity m{kE, kNu, HardeningCurve({0, 20}, {200, 20200}), J2Plasticity::Hardening::Kinematic};
  State state(J2Plasticity::kStateSize, 0.0);
  double previous = 0;
  int drops = 0;
  Eigen::Matrix3d tau;
  for (int k = 1; k <= 800; ++k) {
    Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
    F(0, 1) = 8.0 * k / 800;
    State next(state.size());
    const MaterialResponse r = respond(m, F.transpose() * F, state, &next);
    tau = F * from_voigt_stress(r.stress) * F.transpose();
    if (tau(0, 1) <= previous) ++drops;
    previous = tau(0, 1);
    state = next;
  }
  std::printf("simple shear to 8: tau12 %.1f, tau11 %.1f, PEEQ %.3f\n", tau(0, 1), tau(0, 0), state[12]);
  EXPECT_EQ(drops, 0);
  EXPECT_GT(tau(0, 1), 1700);
  EXPECT_GT(tau(0, 0), 0);
  EXPECT_NEAR(tau(0, 0), -tau(1, 1), 1e-6 * tau(0, 0));
}
