// Constraints in whole analyses: exact answers with every enforcement method.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "run_deck.hpp"

using namespace tether;
using tether::testing::run_deck_text;

namespace {

/// Rigid link of length 2 from a pin at A (node 1) to B (node 2), B starting
/// at 60 deg below the horizontal, moved horizontally to x = L cos(theta)
/// under a downward load P: the link force is P / sin(theta), the horizontal
/// reaction at B is P cot(theta).
std::string rigid_link_deck(double theta_deg, double load) {
  const double l = 2.0, t0 = 60 * std::numbers::pi / 180, t = theta_deg * std::numbers::pi / 180;
  std::ostringstream d;
  d.precision(17);
  d << "*NODE\n1, 0, 0\n2, " << l * std::cos(t0) << ", " << -l * std::sin(t0) << "\n"
    << "*MPC, NAME=LINK\nLINK, 1, 2\n"
    << "*BOUNDARY\n1, 1, 2\n"
    << "*STEP, NLGEOM\n*STATIC\n0.25, 1.\n*CONTROLS, PARAMETERS=FIELD\n1e-10, 1e-10\n"
    << "*BOUNDARY\n2, 1, 1, " << l * std::cos(t) - l * std::cos(t0) << "\n"
    << "*CLOAD\n2, 2, " << -load << "\n*END STEP\n";
  return d.str();
}

}  // namespace

TEST(Constraints, RigidLinkForceUnderLargeRotation) {
  for (double theta : {45.0, 30.0}) {
    const double load = 3.0;
    const auto run = run_deck_text(rigid_link_deck(theta, load));
    ASSERT_TRUE(run.summary.completed) << run.summary.message;
    const double s = std::sin(theta * std::numbers::pi / 180), c = std::cos(theta * std::numbers::pi / 180);
    const auto& m = run.last().multipliers.at(0);
    EXPECT_EQ(m.owner, "LINK");
    EXPECT_NEAR(m.value[0] / load, 1 / s, 1e-8) << theta;  // 1.41421 at 45, 2.0000 at 30
    EXPECT_NEAR(std::abs(m.constraint[0]), 0.0, 1e-10 * 2.0);
    EXPECT_NEAR(run.last().reaction[run.node(2)].x() / load, c / s, 1e-8) << theta;
    // B ends on the circle, below A.
    EXPECT_NEAR(run.model.coords[run.node(2)].y() + run.last().displacement[run.node(2)].y(), -2 * s, 1e-10);
  }
}

namespace {

/// Two CPE4 bars [0,1] and [1,2] (nodes not shared) joined at x = 1 by
/// *EQUATION ties u(2) = u(5), u(3) = u(8) in both directions; the left end
/// is fixed, the right end pulled by F. The tie is the seed's u_a - u_b = 0.
std::string tied_bars_deck(const std::string& parameters, bool reversed) {
  std::ostringstream d;
  d << "*NODE\n1,0,0\n2,1,0\n3,1,1\n4,0,1\n5,1,0\n6,2,0\n7,2,1\n8,1,1\n"
    << "*ELEMENT, TYPE=CPE4, ELSET=E\n1, 1,2,3,4\n2, 5,6,7,8\n"
    << "*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.\n*SOLID SECTION, ELSET=E, MATERIAL=M\n"
    << "*BOUNDARY\n1, 1, 2\n4, 1\n";
  for (auto [a, b] : {std::pair{2, 5}, std::pair{3, 8}})
    for (int dof : {1, 2}) {
      if (reversed) std::swap(a, b);
      d << "*EQUATION" << parameters << "\n2\n" << a << ", " << dof << ", 1., " << b << ", " << dof << ", -1.\n";
    }
  d << "*STEP\n*STATIC\n*CONTROLS, PARAMETERS=FIELD\n1e-10, 1e-10\n*CLOAD\n6, 1, 5.\n7, 1, 5.\n*END STEP\n";
  return d.str();
}

}  // namespace

