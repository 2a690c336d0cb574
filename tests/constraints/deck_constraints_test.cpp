// User-library and formula constraints run from decks reproduce the built-in
// constraints' answers (issue: to 1e-10).

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "analysis/run_deck.hpp"

using namespace tether;
using tether::testing::run_deck_text;

namespace {

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string replace_all(std::string text, const std::string& from, const std::string& to) {
  for (auto pos = text.find(from); pos != std::string::npos; pos = text.find(from, pos + to.size()))
    text.replace(pos, from.size(), to);
  return text;
}

/// The worked example deck of examples/user_constraint, with its library path
/// pointing at the module the test build made.
std::string user_example_deck() {
  const std::string deck = read_file(std::string(TETHER_SOURCE_DIR) + "/examples/user_constraint/equal_displacement.inp");
  return replace_all(deck, "LIBRARY=build/libequal_displacement.so", std::string("LIBRARY=") + TETHER_USER_CONSTRAINT_EXAMPLE);
}

}  // namespace

TEST(DeckConstraints, UserExampleDeckGivesTheExactAnswer) {
  const auto run = run_deck_text(user_example_deck());
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  // Documented in the deck: sigma_xx = 100, u_x(x = 2) = 0.2, u_y(y = 1) = -0.03, lambda = -50 on the x ties.
  EXPECT_NEAR(run.last().displacement[run.node(6)].x(), 0.2, 1e-12);
  EXPECT_NEAR(run.last().displacement[run.node(7)].y(), -0.03, 1e-12);
  ASSERT_EQ(run.last().multipliers.size(), 4u);
  EXPECT_NEAR(run.last().multipliers[0].value[0], -50.0, 1e-9);
  for (const auto& element : run.last().points)
    for (const auto& p : element) EXPECT_NEAR(p.stress[0], 100.0, 1e-9);
}

TEST(DeckConstraints, UserLibraryReproducesBuiltInEquation) {
  std::string builtin = read_file(std::string(TETHER_SOURCE_DIR) + "/examples/user_constraint/equal_displacement.inp");
  // Replace each user tie (a, b, component) by the same *EQUATION.
  std::istringstream in(builtin);
  std::ostringstream out;
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("*CONSTRAINT", 0) == 0) {
      std::string nodes, props;
      std::getline(in, nodes);
      std::getline(in, props);
      const std::string a = nodes.substr(0, nodes.find(',')), b = nodes.substr(nodes.find(',') + 1);
      const std::string dof = props.substr(0, props.find(','));
      out << "*EQUATION\n2\n" << a << ", " << dof << ", 1., " << b << ", " << dof << ", -1.\n";
      continue;
    }
    out << line << "\n";
  }
  const auto user = run_deck_text(user_example_deck());
  const auto eq = run_deck_text(out.str());
  ASSERT_TRUE(user.summary.completed && eq.summary.completed) << eq.summary.message;
  for (int n = 0; n < user.model.n_nodes(); ++n)
    EXPECT_LT((user.last().displacement[n] - eq.last().displacement[n]).norm(), 1e-10);
  for (std::size_t k = 0; k < eq.last().multipliers.size(); ++k)
    EXPECT_NEAR(user.last().multipliers[k].value[0], eq.last().multipliers[k].value[0], 1e-10);
}

TEST(DeckConstraints, FormulaReproducesBuiltInLink) {
  // The rigid link of the constraint tests, once as *MPC LINK and once as a formula.
  auto deck = [](const std::string& constraint) {
    const double l = 2.0, t0 = std::numbers::pi / 3, t = std::numbers::pi / 6;
    std::ostringstream d;
    d.precision(17);
    d << "*NODE\n1, 0, 0\n2, " << l * std::cos(t0) << ", " << -l * std::sin(t0) << "\n" << constraint
      << "*BOUNDARY\n1, 1, 2\n*STEP, NLGEOM\n*STATIC\n0.25, 1.\n*CONTROLS, PARAMETERS=FIELD\n1e-10, 1e-10\n"
      << "*BOUNDARY\n2, 1, 1, " << l * std::cos(t) - l * std::cos(t0) << "\n*CLOAD\n2, 2, -3.\n*END STEP\n";
    return d.str();
  };
  const auto link = run_deck_text(deck("*MPC\nLINK, 1, 2\n"));
  const auto formula = run_deck_text(deck(
      "*CONSTRAINT, TYPE=EXPRESSION, NAME=ROD\n1, 2\n"
      "sqrt((X2+U2-X1-U1)^2 + (Y2+V2-Y1-V1)^2) - sqrt((X2-X1)^2 + (Y2-Y1)^2)\n"));
  ASSERT_TRUE(link.summary.completed) << link.summary.message;
  ASSERT_TRUE(formula.summary.completed) << formula.summary.message;
  EXPECT_NEAR(formula.last().multipliers[0].value[0], link.last().multipliers[0].value[0], 1e-10);
  EXPECT_NEAR(formula.last().multipliers[0].value[0] / 6.0, 1.0, 1e-8);  // P / sin 30, to 1e-8 as for LINK
  EXPECT_LT((formula.last().displacement[1] - link.last().displacement[1]).norm(), 1e-10);
}

