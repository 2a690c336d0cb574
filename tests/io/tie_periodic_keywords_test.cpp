// *TIE and *PERIODIC: what they read, their warnings, and every error path
// (file:line and what was expected).

#include <gtest/gtest.h>

#include <cmath>

#include "deck_test_support.hpp"

using namespace tether;
using namespace tether::test;

namespace {

/// A left square (element 1, nodes 1-4) and a right body of two elements
/// (nodes 5-10) whose left side x = 1 has a node at y = 0.5: non-matching.
/// SL = right side of element 1 (nodes 2, 3); MA = left sides of elements 2, 3.
const std::string kTieMesh = R"(*NODE
1, 0, 0
2, 1, 0
3, 1, 1
4, 0, 1
5, 1, 0
6, 2, 0
7, 2, 0.5
8, 2, 1
9, 1, 0.5
10, 1, 1
*ELEMENT, TYPE=CPE4, ELSET=ALL
1, 1, 2, 3, 4
2, 5, 6, 7, 9
3, 9, 7, 8, 10
*SURFACE, NAME=SL
1, S2
*SURFACE, NAME=MA
2, S4
3, S4
*SURFACE, NAME=SN, TYPE=NODE
2
3
*MATERIAL, NAME=M
*ELASTIC
1000, 0.3
*SOLID SECTION, ELSET=ALL, MATERIAL=M
)";

const std::string kStep = "*STEP\n*STATIC\n*END STEP\n";

std::string tie_deck(const std::string& tie) { return kTieMesh + tie + kStep; }

/// kDeck (nodes 1..6 on [0,2]x[0,1], LEFT = {1,4}, RIGHT = {3,6}) with two
/// reference nodes 101, 102 and `block` before the step.
std::string periodic_deck(const std::string& block) {
  return replaced(kDeck, "*STEP", "*NODE\n101, 5, 0\n102, 5, 1\n*NSET, NSET=BOT\n1, 2, 3\n*NSET, NSET=TOPN\n4, 5, 6\n" +
                                      block + "*STEP");
}

double row_sum(const std::vector<EquationTerm>& row) {
  double s = 0;
  for (const auto& t : row) s += t.coefficient;
  return s;
}

}  // namespace

TEST(TieKeyword, SurfaceToSurfaceRowsReproduceRigidMotion) {
  const Model m = read_deck_string(tie_deck("*TIE, NAME=T\nSL, MA\n"), "t.inp");
  ASSERT_EQ(m.constraints.size(), 2u);  // slave nodes 2 and 3
  for (const auto& c : m.constraints) {
    EXPECT_EQ(c.kind, ConstraintData::Kind::Linear);
    ASSERT_EQ(c.rows.size(), 2u);
    EXPECT_EQ(c.rows[1][0].dof, 1);
    EXPECT_DOUBLE_EQ(c.rows[0][0].coefficient, 1.0);  // the slave node
    EXPECT_NEAR(row_sum(c.rows[0]), 0.0, 1e-14);       // a rigid translation satisfies it
    EXPECT_NEAR(row_sum(c.rows[1]), 0.0, 1e-14);
  }
  EXPECT_EQ(m.constraints[0].name, "T node 2");
  EXPECT_EQ(m.constraints[0].where.line, line_of(tie_deck("*TIE, NAME=T\nSL, MA\n"), "SL, MA"));
}

