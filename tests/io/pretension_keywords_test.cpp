// *PRE-TENSION SECTION and *BOUNDARY, FIXED: what the reader builds, and a
// file:line error for each kind of bad input.
#include <gtest/gtest.h>

#include "deck_test_support.hpp"
#include "tether/io/deck_reader.hpp"

using namespace tether;
using namespace tether::test;

namespace {

/// A bolt of two CPE4 (one above the other) cut between them by CUT = face S3
/// of element 1; pretension node 100.
const std::string kBolt = R"(*NODE
1, 0, 0
2, 1, 0
3, 0, 1
4, 1, 1
5, 0, 2
6, 1, 2
100, 0.5, 1
101, 0.5, 1.5
*ELEMENT, TYPE=CPE4, ELSET=BOLT
1, 1, 2, 4, 3
2, 3, 4, 6, 5
*NSET, NSET=TWO
100, 101
*SURFACE, NAME=CUT
1, S3
*SURFACE, NAME=BOTTOM
1, S1
*SURFACE, NAME=BOTH
1, S3
2, S1
*SURFACE, NAME=NODES, TYPE=NODE
3, 4
*MATERIAL, NAME=STEEL
*ELASTIC
1000, 0
*SOLID SECTION, ELSET=BOLT, MATERIAL=STEEL
*PRE-TENSION SECTION, SURFACE=CUT, NODE=100
*BOUNDARY
1, 1, 2
2, 1, 2
*STEP
*STATIC
*CLOAD
100, 1, 1.
*END STEP
)";

std::string with(const std::string& from, const std::string& to) { return replaced(kBolt, from, to); }

TEST(PretensionKeywords, CutDuplicatesTheSurfaceNodesForItsElementsAndWritesTheEquations) {
  const Model m = read_deck_string(kBolt, "bolt.inp");
  ASSERT_EQ(m.pretension_sections.size(), 1u);
  const PretensionSection& s = m.pretension_sections[0];
  EXPECT_EQ(s.constraint, "PRETENSION-CUT");
  EXPECT_EQ(s.node, m.node_index.at(100));
  EXPECT_NEAR(s.normal.x(), 0, 1e-15);
  EXPECT_NEAR(s.normal.y(), 1, 1e-15);
  ASSERT_EQ(m.n_nodes(), 10);  // 8 + a duplicate of nodes 4 and 3 (face S3 runs 4 -> 3), labelled 102 and 103
  ASSERT_EQ(s.pairs.size(), 2u);
  EXPECT_EQ(s.pairs[0], std::make_pair(m.node_index.at(4), m.node_index.at(102)));
  EXPECT_EQ(s.pairs[1], std::make_pair(m.node_index.at(3), m.node_index.at(103)));
  const auto& lower = m.elements[static_cast<std::size_t>(m.element_index.at(1))].nodes;
  const auto& upper = m.elements[static_cast<std::size_t>(m.element_index.at(2))].nodes;
  EXPECT_EQ(lower, (std::vector<int>{m.node_index.at(1), m.node_index.at(2), m.node_index.at(102), m.node_index.at(103)}));
  EXPECT_EQ(upper, (std::vector<int>{m.node_index.at(3), m.node_index.at(4), m.node_index.at(6), m.node_index.at(5)}));
  EXPECT_EQ(m.coords[static_cast<std::size_t>(m.node_index.at(102))], m.coords[static_cast<std::size_t>(m.node_index.at(4))]);
  const ConstraintData& c = m.constraints.back();
  EXPECT_EQ(c.name, "PRETENSION-CUT");
  ASSERT_EQ(c.rows.size(), 5u);  // tangential and normal per pair, then the pretension node's dof 2
  // (u_102 - u_4)·n - u_p = 0 with n = (0, 1): u_102,y - u_4,y - u_100,x
  const auto& opening = c.rows[1];
  ASSERT_EQ(opening.size(), 3u);
  EXPECT_EQ(opening[0].node, m.node_index.at(102));
  EXPECT_EQ(opening[0].dof, 1);
  EXPECT_EQ(opening[0].coefficient, 1.0);
  EXPECT_EQ(opening[1].node, m.node_index.at(4));
  EXPECT_EQ(opening[1].coefficient, -1.0);
  EXPECT_EQ(opening[2].node, m.node_index.at(100));
  EXPECT_EQ(opening[2].dof, 0);
  EXPECT_EQ(opening[2].coefficient, -1.0);
  EXPECT_EQ(c.rows[4].size(), 1u);
  EXPECT_EQ(c.rows[4][0].dof, 1);
}

