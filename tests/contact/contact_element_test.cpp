// The node-to-segment contact element: tangent against finite differences in
// every branch (HARD closed/open, soft laws, friction stick/slip with exact
// and penalty stick, linear, quadratic and smoothed (SMOOTH=0.2, corner and
// straight pieces) masters), complementarity residuals and the
// pressure-overclosure laws.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "support/tangent_check.hpp"
#include "tether/contact/contact_pair.hpp"
#include "tether/contact/pressure_overclosure.hpp"

namespace tether {
namespace {

using testing::tangent_error;

/// Linear: two straight faces; Quadratic: one curved 3-node face; SmoothCorner
/// / SmoothStraight: two faces with a kink at node 2 and SMOOTH=0.2, slave over
/// the rounded corner (3 real master nodes) or over a shortened straight piece.
/// QuadraticPair: two curved 3-node faces meeting at node 2 (x = 0).
/// Kink: the SmoothCorner geometry without SMOOTH (a convex kink at node 2).
enum class Master { Linear, Quadratic, QuadraticPair, SmoothCorner, SmoothStraight, Kink };
enum class Friction { None, Exact, Slope, ElasticSlip };

/// A slave node (node 0) over a master surface: two straight segments
/// (nodes 1-2-3, top faces of a body below y = 0), one curved 3-node segment,
/// or two segments with a convex kink at node 2 (x = 0), smoothed by s = 0.2
/// (corner piece over -0.4 < x < 0.4).
struct Fixture {
  std::vector<Eigen::Vector2d> reference;
  std::unique_ptr<ContactPair> pair;
  Eigen::VectorXd u, u_start;
  int n_disp = 0;
  double x0 = 0.3;  ///< slave x at the start of the increment

  Fixture(Master master, PressureOverclosure law, Friction friction, double mu = 0.3) {
    ContactPairSetup setup;
    setup.name = "TEST";
    if (master == Master::Linear) {
      reference = {{0.3, 0.2}, {2.0, 0.0}, {0.0, 0.0}, {-2.0, 0.0}};
      setup.master_faces = {{1, 2}, {2, 3}};
      setup.master_face_labels = {{1, 3}, {2, 3}};
    } else if (master == Master::SmoothCorner || master == Master::SmoothStraight || master == Master::Kink) {
      reference = {{0.3, 0.2}, {2.0, 0.0}, {0.0, 0.05}, {-2.0, -0.02}};
      setup.master_faces = {{1, 2}, {2, 3}};
      setup.master_face_labels = {{1, 3}, {2, 3}};
      setup.smoothing = master == Master::Kink ? 0.0 : 0.2;
      x0 = master == Master::SmoothCorner ? 0.1 : 1.0;
    } else if (master == Master::QuadraticPair) {
      reference = {{0.3, 0.2}, {2.0, 0.0}, {0.0, 0.0}, {1.0, 0.08}, {-2.0, 0.0}, {-1.0, 0.05}};
      setup.master_faces = {{1, 2, 3}, {2, 4, 5}};
      setup.master_face_labels = {{1, 3}, {2, 3}};
    } else {
      reference = {{0.3, 0.2}, {1.0, 0.0}, {-1.0, 0.0}, {0.0, 0.15}};
      setup.master_faces = {{1, 2, 3}};
      setup.master_face_labels = {{1, 3}};
    }
    setup.slave_nodes = {0};
    setup.slave_area = {0.7};
    setup.law = law;
    if (friction != Friction::None) {
      FrictionData f;
      f.mu = mu;
      if (friction == Friction::Slope) f.stick_slope = 2.0;
      if (friction == Friction::ElasticSlip) f.elastic_slip = 0.05;
      setup.friction = f;
    }
    setup.search_radius = 5;
    setup.complementarity_stiffness = 1.5;
    n_disp = 2 * static_cast<int>(reference.size());
    const int per = ContactPair::multipliers_per_slave(setup.law, setup.friction);
    pair = std::make_unique<ContactPair>(setup, reference, per > 0 ? n_disp : -1);
    u.setZero(n_disp + per);
    u_start.setZero(n_disp + per);
  }

