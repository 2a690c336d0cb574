// Prescribed motion over a step: *BOUNDARY, TYPE=VELOCITY (the displacement
// is the integral of the velocity, exact for tabular amplitudes), and the
// default variation of prescribed displacements, which ABAQUS/Standard and
// CalculiX define differently in dynamic steps (ramped against held).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "run_deck.hpp"
#include "tether/analysis/amplitude.hpp"
#include "tether/core/error.hpp"
#include "tether/io/deck_reader.hpp"

namespace tether {
namespace {

using DeckRun = tether::testing::Run;
using tether::testing::run_deck_text;
using tether::testing::run_deck_text_in;

TEST(AmplitudeIntegral, IsExactForThePiecewiseLinearTable) {
  Amplitude a;
  a.times = {0, 1, 3};
  a.values = {0, 2, 2};
  EXPECT_DOUBLE_EQ(amplitude_integral(a, 0, 1, 0), 1.0);      // the rising part
  EXPECT_DOUBLE_EQ(amplitude_integral(a, 0.5, 2, 0), 0.75 + 2);  // across a knot: 0.5 * (1 + 2) * 0.5 + 2 * 1
  EXPECT_DOUBLE_EQ(amplitude_integral(a, 3, 5, 0), 4.0);      // held beyond the table's end
  EXPECT_DOUBLE_EQ(amplitude_integral(a, -1, 0, 0), 0.0);     // and before its start
  a.total_time = true;                                        // the step starts at total time 1
  EXPECT_DOUBLE_EQ(amplitude_integral(a, 0, 2, 1), 4.0);
}

TEST(AmplitudeIntegral, RampAndHeldMagnitudes) {
  const Model model;
  // Ramped from 1 to 3 over a period of 2: integral to t is t + t^2/2; held at 3 after the period.
  EXPECT_DOUBLE_EQ(step_magnitude_integral(model, -1, 1, 3, 1, 2, 1), 1.5);
  EXPECT_DOUBLE_EQ(step_magnitude_integral(model, -1, 1, 3, 2, 2, 2), 4.0);
  EXPECT_DOUBLE_EQ(step_magnitude_integral(model, -1, 1, 3, 3, 2, 3), 7.0);
}

/// One CPE4 on rollers at x = 0 whose right edge (nodes 2, 3) is driven in x.
std::string driven_deck(const std::string& boundary, const std::string& procedure,
                        const std::string& step_parameters = "") {
  return "*NODE\n1, 0, 0\n2, 1, 0\n3, 1, 1\n4, 0, 1\n*ELEMENT, TYPE=CPE4, ELSET=ALL\n1, 1, 2, 3, 4\n"
         "*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.3\n*DENSITY\n1.\n*SOLID SECTION, ELSET=ALL, MATERIAL=M\n"
         "*NSET, NSET=RIGHT\n2, 3\n*BOUNDARY\n1, 1, 2\n4, 1\n2, 2\n"
         "*AMPLITUDE, NAME=PULSE\n0., 0., 0.2, 1., 0.6, 1., 0.8, 0.\n"
         "*STEP, INC=1000" + step_parameters + "\n" + procedure + boundary + "*END STEP\n";
}

double right_x(const DeckRun& run, const IncrementResults& r) {
  return r.displacement[static_cast<std::size_t>(run.node(2))].x();
}

TEST(PrescribedVelocity, MovesTheDofByTheVelocityTimesTime) {
  // Implicit dynamic, static and explicit steps: u = v t, held from the step's start.
  for (const std::string procedure :
       {"*DYNAMIC, DIRECT\n0.1, 1.\n", "*STATIC\n0.1, 1.\n", "*DYNAMIC, EXPLICIT\n, 1.\n"}) {
    const DeckRun run = run_deck_text(driven_deck("*BOUNDARY, TYPE=VELOCITY\nRIGHT, 1, 1, 0.02\n", procedure));
    ASSERT_TRUE(run.summary.completed) << procedure << run.summary.message;
    for (const IncrementResults& r : run.recorder.results)
      EXPECT_NEAR(right_x(run, r), 0.02 * r.step_time, 1e-15) << procedure << " at " << r.step_time;
    if (procedure.find("DYNAMIC") != std::string::npos)
      EXPECT_NEAR(run.last().velocity[static_cast<std::size_t>(run.node(3))].x(), 0.02, 1e-12) << procedure;
  }
}

TEST(PrescribedVelocity, WithAnAmplitudeIntegratesItExactly) {
  // PULSE: 0 -> 1 over 0.2, held to 0.6, back to 0 at 0.8: integral 0.6 over the pulse.
  const DeckRun run = run_deck_text(
      driven_deck("*BOUNDARY, TYPE=VELOCITY, AMPLITUDE=PULSE\nRIGHT, 1, 1, 0.05\n", "*DYNAMIC, DIRECT\n0.05, 1.\n"));
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  for (const IncrementResults& r : run.recorder.results) {
    const double t = r.step_time;
    const double integral = t <= 0.2   ? 2.5 * t * t
                            : t <= 0.6 ? 0.1 + (t - 0.2)
                            : t <= 0.8 ? 0.5 + (t - 0.6) - 2.5 * (t - 0.6) * (t - 0.6)
                                       : 0.6;
    EXPECT_NEAR(right_x(run, r), 0.05 * integral, 1e-15) << "at " << t;
  }
}

TEST(PrescribedVelocity, ALaterStepKeepsTheVelocityFromWhereTheDofIs) {
  const std::string deck = driven_deck("*BOUNDARY, TYPE=VELOCITY\nRIGHT, 1, 1, 0.02\n", "*DYNAMIC, DIRECT\n0.1, 1.\n") +
                           "*STEP\n*DYNAMIC, DIRECT\n0.1, 0.5\n*END STEP\n";
  const DeckRun run = run_deck_text(deck);
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  EXPECT_NEAR(right_x(run, run.last()), 0.02 * 1.5, 1e-15);
}

TEST(PrescribedVelocity, BadUseIsRefusedWithItsLine) {
  const auto message = [](const std::string& deck) {
    try {
      (void)read_deck_string(deck, "v.inp");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  std::string model_data = driven_deck("", "*STATIC\n");
  model_data.insert(model_data.find("*STEP"), "*BOUNDARY, TYPE=VELOCITY\n2, 1, 1, 1.\n");
  EXPECT_NE(message(model_data).find("history data"), std::string::npos) << message(model_data);
  const std::string typed = driven_deck("*BOUNDARY, TYPE=VELOCITY\nRIGHT, ENCASTRE\n", "*STATIC\n");
  EXPECT_NE(message(typed).find("v.inp:"), std::string::npos) << message(typed);
  EXPECT_NE(message(typed).find("TYPE=VELOCITY"), std::string::npos) << message(typed);
}

TEST(PrescribedDisplacement, DynamicStepsRampItInAbaqusAndHoldItInCalculix) {
  // ABAQUS/Standard ramps a TYPE=DISPLACEMENT value without an amplitude in
  // every step; CalculiX applies it at once in dynamic steps (ccx 2.20 prints
  // the full value at every increment of a *DYNAMIC step).
  const std::string deck = driven_deck("*BOUNDARY\nRIGHT, 1, 1, 0.01\n", "*DYNAMIC, DIRECT\n0.1, 1.\n");
  const DeckRun abaqus = run_deck_text_in(deck, Dialect::Abaqus);
  const DeckRun calculix = run_deck_text_in(deck, Dialect::Calculix);
  ASSERT_TRUE(abaqus.summary.completed) << abaqus.summary.message;
  ASSERT_TRUE(calculix.summary.completed) << calculix.summary.message;
  for (const IncrementResults& r : abaqus.recorder.results) EXPECT_NEAR(right_x(abaqus, r), 0.01 * r.step_time, 1e-15);
  for (const IncrementResults& r : calculix.recorder.results) EXPECT_EQ(right_x(calculix, r), 0.01);
  // Explicit: held in both (ABAQUS/Explicit's STEP default).
  const DeckRun explicit_run =
      run_deck_text_in(driven_deck("*BOUNDARY\nRIGHT, 1, 1, 0.01\n", "*DYNAMIC, EXPLICIT\n, 0.1\n"), Dialect::Abaqus);
  ASSERT_TRUE(explicit_run.summary.completed) << explicit_run.summary.message;
  for (const IncrementResults& r : explicit_run.recorder.results) EXPECT_EQ(right_x(explicit_run, r), 0.01);
  // *STEP, AMPLITUDE=STEP on a static step: ABAQUS still ramps, CalculiX holds.
  const std::string held = driven_deck("*BOUNDARY\nRIGHT, 1, 1, 0.01\n", "*STATIC\n0.5, 1.\n", ", AMPLITUDE=STEP");
  EXPECT_NEAR(right_x(abaqus, run_deck_text_in(held, Dialect::Abaqus).recorder.results.front()), 0.005, 1e-15);
  EXPECT_EQ(right_x(abaqus, run_deck_text_in(held, Dialect::Calculix).recorder.results.front()), 0.01);
}

}  // namespace
}  // namespace tether
