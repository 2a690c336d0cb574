#pragma once
/// \file Fixture of the contact element tests: one slave node over a small
/// master surface (two straight faces, a curved one, two curved ones, a
/// smoothed or an unsmoothed kink), the laws the tests use, and the finite
/// difference check of the element's tangent.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "support/tangent_check.hpp"
#include "tether/contact/contact_pair.hpp"
#include "tether/contact/pressure_overclosure.hpp"

namespace tether::contact_test {

using testing::tangent_error;

/// Linear: two straight faces; Quadratic: one curved 3-node face; SmoothCorner
/// / SmoothStraight: two faces with a kink at node 2 and SMOOTH=0.2, slave over
/// the rounded corner (3 real master nodes) or over a shortened straight piece.
/// QuadraticPair: two curved 3-node faces meeting at node 2 (x = 0).
/// Kink: the SmoothCorner geometry without SMOOTH (a convex kink at node 2).
enum class Master { Linear, Quadratic, QuadraticPair, SmoothCorner, SmoothStraight, Kink };
enum class Friction { None, Exact, Slope, ElasticSlip };
/// The slave node's area: fixed (0.7), or CalculiX's on the current master
/// face (dialect calculix, node-based slave): plane with thickness 0.8, or
/// axisymmetric (the whole fixture moved to x + 3, so r > 0).
enum class NodeArea { Fixed, Plane, Axisymmetric };

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

  Fixture(Master master, PressureOverclosure law, Friction friction, double mu = 0.3,
          NodeArea area = NodeArea::Fixed) {
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
    if (area != NodeArea::Fixed) {
      setup.node_based_slave = true;
      const bool axisymmetric = area == NodeArea::Axisymmetric;
      const MasterFaceArea rule{axisymmetric ? MasterFaceArea::Kind::axisymmetric : MasterFaceArea::Kind::plane, 0.8};
      setup.calculix_face_areas.assign(setup.master_faces.size(), rule);
      if (axisymmetric) {
        for (Eigen::Vector2d& x : reference) x.x() += 3;
        x0 += 3;
      }
    }
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

inline PressureOverclosure hard() { return {}; }
inline PressureOverclosure hard_with(Enforcement::Method method, double epsilon = 0) {
  PressureOverclosure p;
  p.enforcement.method = method;
  p.enforcement.epsilon = epsilon;
  p.enforcement.penalty = 25;
  return p;
}
inline PressureOverclosure linear_law() {
  PressureOverclosure p;
  p.law = PressureOverclosure::Law::Linear;
  p.stiffness = 40;
  p.c0 = 0.01;
  return p;
}
/// CalculiX's LINEAR law (dialect calculix): K = 40, sigma_inf = 0.5
/// (eps = 0.039), c0 = 0.2: with the fixture's area 0.7 the reach is
/// 0.2 sqrt(0.35) = 0.118.
inline PressureOverclosure calculix_linear_law() {
  PressureOverclosure p;
  p.law = PressureOverclosure::Law::Linear;
  p.meaning = Dialect::Calculix;
  p.stiffness = 40;
  p.sigma_inf = 0.5;
  p.reach_factor = 0.2;
  return p;
}
inline PressureOverclosure exponential_law() {
  PressureOverclosure p;
  p.law = PressureOverclosure::Law::Exponential;
  p.c0 = 0.2;
  p.p0 = 3;
  return p;
}

}  // namespace tether::contact_test
