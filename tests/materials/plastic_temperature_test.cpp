// *PLASTIC with a temperature column: the hardening table interpolated in
// the temperature against hand values, constant outside its range; the von
// Mises return at a temperature between two curves against the return with
// the hand-interpolated curve; the tangent against finite differences there.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "material_fixtures.hpp"
#include "tether/materials/j2_plasticity.hpp"

using namespace tether;

namespace {

constexpr double kE = 200000, kNu = 0.3;

/// T = 100: (0, 200), (0.01, 300), (0.05, 350); T = 300: (0, 100), (0.02, 180).
HardeningTable two_temperatures() {
  return {{100, 300}, {HardeningCurve({0, 0.01, 0.05}, {200, 300, 350}), HardeningCurve({0, 0.02}, {100, 180})}};
}

/// Expects a == b to `rel` of |b| (1e-14: the table's own arithmetic).
void expect_close(double a, double b, double rel = 1e-14) { EXPECT_NEAR(a, b, rel * std::abs(b)) << a << " vs " << b; }

PointContext at_temperature(double T, bool loading = false) {
  PointContext c;
  c.temperature = T;
  if (loading) c.step_time = 1, c.dt = 0.5;  // not the first increment: the loading tangent on the surface
  return c;
}

using State = std::vector<double>;

MaterialResponse respond(const J2Plasticity& m, Vec6 eps, bool plane, const State& old, double T,
                         State* next = nullptr) {
  State scratch(old.size());
  MaterialResponse r;
  m.update_small_strain(eps, plane, old, next ? *next : scratch, at_temperature(T), r);
  return r;
}

}  // namespace

TEST(HardeningTable, InterpolatesLinearlyInTemperatureAtTheSamePlasticStrain) {
  const HardeningTable t = two_temperatures();
  // T = 150: w = 1/4 of the hot curve. p = 0.005: 0.75 * 250 + 0.25 * 120.
  expect_close(t.value(0.005, 150), 217.5);
  expect_close(t.slope(0.005, 150), 0.75 * 10000 + 0.25 * 4000);
  // p = 0.03: 0.75 * (300 + 1250 * 0.02) + 0.25 * 180 (the hot curve flat beyond 0.02).
  expect_close(t.value(0.03, 150), 288.75);
  expect_close(t.slope(0.03, 150), 0.75 * 1250);
  expect_close(t.initial(150), 175);
  // T = 250: w = 3/4. p = 0.015: 0.25 * 306.25 + 0.75 * 160.
  expect_close(t.value(0.015, 250), 0.25 * 306.25 + 0.75 * 160);
  expect_close(t.slope(0.015, 250), 0.25 * 1250 + 0.75 * 4000);
  // Integral over [0, 0.005] at 150: trapezoids of each curve, mixed.
  expect_close(t.integral(0, 0.005, 150), 0.75 * 0.5 * (200 + 250) * 0.005 + 0.25 * 0.5 * (100 + 120) * 0.005);
  // At the table temperatures: the curves themselves.
  expect_close(t.value(0.005, 100), 250);
  expect_close(t.value(0.005, 300), 120);
  EXPECT_TRUE(t.depends_on_temperature());
  EXPECT_EQ(t.n_temperatures(), 2);
  EXPECT_EQ(t.n_points(), 5);
}

TEST(HardeningTable, IsConstantOutsideItsTemperatureRange) {
  const HardeningTable t = two_temperatures();
  for (double p : {0.0, 0.005, 0.03, 0.2}) {
    EXPECT_EQ(t.value(p, -50), t.value(p, 100));
    EXPECT_EQ(t.value(p, 20), t.value(p, 100));
    EXPECT_EQ(t.slope(p, 20), t.slope(p, 100));
    EXPECT_EQ(t.value(p, 1000), t.value(p, 300));
    EXPECT_EQ(t.slope(p, 1000), t.slope(p, 300));
  }
  expect_close(t.value(0.005, 20), 250);
  expect_close(t.value(0.005, 1000), 120);
  // One curve: no temperature dependence at all.
  const HardeningTable one(HardeningCurve({0, 0.01}, {200, 300}));
  EXPECT_FALSE(one.depends_on_temperature());
  EXPECT_EQ(one.value(0.005, -1e6), 250);
  EXPECT_EQ(one.value(0.005, 1e6), 250);
}

