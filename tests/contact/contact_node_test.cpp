// The contact element node by node: complementarity residuals, hand-over
// dofs, the friction branch a node takes (slip direction, closing, touching
// at rest or within round-off, penalty at rest), the friction force at a
// convex corner, and the force reported on the slave.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "contact_fixture.hpp"
#include "tether/contact/calculix_area.hpp"

namespace tether {
namespace {

using namespace contact_test;

TEST(ContactNode, HandOverDofsAreDroppedAtTheNextIncrement) {
  // After the commit that ends the hand-over increment the committed segment
  // is the current one again: the extra node leaves the dof list, and
  // update_connectivity reports the change so the assembler rebuilds its pattern.
  Fixture f(Master::Linear, hard(), Friction::Exact);
  f.hand_over(0.3, -0.04, -0.3, -0.04);
  EXPECT_EQ(f.node().dofs().size(), 2u * 4 + 2);
  f.pair->commit(f.state());
  f.time += 1;
  f.u_start = f.u;
  EXPECT_TRUE(f.pair->update_connectivity(f.state()));
  EXPECT_FALSE(f.pair->slave(0).handed_over);
  EXPECT_EQ(f.node().dofs().size(), 2u * 3 + 2);
  EXPECT_NEAR(f.node().values(f.state()).slip, 0.0, 1e-14);
  // Frictionless, a hand-over adds no dofs.
  Fixture g(Master::Linear, hard(), Friction::None);
  g.hand_over(0.3, -0.04, -0.3, -0.04);
  EXPECT_FALSE(g.pair->slave(0).handed_over);
  EXPECT_EQ(g.node().dofs().size(), 2u * 3 + 1);
}

TEST(ContactNode, HardResidualIsTheComplementarityFunction) {
  Fixture f(Master::Linear, hard(), Friction::None);
  f.place(0.3, 0.2, 0.3, -0.04);  // penetrates by 0.04
  const auto dofs = f.node().dofs();
  LocalSystem out;
  out.reset(static_cast<Eigen::Index>(dofs.size()));
  f.u[f.n_disp] = 0.0;  // λ - c g = 0.06 > 0: closed, the row is -g
  f.node().evaluate(f.state(), out, false);
  const double g = out.residual[out.residual.size() - 1];
  f.u[f.n_disp] = -1.0;  // λ - c g < 0: open, the row is -λ/c
  out.reset(static_cast<Eigen::Index>(dofs.size()));
  f.node().evaluate(f.state(), out, false);
  EXPECT_NEAR(out.residual[out.residual.size() - 1], 1.0 / 1.5, 1e-15);
  // The gap of the moved master: the slave is below the surface.
  EXPECT_GT(g, 0.0);
  EXPECT_LT(g, 0.1);
}

TEST(ContactNode, SmoothedResidualIsTheGapGradientOverTheRealNodes) {
  // The finite-difference tangent check cannot see a wrong map of the
  // residual itself (it differentiates whatever the residual is); here
  // r_u = -λ ∂g/∂u is checked against central differences of the gap over
  // the real dofs, on the corner piece (3 master nodes) and a straight piece.
  for (const Master master : {Master::SmoothCorner, Master::SmoothStraight}) {
    Fixture f(master, hard(), Friction::None);
    f.place(f.x0, -0.04, f.x0 + 0.02, -0.04);
    const double lambda = 0.8;
    f.u[f.n_disp] = lambda;
    const auto dofs = f.node().dofs();
    const auto n = static_cast<Eigen::Index>(dofs.size());
    LocalSystem out;
    out.reset(n);
    f.node().evaluate(f.state(), out, false);
    double error = 0;
    for (Eigen::Index j = 0; j + 1 < n; ++j) {  // displacement dofs (λn last)
      const double h = 1e-7, keep = f.u[dofs[j]];
      f.u[dofs[j]] = keep + h;
      const double plus = f.node().values(f.state()).gap;
      f.u[dofs[j]] = keep - h;
      const double minus = f.node().values(f.state()).gap;
      f.u[dofs[j]] = keep;
      error = std::max(error, std::abs(out.residual[j] + lambda * (plus - minus) / (2 * h)));
    }
    std::printf("[ smooth ] residual vs -lambda dg/du (FD): %.2e over %d dofs\n", error, static_cast<int>(n));
    EXPECT_LT(error, 1e-8);
    // Rows of W sum to 1: the forces on the slave and the master nodes balance.
    EXPECT_NEAR(out.residual.head(n - 1).reshaped(2, (n - 1) / 2).rowwise().sum().norm(), 0.0, 1e-14);
  }
}

TEST(ContactNode, SlaveBeyondAnOpenEndIsFree) {
  Fixture f(Master::Linear, hard(), Friction::None);
  f.place(3.0, -0.01, 3.0, -0.01);  // right of the surface's end at x = 2, slightly below
  EXPECT_FALSE(f.pair->slave(0).pairing.found());
  EXPECT_EQ(f.node().dofs().size(), 3u);  // slave x, y and its multiplier only
  EXPECT_EQ(f.node().status(f.state()), ContactStatus::Open);
}

TEST(ContactNode, SlipDirectionIsTheBranchTheResidualTakes) {
  // Exact stick during Newton: λt still carries the sign of the previous
  // iteration's slip branch while τ = λt + cΔs has turned. The direction the
  // friction guard counts reversals of must be sign(τ), the branch the slip
  // row drives λt to (λt → μN sgn τ); sign(λt) lags one iteration behind, so
  // a period-2 cycle was held one iteration late (ironing indentation deck:
  // one cut-back, none with sign(τ)).
  Fixture f(Master::Linear, hard(), Friction::Exact);
  f.place(0.3, -0.04, 0.8, -0.04);
  const double c = 1.5, mu = 0.3, lambda_n = 0.8;
  f.u[f.n_disp] = lambda_n;
  const double ds = f.node().values(f.state()).slip;
  ASSERT_GT(std::abs(c * ds), 2 * mu * lambda_n);  // so that τ and λt = -μN sgn Δs differ in sign
  const int sign = ds > 0 ? 1 : -1;
  f.u[f.n_disp + 1] = -sign * mu * lambda_n;
  const ContactBranch branch = f.node().branch(f.state());
  EXPECT_EQ(branch.status, ContactStatus::Slip);
  EXPECT_EQ(branch.direction, sign);
  EXPECT_TRUE(branch.friction_active);
  // The slip row is -(λt - μN sgn τ)/c: zero at λt = +sign μN.
  LocalSystem out;
  out.reset(static_cast<Eigen::Index>(f.node().dofs().size()));
  f.node().evaluate(f.state(), out, false);
  EXPECT_NEAR(out.residual[out.residual.size() - 1], 2 * sign * mu * lambda_n / c, 1e-14);
  // In stick (|τ| < μN) there is no direction.
  f.u[f.n_disp + 1] = -c * ds;
  EXPECT_EQ(f.node().branch(f.state()).direction, 0);
}

// A node that has just closed has λn = 0 exactly (the open row of the
// previous iteration drove it there): closed (status Slip) but N = 0, so its
// friction row is still the open one, -λt/c. When λn turns positive the row
// becomes the slip (or stick) one while the status stays Slip. That is an
// active-set change of the semi-smooth Newton method, and the pair counts it
// (it was invisible before, and made the ironing test's indentation
// increment 2 look non-quadratic on the force residual:
// docs/verification_contact.md, "Quadratic convergence").
TEST(ContactNode, ANodeStartingToCarryANormalForceChangesItsFrictionBranch) {
  Fixture f(Master::Linear, hard(), Friction::Exact);
  f.place(0.3, -0.04, 0.8, -0.04);  // penetrating, slid by 0.5: slip once pressed
  f.u[f.n_disp] = 0;                // λn = 0: closed (λn - c g >= 0) without a force
  f.u[f.n_disp + 1] = 0;
  f.pair->update_connectivity(f.state());
  const ContactBranch closing = f.node().branch(f.state());
  EXPECT_EQ(closing.status, ContactStatus::Slip);
  EXPECT_FALSE(closing.friction_active);
  EXPECT_EQ(closing.direction, 0);
  // The open friction row: -λt/c with no coupling to λn.
  LocalSystem out;
  out.reset(static_cast<Eigen::Index>(f.node().dofs().size()));
  f.node().evaluate(f.state(), out, true);
  const Eigen::Index it = out.residual.size() - 1;
  EXPECT_EQ(out.tangent(it, it - 1), 0.0);
  EXPECT_EQ(f.pair->statistics().status_changes, 0);
  f.u[f.n_disp] = 0.8;  // the next iterate carries a normal force
  f.pair->update_connectivity(f.state());
  const ContactBranch pressed = f.node().branch(f.state());
  EXPECT_EQ(pressed.status, ContactStatus::Slip);
  EXPECT_TRUE(pressed.friction_active);
  EXPECT_NE(pressed.direction, 0);
  EXPECT_EQ(f.pair->statistics().status_changes, 1);
  f.node().evaluate(f.state(), out, true);
  EXPECT_NE(out.tangent(it, it - 1), 0.0);  // slip row: ∂/∂λn = μ sgn τ / c
  f.pair->update_connectivity(f.state());  // same state: no change
  EXPECT_EQ(f.pair->statistics().status_changes, 0);
}

// A node touching the master at the start of an increment with no friction
// history (g = 0, λn = 0, λt = 0, Δs = 0: τ = 0) is closed without force,
// where the open friction row -λt/c and the stick row Δs meet (both 0). It
// takes the stick row, the limit from N > 0: its friction row equals the
// pressed node's, whose tangent matches central differences. With the open row the first
// iteration gave such nodes no friction (the block pressed onto the faceted
// foundation slid its bottom nodes 1.7e-3, 7 % of a master face, in that
// iteration and was cut back; docs/theory/contact.md, "Friction").
TEST(ContactNode, ANodeTouchingAtRestTakesTheStickRow) {
  Fixture f(Master::Linear, hard(), Friction::Exact);
  f.u.setZero();
  f.u[1] = -f.reference[0].y();  // on the master face y = 0: g = 0
  f.u_start = f.u;               // no motion in the increment: Δs = 0
  f.pair->update_connectivity(f.state());
  const ContactBranch branch = f.node().branch(f.state());
  EXPECT_EQ(branch.status, ContactStatus::Stick);
  EXPECT_TRUE(branch.friction_active);
  const auto n = static_cast<Eigen::Index>(f.node().dofs().size());
  LocalSystem at_rest, pressed;
  at_rest.reset(n);
  pressed.reset(n);
  f.node().evaluate(f.state(), at_rest, true);
  const Eigen::Index it = n - 1;
  EXPECT_EQ(at_rest.residual[it], 0.0);
  EXPECT_EQ(at_rest.tangent(it, it), 0.0);       // not the open row's -1/c
  EXPECT_GT(at_rest.tangent.row(it).norm(), 0.5);  // ∇Δs: |t| = 1 at the slave
  // Pressed (λn = 0.5: |τ| = 0 < μN, stick) the friction row is the same and
  // matches central differences (away from the kinks at λn = 0 and |τ| = μN).
  f.u[f.n_disp] = 0.5;
  EXPECT_EQ(f.node().status(f.state()), ContactStatus::Stick);
  f.node().evaluate(f.state(), pressed, true);
  EXPECT_LT((at_rest.tangent.row(it) - pressed.tangent.row(it)).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_LT(tangent_error(f.node(), f.state(), 1e-7), 2e-6);
}

// A node placed on the master by the mesh generator lands a few ulps either
// side of it. On the positive side (g = +1e-15) it must touch like a node at
// exactly 0 — closed, at rest, the stick row — not be open, carry no friction
// in the first iteration and slide freely: that stopped a block pressed with
// friction onto a smoothed foundation at any increment size (x0 = 0.52 in
// tests/analysis/faceted_master_test.cpp). A real clearance (1e-9) stays open.
TEST(ContactNode, AGapWithinRoundOffTouchesAndAClearanceDoesNot) {
  Fixture f(Master::Linear, hard(), Friction::Exact);
  f.u.setZero();
  f.u[1] = -f.reference[0].y() + 1e-15;
  f.u_start = f.u;
  f.pair->update_connectivity(f.state());
  ASSERT_GT(f.node().values(f.state()).gap, 0.0);
  const ContactBranch touching = f.node().branch(f.state());
  EXPECT_EQ(touching.status, ContactStatus::Stick);
  EXPECT_TRUE(touching.friction_active);
  f.u[1] = -f.reference[0].y() + 1e-9;
  f.u_start = f.u;
  f.pair->update_connectivity(f.state());
  EXPECT_EQ(f.node().branch(f.state()).status, ContactStatus::Open);
}

// Penalty friction (stick slope) at rest: committed force 0 and Δs = 0, so
// T = 0, but the stick stiffness F ⊗ k∇Δs is there (it was skipped with
// T = 0, which let such a node slide freely in its first iteration).
TEST(ContactNode, PenaltyFrictionAtRestHasItsStickStiffness) {
  Fixture f(Master::Linear, hard(), Friction::Slope);
  f.u.setZero();
  f.u[1] = -f.reference[0].y();  // on the master face y = 0
  f.u[f.n_disp] = 0.8;           // λn: closed, N = 0.8
  f.u_start = f.u;               // no motion in the increment: Δs = 0
  f.pair->update_connectivity(f.state());
  EXPECT_EQ(f.node().status(f.state()), ContactStatus::Stick);
  EXPECT_EQ(f.node().values(f.state()).tangential_force, 0.0);
  const double err = tangent_error(f.node(), f.state(), 1e-7);
  std::printf("[ contact ] penalty stick at rest: tangent error %.2e\n", err);
  EXPECT_LT(err, 2e-6);
}

// A slave in the shadow of a convex kink is in node-to-node contact with the
// kink node (normal e along y_s - y_kink). Its friction force acts there too,
// along e turned by 90°, on the slave and the kink node only, at right
// angles to the normal force (it was spread over the segment with ξ* past
// its end: weights -0.15 and 1.15 at ξ* = 1.3).
TEST(ContactNode, FrictionAtAConvexCornerActsAtTheCornerNodeAtRightAnglesToTheNormal) {
  for (const double lambda_t : {0.1, -0.2}) {
    Fixture f(Master::Kink, hard(), Friction::Exact);
    f.place(0.05, 0.08, 0.0, 0.065);
    // Right above the (slightly moved) kink node: outside both faces.
    const Eigen::Vector2d kink = f.reference[2] + f.u.segment<2>(4);
    f.u[0] = kink.x() - f.reference[0].x(), f.u[1] = kink.y() + 0.012 - f.reference[0].y();
    f.pair->update_connectivity(f.state());
    ASSERT_TRUE(f.pair->slave(0).pairing.at_corner);
    f.u[f.n_disp] = 0.8, f.u[f.n_disp + 1] = lambda_t;
    f.pair->update_connectivity(f.state());
    LocalSystem out;
    out.reset(static_cast<Eigen::Index>(f.node().dofs().size()));
    f.node().evaluate(f.state(), out, true);
    // Slave force: the normal part along e, the rest (friction) at right angles to it.
    const Eigen::Vector2d ys = f.reference[0] + f.u.segment<2>(0), yk = f.reference[2] + f.u.segment<2>(4);
    const Eigen::Vector2d e = (ys - yk).normalized();
    const Eigen::Vector2d r_s = out.residual.segment<2>(0);
    EXPECT_NEAR(std::abs(r_s.dot(Eigen::Vector2d(-e.y(), e.x()))), std::abs(lambda_t), 1e-12);
    EXPECT_NEAR(std::abs(r_s.dot(e)), 0.8, 1e-12);
    // Nothing on the far ends of the two faces (nodes 1 and 3).
    const auto& dofs = f.node().dofs();
    for (std::size_t k = 0; k < dofs.size(); ++k)
      if (dofs[k] < f.n_disp && (dofs[k] / 2 == 1 || dofs[k] / 2 == 3))
        EXPECT_EQ(out.residual[static_cast<Eigen::Index>(k)], 0.0) << "dof " << dofs[k];
    const double err = tangent_error(f.node(), f.state(), 1e-7);
    std::printf("[ contact ] friction at a convex corner, lambda_t %.1f: tangent error %.2e\n", lambda_t, err);
    EXPECT_LT(err, 2e-6);
  }
}

TEST(ContactNode, ForceOnTheSlaveIsNormalForceAlongTheOutwardNormal) {
  Fixture f(Master::Linear, linear_law(), Friction::None);
  f.u.setZero();
  f.u_start.setZero();
  f.u[1] = -0.22;  // slave at (0.3, -0.02): overclosure 0.02
  f.pair->update_connectivity(f.state());
  const ContactNodeValues v = f.node().values(f.state());
  EXPECT_NEAR(v.gap, -0.02, 1e-14);
  EXPECT_NEAR(v.pressure, 40 * (0.02 + 0.01), 1e-12);
  EXPECT_NEAR(v.normal_force, 0.7 * 40 * 0.03, 1e-12);
  EXPECT_NEAR(v.force.y(), v.normal_force, 1e-12);
  EXPECT_NEAR(v.force.x(), 0, 1e-14);
  EXPECT_EQ(v.master_element, 1);
}

}  // namespace
}  // namespace tether

namespace tether {
namespace {

using namespace contact_test;

/// Positions of the slave's segment (the current master face) at the fixture's state.
std::vector<Eigen::Vector2d> current_face(const Fixture& f) {
  const ContactSlave& s = f.pair->slave(0);
  std::vector<Eigen::Vector2d> y;
  for (std::size_t a = 1; a < s.nodes.size(); ++a) {
    const int n = s.nodes[a];
    y.push_back(f.reference[static_cast<std::size_t>(n)] + f.u.segment<2>(2 * n));
  }
  return y;
}

// CalculiX's area of a node-based slave (dialect calculix) at random states:
// slave over the face, penetrating, master nodes moved by up to 0.02; plane
// and axisymmetric rules, linear and curved faces, with and without a
// penalty-stick friction whose stiffness is per area. The tangent, with
// ∇N = -A p' ∇g + p ∇A through the master nodes and ξ*, against central
// differences; the pressure is N over the area on the current face.
TEST(ContactNode, CalculixAreaOnTheCurrentFaceHasAConsistentTangentAtRandomStates) {
  std::mt19937 random(20261126);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int checked = 0;
  double worst = 0;
  for (const NodeArea area : {NodeArea::Plane, NodeArea::Axisymmetric})
    for (const Master master : {Master::Linear, Master::Quadratic, Master::QuadraticPair})
      for (const Friction friction : {Friction::None, Friction::Slope})
        for (int trial = 0; trial < 8; ++trial) {
          Fixture f(master, calculix_linear_law(), friction, 0.3, area);
          // Penetrating by 0.01 to 0.07 wherever the master nodes are.
          const bool dome = master == Master::Quadratic;  // face y = 0.15 (1 - x²) before moving
          const double x = f.x0 + (dome ? 0.3 : 0.6) * unit(random);
          const double y = (dome ? 0.05 : -0.05) + 0.01 * unit(random);
          f.place(f.x0, y, x, y);
          for (int k = 2; k < f.n_disp; ++k) f.u[k] = 0.02 * unit(random);
          f.pair->update_connectivity(f.state());
          const ContactNodeValues v = f.node().values(f.state());
          ASSERT_GT(v.normal_force, 0) << "trial " << trial;
          // The area on the current face at the current ξ* (at a convex corner, which
          // the moved master nodes may make, at the face's end).
          const ContactSlave& s = f.pair->slave(0);
          const double xi = s.pairing.at_corner ? (s.pairing.xi < 0 ? -1.0 : 1.0) : v.xi;
          const FaceArea a = calculix_face_area(f.pair->setup().calculix_face_areas[0], current_face(f), xi);
          EXPECT_NEAR(v.pressure * a.area, v.normal_force, 1e-12 * v.normal_force)
              << "area " << static_cast<int>(area) << " master " << static_cast<int>(master) << " trial " << trial
              << " xi " << v.xi << " corner " << s.pairing.at_corner << " segment " << s.pairing.segment;
          EXPECT_GT(std::abs(a.area / s.area - 1), 1e-4) << "the area moved with the master";
          const double err = tangent_error(f.node(), f.state(), 1e-7);
          EXPECT_LT(err, 2e-6) << "area " << static_cast<int>(area) << " master " << static_cast<int>(master)
                               << " friction " << static_cast<int>(friction) << " trial " << trial;
          worst = std::max(worst, err), ++checked;
        }
  std::printf("[ contact ] CalculiX's current area: %d random states, worst tangent error %.2e\n", checked, worst);
}

// The area's derivatives against differences of calculix_face_area itself
// (∂A/∂y_a at fixed ξ, ∂A/∂ξ), on a curved face, for both rules; and its
// closed forms on a straight face: 2 t |y'| = L t (plane), 180 · 4 sin 1° r
// |(cos 1° r', y')| (axisymmetric, linear face).
TEST(ContactNode, CalculixFaceAreaDerivativesAndClosedForms) {
  const std::vector<Eigen::Vector2d> curved = {{3.2, 0.1}, {1.1, -0.05}, {2.0, 0.3}};
  for (const auto kind : {MasterFaceArea::Kind::plane, MasterFaceArea::Kind::axisymmetric}) {
    const MasterFaceArea rule{kind, 0.8};
    const double xi = 0.37, h = 1e-6;
    const FaceArea a = calculix_face_area(rule, curved, xi);
    EXPECT_NEAR(a.d_xi, (calculix_face_area(rule, curved, xi + h).area - calculix_face_area(rule, curved, xi - h).area) / (2 * h),
                1e-7 * a.area);
    for (std::size_t n = 0; n < curved.size(); ++n)
      for (int c = 0; c < 2; ++c) {
        std::vector<Eigen::Vector2d> up = curved, down = curved;
        up[n][c] += h, down[n][c] -= h;
        const double fd = (calculix_face_area(rule, up, xi).area - calculix_face_area(rule, down, xi).area) / (2 * h);
        EXPECT_NEAR(a.d_nodes[n][c], fd, 1e-7 * a.area) << "node " << n << " component " << c;
      }
  }
  const std::vector<Eigen::Vector2d> straight = {{2.0, 1.0}, {1.0, 1.2}};
  const double length = std::hypot(1.0, 0.2);
  EXPECT_NEAR(calculix_face_area({MasterFaceArea::Kind::plane, 0.8}, straight, 0.3).area, 0.8 * length, 1e-14);
  const double phi = std::numbers::pi / 180, r = 0.35 * 2.0 + 0.65 * 1.0;  // r at ξ = 0.3
  EXPECT_NEAR(calculix_face_area({MasterFaceArea::Kind::axisymmetric, 0}, straight, 0.3).area,
              180 * 4 * std::sin(phi) * r * std::hypot(std::cos(phi) * 0.5, 0.1), 1e-13);
}

// At a convex corner (node-to-node contact with the kink node) the area is
// the face's at its end, ξ = ±1, fixed: its gradient goes through the face's
// nodes only, and the tangent stays consistent.
TEST(ContactNode, CalculixAreaAtAConvexCornerIsTheFaceEndsAndConsistent) {
  Fixture f(Master::Kink, exponential_law(), Friction::None, 0.3, NodeArea::Plane);
  f.place(0.05, 0.08, 0.0, 0.065);
  const Eigen::Vector2d kink = f.reference[2] + f.u.segment<2>(4);
  f.u[0] = kink.x() - f.reference[0].x(), f.u[1] = kink.y() + 0.012 - f.reference[0].y();
  f.pair->update_connectivity(f.state());
  ASSERT_TRUE(f.pair->slave(0).pairing.at_corner);
  const ContactNodeValues v = f.node().values(f.state());
  ASSERT_GT(v.normal_force, 0);
  const double xi_end = f.pair->slave(0).pairing.xi < 0 ? -1.0 : 1.0;
  const FaceArea a = calculix_face_area(f.pair->setup().calculix_face_areas[0], current_face(f), xi_end);
  EXPECT_NEAR(v.pressure * a.area, v.normal_force, 1e-12 * v.normal_force);
  const double err = tangent_error(f.node(), f.state(), 1e-7);
  std::printf("[ contact ] CalculiX's area at a convex corner: tangent error %.2e\n", err);
  EXPECT_LT(err, 2e-6);
}

}  // namespace
}  // namespace tether
