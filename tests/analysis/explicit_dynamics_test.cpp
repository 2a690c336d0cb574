// *DYNAMIC, EXPLICIT (central differences, lumped mass): stress waves in a
// 1D-strain bar against c_p and rho c_p v, free flight, gravity, refused
// input, restarts within a step.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Eigenvalues>

#include "bar_decks.hpp"
#include "run_deck.hpp"
#include "tether/analysis/increment_controller.hpp"
#include "tether/analysis/stable_increment.hpp"
#include "tether/analysis/step_system.hpp"
#include "tether/io/deck_reader.hpp"
#include "tether/output/restart_file.hpp"
#include "explicit_decks.hpp"

namespace tether {
namespace {

using DeckRun = tether::testing::Run;
using tether::testing::run_deck_text;
using namespace tether::testing;  // explicit_decks.hpp, bar_decks.hpp


/// Where the x velocity along the bar's bottom edge first crosses `level`
/// coming from x = 0 (linear between nodes) [length].
double front_position(const DeckRun& run, const IncrementResults& r, int n, double h, double level) {
  for (int i = 0; i < n; ++i) {
    const double a = r.velocity[static_cast<std::size_t>(run.node(i + 1))].x() - level;
    const double b = r.velocity[static_cast<std::size_t>(run.node(i + 2))].x() - level;
    if (a * b <= 0 && a != b) return h * (i + a / (a - b));
  }
  return -1;
}

TEST(ExplicitDynamics, ImpactWaveTravelsAtTheDilatationalSpeedWithAmplitudeRhoCpV) {
  // The bar moves at -v0 onto its held left end: a compression wave of
  // stress rho c_p v0 runs to the free end and brings the bar to rest there.
  const int n = 200;
  const double h = 0.01, length = n * h, v0 = 1, transit = length / kCp;
  const DeckRun run = run_deck_text(bar_deck(n, h, "LEFT, 1, 1\n*INITIAL CONDITIONS, TYPE=VELOCITY\nINNER, 1, -1.\nRIGHT, 1, -1.\n",
                                             "*DYNAMIC, EXPLICIT\n, " + num(transit) + "\n"));
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  ASSERT_EQ(run.recorder.results.size(), 100u);
  double worst_front = 0, force_sum = 0;
  int n_force = 0;
  for (const IncrementResults& r : run.recorder.results) {
    const double t = r.step_time;
    if (t < 0.1 * transit || t > 0.9 * transit) continue;
    // The front: where the velocity is halfway between -v0 (ahead) and 0 (behind).
    const double front = front_position(run, r, n, h, -0.5 * v0);
    worst_front = std::max(worst_front, std::abs(front - kCp * t));
    double reaction = 0;
    for (int node : run.model.node_sets.at("LEFT")) reaction += r.reaction[static_cast<std::size_t>(node)].x();
    force_sum += reaction, ++n_force;
  }
  const double force = force_sum / n_force, expected = kRho * kCp * v0 * h;  // area h x 1
  std::printf("front error %.3g elements, wall force %.6g against %.6g (%.3g %%)\n", worst_front / h, force, expected,
              100 * (force / expected - 1));
  EXPECT_LT(worst_front, 2 * h);                  // 1 % of the bar
  EXPECT_NEAR(force / expected, 1, 0.01);         // the wall holds rho c_p v0 A
  // At L / c_p the whole bar is at rest (to the scheme's dispersion).
  double fastest = 0;
  for (const Eigen::Vector2d& v : run.last().velocity) fastest = std::max(fastest, std::abs(v.x()));
  EXPECT_LT(fastest, 0.5 * v0);  // the dispersive tail of the front only
  double mean = 0;
  for (int i = 0; i < 2 * n + 2; ++i) mean += run.last().velocity[static_cast<std::size_t>(i)].x();
  EXPECT_NEAR(mean / (2 * n + 2), 0, 0.02 * v0);
}

TEST(ExplicitDynamics, PrescribedEndVelocityDrivesAWaveAndTheEnergyBalances) {
  // The left end pushed at v0 into the resting bar: the driving force is
  // rho c_p v0 A and its work becomes kinetic and strain energy in equal parts.
  const int n = 200;
  const double h = 0.01, length = n * h, v0 = 2, transit = length / kCp;
  const DeckRun run = run_deck_text(
      bar_deck(n, h, "*AMPLITUDE, NAME=LINEAR\n0., 0., 1., 1.\n*BOUNDARY, AMPLITUDE=LINEAR\nLEFT, 1, 1, " + num(v0) + "\n",
               "*DYNAMIC, EXPLICIT\n, " + num(0.8 * transit) + "\n*NODE PRINT, NSET=LEFT\nU, V, A, RF\n"));
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  const IncrementResults& end = run.last();
  const double t = end.step_time;
  EXPECT_NEAR(end.displacement[static_cast<std::size_t>(run.node(1))].x(), v0 * t, 1e-12 * v0 * t);
  EXPECT_NEAR(end.velocity[static_cast<std::size_t>(run.node(1))].x(), v0, 1e-9 * v0);
  const double force = run.reaction_sum("LEFT", 0), expected = kRho * kCp * v0 * h;
  const EnergyTotals& e = *end.energy;
  const double work = expected * v0 * t;  // constant force times the displacement
  std::printf("driving force %.6g against %.6g; ALLWK %.6g against %.6g; ALLKE %.6g ALLSE %.6g numerical %.3g\n", force,
              expected, e.work, work, e.kinetic, e.strain, e.numerical);
  EXPECT_NEAR(force / expected, 1, 0.01);
  EXPECT_NEAR(e.work / work, 1, 0.01);
  EXPECT_NEAR(e.kinetic / e.strain, 1, 0.02);
  EXPECT_LT(std::abs(e.numerical), 2e-3 * e.work);
  for (const IncrementResults& r : run.recorder.results) EXPECT_LT(std::abs(r.energy->numerical), 2e-3 * e.work + 1e-9);
}

TEST(ExplicitDynamics, AFreeBodyFliesAtItsInitialVelocity) {
  const std::string deck =
      "*NODE\n1, 0, 0\n2, 2, 0\n3, 2, 1\n4, 0, 1\n5, 4, 0\n6, 4, 1\n*ELEMENT, TYPE=CPE4, ELSET=ALL\n1, 1, 2, 3, 4\n"
      "2, 2, 5, 6, 3\n*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.3\n*DENSITY\n2.\n*SOLID SECTION, ELSET=ALL, MATERIAL=M\n"
      "*NSET, NSET=ALLN, GENERATE\n1, 6, 1\n*INITIAL CONDITIONS, TYPE=VELOCITY\nALLN, 1, 3.\nALLN, 2, -1.\n"
      "*STEP\n*DYNAMIC, EXPLICIT\n, 1.\n*END STEP\n";
  const DeckRun run = run_deck_text(deck);
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  for (const IncrementResults& r : run.recorder.results)
    for (std::size_t i = 0; i < r.displacement.size(); ++i) {
      ASSERT_NEAR(r.displacement[i].x(), 3 * r.step_time, 1e-12);
      ASSERT_NEAR(r.displacement[i].y(), -r.step_time, 1e-12);
      ASSERT_NEAR(r.velocity[i].x(), 3, 1e-12);
      ASSERT_NEAR(r.acceleration[i].norm(), 0, 1e-9);
    }
  const EnergyTotals& e = *run.last().energy;
  EXPECT_NEAR(e.kinetic, 0.5 * 2 * 4 * 10, 1e-9);  // rho 2, area 4, |v|^2 10
  EXPECT_NEAR(e.strain, 0, 1e-12);
  EXPECT_EQ(e.work, 0);
}

TEST(ExplicitDynamics, GravityActsFromTheStartOfADynamicStep) {
  // Dynamic steps hold their loads from the start (AMPLITUDE=STEP by
  // default), body loads too: a free block falls g t^2 / 2, which central
  // differences integrate exactly. A RAMP step ramps it: g t^3 / (6 T).
  for (const std::string amplitude : {"", ", AMPLITUDE=RAMP"}) {
    const std::string deck =
        "*NODE\n1, 0, 0\n2, 1, 0\n3, 1, 1\n4, 0, 1\n*ELEMENT, TYPE=CPE4, ELSET=ALL\n1, 1, 2, 3, 4\n*MATERIAL, NAME=M\n"
        "*ELASTIC\n1000., 0.3\n*DENSITY\n2.\n*SOLID SECTION, ELSET=ALL, MATERIAL=M\n*STEP" + amplitude +
        "\n*DYNAMIC, EXPLICIT\n, 0.5\n*DLOAD\nALL, GRAV, 9.8, 0., -1.\n*END STEP\n";
    const DeckRun run = run_deck_text(deck);
    ASSERT_TRUE(run.summary.completed) << run.summary.message;
    const double t = run.last().step_time;
    const double expected = amplitude.empty() ? -9.8 * t * t / 2 : -9.8 * t * t * t / (6 * 0.5);
    // Exact for a constant acceleration; O(h^2) for the ramp (18 increments: 0.3 %).
    const double tolerance = amplitude.empty() ? 1e-12 : 1e-2;
    for (const Eigen::Vector2d& u : run.last().displacement)
      EXPECT_NEAR(u.y(), expected, tolerance * std::abs(expected)) << amplitude;
  }
}

TEST(ExplicitDynamics, UnsupportedContributionsAreRefusedByName) {
  const std::string base = bar_deck(2, 0.01, "", "*DYNAMIC, EXPLICIT\n, 1e-5\n");
  // Constraints: exact multipliers only (eliminated, penalty and regularised ones are refused).
  for (const auto& [enforcement, why] : std::vector<std::pair<std::string, std::string>>{
           {"ENFORCEMENT=ELIMINATION", "does not support eliminated dofs"},
           {"ENFORCEMENT=PENALTY, PENALTY=1e9", "without a multiplier"},
           {"EPSILON=1e-9", "regularised"}}) {
    std::string equation = base;
    equation.replace(equation.find("*STEP"), 5, "*EQUATION, " + enforcement + "\n2\n2, 1, 1., 3, 1, -1.\n*STEP");
    const DeckRun eq = run_deck_text(equation);
    EXPECT_FALSE(eq.summary.completed) << enforcement;
    EXPECT_NE(eq.summary.message.find("*DYNAMIC, EXPLICIT"), std::string::npos) << eq.summary.message;
    EXPECT_NE(eq.summary.message.find(why), std::string::npos) << eq.summary.message;
  }

  std::string no_density = base;
  no_density.erase(no_density.find("*DENSITY"), std::string("*DENSITY\n7800\n").size());
  const DeckRun nd = run_deck_text(no_density);
  EXPECT_FALSE(nd.summary.completed);
  EXPECT_NE(nd.summary.message.find("STEEL"), std::string::npos) << nd.summary.message;
}


/// Keeps the restart states (through the file format) and the results.
class StateRecorder final : public AnalysisObserver {
 public:
  void on_results(const IncrementResults& r, const Step&, bool) override { results.push_back(r); }
  void on_restart_state(const RestartState& s) override {
    states.push_back(decode_restart(encode_restart(s), "memory.rst"));
  }
  std::vector<IncrementResults> results;
  std::vector<RestartState> states;
};

TEST(ExplicitDynamics, ARestartWithinTheStepContinuesTheSameMotion) {
  // The bar on the wall, saved at every report: resumed during the contact
  // and after it, the run ends where the uninterrupted one does.
  std::string deck = wall_deck(40, 0.01, 1, 2.2 * 0.4 / kCp);
  deck.replace(deck.find("*STEP"), 5, "*RESTART, WRITE, FREQUENCY=1\n*STEP");
  const Model model = read_deck_string(deck, "test.inp");
  StateRecorder full;
  StaticAnalysis uninterrupted(model, full);
  ASSERT_TRUE(uninterrupted.run().completed);
  const Eigen::VectorXd u_full = uninterrupted.solution();
  ASSERT_GE(full.states.size(), 90u);
  for (const std::size_t k : {std::size_t{30}, std::size_t{95}}) {
    StateRecorder resumed;
    StaticAnalysis analysis(model, resumed);
    analysis.resume(full.states[k], "memory.rst");
    ASSERT_TRUE(analysis.run().completed) << "from report " << k + 1;
    const Eigen::VectorXd u = analysis.solution();
    const int n_disp = 2 * static_cast<int>(model.coords.size());
    EXPECT_LT((u - u_full).head(n_disp).cwiseAbs().maxCoeff(), 1e-12 * u_full.head(n_disp).cwiseAbs().maxCoeff())
        << "from report " << k + 1;
    EXPECT_NEAR(resumed.results.back().velocity[0].x(), full.results.back().velocity[0].x(), 1e-9)
        << "from report " << k + 1;
  }
}

TEST(ExplicitDamping, ARestartWithMassDampingContinuesTheSameMotion) {
  // The exponential update composes exactly (two half increments make one),
  // so a restart from the full-step state of a report continues the run.
  std::string deck = wall_deck(40, 0.01, 1, 2.2 * 0.4 / kCp);
  deck.replace(deck.find("*DENSITY\n7800"), 13, "*DAMPING, ALPHA=2000.\n*DENSITY\n7800");
  deck.replace(deck.find("*STEP"), 5, "*RESTART, WRITE, FREQUENCY=1\n*STEP");
  const Model model = read_deck_string(deck, "test.inp");
  StateRecorder full;
  StaticAnalysis uninterrupted(model, full);
  ASSERT_TRUE(uninterrupted.run().completed);
  const Eigen::VectorXd u_full = uninterrupted.solution();
  ASSERT_GT(full.results.back().energy->viscous, 0.01 * full.results.front().energy->kinetic);  // it damps
  StateRecorder resumed;
  StaticAnalysis analysis(model, resumed);
  analysis.resume(full.states[40], "memory.rst");
  ASSERT_TRUE(analysis.run().completed);
  const int n_disp = 2 * static_cast<int>(model.coords.size());
  EXPECT_LT((analysis.solution() - u_full).head(n_disp).cwiseAbs().maxCoeff(),
            1e-12 * u_full.head(n_disp).cwiseAbs().maxCoeff());
  // ALLVD is a sum of force x displacement over increments: the restart's half
  // increment splits one of them differently (measured 1.5e-5 of ALLVD).
  EXPECT_NEAR(resumed.results.back().energy->viscous, full.results.back().energy->viscous,
              1e-4 * full.results.back().energy->viscous);
}

}  // namespace
}  // namespace tether
