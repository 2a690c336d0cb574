// The smoothed (C¹) master surface of SMOOTH=s: which corners are rounded,
// position and tangent continuity at every joint, the corner piece is the
// quadratic Bézier curve of its control points, the search's point view
// agrees with the segments' weights, and the search walks across the pieces.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tether/contact/master_segments.hpp"
#include "tether/fem/shape_functions.hpp"

namespace tether {
namespace {

using Eigen::Vector2d;

/// Point and unit tangent of segment k at ξ, from the search's point positions.
std::pair<Vector2d, Vector2d> point_and_tangent(const MasterSegments& m, const std::vector<Vector2d>& points, int k,
                                                double xi) {
  const auto nodes = m.surface().segment_nodes(k);
  Eigen::Vector3d N, dN;
  face_shape_functions(static_cast<int>(nodes.size()), xi, N, dN);
  Vector2d y(0, 0), a(0, 0);
  for (std::size_t p = 0; p < nodes.size(); ++p) {
    y += N[static_cast<Eigen::Index>(p)] * points[static_cast<std::size_t>(nodes[p])];
    a += dN[static_cast<Eigen::Index>(p)] * points[static_cast<std::size_t>(nodes[p])];
  }
  return {y, a.normalized()};
}

/// An open polyline of 4 faces with corners of different angles and face
/// lengths (counter-clockwise around a body below it), node k = index k.
struct Polyline {
  std::vector<Vector2d> nodes{{4.0, 0.3}, {2.5, 0.0}, {1.0, 0.4}, {0.0, -0.5}, {-2.0, -0.2}};
  std::vector<std::vector<int>> faces{{0, 1}, {1, 2}, {2, 3}, {3, 4}};
};

/// Largest jump of position and of unit tangent over all joints (segment ends
/// shared through the search topology).
std::pair<double, double> joint_jumps(const MasterSegments& m, const std::vector<Vector2d>& points) {
  double dy = 0, dt = 0;
  for (int k = 0; k < m.n_segments(); ++k)
    for (int q : m.surface().neighbours(k, 1)) {
      const auto [y0, t0] = point_and_tangent(m, points, k, 1.0);
      const auto [y1, t1] = point_and_tangent(m, points, q, -1.0);
      dy = std::max(dy, (y1 - y0).norm());
      dt = std::max(dt, (t1 - t0).norm());
    }
  return {dy, dt};
}

TEST(MasterSegments, WithoutSmoothingTheSegmentsAreTheFaces) {
  const Polyline p;
  const MasterSegments m(p.faces, 0.0);
  ASSERT_EQ(m.n_segments(), 4);
  EXPECT_FALSE(m.smoothed());
  for (int k = 0; k < 4; ++k) {
    EXPECT_TRUE(m.segment(k).identity);
    EXPECT_EQ(m.segment(k).nodes[0], p.faces[static_cast<std::size_t>(k)][0]);
    EXPECT_EQ(m.segment(k).face_at(-0.5), k);
    const auto nodes = m.surface().segment_nodes(k);
    EXPECT_EQ(std::vector<int>(nodes.begin(), nodes.end()), p.faces[static_cast<std::size_t>(k)]);
  }
  // A kinked unsmoothed surface: the tangent jumps at the interior nodes.
  std::vector<Vector2d> points;
  m.point_positions(p.nodes, points);
  EXPECT_GT(joint_jumps(m, points).second, 0.1);
}

TEST(MasterSegments, SmoothedSurfaceIsC1AtEveryJoint) {
  const Polyline p;
  for (double s : {0.05, 0.2, 0.5}) {
    const MasterSegments m(p.faces, s);
    EXPECT_EQ(m.n_rounded(), 3) << s;  // the 3 interior nodes; the open ends are not rounded
    // 4 straight pieces + 3 corners; with s = 0.5 the two middle faces keep no straight piece.
    EXPECT_EQ(m.n_segments(), s == 0.5 ? 5 : 7) << s;
    std::vector<Vector2d> points;
    m.point_positions(p.nodes, points);
    const auto [dy, dt] = joint_jumps(m, points);
    std::printf("[ smooth ] s = %.2f: largest jump at the joints |dy| = %.2e, |dt| = %.2e\n", s, dy, dt);
    EXPECT_LT(dy, 1e-12) << s;
    EXPECT_LT(dt, 1e-12) << s;
    // Every segment is joined to its neighbours: 6 (4) joints of a chain of 7 (5).
    int joints = 0;
    for (int k = 0; k < m.n_segments(); ++k) joints += static_cast<int>(m.surface().neighbours(k, 1).size());
    EXPECT_EQ(joints, m.n_segments() - 1) << s;
  }
}

TEST(MasterSegments, CornerPieceIsTheBezierCurveOfItsControlPoints) {
  const Polyline p;
  const double s = 0.3;
  const MasterSegments m(p.faces, s);
  std::vector<Vector2d> points;
  m.point_positions(p.nodes, points);
  int corners = 0;
  for (int k = 0; k < m.n_segments(); ++k) {
    const MasterSegment& g = m.segment(k);
    if (g.n_nodes != 3) continue;
    ++corners;
    const Vector2d A = p.nodes[static_cast<std::size_t>(g.nodes[0])], B = p.nodes[static_cast<std::size_t>(g.nodes[1])],
                   C = p.nodes[static_cast<std::size_t>(g.nodes[2])];
    const Vector2d P0 = B + s * (A - B), P2 = B + s * (C - B);
    EXPECT_EQ(g.face_at(-0.1) + 1, g.face_at(0.1));  // the faces before and after the corner
    for (double xi : {-1.0, -0.6, 0.0, 0.35, 1.0}) {
      const double t = (xi + 1) / 2;
      const Vector2d bezier = (1 - t) * (1 - t) * P0 + 2 * t * (1 - t) * B + t * t * P2;
      const Vector2d slope = ((1 - t) * (B - P0) + t * (P2 - B)).normalized();
      const auto [y, tangent] = point_and_tangent(m, points, k, xi);
      EXPECT_LT((y - bezier).norm(), 1e-14) << k << " " << xi;
      EXPECT_LT((tangent - slope).norm(), 1e-14) << k << " " << xi;
      // The weights give the same virtual nodes as the search's points.
      std::array<Vector2d, 3> real{A, B, C}, z;
      m.virtual_positions(k, real, z);
      const auto ids = m.surface().segment_nodes(k);
      for (int a = 0; a < 3; ++a) EXPECT_LT((z[static_cast<std::size_t>(a)] - points[static_cast<std::size_t>(ids[static_cast<std::size_t>(a)])]).norm(), 1e-15);
    }
  }
  EXPECT_EQ(corners, 3);
}

TEST(MasterSegments, ClosedRingIsRoundedEverywhere) {
  // A square, counter-clockwise: 4 corners, 4 straight pieces, all C¹.
  const std::vector<Vector2d> nodes{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<std::vector<int>> faces{{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  const MasterSegments m(faces, 0.2);
  EXPECT_EQ(m.n_rounded(), 4);
  EXPECT_EQ(m.n_segments(), 8);
  std::vector<Vector2d> points;
  m.point_positions(nodes, points);
  const auto [dy, dt] = joint_jumps(m, points);
  EXPECT_LT(dy, 1e-12);
  EXPECT_LT(dt, 1e-12);
  for (int k = 0; k < m.n_segments(); ++k) {
    EXPECT_EQ(m.surface().neighbours(k, 0).size(), 1u);
    EXPECT_EQ(m.surface().neighbours(k, 1).size(), 1u);
  }
}

TEST(MasterSegments, NonManifoldAndReversedNodesAreNotRounded) {
  // Node 1 is shared by three faces; node 3 is where two faces both start.
  const std::vector<std::vector<int>> faces{{0, 1}, {1, 2}, {5, 1}, {3, 4}, {3, 6}};
  const MasterSegments m(faces, 0.2);
  EXPECT_EQ(m.n_rounded(), 0);
  EXPECT_EQ(m.n_segments(), 5);
  for (int k = 0; k < 5; ++k) EXPECT_TRUE(m.segment(k).identity);
}

TEST(MasterSegments, RefusesQuadraticFacesAndFractionsOutOfRange) {
  const std::vector<std::vector<int>> quadratic{{0, 1, 2}};
  EXPECT_NO_THROW(MasterSegments(quadratic, 0.0));
  EXPECT_THROW(MasterSegments(quadratic, 0.2), std::invalid_argument);
  const Polyline p;
  EXPECT_THROW(MasterSegments(p.faces, 0.7), std::invalid_argument);
  EXPECT_THROW(MasterSegments(p.faces, -0.1), std::invalid_argument);
  EXPECT_THROW(MasterSegments(p.faces, std::nan("")), std::invalid_argument);
}

TEST(MasterSegments, MapToRealNodesIsTheTransposeOfTheWeights) {
  // v_real = Tᵀ v_virtual, T = I₂ ⊕ (W⊗I₂) ⊕ I: check against the explicit matrix.
  const Polyline p;
  const MasterSegments m(p.faces, 0.25);
  for (int k = 0; k < m.n_segments(); ++k) {
    const MasterSegment& g = m.segment(k);
    const int n = 2 + 2 * g.n_nodes + 1;  // slave, nodes, one multiplier
    Eigen::MatrixXd T = Eigen::MatrixXd::Identity(n, n);
    for (int a = 0; a < g.n_nodes; ++a)
      for (int b = 0; b < g.n_nodes; ++b)
        T.block<2, 2>(2 + 2 * a, 2 + 2 * b) = g.weights(a, b) * Eigen::Matrix2d::Identity();
    const Eigen::VectorXd v = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
    Eigen::MatrixXd K = Eigen::MatrixXd::Random(n, n);
    Eigen::VectorXd v_real = v;
    Eigen::MatrixXd K_real = K;
    map_to_real_nodes(g, v_real);
    map_to_real_nodes(g, K_real);
    EXPECT_LT((v_real - T.transpose() * v).norm(), 1e-14);
    EXPECT_LT((K_real - T.transpose() * K * T).norm(), 1e-13);
  }
}

TEST(MasterSegments, SearchWalksAcrossTheCornerPieces) {
  // A slave point slides at constant height over the smoothed polyline; the
  // incremental search (previous pairing) visits straight - corner - straight
  // ... in order, without the broad phase, and agrees with the full search.
  const Polyline p;
  const MasterSegments m(p.faces, 0.2);
  std::vector<Vector2d> points;
  m.point_positions(p.nodes, points);
  SearchOptions options;
  options.search_radius = 1.0;
  std::vector<ContactPairing> previous;
  std::vector<int> visited;
  SearchStatistics walk;
  for (int k = 0; k < m.n_segments(); ++k)
    for (int i = k == 0 ? 0 : 1; i <= 40; ++i) {
      const double xi = -1 + i / 20.0;
      const auto [y, t] = point_and_tangent(m, points, k, xi);
      const std::vector<Vector2d> slave{y + 0.01 * Vector2d(t.y(), -t.x())};  // 0.01 outside
      const auto full = find_closest(m.surface(), points, slave, options);
      const auto local = find_closest(m.surface(), points, slave, options, previous, &walk);
      ASSERT_TRUE(local.front().found());
      EXPECT_EQ(local.front().segment, full.front().segment) << k << " " << xi;
      EXPECT_EQ(local.front().segment, k) << xi;  // at a joint (ξ = 1) the lower index wins the tie
      EXPECT_NEAR(local.front().gap, 0.01, 1e-12) << k << " " << xi;
      EXPECT_FALSE(local.front().at_corner) << k << " " << xi;  // no corner pairings on a C¹ surface
      if (visited.empty() || visited.back() != local.front().segment) visited.push_back(local.front().segment);
      previous = local;
    }
  // Segments in surface order: 0 straight, 1 corner, 2 straight, ... 6 straight.
  EXPECT_EQ(visited, (std::vector<int>{0, 1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(walk.n_broad_phase, 1);  // the first search only
}

}  // namespace
}  // namespace tether