TEST(Constraints, SeedEqualityTieWithEveryEnforcement) {
  // nu = 0: a bar of length 2, E = 1000, area 1, force 10: u(2) = 0.02 exactly.
  struct Case {
    std::string parameters;
    double tolerance;  // on the tip displacement, what the method promises
  };
  const std::vector<Case> cases = {
      {"", 1e-12},                                                  // exact
      {", ENFORCEMENT=LAGRANGE, EPSILON=1e-9", 1e-7},               // f = eps * lambda
      {", ENFORCEMENT=PENALTY, PENALTY=1e9", 1e-7},                 // f = lambda / rho
      {", ENFORCEMENT=AUGMENTED, PENALTY=1e4, TOLERANCE=1e-12", 1e-11},
  };
  for (const auto& c : cases) {
    for (bool reversed : {false, true}) {
      const auto run = run_deck_text(tied_bars_deck(c.parameters, reversed));
      ASSERT_TRUE(run.summary.completed) << c.parameters << ": " << run.summary.message;
      EXPECT_NEAR(run.last().displacement[run.node(6)].x(), 0.02, c.tolerance) << c.parameters;
      EXPECT_NEAR(run.last().displacement[run.node(7)].x(), 0.02, c.tolerance) << c.parameters;
      // The constraint force is the transmitted force: 5 per tied node pair in x.
      const auto& m = run.last().multipliers;
      ASSERT_EQ(m.size(), 4u);
      EXPECT_NEAR(std::abs(m[0].value[0]), 5.0, 1e-6) << c.parameters;
      if (c.parameters.find("EPSILON") != std::string::npos)
        for (const auto& v : m) EXPECT_NEAR(v.constraint[0], 1e-9 * v.value[0], 1e-15);  // f = eps * lambda
    }
  }
}

TEST(Constraints, LagrangeSatisfiesTheEquationToRoundOff) {
  const auto run = run_deck_text(tied_bars_deck("", false));
  ASSERT_TRUE(run.summary.completed);
  for (const auto& m : run.last().multipliers) EXPECT_LE(std::abs(m.constraint[0]), 1e-10 * 2.0);
}

TEST(Constraints, LinkBracedBodyRotatesWithoutStrain) {
  // One CPE4 made rigid by four LINKs (three edges and a diagonal; node 1 is
  // pinned and node 2 driven, so edge 1-2 needs none). Node 2 is driven around
  // node 1 on the unit circle (amplitudes give the exact circle at every 10
  // degrees, where the fixed increments end).
  std::ostringstream d;
  d.precision(17);
  d << "*NODE\n1,0,0\n2,1,0\n3,1,1\n4,0,1\n*ELEMENT, TYPE=CPE4, ELSET=E\n1, 1,2,3,4\n"
    << "*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.3\n*SOLID SECTION, ELSET=E, MATERIAL=M\n"
    << "*MPC\nLINK, 2, 3\nLINK, 3, 4\nLINK, 4, 1\nLINK, 1, 3\n";
  d << "*AMPLITUDE, NAME=UX\n";
  for (int k = 0; k <= 36; ++k) d << k / 36.0 << ", " << std::cos(k * std::numbers::pi / 18) - 1 << "\n";
  d << "*AMPLITUDE, NAME=UY\n";
  for (int k = 0; k <= 36; ++k) d << k / 36.0 << ", " << std::sin(k * std::numbers::pi / 18) << "\n";
  d << "*BOUNDARY\n1, 1, 2\n*STEP, NLGEOM, INC=100\n*STATIC, DIRECT\n" << 1 / 36.0 << ", 1.\n"
    << "*CONTROLS, PARAMETERS=FIELD\n1e-10, 1e-10\n"
    << "*BOUNDARY, AMPLITUDE=UX\n2, 1, 1, 1.\n*BOUNDARY, AMPLITUDE=UY\n2, 2, 2, 1.\n*END STEP\n";
  const auto run = run_deck_text(d.str());
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  ASSERT_EQ(run.recorder.results.size(), 36u);
  for (int k : {8, 35}) {  // 90 and 360 degrees
    const auto& r = run.recorder.results[k];
    for (const auto& p : r.points[0]) {
      for (double e : p.strain) EXPECT_NEAR(e, 0.0, 1e-10) << "increment " << k + 1;
      for (double s : p.stress) EXPECT_NEAR(s, 0.0, 1e-6) << "increment " << k + 1;
    }
    const double angle = (k + 1) * std::numbers::pi / 18;
    // Node 3 at (1,1) rotated by the angle.
    const Eigen::Vector2d x3 = run.model.coords[run.node(3)] + r.displacement[run.node(3)];
    EXPECT_NEAR(x3.x(), std::cos(angle) - std::sin(angle), 1e-10);
    EXPECT_NEAR(x3.y(), std::sin(angle) + std::cos(angle), 1e-10);
  }
}

