// The closed normal multipliers of node-to-segment (NTS) pairs eliminated
// from the dense interface system of the condensed solver, each with a
// displacement of its own slave node (contact_dual_equations,
// CondensedSolver::eliminate_dual_multipliers): which nodes are registered
// (a node with a second contact row or on a master surface is not; a
// prescribed dof is never a pivot), and whole analyses — the NTS Hertz
// example, the block slid over a foundation with and without friction, the
// frictional CGS-4 deck — that take the same increments and iterations and
// end with the same displacements and pressures as with the multipliers
// kept in the dense system (LU of the whole interface system).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>

#include "dual_elimination_check.hpp"
#include "run_deck.hpp"
#include "support/foundation_deck.hpp"
#include "tether/analysis/contact_builder.hpp"
#include "tether/analysis/discretization.hpp"

using namespace tether;
using tether::testing::run_deck_text;

namespace {

const std::string kHard = "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD\n";

std::string source_file(const std::string& path) {
  std::ifstream in(std::string(TETHER_SOURCE_DIR) + "/" + path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The deck with `more` inserted before the first *STEP.
std::string before_step(std::string deck, const std::string& more) {
  return deck.insert(deck.find("*STEP"), more);
}

/// The slave node indices that contact_dual_equations registers for `deck`
/// (one entry per registered multiplier, through its multiplier's pair),
/// with `prescribed` dofs and `other` nodes.
struct Registered {
  std::vector<DualNodeEquations> equations;
  std::vector<int> nodes;  ///< node index of each entry
};
Registered registered(const std::string& deck, const std::vector<std::pair<int, int>>& prescribed_node_dofs,
                      const std::vector<int>& other_labels) {
  const Model model = read_deck_string(deck, "test.inp");
  const Discretization disc(model);
  std::vector<bool> prescribed(static_cast<std::size_t>(disc.dofs().n_dofs()), false);
  for (const auto& [label, c] : prescribed_node_dofs)
    prescribed[static_cast<std::size_t>(disc.dofs().displacement(model.node_index.at(label), c))] = true;
  const EquationMap map(prescribed, disc.elimination_rows());
  std::vector<int> other;
  for (int label : other_labels) other.push_back(model.node_index.at(label));
  Registered out;
  out.equations = contact_dual_equations(disc.contact_pairs(), disc.dofs(), map, other);
  for (const DualNodeEquations& e : out.equations)
    for (const auto& pair : disc.contact_pairs())
      for (int i = 0; i < pair->n_slaves(); ++i)
        if (map.weights(pair->slave(i).normal_multiplier)[0].equation == e.multiplier)
          out.nodes.push_back(pair->slave(i).node);
  return out;
}

// Block on foundation: slave nodes 1..9 (the block's bottom), master the
// foundation's top (nodes 3431..3511), node 1001 the foundation's corner.
TEST(NtsDualEquations, OneEntryPerSlaveNodeWithItsOwnDisplacements) {
  const std::string deck = tether::testing::block_on_foundation(0.5123, kHard);
  const Registered r = registered(deck, {{1, 0}}, {});
  ASSERT_EQ(r.equations.size(), 9u);
  const Model model = read_deck_string(deck, "test.inp");
  for (std::size_t k = 0; k < r.equations.size(); ++k) {
    const DualNodeEquations& e = r.equations[k];
    EXPECT_GE(e.multiplier, 0);
    EXPECT_GE(e.displacement[1], 0);
    // Node 1's x is prescribed: never a pivot.
    if (r.nodes[k] == model.node_index.at(1))
      EXPECT_EQ(e.displacement[0], -1);
    else
      EXPECT_GE(e.displacement[0], 0);
  }
}

TEST(NtsDualEquations, RefusesANodeWithASecondContactRowOrOnAMasterSurface) {
  const std::string base = tether::testing::block_on_foundation(0.5123, kHard);
  const Model model = read_deck_string(base, "test.inp");
  const auto has = [&](const Registered& r, int label) {
    return std::find(r.nodes.begin(), r.nodes.end(), model.node_index.at(label)) != r.nodes.end();
  };
  // Node 3 is also the slave of a second pair: neither of its rows is registered.
  const std::string two_pairs = before_step(
      base, "*SURFACE, NAME=THIRD, TYPE=NODE\n3,\n*CONTACT PAIR, INTERACTION=I, TYPE=NODE TO SURFACE\nTHIRD, MASTER\n");
  const Registered r2 = registered(two_pairs, {}, {});
  EXPECT_EQ(r2.equations.size(), 8u);
  EXPECT_FALSE(has(r2, 3));
  EXPECT_TRUE(has(r2, 2));
  // The block's bottom is the master of a third pair (slave: foundation node
  // 1001): none of its nodes is registered, node 1001 is.
  const std::string master_too = before_step(
      two_pairs, "*SURFACE, NAME=CORNER, TYPE=NODE\n1001,\n*CONTACT PAIR, INTERACTION=I, TYPE=NODE TO SURFACE\n"
                 "CORNER, SLAVE\n");
  const Registered r3 = registered(master_too, {}, {});
  ASSERT_EQ(r3.equations.size(), 1u);
  EXPECT_TRUE(has(r3, 1001));
  // Nodes of other (mortar) pairs are left out.
  const Registered r4 = registered(base, {}, {2, 5});
  EXPECT_EQ(r4.equations.size(), 7u);
  EXPECT_FALSE(has(r4, 2));
  EXPECT_FALSE(has(r4, 5));
  // Nodes 6 and 7 tied in x by an eliminated *EQUATION (6's x dependent):
  // they share an equation, and neither is registered.
  const Registered tied =
      registered(before_step(base, "*EQUATION, ENFORCEMENT=ELIMINATION\n2\n6, 1, 1.0, 7, 1, -1.0\n"), {}, {});
  EXPECT_EQ(tied.equations.size(), 7u);
  EXPECT_FALSE(has(tied, 6));
  EXPECT_FALSE(has(tied, 7));
  // Friction adds tangential multipliers, which are not registered; soft laws no multiplier at all.
  const Registered friction =
      registered(tether::testing::block_on_foundation(0.5123, kHard + "*FRICTION\n0.3\n"), {}, {});
  EXPECT_EQ(friction.equations.size(), 9u);
  const Registered soft = registered(
      tether::testing::block_on_foundation(0.5123, "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n1e4\n"), {}, {});
  EXPECT_TRUE(soft.equations.empty());
}

/// The run with the NTS multipliers eliminated (MortarCondensation::Dense,
/// the default) against the one with them kept (Kept), both condensed onto
/// the contact equations (condense_any_size). Same increments; iterations
/// within `iteration_slack` (frictional stick/slip decisions at the cone's
/// edge rest on round-off); displacements within `tolerance` of the largest,
/// contact pressures within `tolerance` of the largest. The elimination's log
/// line must name at least one closed multiplier.
void expect_same_as_kept(const std::string& what, const std::string& deck, double tolerance,
                         int iteration_slack = 0) {
  tether::testing::expect_elimination_same_as_kept(
      "NTS dual elimination", what, deck, tolerance, iteration_slack,
      [&](const std::string&, const std::string& b_log) {
        std::smatch closed;
        ASSERT_TRUE(std::regex_search(b_log, closed,
                                      std::regex("dual elimination of the contact multipliers \\(\\d+ "
                                                 "factorizations, (\\d+) closed in the last\\)")))
            << what << ": " << b_log;
        EXPECT_GT(std::stoi(closed[1]), 0) << what << ": " << b_log;
      });
}

TEST(NtsDenseElimination, HertzExampleSameAsWithTheMultipliersKept) {
  expect_same_as_kept("NTS Hertz example", source_file("examples/hertz/hertz.inp"), 1e-10);
}

TEST(NtsDenseElimination, SlidingBlockSameAsWithTheMultipliersKept) {
  expect_same_as_kept("sliding block", tether::testing::block_on_foundation(0.5123, kHard), 1e-10);
  // Smoothed master: over the faceted one this deck's increment 6 has two
  // converged states a round-off apart at the cone's edge, and the runs with
  // the multipliers kept, condensed or not (condense_contact false), already
  // end on either.
  expect_same_as_kept("sliding block, friction 0.3, SMOOTH 0.2",
                      tether::testing::block_on_foundation(0.5123, kHard + "*FRICTION\n0.3\n", ", SMOOTH=0.2"), 1e-8,
                      2);
}

TEST(NtsDenseElimination, FrictionalCgs4SameAsWithTheMultipliersKept) {
  expect_same_as_kept("CGS-4 NTS G 40, friction", source_file("tests/verification/decks/cgs4_nts_g40.inp"), 1e-8, 2);
}

}  // namespace