TEST(PretensionKeywords, DataLineNormalIsNormalised) {
  const Model m = read_deck_string(with("NODE=100\n", "NODE=100\n0.3, 4., 0.\n"), "bolt.inp");
  EXPECT_NEAR(m.pretension_sections[0].normal.x(), 0.3 / std::hypot(0.3, 4.), 1e-15);
  EXPECT_NEAR(m.pretension_sections[0].normal.norm(), 1, 1e-15);
}

TEST(PretensionKeywords, BadSectionsAreRefusedAtTheirLine) {
  const std::string kw = "*PRE-TENSION SECTION, SURFACE=CUT, NODE=100";
  expect_deck_error_at(with("SURFACE=CUT", "SURFACE=NONE"), "*PRE-TENSION", {"undefined surface 'NONE'"});
  expect_deck_error_at(with(", NODE=100\n", "\n"), "*PRE-TENSION", {"requires the parameter NODE"});
  expect_deck_error_at(with("NODE=100", "NODE=3"), "*PRE-TENSION", {"pretension node 3 belongs to element", "no element uses"});
  expect_deck_error_at(with("NODE=100", "NODE=TWO"), "*PRE-TENSION", {"names 2 nodes", "one pretension node"});
  expect_deck_error_at(with("NODE=100", "NODE=999"), "*PRE-TENSION", {"undefined node 999"});
  expect_deck_error_at(with("SURFACE=CUT, NODE=100", "ELEMENT=1, NODE=100"), "*PRE-TENSION",
                       {"ELEMENT=", "truss or beam", "SURFACE="});
  expect_deck_error_at(with("SURFACE=CUT", "SURFACE=NODES"), "*PRE-TENSION", {"made of nodes", "TYPE=ELEMENT"});
  expect_deck_error_at(with("SURFACE=CUT", "SURFACE=BOTTOM"), "*PRE-TENSION", {"no element on the far side", "cut through"});
  expect_deck_error_at(with("SURFACE=CUT", "SURFACE=BOTH"), "*PRE-TENSION", {"cancel out", "normal"});
  expect_deck_error_at(with("SURFACE=CUT, NODE=100\n", "SURFACE=BOTH, NODE=100\n0, 1, 0\n"), "*PRE-TENSION",
                       {"face S1 of element 2 points against the section's normal", "one side"});
  expect_deck_error_at(with("NODE=100\n", "NODE=100\n0, 1, 0.5\n"), "0, 1, 0.5", {"z component"});
  expect_deck_error_at(with("NODE=100\n", "NODE=100\n0, 0, 0\n"), "0, 0, 0", {"normal is zero"});
  expect_deck_error_at(with("NODE=100\n", "NODE=100\n0, 1, 0\n0, 1, 0\n"), "0, 1, 0\n*BOUNDARY",
                       {"second data line"});
  expect_deck_error_at(with(kw + "\n", kw + "\n" + "*PRE-TENSION SECTION, SURFACE=CUT, NODE=101\n"),
                       "NODE=101", {"surface 'CUT' already cuts"});
}

TEST(PretensionKeywords, OnlyDofOneOfThePretensionNodeMayBeLoadedOrPrescribed) {
  expect_deck_error_at(with("*CLOAD\n100, 1, 1.\n", "*CLOAD\n100, 2, 1.\n"), "100, 2, 1.",
                       {"load on dof 2 of pretension node 100", "dof 1 only"});
  expect_deck_error_at(with("2, 1, 2\n", "2, 1, 2\n100, 2\n"), "100, 2\n", {"dof 2 of pretension node 100"});
}

TEST(BoundaryFixed, HoldsTheListedDofsAndIsRefusedWhereItMeansNothing) {
  const Model m = read_deck_string(with("*CLOAD\n100, 1, 1.\n", "*BOUNDARY, FIXED\n100, 1\n"), "bolt.inp");
  const auto& b = m.steps.at(0).boundary;
  ASSERT_FALSE(b.empty());
  EXPECT_TRUE(b.back().fixed);
  EXPECT_EQ(b.back().node, m.node_index.at(100));
  EXPECT_FALSE(b.front().fixed);
  expect_deck_error_at(with("*BOUNDARY\n1, 1, 2", "*BOUNDARY, FIXED\n1, 1, 2"), "*BOUNDARY, FIXED", {"model data", "*STEP"});
  expect_deck_error_at(with("*CLOAD\n100, 1, 1.\n", "*BOUNDARY, FIXED\n100, 1, 1, 0.5\n"), "100, 1, 1, 0.5",
                       {"FIXED takes no value"});
  expect_deck_error_at(with("*CLOAD\n100, 1, 1.\n", "*AMPLITUDE, NAME=A\n0, 0, 1, 1\n*BOUNDARY, FIXED, AMPLITUDE=A\n100, 1\n"),
                       "*BOUNDARY, FIXED, AMPLITUDE=A", {"AMPLITUDE="});
}

}  // namespace