TEST(Constraints, RedundantConstraintIsNamed) {
  // A link between two fully prescribed nodes has no free dof: a zero row.
  std::string deck = rigid_link_deck(45, 1.0);
  deck.replace(deck.find("*BOUNDARY\n2, 1, 1,"), 19, "*BOUNDARY\n2, 2, 2, 0.\n2, 1, 1,");
  const auto run = run_deck_text(deck);
  EXPECT_FALSE(run.summary.completed);
  EXPECT_NE(run.summary.message.find("LINK"), std::string::npos) << run.summary.message;
  EXPECT_NE(run.summary.message.find("gradient vanishes on the free dofs"), std::string::npos) << run.summary.message;
}

TEST(Constraints, DuplicateTieIsNamedBeforeTheSolve) {
  std::string deck = tied_bars_deck("", false);
  deck.replace(deck.find("*STEP"), 5, "*EQUATION, NAME=AGAIN\n2\n5, 1, -2., 2, 1, 2.\n*STEP");
  const auto run = run_deck_text(deck);
  EXPECT_FALSE(run.summary.completed);
  EXPECT_NE(run.summary.message.find("AGAIN"), std::string::npos) << run.summary.message;
  EXPECT_NE(run.summary.message.find("repeats EQUATION-1"), std::string::npos) << run.summary.message;
}

TEST(Constraints, SubtleDependenceIsNamedByTheFactorization) {
  // u2 = u5, u5 = u3, u3 = u2 (x): each pair differs, their sum is zero.
  std::string deck = tied_bars_deck("", false);
  deck.replace(deck.find("*STEP"), 5,
               "*EQUATION, NAME=LOOP-A\n2\n5, 1, 1., 3, 1, -1.\n*EQUATION, NAME=LOOP-B\n2\n3, 1, 1., 2, 1, -1.\n*STEP");
  const auto run = run_deck_text(deck);
  EXPECT_FALSE(run.summary.completed);
  EXPECT_NE(run.summary.message.find("multiplier"), std::string::npos) << run.summary.message;
  EXPECT_NE(run.summary.message.find("redundant"), std::string::npos) << run.summary.message;
}

TEST(Constraints, EliminationMatchesLagrangeWhicheverSideIsDependent) {
  const auto lagrange = run_deck_text(tied_bars_deck("", false));
  ASSERT_TRUE(lagrange.summary.completed);
  for (bool reversed : {false, true}) {
    const auto elim = run_deck_text(tied_bars_deck(", ENFORCEMENT=ELIMINATION", reversed));
    ASSERT_TRUE(elim.summary.completed) << elim.summary.message;
    for (int n = 0; n < elim.model.n_nodes(); ++n)
      EXPECT_LT((elim.last().displacement[n] - lagrange.last().displacement[n]).norm(), 1e-12) << "node " << n;
    // The eliminated constraints still report their force (from the residual at the dependent dof).
    ASSERT_EQ(elim.last().multipliers.size(), 4u);
    for (std::size_t k = 0; k < 4; ++k) {
      const double sign = reversed ? -1.0 : 1.0;  // f changes sign with the order of the terms
      EXPECT_NEAR(elim.last().multipliers[k].value[0], sign * lagrange.last().multipliers[k].value[0], 1e-9) << k;
      EXPECT_NEAR(elim.last().multipliers[k].constraint[0], 0.0, 1e-14);
      // The nodal constraint forces do not depend on the method or the order.
      const auto& fe = elim.last().multipliers[k].nodal_force;
      const auto& fl = lagrange.last().multipliers[k].nodal_force;
      ASSERT_EQ(fe.size(), fl.size());
      for (const auto& a : fe) {
        const auto b = std::find_if(fl.begin(), fl.end(), [&](const auto& n) { return n.node == a.node; });
        ASSERT_NE(b, fl.end());
        EXPECT_LT((a.force - b->force).norm(), 1e-9) << "constraint " << k << " node " << a.node;
      }
    }
    // Reactions at the support are complete with elimination too.
    EXPECT_NEAR(elim.last().reaction[elim.node(1)].x() + elim.last().reaction[elim.node(4)].x(), -10.0, 1e-9);
  }
}