TEST(HardeningTable, RefusesTemperaturesThatDoNotIncrease) {
  const HardeningCurve c({0, 0.01}, {200, 300});
  EXPECT_THROW(HardeningTable({100, 100}, {c, c}), std::invalid_argument);
  EXPECT_THROW(HardeningTable({300, 100}, {c, c}), std::invalid_argument);
  EXPECT_THROW(HardeningTable({100}, {c, c}), std::invalid_argument);
  EXPECT_THROW(HardeningTable(std::vector<double>{}, std::vector<HardeningCurve>{}), std::invalid_argument);
}

TEST(J2PlasticityTemperature, ReturnBetweenTwoCurvesEqualsTheReturnOnTheInterpolatedCurve) {
  // At T = 150 the curve is piecewise linear through the union of the table
  // points: (0, 175), (0.01, 260), (0.02, 279.375), (0.05, 307.5).
  const HardeningCurve hand({0, 0.01, 0.02, 0.05}, {175, 260, 279.375, 307.5});
  using H = J2Plasticity::Hardening;
  for (H kind : {H::Isotropic, H::Kinematic}) {
    const J2Plasticity table(kE, kNu, two_temperatures(), kind), single(kE, kNu, hand, kind);
    for (bool plane : {false, true}) {
      State s_table(J2Plasticity::kStateSize, 0.0), s_single = s_table, next_table = s_table, next = s_table;
      Vec6 eps = Vec6::Zero();
      // Load, unload, reverse: a path through several segments of the curve.
      for (double e11 : {0.004, 0.012, 0.025, 0.02, -0.01}) {
        eps(0) = e11, eps(1) = -0.4 * e11, eps(3) = 0.3 * e11;
        if (!plane) eps(2) = -0.2 * e11;
        const MaterialResponse a = respond(table, eps, plane, s_table, 150, &next_table);
        const MaterialResponse b = respond(single, eps, plane, s_single, 150, &next);
        s_table.swap(next_table), s_single.swap(next);  // (a copy here trips GCC 12's -Wstringop-overflow)
        EXPECT_LT((a.stress - b.stress).norm(), 1e-10 * b.stress.norm()) << e11;
        EXPECT_LT((a.tangent - b.tangent).norm(), 1e-10 * b.tangent.norm()) << e11;
        for (int i = 0; i < J2Plasticity::kStateSize; ++i)
          EXPECT_NEAR(s_table[i], s_single[i], 1e-12 * std::max(1.0, std::abs(s_single[i]))) << i;
        EXPECT_NEAR(a.dissipation, b.dissipation, 1e-10 * std::max(1.0, std::abs(b.dissipation)));
      }
      EXPECT_GT(s_table[12], 0.02);  // well into the third segment
    }
  }
}

