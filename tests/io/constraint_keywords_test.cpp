// *EQUATION, *MPC and *CONSTRAINT: what they read, and every error path.

#include <gtest/gtest.h>

#include <algorithm>

#include "deck_test_support.hpp"

using namespace tether;
using namespace tether::test;

namespace {

/// kDeck with `block` inserted before the first *STEP (model data).
std::string with_model_data(const std::string& block) { return replaced(kDeck, "*STEP", block + "*STEP"); }

}  // namespace

TEST(ConstraintKeywords, EquationTermsAcrossLinesAndSets) {
  const Model m = read_deck_string(with_model_data("*EQUATION, NAME=EQ\n3\n2, 1, 1.0, 5, 1, -0.5,\n6, 2, 2.5\n"
                                                   "2\n3, 2, 1., 2, 2, -1.\n"
                                                   "*EQUATION\n2\nLEFT, 2, 1., RIGHT, 2, -1.\n"),
                                   "c.inp");
  ASSERT_EQ(m.constraints.size(), 4u);
  const auto& c = m.constraints[0];
  EXPECT_EQ(c.kind, ConstraintData::Kind::Equation);
  EXPECT_EQ(c.name, "EQ");
  ASSERT_EQ(c.terms.size(), 3u);
  EXPECT_EQ(c.terms[1].node, m.node_index.at(5));
  EXPECT_EQ(c.terms[2].dof, 1);
  EXPECT_DOUBLE_EQ(c.terms[2].coefficient, 2.5);
  EXPECT_EQ(c.enforcement.method, Enforcement::Method::Lagrange);
  // Sets apply the equation member by member: LEFT = {1, 4}, RIGHT = {3, 6}.
  EXPECT_EQ(m.constraints[2].terms[0].node, m.node_index.at(1));
  EXPECT_EQ(m.constraints[3].terms[1].node, m.node_index.at(6));
}

TEST(ConstraintKeywords, EnforcementParameters) {
  const Model m = read_deck_string(
      with_model_data("*EQUATION, ENFORCEMENT=AUGMENTED, PENALTY=1e6, TOLERANCE=1e-9\n2\n2, 1, 1., 5, 1, -1.\n"
                      "*MPC, ENFORCEMENT=LAGRANGE, EPSILON=1e-6\nLINK, 2, 6\nSLIDER, 5, 1, 3\nPIN, 2, 5\n"),
      "c.inp");
  ASSERT_EQ(m.constraints.size(), 4u);
  EXPECT_EQ(m.constraints[0].enforcement.method, Enforcement::Method::Augmented);
  EXPECT_DOUBLE_EQ(m.constraints[0].enforcement.penalty, 1e6);
  EXPECT_DOUBLE_EQ(m.constraints[0].enforcement.tolerance, 1e-9);
  EXPECT_EQ(m.constraints[1].kind, ConstraintData::Kind::Link);
  EXPECT_DOUBLE_EQ(m.constraints[1].enforcement.epsilon, 1e-6);
  EXPECT_EQ(m.constraints[2].kind, ConstraintData::Kind::Slider);
  EXPECT_EQ(m.constraints[2].nodes.size(), 3u);
  EXPECT_EQ(m.constraints[3].kind, ConstraintData::Kind::Tie);
}

TEST(ConstraintKeywords, ConstraintExpressionAndUser) {
  const Model m = read_deck_string(
      with_model_data("*CONSTRAINT, TYPE=EXPRESSION, NAME=ROD\n2, 6\n"
                      "sqrt((X2+U2-X1-U1)^2 + (Y2+V2-Y1-V1)^2) - sqrt((X2-X1)^2 + (Y2-Y1)^2)\n"
                      "*CONSTRAINT, TYPE=USER, LIBRARY=lib/libeq.so, MULTIPLIERS=2\n2, 5,\n6\n1., 0.5\n3\n"),
      "dir/c.inp");
  ASSERT_EQ(m.constraints.size(), 2u);
  EXPECT_EQ(m.constraints[0].kind, ConstraintData::Kind::Expression);
  ASSERT_EQ(m.constraints[0].formulas.size(), 1u);
  EXPECT_NE(m.constraints[0].formulas[0].find("sqrt((X2+U2"), std::string::npos);  // commas kept
  const auto& u = m.constraints[1];
  EXPECT_EQ(u.kind, ConstraintData::Kind::User);
  EXPECT_EQ(u.nodes.size(), 3u);
  EXPECT_EQ(u.library, "dir/lib/libeq.so");  // relative to the deck
  EXPECT_EQ(u.symbol, "tether_user_constraint");
  EXPECT_EQ(u.n_multipliers, 2);
  EXPECT_EQ(u.properties, (std::vector<double>{1.0, 0.5, 3.0}));
}