TEST(Constraints, PrescribedDofMayAppearInAnEquation) {
  // Node 1 is prescribed (x and y) and also in the equation u_x(5) - u_x(1) = 0
  // (CalculiX refuses a prescribed dof there as dependent). With u_x(1) = 0
  // the tie still holds node 5 to it: both methods give the same answer.
  auto deck = [](const std::string& parameters) {
    std::ostringstream d;
    d << "*NODE\n1,0,0\n2,1,0\n3,1,1\n4,0,1\n5,1,0\n6,2,0\n7,2,1\n8,1,1\n"
      << "*ELEMENT, TYPE=CPE4, ELSET=E\n1, 1,2,3,4\n2, 5,6,7,8\n"
      << "*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.\n*SOLID SECTION, ELSET=E, MATERIAL=M\n"
      << "*BOUNDARY\n1, 1, 2\n4, 1\n"
      << "*EQUATION" << parameters << "\n2\n5, 1, 1., 1, 1, -1.\n2\n8, 1, 1., 4, 1, -1.\n2\n5, 2, 1., 1, 2, -1.\n"
      << "*STEP\n*STATIC\n*CONTROLS, PARAMETERS=FIELD\n1e-10, 1e-10\n*CLOAD\n6, 1, 5.\n7, 1, 5.\n*END STEP\n";
    return d.str();
  };
  const auto lagrange = run_deck_text(deck(""));
  const auto elim = run_deck_text(deck(", ENFORCEMENT=ELIMINATION"));
  ASSERT_TRUE(lagrange.summary.completed) << lagrange.summary.message;
  ASSERT_TRUE(elim.summary.completed) << elim.summary.message;
  EXPECT_NEAR(lagrange.last().displacement[lagrange.node(6)].x(), 0.01, 1e-12);  // bar 2 of length 1 under 10
  for (int n = 0; n < elim.model.n_nodes(); ++n)
    EXPECT_LT((elim.last().displacement[n] - lagrange.last().displacement[n]).norm(), 1e-12);
  // The support takes the whole load through the ties in both cases.
  for (const auto* run : {&lagrange, &elim})
    EXPECT_NEAR(run->last().reaction[run->node(1)].x() + run->last().reaction[run->node(4)].x(), -10.0, 1e-9);
}

TEST(Constraints, EliminationResolvesChainsAndNamesRedundantRows) {
  // u_x(2) = u_x(5) and u_x(5) = u_x(3): a chain; then a repeated row is redundant.
  std::ostringstream d;
  d << "*NODE\n1,0,0\n2,1,0\n3,1,1\n4,0,1\n5,1,0\n6,2,0\n7,2,1\n8,1,1\n"
    << "*ELEMENT, TYPE=CPE4, ELSET=E\n1, 1,2,3,4\n2, 5,6,7,8\n"
    << "*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.\n*SOLID SECTION, ELSET=E, MATERIAL=M\n*BOUNDARY\n1, 1, 2\n4, 1\n"
    << "*EQUATION, ENFORCEMENT=ELIMINATION\n2\n2, 1, 1., 5, 1, -1.\n2\n5, 1, 1., 3, 1, -1.\n2\n8, 1, 1., 3, 1, -1.\n"
    << "2\n8, 2, 1., 3, 2, -1.\n2\n5, 2, 1., 2, 2, -1.\n"
    << "*STEP\n*STATIC\n*CLOAD\n6, 1, 5.\n7, 1, 5.\n*END STEP\n";
  const auto run = run_deck_text(d.str());
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  const auto& u = run.last().displacement;
  EXPECT_NEAR(u[run.node(2)].x(), u[run.node(5)].x(), 1e-14);
  EXPECT_NEAR(u[run.node(3)].x(), u[run.node(5)].x(), 1e-14);
  EXPECT_NEAR(u[run.node(8)].x(), u[run.node(3)].x(), 1e-14);

  std::string redundant = d.str();
  redundant.replace(redundant.find("*STEP"), 5, "*EQUATION, ENFORCEMENT=ELIMINATION, NAME=AGAIN\n2\n3, 1, 2., 2, 1, -2.\n*STEP");
  const auto bad = run_deck_text(redundant);
  EXPECT_FALSE(bad.summary.completed);
  EXPECT_NE(bad.summary.message.find("AGAIN"), std::string::npos) << bad.summary.message;
  EXPECT_NE(bad.summary.message.find("redundant"), std::string::npos) << bad.summary.message;
}