  double time = 1.0;  ///< total time at the end of the increment (a new value starts a new increment)
  EvaluationState state() const { return EvaluationState{u, u_start, time, time, 1.0, true}; }
  ContactNode& node() const { return *static_cast<ContactNode*>(pair->nodes().front()); }
  /// Moves the slave to (x, y) at the end of the increment, from (x0, y0) at its start.
  void place(double x0, double y0, double x, double y) {
    u_start[0] = x0 - reference[0].x(), u_start[1] = y0 - reference[0].y();
    u[0] = x - reference[0].x(), u[1] = y - reference[0].y();
    // Master nodes moved a little, so no derivative is trivially zero.
    for (int k = 2; k < n_disp; ++k) u[k] = 0.013 * std::sin(3.1 * k);
    pair->update_connectivity(state());
  }
  /// A converged increment ending with the slave at (x0, y0) (master
  /// undeformed, multipliers zero), then an increment moving it to (x, y),
  /// the master nodes moved a little: the slave is paired with the segment
  /// under (x, y), its slip measured from the point under (x0, y0).
  void hand_over(double x0, double y0, double x, double y) {
    u.setZero();
    u[0] = x0 - reference[0].x(), u[1] = y0 - reference[0].y();
    u_start = u;
    pair->update_connectivity(state());
    pair->commit(state());
    time += 1;
    u[0] = x - reference[0].x(), u[1] = y - reference[0].y();
    for (int k = 2; k < n_disp; ++k) u[k] = 0.013 * std::sin(3.1 * k);
    pair->update_connectivity(state());
  }
};

PressureOverclosure hard() { return {}; }
PressureOverclosure hard_with(Enforcement::Method method, double epsilon = 0) {
  PressureOverclosure p;
  p.enforcement.method = method;
  p.enforcement.epsilon = epsilon;
  p.enforcement.penalty = 25;
  return p;
}
PressureOverclosure linear_law() {
  PressureOverclosure p;
  p.law = PressureOverclosure::Law::Linear;
  p.stiffness = 40;
  p.c0 = 0.01;
  return p;
}
PressureOverclosure exponential_law() {
  PressureOverclosure p;
  p.law = PressureOverclosure::Law::Exponential;
  p.c0 = 0.2;
  p.p0 = 3;
  return p;
}

struct Case {
  const char* name;
  Master master;
  PressureOverclosure law;
  Friction friction;
  double lambda_n;  ///< HARD multiplier
  double lambda_t;  ///< exact-stick multiplier
  double slave_y;   ///< slave height at the end (penetration < 0)
  double slip;      ///< x-motion of the slave over the increment
  ContactStatus expected;
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

class ContactTangent : public ::testing::TestWithParam<Case> {};

TEST_P(ContactTangent, MatchesFiniteDifferences) {
  const Case& c = GetParam();
  Fixture f(c.master, c.law, c.friction);
  f.place(f.x0, c.slave_y, f.x0 + c.slip, c.slave_y);
  int k = f.n_disp;
  if (c.law.law == PressureOverclosure::Law::Hard && c.law.enforcement.method == Enforcement::Method::Lagrange)
    f.u[k++] = c.lambda_n;
  if (c.friction == Friction::Exact) f.u[k++] = c.lambda_t;
  EXPECT_EQ(f.node().status(f.state()), c.expected);
  const double error = tangent_error(f.node(), f.state(), 1e-7);
  EXPECT_LT(error, 2e-6) << c.name;
  if (c.master == Master::SmoothCorner || c.master == Master::SmoothStraight) {
    // The slave is paired with the intended smoothed piece (all its real nodes are dofs).
    const ContactSlave& s = f.pair->slave(0);
    ASSERT_TRUE(s.pairing.found());
    const MasterSegment& m = f.pair->segments().segment(s.pairing.segment);
    EXPECT_FALSE(m.identity);
    EXPECT_EQ(m.n_nodes, c.master == Master::SmoothCorner ? 3 : 2);
    std::printf("[ smooth ] %s: tangent error %.2e (%zu dofs)\n", c.name, error, f.node().dofs().size());
  }
}

// Forces, with c = 1.5, mu = 0.3, area 0.7: the slave penetrates by ~0.03–0.05.
INSTANTIATE_TEST_SUITE_P(
    Branches, ContactTangent,
    ::testing::Values(
        Case{"hard_closed_linear", Master::Linear, hard(), Friction::None, 0.8, 0, -0.04, 0.02, ContactStatus::Slip},
        Case{"hard_open_linear", Master::Linear, hard(), Friction::None, -0.2, 0, 0.06, 0.02, ContactStatus::Open},
        Case{"hard_closed_quadratic", Master::Quadratic, hard(), Friction::None, 0.8, 0, 0.1, 0.02,
             ContactStatus::Slip},
        Case{"hard_regularised", Master::Quadratic, hard_with(Enforcement::Method::Lagrange, 0.01), Friction::None,
             0.8, 0, 0.1, 0.02, ContactStatus::Slip},
        Case{"hard_penalty", Master::Linear, hard_with(Enforcement::Method::Penalty), Friction::None, 0, 0, -0.03,
             0.02, ContactStatus::Slip},
        Case{"hard_augmented_friction", Master::Quadratic, hard_with(Enforcement::Method::Augmented),
             Friction::Exact, 0, 0.5, 0.1, 0.05, ContactStatus::Slip},
        Case{"linear_law", Master::Linear, linear_law(), Friction::None, 0, 0, -0.03, 0.02, ContactStatus::Slip},
        Case{"exponential_law_quadratic", Master::Quadratic, exponential_law(), Friction::None, 0, 0, 0.12, 0.02,
             ContactStatus::Slip},
        Case{"exact_stick", Master::Linear, hard(), Friction::Exact, 0.8, 0.05, -0.04, 0.01, ContactStatus::Stick},
        Case{"exact_slip", Master::Linear, hard(), Friction::Exact, 0.8, 0.5, -0.04, 0.05, ContactStatus::Slip},
        Case{"exact_slip_negative", Master::Quadratic, hard(), Friction::Exact, 0.8, -0.5, 0.1, -0.05,
             ContactStatus::Slip},
        Case{"exact_open", Master::Linear, hard(), Friction::Exact, -0.3, 0.1, 0.06, 0.05, ContactStatus::Open},
        Case{"slope_stick", Master::Linear, hard(), Friction::Slope, 0.8, 0, -0.04, 0.01, ContactStatus::Stick},
        Case{"slope_slip", Master::Quadratic, hard(), Friction::Slope, 0.8, 0, 0.1, 0.3, ContactStatus::Slip},
        Case{"elastic_slip_stick", Master::Linear, hard(), Friction::ElasticSlip, 0.8, 0, -0.04, 0.01,
             ContactStatus::Stick},
        Case{"elastic_slip_slip", Master::Linear, hard(), Friction::ElasticSlip, 0.8, 0, -0.04, 0.2,
             ContactStatus::Slip},
        Case{"soft_law_friction_slip", Master::Linear, linear_law(), Friction::Slope, 0, 0, -0.03, 0.3,
             ContactStatus::Slip},
        Case{"soft_law_friction_stick", Master::Quadratic, exponential_law(), Friction::ElasticSlip, 0, 0, 0.12,
             0.001, ContactStatus::Stick}),
    [](const ::testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });

// The same branches on the smoothed surface (kink height 0.05: the slave at
// y = -0.04 penetrates by ~0.08, at 0.06 it is open), over the corner piece
// (x from 0.1) and over the shortened straight piece (x from 1.0).
std::vector<Case> smoothed_cases() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const char* where : {"corner", "straight"})
      for (const char* branch : {"hard_closed", "hard_open", "hard_penalty", "linear_law", "exact_stick", "exact_slip",
                                 "exact_slip_negative", "slope_slip", "elastic_slip_stick", "soft_law_friction_slip"})
        n.push_back(std::string(where) + "_" + branch);
    return n;
  }();
  std::vector<Case> cases;
  for (const Master m : {Master::SmoothCorner, Master::SmoothStraight}) {
    const auto name = [&] { return names[cases.size()].c_str(); };
    cases.push_back({name(), m, hard(), Friction::None, 0.8, 0, -0.04, 0.02, ContactStatus::Slip});
    cases.push_back({name(), m, hard(), Friction::None, -0.2, 0, 0.06, 0.02, ContactStatus::Open});
    cases.push_back({name(), m, hard_with(Enforcement::Method::Penalty), Friction::None, 0, 0, -0.03, 0.02,
                     ContactStatus::Slip});
    cases.push_back({name(), m, linear_law(), Friction::None, 0, 0, -0.03, 0.02, ContactStatus::Slip});
    cases.push_back({name(), m, hard(), Friction::Exact, 0.8, 0.05, -0.04, 0.01, ContactStatus::Stick});
    cases.push_back({name(), m, hard(), Friction::Exact, 0.8, 0.5, -0.04, 0.05, ContactStatus::Slip});
    cases.push_back({name(), m, hard(), Friction::Exact, 0.8, -0.5, -0.04, -0.05, ContactStatus::Slip});
    cases.push_back({name(), m, hard(), Friction::Slope, 0.8, 0, -0.04, 0.2, ContactStatus::Slip});
    cases.push_back({name(), m, hard(), Friction::ElasticSlip, 0.8, 0, -0.04, 0.01, ContactStatus::Stick});
    cases.push_back({name(), m, linear_law(), Friction::Slope, 0, 0, 0.01, -0.4, ContactStatus::Slip});
  }
  return cases;
}

