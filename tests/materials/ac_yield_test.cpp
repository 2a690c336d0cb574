// The yield flag of J2Plasticity (ABAQUS's AC YIELD, actively_yielding()):
// 1 exactly when the increment flowed plastically, on every return (3D and
// plane stress, small and finite strain) and every hardening kind; 0 for
// the elastic models and through the thermal wrapper.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "tether/materials/j2_plasticity.hpp"
#include "tether/materials/linear_elastic.hpp"
#include "tether/materials/thermal_model.hpp"

using namespace tether;

namespace {

constexpr double kE = 200000, kNu = 0.3, kYield = 200;
using State = std::vector<double>;

J2Plasticity model(J2Plasticity::Hardening kind) {
  if (kind == J2Plasticity::Hardening::Combined)
    return {kE, kNu, HardeningCurve({0, 0.01, 1}, {200, 260, 1000}), kind, HardeningCurve({0, 0.005, 1}, {200, 300, 900})};
  return {kE, kNu, HardeningCurve({0, 0.01, 0.05}, {kYield, 300, 350}), kind};
}

/// The isochoric strain diag(e, -e/2, -e/2) reaches the yield stress at e = kYield / (3 mu) (3D).
double yield_strain() { return kYield / (3 * kE / (2 * (1 + kNu))); }

/// One update of `m` from `old` at the strain measure e (see yield_strain):
/// small strain diag(e, -e/2, -e/2), or under `finite` the stretch
/// diag(exp(e), exp(-e/2), exp(-e/2)); plane stress leaves the thickness
/// free. Returns the trial state (the flag, PEEQ, ...).
State update(const ConstitutiveModel& m, const State& old, double e, bool plane, bool finite) {
  State next(old.size());
  MaterialResponse r;
  PointContext where;
  if (finite) {
    Eigen::Matrix3d C = Eigen::Vector3d(std::exp(2 * e), std::exp(-e), std::exp(-e)).asDiagonal();
    m.update_finite_strain(C, plane, old, next, where, r);
  } else {
    Vec6 eps = Vec6::Zero();
    eps << e, -e / 2, -e / 2, 0, 0, 0;
    m.update_small_strain(eps, plane, old, next, where, r);
  }
  return next;
}

const char* name(J2Plasticity::Hardening kind) {
  return kind == J2Plasticity::Hardening::Isotropic ? "isotropic"
         : kind == J2Plasticity::Hardening::Kinematic ? "kinematic"
                                                      : "combined";
}

}  // namespace

TEST(AcYield, LoadElasticallyThenPlasticallyThenUnloadGivesZeroOneZero) {
  const double ey = yield_strain();
  for (const auto kind :
       {J2Plasticity::Hardening::Isotropic, J2Plasticity::Hardening::Kinematic, J2Plasticity::Hardening::Combined})
    for (const bool plane : {false, true})
      for (const bool finite : {false, true}) {
        SCOPED_TRACE(std::string(name(kind)) + (plane ? ", plane stress" : ", 3D") + (finite ? ", NLGEOM" : ""));
        const J2Plasticity m = model(kind);
        State state(J2Plasticity::kStateSize, 0.0);
        m.initial_state(state);
        EXPECT_FALSE(m.actively_yielding(state));  // a virgin point
        // (strain, flag): elastic, plastic, plastic again, unloaded a little, reloaded below the new
        // yield point, reversed into compressive yield.
        const std::vector<std::pair<double, bool>> path = {
            {0.5 * ey, false}, {4 * ey, true}, {8 * ey, true}, {7.5 * ey, false}, {7.9 * ey, false}, {-8 * ey, true}};
        for (const auto& [e, yielding] : path) {
          const State next = update(m, state, e, plane, finite);
          EXPECT_EQ(m.actively_yielding(next), yielding) << "at e = " << e / ey << " e_y";
          EXPECT_EQ(next[J2Plasticity::kYielding], yielding ? 1.0 : 0.0);  // stored as exactly 0 or 1
          EXPECT_EQ(next[J2Plasticity::kPeeq] > state[J2Plasticity::kPeeq], yielding) << "at e = " << e / ey;
          state = next;
        }
      }
}

TEST(AcYield, FlagIsSetExactlyWhenPeeqGrowsOnRandomIncrements) {
  std::mt19937 gen(17);
  std::uniform_real_distribution<double> d(-1, 1);
  const double ey = yield_strain();
  int plastic = 0, elastic = 0;
  for (const auto kind :
       {J2Plasticity::Hardening::Isotropic, J2Plasticity::Hardening::Kinematic, J2Plasticity::Hardening::Combined}) {
    const J2Plasticity m = model(kind);
    for (const bool plane : {false, true})
      for (const bool finite : {false, true}) {
        State state(J2Plasticity::kStateSize, 0.0);
        for (int k = 0; k < 40; ++k) {  // a random walk in e, history carried on
          const double e = 6 * ey * d(gen);
          const State next = update(m, state, e, plane, finite);
          const bool grew = next[J2Plasticity::kPeeq] > state[J2Plasticity::kPeeq];
          EXPECT_EQ(m.actively_yielding(next), grew) << name(kind) << " step " << k;
          (grew ? plastic : elastic) += 1;
          state = next;
        }
      }
  }
  EXPECT_GT(plastic, 50);  // both branches were taken often
  EXPECT_GT(elastic, 50);
}

TEST(AcYield, PointOnTheSurfaceWithTheLoadingTangentDoesNotYield) {
  // A point left on the yield surface by the last increment, evaluated at the
  // same strain in the next increment of the step: the loading tangent, no flow.
  const J2Plasticity m = model(J2Plasticity::Hardening::Isotropic);
  const double ey = yield_strain();
  State state(J2Plasticity::kStateSize, 0.0);
  state = update(m, state, 3 * ey, false, false);
  ASSERT_TRUE(m.actively_yielding(state));
  PointContext later;
  later.step_time = 0.5, later.dt = 0.1;
  ASSERT_TRUE(J2Plasticity::loading_tangent_applies(later));
  Vec6 eps = Vec6::Zero();
  eps << 3 * ey, -1.5 * ey, -1.5 * ey, 0, 0, 0;
  State next(state.size());
  MaterialResponse r;
  m.update_small_strain(eps, false, state, next, later, r);
  EXPECT_EQ(next[J2Plasticity::kPeeq], state[J2Plasticity::kPeeq]);
  EXPECT_FALSE(m.actively_yielding(next));
  EXPECT_LT(r.tangent(0, 0), isotropic_stiffness(kE * kNu / ((1 + kNu) * (1 - 2 * kNu)), kE / (2 * (1 + kNu)))(0, 0));
}

TEST(AcYield, ElasticModelsNeverYieldAndTheThermalWrapperForwardsTheFlag) {
  const LinearElastic elastic(kE, kNu);
  EXPECT_FALSE(elastic.actively_yielding({}));
  const double ey = yield_strain();
  const ThermalModel hot(std::make_unique<J2Plasticity>(model(J2Plasticity::Hardening::Isotropic)),
                         TemperatureTable{{}, {1e-5}}, 0, TemperatureTable{}, TemperatureTable{});
  State state(static_cast<std::size_t>(hot.n_state()), 0.0);
  EXPECT_TRUE(hot.actively_yielding(update(hot, state, 4 * ey, false, false)));
  EXPECT_FALSE(hot.actively_yielding(update(hot, state, 0.5 * ey, false, false)));
}
