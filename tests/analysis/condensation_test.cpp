// Condensation onto the contact equations (CondensedSolver) in whole
// analyses: the same answer as the full factorization at every iteration
// (`--no-condense`), with one bulk factorization per step, for frictionless
// and frictional (unsymmetric) contact on an elastic foundation.

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

#include "run_deck.hpp"
#include "support/foundation_deck.hpp"

using namespace tether;
using tether::testing::block_on_foundation;
using tether::testing::run_deck_text;

namespace {

/// Largest nodal displacement difference over all converged increments, relative to the largest displacement.
double largest_difference(const tether::testing::Run& a, const tether::testing::Run& b) {
  double diff = 0, scale = 0;
  const std::size_t n = std::min(a.recorder.results.size(), b.recorder.results.size());
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t i = 0; i < a.recorder.results[k].displacement.size(); ++i) {
      diff = std::max(diff, (a.recorder.results[k].displacement[i] - b.recorder.results[k].displacement[i]).norm());
      scale = std::max(scale, b.recorder.results[k].displacement[i].norm());
    }
  return diff / scale;
}

std::string condensation_message(const tether::testing::Run& run) {
  std::string all;
  for (const std::string& m : run.recorder.messages)
    if (m.find("condensed onto") != std::string::npos) all += m + "\n";
  return all;
}

/// `equations`: the contact equations expected (2 per slave and master node, the multipliers).
void check(const std::string& interaction, double slide, int equations) {
  // SMOOTH: the loaded foundation forms a concave kink at every master node;
  // sliding over them without rounding is a case of its own (faceted_master_test.cpp).
  const std::string deck = block_on_foundation(0.5, interaction, ", SMOOTH=0.2", slide);
  const auto condensed = run_deck_text(deck);
  AnalysisOptions full;
  full.condense_contact = false;
  const auto reference = run_deck_text(deck, full);
  ASSERT_TRUE(condensed.summary.completed) << condensed.summary.message;
  ASSERT_TRUE(reference.summary.completed) << reference.summary.message;
  const std::string messages = condensation_message(condensed);
  std::printf("[ condensed ] %s%d increments, %d iterations (full factorization: %d, %d); "
              "max |du| / max |u| = %.2e\n",
              messages.c_str(), condensed.summary.increments, condensed.summary.iterations,
              reference.summary.increments, reference.summary.iterations, largest_difference(condensed, reference));
  // One bulk factorization per step, every other iteration reused it.
  const std::string onto = "linear solver condensed onto " + std::to_string(equations) + " contact equations: 1 sparse";
  EXPECT_NE(messages.find("step 1: " + onto), std::string::npos) << messages;
  EXPECT_NE(messages.find("step 2: " + onto), std::string::npos) << messages;
  EXPECT_EQ(condensation_message(reference), "");
  EXPECT_EQ(condensed.summary.increments, reference.summary.increments);
  // Round-off differs between the two solves; with friction it can tip a
  // stick/slip decision at one iteration (measured: 65 against 64), not the answer.
  EXPECT_NEAR(condensed.summary.iterations, reference.summary.iterations, 2);
  EXPECT_LT(largest_difference(condensed, reference), 1e-8);
}

}  // namespace

TEST(Condensation, FrictionlessContactEqualsTheFullFactorization) {
  check("", 0.05, 2 * (9 + 81) + 9);  // HARD: one multiplier per slave node
}

TEST(Condensation, FrictionalContactEqualsTheFullFactorization) {
  check("*FRICTION\n0.3\n", 0.05, 2 * (9 + 81) + 2 * 9);  // and one for exact stick
}