TEST(J2PlasticityTemperature, TangentMatchesFiniteDifferencesBetweenTwoCurves) {
  using H = J2Plasticity::Hardening;
  // Combined: the cyclic table has its own temperatures.
  const HardeningTable cyclic({50, 250}, {HardeningCurve({0, 0.005, 1}, {200, 300, 900}),
                                          HardeningCurve({0, 0.01, 1}, {120, 150, 400})});
  const std::vector<J2Plasticity> models = {J2Plasticity(kE, kNu, two_temperatures(), H::Isotropic),
                                            J2Plasticity(kE, kNu, two_temperatures(), H::Kinematic),
                                            J2Plasticity(kE, kNu, two_temperatures(), H::Combined, cyclic)};
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> d(-1, 1);
  const double T = 187;  // strictly between the table temperatures of both tables
  for (const J2Plasticity& m : models)
    for (bool plane : {false, true}) {
      int n_plastic = 0;
      for (int k = 0; k < 20; ++k) {
        State old(J2Plasticity::kStateSize, 0.0), next(old.size());
        old[12] = 0.003 + 0.004 * (1 + d(gen));  // PEEQ in (0.003, 0.011): inside the first segments
        for (int i : {6, 7, 9}) old[i] = 20 * d(gen);
        old[8] = -(old[6] + old[7]);
        Vec6 eps = Vec6::Zero();
        for (int i : {0, 1, 3}) eps(i) = 5e-3 * d(gen);
        if (!plane) eps(2) = 5e-3 * d(gen), eps(4) = 5e-3 * d(gen), eps(5) = 5e-3 * d(gen);
        const MaterialResponse r = respond(m, eps, plane, old, T, &next);
        if (!(next[12] > old[12])) continue;
        ++n_plastic;
        const double h = 1e-8;
        for (int j = 0; j < 6; ++j) {
          if (plane && (j == 2 || j > 3)) continue;
          Vec6 ep = eps, em = eps;
          ep(j) += h, em(j) -= h;
          const Vec6 fd = (respond(m, ep, plane, old, T).stress - respond(m, em, plane, old, T).stress) / (2 * h);
          EXPECT_LT((fd - r.tangent.col(j)).norm(), 1e-6 * r.tangent.norm())
              << m.describe() << " column " << j << (plane ? " plane stress" : " 3D");
        }
      }
      EXPECT_GE(n_plastic, 10) << m.describe();
    }
}

TEST(J2PlasticityTemperature, FiniteStrainTangentMatchesFiniteDifferencesBetweenTwoCurves) {
  const J2Plasticity m(kE, kNu, two_temperatures(), J2Plasticity::Hardening::Isotropic);
  State old(J2Plasticity::kStateSize, 0.0), next(old.size());
  old[12] = 0.004;
  Eigen::Matrix3d F;
  F << 1.006, 0.002, 0, -0.001, 0.997, 0, 0, 0, 0.998;
  const auto stress = [&](const Eigen::Matrix3d& C, State& out, MaterialResponse& r) {
    Eigen::Matrix3d c = C;
    m.update_finite_strain(c, false, old, out, at_temperature(150), r);
  };
  const Eigen::Matrix3d C = F.transpose() * F;
  MaterialResponse r, rp, rm;
  stress(C, next, r);
  ASSERT_GT(next[12], old[12]);
  EXPECT_GT(m.yield_radius(next[12], 150), m.yield_radius(next[12], 300));
  State scratch(old.size());
  const double h = 1e-8;
  for (int j = 0; j < 6; ++j) {
    Vec6 Ep = test::green_lagrange_of(C), Em = Ep;
    Ep(j) += h, Em(j) -= h;
    stress(test::cauchy_green_of(Ep), scratch, rp);
    stress(test::cauchy_green_of(Em), scratch, rm);
    const Vec6 fd = (rp.stress - rm.stress) / (2 * h);
    EXPECT_LT((fd - r.tangent.col(j)).norm(), 1e-6 * r.tangent.norm()) << "column " << j;
  }
}

TEST(J2PlasticityTemperature, YieldSurfaceIsThatOfTheCurrentTemperature) {
  // A virgin point strained uniaxially to just below the yield stress of 100
  // degrees is elastic there, plastic at 300 degrees (the return uses the
  // temperature of the end of the increment).
  const J2Plasticity m(kE, kNu, two_temperatures(), J2Plasticity::Hardening::Isotropic);
  const State old(J2Plasticity::kStateSize, 0.0);
  State next(old.size());
  Vec6 eps = Vec6::Zero();
  eps(0) = 190.0 / kE;
  respond(m, eps, true, old, 100, &next);
  EXPECT_EQ(next[12], 0);
  const MaterialResponse hot = respond(m, eps, true, old, 300, &next);
  ASSERT_GT(next[12], 0);
  // On the hot curve: the von Mises stress (plane stress) is 100 + 4000 p.
  const double s11 = hot.stress(0), s22 = hot.stress(1), s12 = hot.stress(3);
  const double q = std::sqrt(s11 * s11 - s11 * s22 + s22 * s22 + 3 * s12 * s12);
  EXPECT_NEAR(q, 100 + 4000 * next[12], 1e-10 * q);
}
