// A step whose bulk is linear in u holds the bulk's tangent, reuses the
// factorization of an unchanged tangent and takes the bulk's residual from
// the held tangent within a Newton solve (SolverSettings::reuse_linear_bulk,
// Assembler::enable_residual_updates): the answer must be the one that
// assembling and factorizing everything at every iteration gives, to
// round-off (the residual's sums are taken in another order), with the same
// increments and iterations, also when the increment size changes in a
// dynamic step (the inertia's tangent M / (beta dt^2) changes with it) and
// from one step to the next.

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "run_deck.hpp"
#include "support/block_mesh.hpp"
#include "support/foundation_deck.hpp"

using namespace tether;
using tether::testing::Block;
using tether::testing::block_on_foundation;
using tether::testing::run_deck_text;
using DeckRun = tether::testing::Run;

namespace {

/// Relative round-off allowed between the held and the fresh answer: the
/// largest difference of a field over its largest magnitude.
constexpr double kRoundOff = 1e-10;

/// max |a - b| over max |b| (0 when both are zero) of one field over the nodes.
double relative_difference(const std::vector<Eigen::Vector2d>& a, const std::vector<Eigen::Vector2d>& b) {
  double difference = 0, scale = 0;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
    difference = std::max(difference, (a[i] - b[i]).cwiseAbs().maxCoeff());
    scale = std::max(scale, b[i].cwiseAbs().maxCoeff());
  }
  return scale > 0 ? difference / scale : difference;
}

/// Runs `deck` with the linear bulk held and with everything assembled and
/// factorized at every iteration, and expects the same increments and
/// iterations, and displacements and reactions within kRoundOff, at every
/// converged increment.
DeckRun expect_same_as_fresh(const std::string& deck) {
  DeckRun held = run_deck_text(deck);
  AnalysisOptions fresh_options;
  fresh_options.reuse_linear_bulk = false;
  const DeckRun fresh = run_deck_text(deck, fresh_options);
  EXPECT_TRUE(held.summary.completed) << held.summary.message;
  EXPECT_TRUE(fresh.summary.completed) << fresh.summary.message;
  EXPECT_EQ(held.summary.increments, fresh.summary.increments);
  EXPECT_EQ(held.summary.iterations, fresh.summary.iterations);
  EXPECT_EQ(fresh.summary.timing.held_tangents, 0);
  EXPECT_EQ(fresh.summary.timing.reused_factorizations, 0);
  EXPECT_EQ(held.recorder.results.size(), fresh.recorder.results.size());
  for (std::size_t k = 0; k < std::min(held.recorder.results.size(), fresh.recorder.results.size()); ++k) {
    const IncrementResults& a = held.recorder.results[k];
    const IncrementResults& b = fresh.recorder.results[k];
    EXPECT_EQ(a.total_time, b.total_time) << "increment " << k;
    EXPECT_EQ(a.displacement.size(), b.displacement.size());
    EXPECT_LE(relative_difference(a.displacement, b.displacement), kRoundOff) << "displacements, increment " << k;
    EXPECT_LE(relative_difference(a.reaction, b.reaction), kRoundOff) << "reactions, increment " << k;
  }
  return held;
}

/// A 12 x 3 CPE4 cantilever with density, held at its left end, loaded at
/// its right end in two *DYNAMIC steps: `first` and `second` are the steps'
/// time lines (initial increment, period) of DIRECT incrementation, `more`
/// further step data of the first step.
std::string cantilever(const std::string& first, const std::string& second, const std::string& more = "") {
  const Block beam{0, 4, 0, 1, 12, 3, false, 1, 1, "BEAM"};
  std::ostringstream d;
  beam.write(d);
  d << "*MATERIAL, NAME=M\n*ELASTIC\n1000, 0.3\n*DENSITY\n1.\n*SOLID SECTION, ELSET=BEAM, MATERIAL=M\n";
  d << "*NSET, NSET=LEFT, GENERATE\n" << beam.grid(0, 0) << ", " << beam.grid(0, beam.ny) << ", " << beam.nx + 1 << "\n";
  d << "*BOUNDARY\nLEFT, 1, 2\n";
  d << "*STEP, INC=100\n*DYNAMIC, ALPHA=-0.05, DIRECT\n" << first << "\n*CLOAD\n"
    << beam.grid(beam.nx, beam.ny) << ", 2, -1.\n" << more << "*END STEP\n";
  d << "*STEP, INC=100\n*DYNAMIC, ALPHA=-0.05, DIRECT\n" << second << "\n*CLOAD\n"
    << beam.grid(beam.nx, beam.ny) << ", 2, 0.5\n*END STEP\n";
  return d.str();
}

}  // namespace