TEST(ConstraintKeywords, ErrorsNameTheLine) {
  struct Case {
    std::string block, marker;
    std::vector<std::string> words;
  };
  const std::vector<Case> cases = {
      {"*EQUATION\n2\n2, 1, 1.\n", "2\n2, 1, 1.\n", {"announces 2 terms but 1 follow"}},
      {"*EQUATION\n1\n2, 1, 1., 5, 1, -1.\n", "2, 1, 1., 5", {"announces 1 terms but 2 are given"}},
      {"*EQUATION\n2\n2, 3, 1., 5, 1, -1.\n", "2, 3, 1.", {"dof 3", "expected 1 or 2"}},
      {"*EQUATION\n2\n2, 1, 0., 5, 1, -1.\n", "2, 1, 0.", {"coefficient of term 1 is zero"}},
      {"*EQUATION\n2\n2, 1, 1., 99, 1, -1.\n", "2, 1, 1., 99", {"99"}},
      {"*EQUATION\n2\n2, 1, 1., 5, 1\n", "2, 1, 1., 5, 1", {"node, dof, coefficient"}},
      {"*EQUATION\nx\n", "x\n", {"'x'", "number of terms"}},
      {"*EQUATION\n", "*EQUATION", {"needs data lines"}},
      {"*EQUATION, ENFORCEMENT=PENALTY\n2\n2, 1, 1., 5, 1, -1.\n", "*EQUATION", {"PENALTY=rho"}},
      {"*EQUATION, EPSILON=-1\n2\n2, 1, 1., 5, 1, -1.\n", "*EQUATION", {"EPSILON must be >= 0"}},
      {"*EQUATION, ENFORCEMENT=PENALTY, PENALTY=1, EPSILON=1\n2\n2, 1, 1., 5, 1, -1.\n", "*EQUATION",
       {"EPSILON applies to ENFORCEMENT=LAGRANGE"}},
      {"*EQUATION, ENFORCEMENT=FOO\n2\n2, 1, 1., 5, 1, -1.\n", "*EQUATION", {"FOO"}},
      {"*EQUATION\n2\nLEFT, 1, 1., ALL, 1, -1.\n", "LEFT, 1, 1., ALL", {"same number of nodes"}},
      {"*MPC\nBEAM, 2\n", "BEAM", {"takes 2 nodes, got 1"}},
      {"*MPC\nWELD, 2, 5\n", "WELD", {"unknown *MPC type 'WELD'", "TIE, PIN, LINK, SLIDER or BEAM"}},
      {"*MPC, USER, MODE=DOF\n1, 2, 5\n", "*MPC", {"LIBRARY="}},
      {"*MPC, USER, LIBRARY=x.so\nA, 2, 5\n", "A, 2, 5", {"'A'", "JTYPE"}},
      {"*MPC, USER, LIBRARY=x.so\n1\n", "1\n*STEP", {"JTYPE, node1"}},
      {"*MPC, USER, LIBRARY=x.so\n9, 2,\n", "9, 2,", {"ends with ','"}},
      {"*MPC, USER, LIBRARY=x.so, MODE=EDGE\n1, 2\n", "*MPC", {"EDGE"}},
      {"*MPC\nLINK, 2\n", "LINK, 2", {"takes 2 nodes, got 1"}},
      {"*MPC\nSLIDER, 2, 5\n", "SLIDER", {"takes 3 nodes"}},
      {"*MPC\nLINK, 2, 2\n", "LINK, 2, 2", {"names node 2 twice"}},
      {"*MPC\nLINK, 2, ALL\n", "LINK, 2, ALL", {"'ALL' names 6 nodes"}},
      {"*MPC, ENFORCEMENT=ELIMINATION\nLINK, 2, 5\n", "*MPC", {"ELIMINATION needs a linear constraint"}},
      {"*MPC\n", "*MPC", {"needs data lines"}},
      {"*CONSTRAINT, NAME=X\n1, 2\nU1\n", "*CONSTRAINT", {"TYPE"}},
      {"*CONSTRAINT, TYPE=EXPRESSION\n1, 2\n", "*CONSTRAINT", {"one formula line per equation"}},
      {"*CONSTRAINT, TYPE=EXPRESSION\n", "*CONSTRAINT", {"node labels"}},
      {"*CONSTRAINT, TYPE=EXPRESSION\n1, 77\nU1\n", "1, 77", {"77"}},
      {"*CONSTRAINT, TYPE=USER\n1, 2\n", "*CONSTRAINT", {"LIBRARY="}},
      {"*CONSTRAINT, TYPE=USER, LIBRARY=x.so\n1, 2\n1., y\n", "1., y", {"'y'", "property"}},
      {"*CONSTRAINT, TYPE=USER, LIBRARY=x.so, MULTIPLIERS=0\n1, 2\n", "*CONSTRAINT", {"MULTIPLIERS=0"}},
      {"*CONSTRAINT, TYPE=USER, LIBRARY=x.so, ENFORCEMENT=PENALTY, PENALTY=1\n1, 2\n", "*CONSTRAINT",
       {"only ENFORCEMENT=LAGRANGE"}},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.block);
    expect_deck_error_at(with_model_data(c.block), c.marker, c.words);
  }
}

