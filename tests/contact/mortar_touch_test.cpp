// The mortar active set at a point contact: a cylinder of quadratic faces
// touching a flat at one slave node (the Hertz half model's first
// configuration). The node's weighted gap is not zero there but a small
// positive discretisation quantity (the dual-weighted gap of the faces
// around the point, well above round-off on coarse faces); the node must
// still count as closed, as node-to-segment closes it, or a body held by
// contact alone has no closed node at the first iteration.

#include <gtest/gtest.h>

#include <cmath>

#include "tether/contact/mortar_node.hpp"
#include "tether/contact/mortar_pair.hpp"

using namespace tether;

namespace {

constexpr double kR = 10;

/// Slave: quadratic faces on the arc x = R sin θ, y = R (1 - cos θ) from the
/// contact point (0, 0), each `length` long (faces run left to right, outward
/// normal down); master: the flat y = 0 from x = 0 to 1 in 4 linear faces
/// (running right to left, outward normal up). `lift` moves the slave up.
struct PointContact {
  std::vector<Eigen::Vector2d> reference;
  std::unique_ptr<MortarPair> pair;
  int n_disp = 0;
  int n_slave_nodes = 0;  ///< nodes 0 .. n_slave_nodes - 1 are the slave's

  PointContact(double length, int n_faces, PressureOverclosure law = {}) {
    MortarPairSetup setup;
    setup.name = "POINT";
    for (int i = 0; i <= 2 * n_faces; ++i) {
      const double theta = 0.5 * length * i / kR;
      reference.emplace_back(kR * std::sin(theta), kR * (1 - std::cos(theta)));
    }
    n_slave_nodes = static_cast<int>(reference.size());
    for (int k = 0; k < n_faces; ++k) setup.slave_faces.push_back({2 * k, 2 * k + 2, 2 * k + 1});
    const int first = static_cast<int>(reference.size());
    for (int i = 0; i <= 4; ++i) reference.emplace_back(0.25 * i, 0.0);
    for (int k = 0; k < 4; ++k) {
      setup.master_faces.push_back({first + k + 1, first + k});
      setup.master_face_labels.emplace_back(k + 1, 3);
    }
    setup.slave_thickness.assign(setup.slave_faces.size(), 1.0);
    setup.search_radius = 1.0;
    setup.complementarity_stiffness = 2e5;
    setup.law = law;
    n_disp = 2 * static_cast<int>(reference.size());
    pair = std::make_unique<MortarPair>(setup, reference, n_disp);
  }

  [[nodiscard]] const MortarNode& node(int i) const { return dynamic_cast<const MortarNode&>(*pair->nodes()[static_cast<std::size_t>(i)]); }
  /// The slave node at the contact point (node index 0).
  [[nodiscard]] int contact_slave() const {
    for (int i = 0; i < pair->n_slaves(); ++i)
      if (pair->slave(i).node == 0) return i;
    return -1;
  }
};

/// The state with the slave body moved up by `lift` and no pressure.
Eigen::VectorXd lifted(const PointContact& pc, double lift) {
  Eigen::VectorXd u = Eigen::VectorXd::Zero(pc.n_disp + pc.pair->n_slaves());
  for (int a = 0; a < pc.n_slave_nodes; ++a) u[2 * a + 1] = lift;
  return u;
}

TEST(MortarTouch, NodeAtAPointContactIsClosed) {
  // Faces 0.38 long (the 2k Hertz deck's CPE8 arc), as coarse as 0.1.
  for (const double length : {0.38, 0.2, 0.1}) {
    PointContact pc(length, 3);
    const Eigen::VectorXd u = lifted(pc, 0.0);
    const EvaluationState state{u, u, 0, 0, 1, false};
    pc.pair->update_connectivity(state);
    const int j = pc.contact_slave();
    ASSERT_GE(j, 0);
    const MortarNode::Gap g = pc.node(j).gap(u, false);
    ASSERT_TRUE(g.covered);
    std::printf("[ touch ] faces %.2f: weighted gap %.3e, D %.3e, mean gap %.3e\n", length, g.gap, g.D, g.gap / g.D);
    // At 0.38 the weighted gap is positive and far above round-off (1e-12 of
    // the coordinates times D): the point contact, not round-off, is what
    // closes the node.
    if (length == 0.38) EXPECT_GT(g.gap / g.D, 1e-11);
    EXPECT_TRUE(pc.node(j).closed(state)) << "faces " << length;
    for (int i = 0; i < pc.pair->n_slaves(); ++i)
      if (i != j) EXPECT_FALSE(pc.node(i).closed(state)) << "slave " << i << ", faces " << length;
  }
}

TEST(MortarTouch, LiftedByMoreThanRoundOffIsOpen) {
  PointContact pc(0.38, 3);
  for (const double lift : {1e-9, 1e-6}) {
    const Eigen::VectorXd u = lifted(pc, lift);
    const EvaluationState state{u, u, 0, 0, 1, false};
    pc.pair->update_connectivity(state);
    for (int i = 0; i < pc.pair->n_slaves(); ++i) EXPECT_FALSE(pc.node(i).closed(state)) << "lift " << lift;
  }
}

TEST(MortarTouch, ClosedTouchOpensUnderTension) {
  // The touch only decides the active set as a zero gap would: with λ_j < 0
  // the node opens (min(λ, c g̃) = 0 with g̃ taken as 0).
  PointContact pc(0.38, 3);
  Eigen::VectorXd u = lifted(pc, 0.0);
  const int j = pc.contact_slave();
  u[pc.pair->slave(j).multiplier] = -1.0;
  const EvaluationState state{u, u, 0, 0, 1, false};
  pc.pair->update_connectivity(state);
  EXPECT_FALSE(pc.node(j).closed(state));
}

TEST(MortarTouch, SoftLawActsAtAPointContact) {
  // LINEAR law from zero clearance: p = K h for h > 0, with slope K at the
  // touch; the touching node takes the law's row (not the open one).
  PressureOverclosure law;
  law.law = PressureOverclosure::Law::Linear;
  law.stiffness = 1e6;
  PointContact pc(0.38, 3, law);
  const Eigen::VectorXd u = lifted(pc, 0.0);
  const EvaluationState state{u, u, 0, 0, 1, false};
  pc.pair->update_connectivity(state);
  EXPECT_TRUE(pc.node(pc.contact_slave()).closed(state));
}

}  // namespace