TEST(BulkReuse, DynamicStepAtChangingIncrementsGivesTheFreshAnswer) {
  // Increments 0.125, 0.125, 0.125, then 0.0625 (the period's remainder),
  // then a second step at 0.03125 (binary fractions: the increments are
  // exactly equal): every change of dt must assemble the inertia's tangent
  // anew and factorize it again; at a fixed dt neither is done.
  const DeckRun held = expect_same_as_fresh(cantilever("0.125, 0.4375", "0.03125, 0.125"));
  const SolveTiming& t = held.summary.timing;
  EXPECT_EQ(held.summary.increments, 4 + 4);
  // One factorization per increment size per step: 0.125, 0.0625, then 0.03125.
  EXPECT_EQ(t.factorizations, 3) << t.reused_factorizations << " reused";
  EXPECT_GT(t.reused_factorizations, 0);
  EXPECT_GT(t.held_tangents, 0);
  EXPECT_EQ(t.full_tangents, 3);
  EXPECT_GT(t.residual_updates, 0);
}

TEST(BulkReuse, DampedDynamicStepGivesTheFreshAnswer) {
  // Rayleigh damping: C = alpha M + beta K enters the tangent with gamma / (beta dt).
  std::string deck = cantilever("0.1, 0.3", "0.05, 0.1");
  deck.replace(deck.find("*DENSITY"), 8, "*DAMPING, ALPHA=0.5, BETA=0.001\n*DENSITY");
  expect_same_as_fresh(deck);
}

TEST(BulkReuse, StaticContactStepsGiveTheFreshAnswer) {
  // Frictionless HARD contact on an elastic foundation, pressed, then slid
  // (re-pairing the slave nodes): two steps, condensed onto the contact equations.
  const DeckRun held = expect_same_as_fresh(block_on_foundation(0.5, "", ", SMOOTH=0.2", 0.05));
  EXPECT_GT(held.summary.timing.held_tangents, held.summary.timing.full_tangents);
  // Most evaluations take the bulk's residual from the held tangent: all
  // but the first of each Newton solve (and the step's first, which assembles in full).
  EXPECT_GT(held.summary.timing.residual_updates, held.summary.iterations / 2);
}

TEST(BulkReuse, FrictionalContactGivesTheFreshAnswer) {
  // Friction (an unsymmetric tangent) takes every residual from the
  // elements: its stick/slip decisions rest on round-off.
  const DeckRun held = expect_same_as_fresh(block_on_foundation(0.5, "*FRICTION\n0.3\n", ", SMOOTH=0.2", 0.05));
  EXPECT_EQ(held.summary.timing.residual_updates, 0);
}

TEST(BulkReuse, DynamicContactAtChangingIncrementsGivesTheFreshAnswer) {
  // The block pressed onto the foundation and slid in two *DYNAMIC steps
  // (HHT, DIRECT) whose increments change: within an increment size only the
  // contact equations change (the condensed solver keeps the bulk on the
  // assembler's word); a new size must factorize the bulk again.
  std::string deck = block_on_foundation(0.5, "", ", SMOOTH=0.2", 0.05);
  const auto replace = [&](const std::string& from, const std::string& to) {
    const auto at = deck.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    deck.replace(at, from.size(), to);
  };
  replace("*ELASTIC\n1000, 0.3\n", "*ELASTIC\n1000, 0.3\n*DENSITY\n0.01\n");
  replace("*STEP\n*STATIC\n0.5, 1\n", "*STEP, INC=100, AMPLITUDE=RAMP\n*DYNAMIC, ALPHA=-0.05, DIRECT\n0.25, 0.875\n");
  replace("*STEP, INC=100\n*STATIC, DIRECT\n0.125, 1\n", "*STEP, INC=100, AMPLITUDE=RAMP\n*DYNAMIC, ALPHA=-0.05, DIRECT\n0.125, 0.5\n");
  const DeckRun held = expect_same_as_fresh(deck);
  const SolveTiming& t = held.summary.timing;
  EXPECT_EQ(held.summary.increments, 4 + 4);
  EXPECT_EQ(t.full_tangents, 3);  // dt 0.25, 0.125 (the remainder) and 0.125 in the second step
  EXPECT_EQ(t.sparse_factorizations, 3);
}