TEST(ConstraintKeywords, BeamAndUserMpc) {
  const Model m = read_deck_string(
      with_model_data("*MPC\nBEAM, 2, 5\n*MPC, USER, MODE=NODE, LIBRARY=lib/mpc.so\n7, 2, 5,\n6\n3, 1, 4\n"),
      "dir/c.inp");
  ASSERT_EQ(m.constraints.size(), 3u);
  EXPECT_EQ(m.constraints[0].kind, ConstraintData::Kind::Beam);
  const auto& u = m.constraints[1];
  EXPECT_EQ(u.kind, ConstraintData::Kind::UserMpc);
  EXPECT_TRUE(u.node_mode);
  EXPECT_EQ(u.flag, 7);  // JTYPE
  EXPECT_EQ(u.nodes.size(), 3u);
  EXPECT_EQ(u.library, "dir/lib/mpc.so");
  EXPECT_EQ(u.symbol, "tether_user_mpc");
  EXPECT_EQ(m.constraints[2].nodes.size(), 2u);
}

TEST(ConstraintKeywords, LibraryOfADeckWithoutDirectoryStaysInTheCurrentDirectory) {
  // `tether check deck.inp` with LIBRARY=libeq.so must load ./libeq.so: a bare
  // "libeq.so" would make dlopen() search the system library path instead.
  const Model m = read_deck_string(
      with_model_data("*CONSTRAINT, TYPE=USER, LIBRARY=libeq.so, MULTIPLIERS=1\n2, 5\n"
                      "*MPC, USER, LIBRARY=mpc.so\n7, 2, 5\n"
                      "*MPC, USER, LIBRARY=/opt/lib/abs.so\n7, 2, 5\n"),
      "c.inp");
  ASSERT_EQ(m.constraints.size(), 3u);
  EXPECT_EQ(m.constraints[0].library, "./libeq.so");
  EXPECT_EQ(m.constraints[1].library, "./mpc.so");
  EXPECT_EQ(m.constraints[2].library, "/opt/lib/abs.so");  // absolute paths are kept
}

TEST(ConstraintKeywords, RotationDofSixOnBoundaryAndCload) {
  const Model m = read_deck_string(
      replaced(with_model_data("*MPC\nBEAM, 2, 5\n"), "*CLOAD\nRIGHT, 1, 10", "*BOUNDARY\n5, 6, 6, 0.5\n*CLOAD\n5, 6, 2."),
      "c.inp");
  const Step& s = m.steps.at(0);
  const auto b = std::find_if(s.boundary.begin(), s.boundary.end(), [](const Prescribed& p) { return p.dof == 2; });
  ASSERT_NE(b, s.boundary.end());
  EXPECT_DOUBLE_EQ(b->value, 0.5);
  ASSERT_EQ(s.cloads.size(), 1u);
  EXPECT_EQ(s.cloads[0].dof, 2);
}

TEST(ConstraintKeywords, OnlyInModelData) {
  const std::string deck = replaced(kDeck, "*CLOAD", "*EQUATION\n2\n2, 1, 1., 5, 1, -1.\n*CLOAD");
  expect_deck_error_at(deck, "*EQUATION", {"*EQUATION"});
}