TEST(DeckConstraints, MalformedFormulaIsAFileLineError) {
  const std::string deck =
      "*NODE\n1, 0, 0\n2, 1, 0\n*CONSTRAINT, TYPE=EXPRESSION\n1, 2\nU1 - W2\n*BOUNDARY\n1, 1, 2\n"
      "*STEP\n*STATIC\n*END STEP\n";
  try {
    run_deck_text(deck);
    FAIL() << "malformed formula accepted";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("test.inp:6"), std::string::npos) << msg;
    EXPECT_NE(msg.find("'W2'"), std::string::npos) << msg;
  }
}

TEST(DeckConstraints, UserMpcExampleDeckGivesTheExactAnswer) {
  // examples/user_mpc: the rigid link as an ABAQUS-style MODE=DOF routine and a
  // point carried with it in MODE=NODE; exact answer in the deck's comments.
  std::string deck = read_file(std::string(TETHER_SOURCE_DIR) + "/examples/user_mpc/user_mpc.inp");
  deck = replace_all(deck, "LIBRARY=build/libuser_mpc.so", std::string("LIBRARY=") + TETHER_USER_MPC_EXAMPLE);
  const auto run = run_deck_text(deck);
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  const auto& u = run.last().displacement;
  EXPECT_NEAR(u[run.node(2)].x(), 1.622319, 1e-6);
  EXPECT_NEAR(u[run.node(2)].y(), 1.622319, 1e-6);
  EXPECT_NEAR(u[run.node(3)].x(), -0.047277, 1e-6);
  EXPECT_NEAR(u[run.node(3)].y(), 2.067519, 1e-6);
  const auto& m = run.last().multipliers;
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m[0].owner, "LINK");
  EXPECT_NEAR(m[0].value[0], -3.715326, 1e-6);
  EXPECT_NEAR(m[1].value[0], 0.0, 1e-9);
  EXPECT_NEAR(m[1].value[1], -1.0, 1e-9);
}

TEST(DeckConstraints, NumericalFaultsInAUserRoutineCutBackThenStopNamingIt) {
  // A routine that fails (mode 1), returns NaN (2) or Inf in the stiffness (3): every
  // attempt fails, the increment is cut back until the minimum, and the run
  // stops with the constraint named — no NaN is ever written.
  for (const char* mode : {"1", "2", "3"}) {
    std::string deck = user_example_deck();
    const std::string from = std::string("LIBRARY=") + TETHER_USER_CONSTRAINT_EXAMPLE;
    deck.replace(deck.find(from), from.size(),
                 std::string("LIBRARY=") + TETHER_USER_CONSTRAINT_FAILING + ", SYMBOL=misbehaving_constraint");
    deck.replace(deck.find("2, 5\n1, 0.0"), 11, std::string("2, 5\n") + mode + ", 0.0");
    const auto run = run_deck_text(deck);
    EXPECT_FALSE(run.summary.completed) << mode;
    EXPECT_GT(run.summary.cutbacks, 0) << mode;
    EXPECT_NE(run.summary.message.find("TIE-BOTTOM-X"), std::string::npos) << mode << ": " << run.summary.message;
    EXPECT_NE(run.summary.message.find("no increment converged"), std::string::npos) << run.summary.message;
    EXPECT_TRUE(run.recorder.results.empty());
    for (const auto& r : run.recorder.results)
      for (const auto& u : r.displacement) EXPECT_TRUE(u.allFinite());
  }
}