INSTANTIATE_TEST_SUITE_P(Smoothed, ContactTangent, ::testing::ValuesIn(smoothed_cases()),
                         [](const ::testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });

/// A slave handed over from the segment it was on at the last converged
/// increment to another one: its slip is measured from a point of the old
/// segment, whose nodes are then among the element's dofs.
struct HandOverCase {
  const char* name;
  Master master;
  PressureOverclosure law;
  Friction friction;
  double lambda_t;  ///< exact-stick multiplier
  double x0, x;     ///< slave x at the start and the end of the increment (y = -0.04, λn = 0.8 for HARD)
  ContactStatus expected;
  int extra_nodes;  ///< nodes of the committed segment not on the current one
};

void PrintTo(const HandOverCase& c, std::ostream* os) { *os << c.name; }

class ContactHandOverTangent : public ::testing::TestWithParam<HandOverCase> {};

TEST_P(ContactHandOverTangent, MatchesFiniteDifferences) {
  const HandOverCase& c = GetParam();
  Fixture f(c.master, c.law, c.friction);
  const double y = -0.04;
  f.hand_over(c.x0, y, c.x, y);
  const ContactSlave& s = f.pair->slave(0);
  ASSERT_TRUE(s.pairing.found());
  ASSERT_NE(s.committed_segment, s.pairing.segment);
  ASSERT_TRUE(s.handed_over);
  const MasterSegments& segments = f.pair->segments();
  const int n_mult = ContactPair::multipliers_per_slave(f.pair->setup().law, f.pair->setup().friction);
  EXPECT_EQ(static_cast<int>(s.dofs.size()),
            2 * (1 + segments.segment(s.pairing.segment).n_nodes + c.extra_nodes) + n_mult);
  int k = f.n_disp;
  if (c.law.law == PressureOverclosure::Law::Hard) f.u[k++] = 0.8;
  if (c.friction == Friction::Exact) f.u[k++] = c.lambda_t;
  EXPECT_EQ(f.node().status(f.state()), c.expected);
  const double error = tangent_error(f.node(), f.state(), 1e-7);
  EXPECT_LT(error, 2e-6) << c.name;
  std::printf("[ hand-over ] %s: slip %.4f, tangent error %.2e (%zu dofs)\n", c.name, f.node().values(f.state()).slip,
              error, s.dofs.size());
}

