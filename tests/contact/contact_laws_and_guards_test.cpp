// The pressure-overclosure laws (values and slopes) and the contact pair's
// re-pairing guard.
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

TEST(PressureOverclosureLaw, CalculixExponentialIsOnePercentOfP0AtTheClearanceC0) {
  PressureOverclosure e = exponential_law();  // c0 = 0.2, p0 = 3
  e.meaning = Dialect::Calculix;
  EXPECT_NEAR(contact_pressure(e, 0).p, 3.0, 1e-14);
  EXPECT_NEAR(contact_pressure(e, -0.2).p, 0.03, 1e-15);  // p0 exp(-ln 100)
  EXPECT_NEAR(contact_pressure(e, -0.4).p, 3e-4, 1e-16);  // never zero: no cut-off
  EXPECT_NEAR(contact_pressure(e, 0.2).p, 300, 1e-11);
  for (double h : {-0.5, -0.1, 0.0, 0.07}) {
    const double d = 1e-7;
    const double fd = (contact_pressure(e, h + d).p - contact_pressure(e, h - d).p) / (2 * d);
    EXPECT_NEAR(contact_pressure(e, h).dp_dh, fd, 1e-6 * std::max(1.0, std::abs(fd))) << h;
  }
}

TEST(PressureOverclosureLaw, CalculixLinearIsSmoothWithATensionUpToSigmaInfWithinTheReach) {
  const PressureOverclosure law = calculix_linear_law();  // K = 40, sigma_inf = 0.5, c0 = 0.2
  const double K = 40, eps = std::numbers::pi * 0.5 / K, reach = 0.2 * std::sqrt(0.7 / 2);
  EXPECT_DOUBLE_EQ(calculix_linear_reach(law, 0.7), reach);
  EXPECT_EQ(contact_pressure(law, 0, reach).p, 0.0);                        // p(0) = 0 ...
  EXPECT_NEAR(contact_pressure(law, 0, reach).dp_dh, K / 2, 1e-14);         // ... with half the slope
  EXPECT_NEAR(contact_pressure(law, eps, reach).p, K * eps * 0.75, 1e-14);  // atan(1) = pi/4
  EXPECT_NEAR(contact_pressure(law, 1e3 * eps, reach).p, K * 1e3 * eps, 0.51);  // -> K h (+ sigma_inf)
  EXPECT_LT(contact_pressure(law, -reach, reach).p, 0);                     // a tension within the reach ...
  EXPECT_GT(contact_pressure(law, -reach, reach).p, -0.5);                  // ... below sigma_inf
  EXPECT_NEAR(calculix_linear_pressure(K, 0.5, -1e4).p, -0.5, 1e-5);         // -> -sigma_inf far open
  EXPECT_EQ(contact_pressure(law, -reach - 1e-12, reach).p, 0.0);           // nothing beyond the reach
  EXPECT_EQ(contact_pressure(law, -reach - 1e-12, reach).dp_dh, 0.0);
  for (double h : {-0.1, -0.03, -0.001, 0.0, 0.002, 0.04, 0.5}) {
    const double d = 1e-7;
    const double fd = (contact_pressure(law, h + d, reach).p - contact_pressure(law, h - d, reach).p) / (2 * d);
    EXPECT_NEAR(contact_pressure(law, h, reach).dp_dh, fd, 1e-6 * std::max(1.0, std::abs(fd))) << h;
  }
  // Without a reach (the mortar path) CalculiX's law is not evaluated; other laws ignore the reach.
  EXPECT_THROW(contact_pressure(law, 0.01), std::invalid_argument);
  EXPECT_EQ(contact_pressure(linear_law(), 0.01, 1e-9).p, contact_pressure(linear_law(), 0.01).p);
  // c0 not given: CalculiX's 1e-3.
  PressureOverclosure plain = law;
  plain.reach_factor = 0;
  EXPECT_DOUBLE_EQ(calculix_linear_reach(plain, 2.0), 1e-3);
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