TEST(TieKeyword, NodeToSurfaceWeightsAreTheMasterShapeFunctions) {
  // Node surface SN: slave nodes 2 (on master node 5) and 3 (on master node 10).
  const Model m = read_deck_string(tie_deck("*TIE, NAME=T, TYPE=NODE TO SURFACE, ENFORCEMENT=PENALTY, PENALTY=1e6\n"
                                            "SN, MA\n"),
                                   "t.inp");
  ASSERT_EQ(m.constraints.size(), 2u);
  const auto& row = m.constraints[1].rows[0];
  ASSERT_EQ(row.size(), 2u);
  EXPECT_EQ(row[1].node, m.node_index.at(10));
  EXPECT_DOUBLE_EQ(row[1].coefficient, -1.0);
  EXPECT_EQ(m.constraints[1].enforcement.method, Enforcement::Method::Penalty);
  // A slave node in the middle of a master face: weights 1/2, 1/2.
  const Model mid = read_deck_string(
      tie_deck("*SURFACE, NAME=MID, TYPE=NODE\n11\n*TIE, TYPE=NODE TO SURFACE\nMID, MA\n")
          .insert(kTieMesh.find("*ELEMENT"), "*NODE\n11, 1, 0.25\n"),
      "t.inp");
  ASSERT_EQ(mid.constraints.size(), 1u);
  for (std::size_t k = 1; k < 3; ++k) EXPECT_DOUBLE_EQ(mid.constraints[0].rows[0][k].coefficient, -0.5);
}

TEST(TieKeyword, AdjustMovesSlaveNodesAndWarns) {
  // Node 3 moved to x = 1.02 (within 5 % of the master face length 0.5 = 0.025).
  const std::string deck = replaced(tie_deck("*TIE, NAME=T\nSL, MA\n"), "\n3, 1, 1\n", "\n3, 1.02, 1\n");
  std::vector<DeckWarning> warnings;
  const Model m = read_deck_string(deck, "t.inp", &warnings);
  EXPECT_DOUBLE_EQ(m.coords[m.node_index.at(3)].x(), 1.0);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].message.find("ADJUST=YES moved 1 slave node"), std::string::npos) << warnings[0].message;
  EXPECT_EQ(warnings[0].where.line, line_of(deck, "SL, MA"));
  // ADJUST=NO keeps it.
  warnings.clear();
  const Model kept = read_deck_string(replaced(deck, "*TIE, NAME=T", "*TIE, NAME=T, ADJUST=NO"), "t.inp", &warnings);
  EXPECT_DOUBLE_EQ(kept.coords[kept.node_index.at(3)].x(), 1.02);
  EXPECT_TRUE(warnings.empty());
}

TEST(TieKeyword, FarSlaveNodesAreNotTiedAndListed) {
  const std::string deck = replaced(tie_deck("*TIE, NAME=T\nSL, MA\n"), "\n3, 1, 1\n", "\n3, 1.2, 1\n");
  std::vector<DeckWarning> warnings;
  const Model m = read_deck_string(deck, "t.inp", &warnings);
  EXPECT_EQ(m.constraints.size(), 1u);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].message.find("1 slave node(s) farther than POSITION TOLERANCE=0.025"), std::string::npos)
      << warnings[0].message;
  EXPECT_NE(warnings[0].message.find("are not tied: 3"), std::string::npos) << warnings[0].message;
  // A larger tolerance ties it.
  const Model wide = read_deck_string(replaced(deck, "*TIE, NAME=T", "*TIE, NAME=T, POSITION TOLERANCE=0.3"), "t.inp");
  EXPECT_EQ(wide.constraints.size(), 2u);
}