// Linear: from x = 0.3 on face 1-2 to x = -0.3 on face 2-3 (slip ~0.6 along
// t = -x of the new face); the penalty-stick cases slip less (0.1, 0.04) to
// stay in the cone. QuadraticPair: the same over two curved faces.
// SmoothCorner fixture: from the straight piece (x = 0.6) onto the corner
// piece (x = 0.2: the same real nodes, other virtual ones) and from the
// corner piece (0.2, or -0.35 for stick) onto the far straight piece (-0.6,
// -0.45: node 1 extra).
INSTANTIATE_TEST_SUITE_P(
    HandOver, ContactHandOverTangent,
    ::testing::Values(
        HandOverCase{"linear_exact_stick", Master::Linear, hard(), Friction::Exact, -0.85, 0.3, -0.3,
                     ContactStatus::Stick, 1},
        HandOverCase{"linear_exact_slip", Master::Linear, hard(), Friction::Exact, 0.2, 0.3, -0.3,
                     ContactStatus::Slip, 1},
        HandOverCase{"linear_slope_stick", Master::Linear, hard(), Friction::Slope, 0, 0.05, -0.05,
                     ContactStatus::Stick, 1},
        HandOverCase{"linear_slope_slip", Master::Linear, hard(), Friction::Slope, 0, 0.3, -0.3, ContactStatus::Slip,
                     1},
        HandOverCase{"linear_elastic_slip_stick", Master::Linear, hard(), Friction::ElasticSlip, 0, 0.015, -0.015,
                     ContactStatus::Stick, 1},
        HandOverCase{"linear_soft_law_slip", Master::Linear, linear_law(), Friction::Slope, 0, 0.3, -0.3,
                     ContactStatus::Slip, 1},
        HandOverCase{"quadratic_exact_stick", Master::QuadraticPair, hard(), Friction::Exact, -0.85, 0.3, -0.3,
                     ContactStatus::Stick, 2},
        HandOverCase{"quadratic_exact_slip", Master::QuadraticPair, hard(), Friction::Exact, -0.2, -0.3, 0.3,
                     ContactStatus::Slip, 2},
        HandOverCase{"quadratic_slope_stick", Master::QuadraticPair, hard(), Friction::Slope, 0, 0.05, -0.05,
                     ContactStatus::Stick, 2},
        HandOverCase{"quadratic_elastic_slip_slip", Master::QuadraticPair, hard(), Friction::ElasticSlip, 0, 0.3,
                     -0.3, ContactStatus::Slip, 2},
        HandOverCase{"smooth_onto_corner_exact_stick", Master::SmoothCorner, hard(), Friction::Exact, -0.6, 0.6, 0.2,
                     ContactStatus::Stick, 0},
        HandOverCase{"smooth_onto_corner_exact_slip", Master::SmoothCorner, hard(), Friction::Exact, -0.2, 0.6, 0.2,
                     ContactStatus::Slip, 0},
        HandOverCase{"smooth_off_corner_exact_slip", Master::SmoothCorner, hard(), Friction::Exact, 0.2, 0.2, -0.6,
                     ContactStatus::Slip, 1},
        HandOverCase{"smooth_off_corner_slope_stick", Master::SmoothCorner, hard(), Friction::Slope, 0, -0.35, -0.45,
                     ContactStatus::Stick, 1},
        HandOverCase{"smooth_off_corner_elastic_slip_slip", Master::SmoothCorner, hard(), Friction::ElasticSlip, 0, 0.2,
                     -0.6, ContactStatus::Slip, 1}),
    [](const ::testing::TestParamInfo<HandOverCase>& info) { return std::string(info.param.name); });

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