TEST(Constraints, OneNodeModelConverges) {
  // A bead on the unit circle: one node, no element. y is prescribed to -0.5,
  // a force -1 in x: r_x = lambda * 2x + 1 = 0, so lambda = -1/(2x) at
  // x = sqrt(0.75) (the wire pushes outwards).
  const std::string deck =
      "*NODE\n1, 1., 0.\n*CONSTRAINT, TYPE=EXPRESSION, NAME=CIRCLE\n1\n(X1+U1)^2 + (Y1+V1)^2 - 1\n"
      "*STEP, NLGEOM\n*STATIC\n*BOUNDARY\n1, 2, 2, -0.5\n*CLOAD\n1, 1, -1.\n*END STEP\n";
  const auto run = run_deck_text(deck);
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  const double x = std::sqrt(0.75);
  EXPECT_NEAR(1.0 + run.last().displacement[0].x(), x, 1e-10);
  EXPECT_NEAR(run.last().multipliers[0].value[0], -1 / (2 * x), 1e-9);
}

TEST(Constraints, BeamBodyRotatesWithoutStrain) {
  // A CPE4 square attached by four BEAMs to a reference node 100 at its
  // centre. Step 1 turns node 100 by 90 deg, step 2 on to 360 deg (dof 6 is
  // prescribed: finite rotation, exact at every increment): no strain, no force.
  std::ostringstream d;
  d.precision(17);
  d << "*NODE\n1,-0.5,-0.5\n2,0.5,-0.5\n3,0.5,0.5\n4,-0.5,0.5\n100,0,0\n*ELEMENT, TYPE=CPE4, ELSET=E\n1, 1,2,3,4\n"
    << "*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.3\n*SOLID SECTION, ELSET=E, MATERIAL=M\n"
    << "*MPC\nBEAM, 1, 100\nBEAM, 2, 100\nBEAM, 3, 100\nBEAM, 4, 100\n"
    << "*BOUNDARY\n100, 1, 2\n"
    << "*STEP, NLGEOM, INC=100\n*STATIC, DIRECT\n0.125, 1.\n*CONTROLS, PARAMETERS=FIELD\n1e-10, 1e-10\n"
    << "*BOUNDARY\n100, 6, 6, " << std::numbers::pi / 2 << "\n*END STEP\n"
    << "*STEP, NLGEOM, INC=100\n*STATIC, DIRECT\n0.125, 1.\n*CONTROLS, PARAMETERS=FIELD\n1e-10, 1e-10\n"
    << "*BOUNDARY\n100, 6, 6, " << 2 * std::numbers::pi << "\n*END STEP\n";
  const auto run = run_deck_text(d.str());
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  ASSERT_EQ(run.recorder.results.size(), 16u);
  for (int k : {7, 15}) {  // 90 and 360 degrees
    const auto& r = run.recorder.results[k];
    for (const auto& p : r.points[0]) {
      for (double e : p.strain) EXPECT_NEAR(e, 0.0, 1e-10) << "increment " << k + 1;
      for (double s : p.stress) EXPECT_NEAR(s, 0.0, 1e-6) << "increment " << k + 1;
    }
    const double angle = k == 7 ? std::numbers::pi / 2 : 2 * std::numbers::pi;
    const Eigen::Vector2d x3 = run.model.coords[run.node(3)] + r.displacement[run.node(3)];
    EXPECT_NEAR(x3.x(), 0.5 * std::cos(angle) - 0.5 * std::sin(angle), 1e-10);
    EXPECT_NEAR(x3.y(), 0.5 * std::sin(angle) + 0.5 * std::cos(angle), 1e-10);
    for (const auto& m : r.multipliers) EXPECT_NEAR(m.value[0], 0.0, 1e-8);
  }
}