TEST(BulkReuse, LinearStaticStepFactorizesOnce) {
  // A linear elastic step in four increments: one factorization, reused by
  // the other three increments. The load is not proportional to time (an
  // amplitude of 1, 1.5, 3, 3.5 at the increments' ends): under a ramp the
  // predictor, extrapolating the last increment, would already be the
  // solution and no increment after the first would solve.
  const Block plate{0, 2, 0, 1, 8, 4, false, 1, 1, "PLATE"};
  std::ostringstream d;
  plate.write(d);
  d << "*MATERIAL, NAME=M\n*ELASTIC\n1000, 0.3\n*SOLID SECTION, ELSET=PLATE, MATERIAL=M\n";
  d << "*NSET, NSET=LEFT, GENERATE\n" << plate.grid(0, 0) << ", " << plate.grid(0, plate.ny) << ", " << plate.nx + 1
    << "\n*BOUNDARY\nLEFT, 1, 2\n";
  d << "*AMPLITUDE, NAME=A\n0., 0., 0.25, 1., 0.5, 1.5, 0.75, 3.\n1., 3.5\n";
  d << "*STEP\n*STATIC, DIRECT\n0.25, 1\n*CLOAD, AMPLITUDE=A\n" << plate.grid(plate.nx, plate.ny)
    << ", 1, 2.\n*END STEP\n";
  const DeckRun held = expect_same_as_fresh(d.str());
  EXPECT_EQ(held.summary.increments, 4);
  EXPECT_EQ(held.summary.timing.factorizations, 1);
  EXPECT_EQ(held.summary.timing.reused_factorizations, 3);
}

TEST(BulkReuse, ReferenceServesTheStepUnderAmplitudesAndMovingSupports) {
  // Four static increments of an elastic plate: a pressure on its right side
  // under one amplitude (a face load, evaluated again at u_ref per
  // increment), a prescribed displacement of its top right corner under
  // another (the elements at it are evaluated at every residual). The bulk's
  // elements are evaluated for the step's first two residuals only; all
  // later ones, across the increments, come from the held tangent, and the
  // answer is the element loop's to round-off.
  const Block plate{0, 2, 0, 1, 8, 4, false, 1, 1, "PLATE"};
  std::ostringstream d;
  plate.write(d);
  d << "*MATERIAL, NAME=M\n*ELASTIC\n1000, 0.3\n*SOLID SECTION, ELSET=PLATE, MATERIAL=M\n";
  d << "*NSET, NSET=LEFT, GENERATE\n" << plate.grid(0, 0) << ", " << plate.grid(0, plate.ny) << ", " << plate.nx + 1
    << "\n*ELSET, ELSET=RIGHT, GENERATE\n" << plate.element(plate.nx - 1, 0) << ", "
    << plate.element(plate.nx - 1, plate.ny - 1) << ", " << plate.nx << "\n";
  d << "*BOUNDARY\nLEFT, 1, 1\n" << plate.grid(0, 0) << ", 2, 2\n";
  d << "*AMPLITUDE, NAME=A\n0., 0., 0.25, 1., 0.5, 1.5, 0.75, 3.\n1., 3.5\n";
  d << "*AMPLITUDE, NAME=B\n0., 0., 0.25, -1., 0.5, 0.5, 0.75, 2.\n1., 1.\n";
  d << "*STEP\n*STATIC, DIRECT\n0.25, 1\n*DLOAD, AMPLITUDE=A\nRIGHT, P2, 20.\n";
  d << "*BOUNDARY, AMPLITUDE=B\n" << plate.grid(plate.nx, plate.ny) << ", 2, 2, 0.01\n*END STEP\n";
  const DeckRun held = expect_same_as_fresh(d.str());
  const SolveTiming& t = held.summary.timing;
  EXPECT_EQ(held.summary.increments, 4);
  EXPECT_EQ(t.full_tangents, 1);
  // One residual per iteration and one more per increment's Newton solve.
  const int residuals = held.summary.iterations + held.summary.increments;
  EXPECT_EQ(t.residual_updates, residuals - 2);
}