TEST(TieKeyword, Errors) {
  struct Case {
    std::string tie, marker;
    std::vector<std::string> words;
  };
  const std::vector<Case> cases = {
      {"*TIE, NAME=T\n", "*TIE", {"*TIE needs a data line", "`slave_surface, master_surface`"}},
      {"*TIE, NAME=T\nSL\n", "\nSL\n", {"expected `slave_surface, master_surface`"}},
      {"*TIE, NAME=T\nSL, MA, X\n", "SL, MA, X", {"expected `slave_surface, master_surface`"}},
      {"*TIE, NAME=T\nNOPE, MA\n", "NOPE", {"undefined slave surface 'NOPE'", "*SURFACE"}},
      {"*TIE, NAME=T\nSL, NOPE\n", "NOPE", {"undefined master surface 'NOPE'", "*SURFACE"}},
      {"*TIE, NAME=T\nSL, SN\n", "SL, SN", {"master surface SN is a node surface", "element-face surface"}},
      {"*TIE, NAME=T\nMA, MA\n", "MA, MA", {"slave and master are the same surface MA"}},
      {"*TIE, NAME=T, POSITION TOLERANCE=-1\nSL, MA\n", "*TIE", {"POSITION TOLERANCE=-1", ">= 0"}},
      {"*TIE, NAME=T, ENFORCEMENT=PENALTY\nSL, MA\n", "*TIE", {"ENFORCEMENT=PENALTY needs PENALTY=rho > 0"}},
      {"*TIE, NAME=T, ENFORCEMENT=PENALTY, PENALTY=1e3, EPSILON=1\nSL, MA\n", "*TIE",
       {"EPSILON applies to ENFORCEMENT=LAGRANGE only"}},
      {"*TIE, NAME=T, EPSILON=-1\nSL, MA\n", "*TIE", {"EPSILON must be >= 0"}},
      {"*TIE, NAME=T, TYPE=GLUE\nSL, MA\n", "*TIE", {"GLUE", "NODE TO SURFACE", "SURFACE TO SURFACE"}},
  };
  for (const auto& c : cases) {
    const std::string deck = tie_deck(c.tie);
    expect_deck_error(deck, line_of(deck, c.marker), c.words);
  }
  {
    // Every slave node farther than the tolerance: an error naming the *TIE data line.
    const std::string deck = replaced(replaced(tie_deck("*TIE, NAME=T\nSL, MA\n"), "\n3, 1, 1\n", "\n3, 1.2, 1\n"),
                                      "\n2, 1, 0\n", "\n2, 1.2, 0\n");
    expect_deck_error_at(deck, "SL, MA",
                         {"*TIE T ties nothing", "POSITION TOLERANCE=0.025", "the closest is 0.2 away", "expected"});
  }
  {
    // Slave nodes that are all master nodes: nothing to tie.
    const std::string deck = tie_deck("*SURFACE, NAME=SHARED, TYPE=NODE\n5\n10\n*TIE, NAME=T\nSHARED, MA\n");
    expect_deck_error_at(deck, "SHARED, MA", {"ties nothing", "every node of slave surface SHARED is also a node"});
  }
}

TEST(PeriodicKeyword, PairsAndEquations) {
  const Model m = read_deck_string(
      periodic_deck("*PERIODIC, NAME=P, REFERENCE1=101, REFERENCE2=102\nLEFT, RIGHT\nBOT, TOPN\n"), "p.inp");
  // LEFT/RIGHT: (1,3), (4,6); BOT/TOPN: (1,4), (2,5); (3,6) is implied and left out.
  ASSERT_EQ(m.constraints.size(), 4u);
  const auto& c = m.constraints[0];
  EXPECT_EQ(c.name, "P 1-3");
  EXPECT_EQ(c.kind, ConstraintData::Kind::Linear);
  ASSERT_EQ(c.rows.size(), 2u);
  // u_3 - u_1 - H (X_3 - X_1) with X_3 - X_1 = (2, 0): -2 u(101).
  ASSERT_EQ(c.rows[0].size(), 3u);
  EXPECT_EQ(c.rows[0][0].node, m.node_index.at(3));
  EXPECT_EQ(c.rows[0][1].node, m.node_index.at(1));
  EXPECT_EQ(c.rows[0][2].node, m.node_index.at(101));
  EXPECT_DOUBLE_EQ(c.rows[0][2].coefficient, -2.0);
  EXPECT_EQ(c.rows[1][2].dof, 1);
  EXPECT_EQ(m.constraints[3].name, "P 2-5");
  EXPECT_EQ(m.constraints[3].rows[0][2].node, m.node_index.at(102));
  EXPECT_DOUBLE_EQ(m.constraints[3].rows[0][2].coefficient, -1.0);
  // An explicit translation gives the same pairs.
  const Model t = read_deck_string(
      periodic_deck("*PERIODIC, REFERENCE1=101, REFERENCE2=102\nLEFT, RIGHT, 2., 0.\n"), "p.inp");
  EXPECT_EQ(t.constraints.size(), 2u);
}