TEST(PressureOverclosureLaw, ValuesAndSlopes) {
  const PressureOverclosure e = exponential_law();
  EXPECT_NEAR(contact_pressure(e, 0).p, 3.0, 1e-14);         // p0 at zero clearance
  EXPECT_EQ(contact_pressure(e, -0.2).p, 0.0);               // zero at clearance c0
  EXPECT_NEAR(contact_pressure(e, -0.2 + 1e-9).dp_dh, 0, 1e-6);  // C¹ there
  PressureOverclosure t;
  t.law = PressureOverclosure::Law::Tabular;
  t.table = {{0, 0}, {10, 0.1}, {50, 0.2}};
  EXPECT_EQ(contact_pressure(t, -1).p, 0.0);
  EXPECT_NEAR(contact_pressure(t, 0.05).p, 5, 1e-12);
  EXPECT_NEAR(contact_pressure(t, 0.15).p, 30, 1e-12);
  EXPECT_NEAR(contact_pressure(t, 0.3).p, 90, 1e-12);  // extended with the last slope
  for (const PressureOverclosure& law : {e, t, linear_law()})
    for (double h : {-0.15, -0.005, 0.03, 0.12, 0.25}) {
      const double d = 1e-7;
      const double fd = (contact_pressure(law, h + d).p - contact_pressure(law, h - d).p) / (2 * d);
      EXPECT_NEAR(contact_pressure(law, h).dp_dh, fd, 1e-5 * std::max(1.0, std::abs(fd))) << h;
    }
  EXPECT_THROW(contact_pressure(hard(), 0.1), std::invalid_argument);
}


