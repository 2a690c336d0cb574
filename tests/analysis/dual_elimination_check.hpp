#pragma once
// Test helper: a deck run with the contact multipliers kept in the dense
// interface system and with them eliminated (--mortar-condensation kept /
// dense), compared: the same increments, iterations within a slack, and
// displacements and contact pressures within a tolerance of their largest.

#include <gtest/gtest.h>

#include <cstdio>
#include <functional>
#include <string>

#include "run_deck.hpp"

namespace tether::testing {

/// The `.msg` lines of a run that describe its condensed solver.
inline std::string condensation_log(const Run& run) {
  std::string all;
  for (const std::string& m : run.recorder.messages)
    if (m.find("condensed onto") != std::string::npos) all += m + "\n";
  return all;
}

/// Runs `deck` with the multipliers kept and eliminated and expects the same
/// answer: increments equal, iterations within `iteration_slack` (frictional
/// stick/slip decisions at the cone's edge rest on round-off), displacements
/// and contact pressures within `tolerance` of the largest. `check_logs`
/// looks at the two runs' condensation logs (kept, eliminated); `label`
/// heads the printed summary.
inline void expect_elimination_same_as_kept(
    const std::string& label, const std::string& what, const std::string& deck, double tolerance,
    int iteration_slack, const std::function<void(const std::string&, const std::string&)>& check_logs) {
  AnalysisOptions kept;
  kept.condense_any_size = true;
  kept.mortar_condensation = MortarCondensation::Kept;
  AnalysisOptions dense = kept;
  dense.mortar_condensation = MortarCondensation::Dense;
  const Run a = run_deck_text(deck, kept);
  const Run b = run_deck_text(deck, dense);
  ASSERT_TRUE(a.summary.completed) << what << ": " << a.summary.message;
  ASSERT_TRUE(b.summary.completed) << what << ": " << b.summary.message;
  const std::string a_log = condensation_log(a), b_log = condensation_log(b);
  EXPECT_EQ(a_log.find("dual elimination"), std::string::npos) << what << ": " << a_log;
  check_logs(a_log, b_log);
  EXPECT_EQ(b.summary.increments, a.summary.increments) << what;
  EXPECT_NEAR(b.summary.iterations, a.summary.iterations, iteration_slack) << what;
  ASSERT_EQ(b.recorder.results.size(), a.recorder.results.size()) << what;
  const RunDifferences d = run_differences(a, b);
  std::printf("[ %s ] %s: %d increments, %d iterations (kept %d); max |du| / max |u| %.1e, "
              "max |dp| / max |p| %.1e\n%s",
              label.c_str(), what.c_str(), b.summary.increments, b.summary.iterations, a.summary.iterations,
              d.displacement / d.displacement_scale, d.pressure / d.pressure_scale, b_log.c_str());
  EXPECT_LT(d.displacement, tolerance * d.displacement_scale) << what;
  EXPECT_LT(d.pressure, tolerance * d.pressure_scale) << what;
}

}  // namespace tether::testing