TEST(PeriodicKeyword, Errors) {
  struct Case {
    std::string block, marker;
    std::vector<std::string> words;
  };
  const std::string head = "*PERIODIC, REFERENCE1=101, REFERENCE2=102\n";
  const std::vector<Case> cases = {
      {"*PERIODIC, REFERENCE2=102\nLEFT, RIGHT\n", "*PERIODIC", {"*PERIODIC requires the parameter REFERENCE1"}},
      {"*PERIODIC, REFERENCE1=101\nLEFT, RIGHT\n", "*PERIODIC", {"requires the parameter REFERENCE2"}},
      {"*PERIODIC, REFERENCE1=999, REFERENCE2=102\nLEFT, RIGHT\n", "*PERIODIC", {"undefined node 999"}},
      {"*PERIODIC, REFERENCE1=LEFT, REFERENCE2=102\nLEFT, RIGHT\n", "*PERIODIC",
       {"REFERENCE1='LEFT' names 2 nodes", "a set with one node"}},
      {"*PERIODIC, REFERENCE1=101, REFERENCE2=101\nLEFT, RIGHT\n", "*PERIODIC",
       {"REFERENCE1 and REFERENCE2 name the same node"}},
      {head, "*PERIODIC", {"*PERIODIC needs a data line", "`nset_a, nset_b[, dx, dy]`"}},
      {head + "LEFT\n", "\nLEFT\n", {"expected `nset_a, nset_b[, dx, dy]`"}},
      {head + "LEFT, RIGHT, 2.\n", "LEFT, RIGHT, 2.", {"got 3 fields"}},
      {head + "LEFT, RIGHT, 2., x\n", "LEFT, RIGHT, 2., x", {"dy"}},
      {head + "LEFT, NOPE\n", "LEFT, NOPE", {"undefined node set 'NOPE'"}},
      {head + "LEFT, 101\n", "LEFT, 101", {"reference node 101 is in a paired set"}},
      {head + "BOT, LEFT\n", "BOT, LEFT", {"node 1 is in both BOT and LEFT", "disjoint"}},
      {head + "LEFT, RIGHT, 0., 0.\n", "LEFT, RIGHT, 0., 0.", {"translation from LEFT to RIGHT is zero"}},
      {head + "LEFT, RIGHT, 1., 0.\n", "LEFT, RIGHT, 1., 0.",
       {"node 1 of LEFT at (0, 0) has no partner in RIGHT", "expected a node at (1, 0)", "POSITION TOLERANCE=1e-06"}},
      {"*PERIODIC, REFERENCE1=101, REFERENCE2=102, POSITION TOLERANCE=-2\nLEFT, RIGHT\n", "*PERIODIC",
       {"POSITION TOLERANCE=-2"}},
  };
  for (const auto& c : cases) {
    const std::string deck = periodic_deck(c.block);
    expect_deck_error(deck, line_of(deck, c.marker), c.words);
  }
  {
    // Sets of different sizes: the extra node of the second set has no partner.
    const std::string deck =
        periodic_deck("*NSET, NSET=R3\n3, 6, 2\n*NSET, NSET=L3\n1, 4\n" + head + "L3, R3, 2., 0.\n");
    expect_deck_error_at(deck, "L3, R3", {"node 2 of R3 at (1, 0) has no partner in L3", "same number of nodes, 2 and 3"});
  }
  {
    // A line repeating the pairs of an earlier line adds nothing: an error at the second line.
    const std::string deck = periodic_deck(head + "LEFT, RIGHT\nRIGHT, LEFT\n");
    expect_deck_error_at(deck, "RIGHT, LEFT", {"every pair of RIGHT and LEFT repeats pairs of earlier lines"});
  }
}