// Re-pairing guard: over a concave kink (node 2 pulled down to y = -0.2, both
// faces sloping 0.1 towards it) a slave that goes A -> B -> A -> B within one
// Newton attempt (its second return to the segment it left one iteration
// before) is held on A, extended past its end, until convergence;
// on_converged keeps it there while |ξ| <= 1.5 and releases it beyond. Over
// a convex kink it is not held.
TEST(ContactPair, ReturnToTheSegmentLeftIsHeldUntilConvergence) {
  // Segment 0 is x in [0, 2] (ξ = -1 at node 1, x = 2, +1 at node 2), segment 1 is x in [-2, 0].
  struct Kink {
    Fixture f{Master::Linear, hard(), Friction::None};
    double node_y;
    const ContactSlave& at(double x, double y) {
      f.u.setZero();
      f.u[5] = node_y;  // node 2, y
      f.u[0] = x - f.reference[0].x(), f.u[1] = y - f.reference[0].y();
      f.u_start = f.u;
      f.pair->update_connectivity(f.state());
      return f.pair->slave(0);
    }
  };
  Kink k{.node_y = -0.2};
  EXPECT_EQ(k.at(0.05, -0.19).pairing.segment, 0);  // a new attempt: paired by the search
  EXPECT_EQ(k.at(-0.05, -0.19).pairing.segment, 1); // 0.05 in ξ past node 2: beyond kHandOverBand
  EXPECT_EQ(k.f.pair->statistics().repaired, 1);
  ContactSlave s = k.at(0.05, -0.19);  // first return: a Newton overshoot may do that once
  EXPECT_EQ(s.pairing.segment, 0);
  EXPECT_FALSE(s.held_segment);
  s = k.at(-0.05, -0.19);  // second return: held on 0
  EXPECT_EQ(s.pairing.segment, 0);
  EXPECT_TRUE(s.held_segment);
  EXPECT_FALSE(s.pairing.at_corner);
  // (y_s - y_1).(y_2 - y_1) / |y_2 - y_1|^2 = (4.1 + 0.038) / 4.04 -> ξ = 2 t - 1
  EXPECT_NEAR(s.pairing.xi, 2 * (4.1 + 0.038) / 4.04 - 1, 1e-12);
  EXPECT_EQ(k.f.pair->statistics().repaired, 0);
  EXPECT_EQ(k.f.pair->statistics().held_closed, 1);
  // Still held further on, where the search alone would not hesitate.
  s = k.at(-0.4, -0.16);
  EXPECT_EQ(s.pairing.segment, 0);
  EXPECT_TRUE(s.held_segment);
  EXPECT_NEAR(s.pairing.xi, 1.392, 1e-3);
  // Converged there: accepted, the guard is cleared.
  EXPECT_EQ(k.f.pair->on_converged(k.f.state()), Acceptance::Accept);
  EXPECT_FALSE(k.f.pair->slave(0).held_segment);

  // The same cycle, converged at ξ = 1.588: released, another Newton pass;
  // the next iteration pairs it by the search.
  Kink g{.node_y = -0.2};
  g.at(0.05, -0.19), g.at(-0.05, -0.19), g.at(0.05, -0.19), g.at(-0.05, -0.19);
  EXPECT_TRUE(g.at(-0.6, -0.14).held_segment);
  EXPECT_EQ(g.f.pair->on_converged(g.f.state()), Acceptance::Iterate);
  EXPECT_FALSE(g.f.pair->slave(0).held_segment);
  EXPECT_EQ(g.at(-0.6, -0.14).pairing.segment, 1);

  // Over a convex kink (node 2 pushed up to y = 0.2) the same cycle is not held.
  Kink h{.node_y = 0.2};
  h.at(0.3, 0.15), h.at(-0.3, 0.15), h.at(0.3, 0.15);
  s = h.at(-0.3, 0.15);
  EXPECT_EQ(s.pairing.segment, 1);
  EXPECT_FALSE(s.held_segment);
}

}  // namespace
}  // namespace tether