TEST(Constraints, BeamTransmitsAMomentToTheBody) {
  // A cantilever strip clamped on the left, its right edge nodes attached by
  // BEAMs to a reference node; a moment M on the reference node (dof 6).
  // Equilibrium (NLGEOM, so the BEAM's finite rotation and the elements agree
  // on the configuration): the support reactions form a couple equal to -M.
  std::ostringstream d;
  d << "*NODE\n1,0,0\n2,1,0\n3,2,0\n4,0,1\n5,1,1\n6,2,1\n100,2,0.5\n"
    << "*ELEMENT, TYPE=CPE4, ELSET=E\n1, 1,2,5,4\n2, 2,3,6,5\n"
    << "*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.3\n*SOLID SECTION, ELSET=E, MATERIAL=M\n"
    << "*MPC\nBEAM, 3, 100\nBEAM, 6, 100\n*NSET, NSET=LEFT\n1, 4\n*BOUNDARY\nLEFT, 1, 2\n"
    << "*STEP, NLGEOM\n*STATIC\n0.25, 1.\n*CONTROLS, PARAMETERS=FIELD\n1e-10, 1e-10\n*CLOAD\n100, 6, 5.\n*END STEP\n";
  const auto run = run_deck_text(d.str());
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  double moment = 0, fx = 0, fy = 0;
  for (int id : {1, 4}) {
    const auto& rf = run.last().reaction[run.node(id)];
    const auto& x = run.model.coords[run.node(id)];
    moment += x.x() * rf.y() - x.y() * rf.x();
    fx += rf.x(), fy += rf.y();
  }
  EXPECT_NEAR(moment, -5.0, 1e-9);
  EXPECT_NEAR(fx, 0.0, 1e-9);
  EXPECT_NEAR(fy, 0.0, 1e-9);
  // The BEAMs' moments on the reference node's rotation balance M; no other
  // node gets a moment.
  double on_reference = 0;
  for (const MultiplierValues& m : run.last().multipliers)
    for (const NodalConstraintForce& f : m.nodal_force) {
      EXPECT_EQ(f.moment.has_value(), f.node == run.node(100)) << m.owner;
      on_reference += f.moment.value_or(0.0);
    }
  EXPECT_NEAR(on_reference, -5.0, 1e-9);
}

TEST(Constraints, MoreEquationsThanFreeDofsIsNamed) {
  // One free node (2 dofs) under three different equations.
  const std::string deck =
      "*NODE\n1, 0., 0.\n2, 1., 0.\n*EQUATION\n2\n1, 1, 1., 2, 1, -1.\n*EQUATION\n2\n1, 2, 1., 2, 2, -1.\n"
      "*EQUATION\n3\n1, 1, 1., 1, 2, 1., 2, 2, -1.\n*BOUNDARY\n2, 1, 2\n*STEP\n*STATIC\n*END STEP\n";
  const auto run = run_deck_text(deck);
  EXPECT_FALSE(run.summary.completed);
  EXPECT_NE(run.summary.message.find("3 constraint equations act on only 2 free displacement dofs"), std::string::npos)
      << run.summary.message;
}

TEST(Constraints, RotationDofOnANodeWithoutOneIsNamed) {
  // dof 6 exists only at a BEAM reference node: a moment on an ordinary node
  // stops the run naming the deck line and the node.
  const std::string deck =
      "*NODE\n1,0,0\n2,1,0\n3,1,1\n4,0,1\n*ELEMENT, TYPE=CPE4, ELSET=E\n1, 1,2,3,4\n"
      "*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.3\n*SOLID SECTION, ELSET=E, MATERIAL=M\n*BOUNDARY\n1, 1, 2\n4, 1\n"
      "*STEP\n*STATIC\n*CLOAD\n3, 6, 1.\n*END STEP\n";
  const auto run = run_deck_text(deck);
  EXPECT_FALSE(run.summary.completed);
  EXPECT_NE(run.summary.message.find("test.inp:18"), std::string::npos) << run.summary.message;
  EXPECT_NE(run.summary.message.find("node 3 has no rotation (dof 6)"), std::string::npos) << run.summary.message;
}
