// The node-to-segment contact element's tangent against finite differences
// in every branch: HARD closed/open, regularised, penalty, soft laws, friction
// stick/slip with exact and penalty stick, on linear, quadratic and smoothed
// (SMOOTH=0.2, corner and straight pieces) masters, and after a hand-over to
// another segment.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "contact_fixture.hpp"

namespace tether {
namespace {

using namespace contact_test;

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
  NodeArea area = NodeArea::Fixed;
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

class ContactTangent : public ::testing::TestWithParam<Case> {};

TEST_P(ContactTangent, MatchesFiniteDifferences) {
  const Case& c = GetParam();
  Fixture f(c.master, c.law, c.friction, 0.3, c.area);
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
        Case{"calculix_linear_closed", Master::Linear, calculix_linear_law(), Friction::None, 0, 0, -0.04, 0.02,
             ContactStatus::Slip},
        Case{"calculix_linear_tension", Master::Linear, calculix_linear_law(), Friction::None, 0, 0, 0.06, 0.02,
             ContactStatus::Open},
        Case{"calculix_linear_tension_friction", Master::Linear, calculix_linear_law(), Friction::Slope, 0, 0, 0.06,
             0.3, ContactStatus::Open},
        Case{"calculix_linear_friction_slip", Master::Linear, calculix_linear_law(), Friction::Slope, 0, 0, -0.04,
             0.3, ContactStatus::Slip},
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
             0.001, ContactStatus::Stick},
        // CalculiX's area of a node-based slave: the master face's on the current face.
        Case{"calculix_area_plane_linear", Master::Linear, calculix_linear_law(), Friction::None, 0, 0, -0.04, 0.02,
             ContactStatus::Slip, NodeArea::Plane},
        Case{"calculix_area_plane_quadratic", Master::Quadratic, calculix_linear_law(), Friction::None, 0, 0, 0.1,
             0.02, ContactStatus::Slip, NodeArea::Plane},
        Case{"calculix_area_axisymmetric_linear", Master::Linear, calculix_linear_law(), Friction::None, 0, 0, -0.04,
             0.02, ContactStatus::Slip, NodeArea::Axisymmetric},
        Case{"calculix_area_axisymmetric_quadratic", Master::Quadratic, calculix_linear_law(), Friction::None, 0, 0,
             0.1, 0.02, ContactStatus::Slip, NodeArea::Axisymmetric},
        Case{"calculix_area_axisymmetric_quadratic_pair", Master::QuadraticPair, calculix_linear_law(),
             Friction::None, 0, 0, -0.04, 0.02, ContactStatus::Slip, NodeArea::Axisymmetric},
        Case{"calculix_area_slope_stick", Master::Linear, calculix_linear_law(), Friction::Slope, 0, 0, -0.04, 0.001,
             ContactStatus::Stick, NodeArea::Axisymmetric},
        Case{"calculix_area_slope_slip", Master::Quadratic, calculix_linear_law(), Friction::Slope, 0, 0, 0.05, 0.3,
             ContactStatus::Slip, NodeArea::Plane},
        Case{"calculix_area_elastic_slip", Master::Quadratic, calculix_linear_law(), Friction::ElasticSlip, 0, 0, 0.05,
             0.3, ContactStatus::Slip, NodeArea::Axisymmetric},
        Case{"calculix_area_hard_slope_stick", Master::Linear, hard(), Friction::Slope, 0.8, 0, -0.04, 0.001,
             ContactStatus::Stick, NodeArea::Plane}),
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

}  // namespace
}  // namespace tether
