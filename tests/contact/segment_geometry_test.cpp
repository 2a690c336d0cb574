// Contact geometry kernels: projection exactness, flags, gap sign, exact
// derivatives against central finite differences, rigid-motion invariance.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <ctime>
#include <iostream>
#include <numbers>
#include <random>
#include <vector>

#include "tether/contact/segment_geometry.hpp"

using namespace tether;
using Eigen::Vector2d;

namespace {

using Points = std::vector<Vector2d>;  // slave first, then the segment nodes

std::span<const Vector2d> segment_of(const Points& p) { return {p.data() + 1, p.size() - 1}; }

SegmentGeometry geometry_of(const Points& p, ContactDerivatives d = ContactDerivatives::hessian) {
  return segment_geometry(p[0], segment_of(p), d);
}

Points perturbed(const Points& p, int dof, double h) {
  Points q = p;
  q[dof / 2][dof % 2] += h;
  return q;
}

/// Max relative error of the gap/ξ gradients and Hessians against central
/// finite differences (step h): |analytic - FD|∞ / max(1, |analytic|∞).
struct DerivativeErrors {
  double gap_gradient = 0, xi_gradient = 0, gap_hessian = 0, xi_hessian = 0, metric_gradient = 0;
};

double relative(const Eigen::MatrixXd& exact, const Eigen::MatrixXd& fd) {
  return (exact - fd).cwiseAbs().maxCoeff() / std::max(1.0, exact.cwiseAbs().maxCoeff());
}

DerivativeErrors derivative_errors(const Points& p, double h) {
  const SegmentGeometry g = geometry_of(p);
  const int n = g.n_dofs;
  Eigen::VectorXd fd_gap(n), fd_xi(n), fd_metric(n);
  Eigen::MatrixXd fd_gap_h(n, n), fd_xi_h(n, n);
  for (int j = 0; j < n; ++j) {
    const SegmentGeometry gp = geometry_of(perturbed(p, j, h), ContactDerivatives::gradient);
    const SegmentGeometry gm = geometry_of(perturbed(p, j, -h), ContactDerivatives::gradient);
    fd_gap[j] = (gp.gap - gm.gap) / (2 * h);
    fd_xi[j] = (gp.projection.xi - gm.projection.xi) / (2 * h);
    fd_metric[j] = (gp.metric - gm.metric) / (2 * h);
    fd_gap_h.col(j) = (gp.gap_gradient - gm.gap_gradient) / (2 * h);
    fd_xi_h.col(j) = (gp.xi_gradient - gm.xi_gradient) / (2 * h);
  }
  return {relative(g.gap_gradient, fd_gap), relative(g.xi_gradient, fd_xi), relative(g.gap_hessian, fd_gap_h),
          relative(g.xi_hessian, fd_xi_h), relative(g.metric_gradient, fd_metric)};
}

Eigen::Matrix2d rotation(double angle) {
  Eigen::Matrix2d R;
  R << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  return R;
}

/// A random segment (2 or 3 nodes) of length ~1 at a random rotation and
/// position, with a slave point at y(ξ0) + d n(ξ0), ξ0 ∈ [-1.4, 1.4].
Points random_configuration(std::mt19937& rng, int n_nodes) {
  std::uniform_real_distribution<double> u(-1, 1);
  const Eigen::Matrix2d R = rotation(std::numbers::pi * 4 * u(rng));  // large rotations, any quadrant
  const Vector2d shift(10 * u(rng), 10 * u(rng));
  Points seg = {Vector2d(-0.5, 0.1 * u(rng)), Vector2d(0.5 + 0.2 * u(rng), 0.1 * u(rng))};
  if (n_nodes == 3) seg.push_back(0.5 * (seg[0] + seg[1]) + Vector2d(0.1 * u(rng), 0.15 * u(rng)));
  for (auto& x : seg) x = R * x + shift;
  // slave near the segment: start from a point on it and move along its normal
  const double xi0 = 1.4 * u(rng);
  Eigen::Vector3d N, dN;
  Vector2d y = Vector2d::Zero(), a = Vector2d::Zero();
  // evaluate y(ξ0), y'(ξ0) by hand (the same face shape functions)
  if (n_nodes == 2) {
    N << 0.5 * (1 - xi0), 0.5 * (1 + xi0), 0;
    dN << -0.5, 0.5, 0;
  } else {
    N << 0.5 * xi0 * (xi0 - 1), 0.5 * xi0 * (xi0 + 1), 1 - xi0 * xi0;
    dN << xi0 - 0.5, xi0 + 0.5, -2 * xi0;
  }
  for (int k = 0; k < n_nodes; ++k) {
    y += N[k] * seg[k];
    a += dN[k] * seg[k];
  }
  const Vector2d n = Vector2d(a.y(), -a.x()).normalized();
  Points p = {y + 0.3 * u(rng) * n};
  p.insert(p.end(), seg.begin(), seg.end());
  return p;
}

// --- projection exactness and flags -------------------------------------

TEST(SegmentGeometry, StraightSegmentClosedForm) {
  // Bottom face of a body above y = 0, run counter-clockwise from (0,0) to (2,0).
  const Points seg = {Vector2d(0, 0), Vector2d(2, 0)};
  const SegmentGeometry out = segment_geometry(Vector2d(0.5, -0.3), seg);
  EXPECT_EQ(out.projection.status, ProjectionStatus::converged);
  EXPECT_EQ(out.projection.iterations, 0);
  EXPECT_NEAR(out.projection.xi, -0.5, 1e-15);
  EXPECT_TRUE(out.projection.inside);
  EXPECT_TRUE(out.point.isApprox(Vector2d(0.5, 0)));
  EXPECT_TRUE(out.tangent.isApprox(Vector2d(1, 0)));
  EXPECT_TRUE(out.normal.isApprox(Vector2d(0, -1)));  // outward: away from the body above
  EXPECT_NEAR(out.metric, 1, 1e-15);
  EXPECT_NEAR(out.gap, 0.3, 1e-15);  // below the body: open
  EXPECT_EQ(out.curvature, 0);
  // the linear-segment closed form g = ((y_s - y1) × (y2 - y1)) / |y2 - y1|
  const Vector2d ys(1.7, 0.4), c = seg[1] - seg[0], r = ys - seg[0];
  EXPECT_NEAR(segment_geometry(ys, seg).gap, (r.x() * c.y() - r.y() * c.x()) / c.norm(), 1e-15);
}

TEST(SegmentGeometry, GapSignOutsideAndInside) {
  // Unit square body, counter-clockwise faces; points just outside each face are open, inside penetrate.
  const Points square = {Vector2d(0, 0), Vector2d(1, 0), Vector2d(1, 1), Vector2d(0, 1)};
  const Vector2d centre(0.5, 0.5);
  for (int face = 0; face < 4; ++face) {
    const Vector2d y1 = square[face], y2 = square[(face + 1) % 4];
    const Vector2d mid = 0.5 * (y1 + y2), out_dir = (mid - centre).normalized();
    const Points lin = {y1, y2}, quad = {y1, y2, mid};
    for (const Points* seg : {&lin, &quad}) {
      EXPECT_NEAR(segment_geometry(mid + 0.1 * out_dir, *seg).gap, 0.1, 1e-14) << face;
      EXPECT_NEAR(segment_geometry(mid - 0.2 * out_dir, *seg).gap, -0.2, 1e-14) << face;
      EXPECT_TRUE(segment_geometry(mid, *seg).normal.isApprox(out_dir)) << face;
    }
  }
}

TEST(SegmentGeometry, StraightQuadraticEqualsLinear) {
  const Points lin = {Vector2d(0.2, -0.1), Vector2d(1.3, 0.6)};
  const Points quad = {lin[0], lin[1], 0.5 * (lin[0] + lin[1])};
  for (const Vector2d ys : {Vector2d(0.7, 0.9), Vector2d(-0.4, 0.3), Vector2d(1.0, -0.5)}) {
    const SegmentGeometry a = segment_geometry(ys, lin), b = segment_geometry(ys, quad);
    EXPECT_NEAR(a.projection.xi, b.projection.xi, 1e-13);
    EXPECT_NEAR(a.gap, b.gap, 1e-13);
    EXPECT_NEAR(b.curvature, 0, 1e-13);
    EXPECT_LE(b.projection.iterations, 3);
  }
}

TEST(SegmentGeometry, ParabolaProjectionIsExact) {
  // y(ξ) = (ξ, ξ²) exactly: corners (-1,1), (1,1), mid-side node (0,0). The body
  // lies left of the direction of travel, inside the parabola (convex, κ(0) = 2).
  const Points seg = {Vector2d(-1, 1), Vector2d(1, 1), Vector2d(0, 0)};
  for (double xi0 : {-1.2, -0.9, -0.3, 0.0, 0.4, 0.8, 1.0, 1.3}) {
    const Vector2d y(xi0, xi0 * xi0), n = Vector2d(2 * xi0, -1).normalized();
    const double kappa = 2 / std::pow(1 + 4 * xi0 * xi0, 1.5);
    for (double d : {-0.3, -0.05, 0.0, 0.1, 0.7}) {
      const SegmentGeometry out = segment_geometry(y + d * n, seg);
      ASSERT_EQ(out.projection.status, ProjectionStatus::converged) << xi0 << " " << d;
      EXPECT_NEAR(out.projection.xi, xi0, 1e-13) << xi0 << " " << d;
      EXPECT_NEAR(out.gap, d, 1e-13) << xi0 << " " << d;
      EXPECT_TRUE(out.normal.isApprox(n, 1e-13));
      EXPECT_NEAR(out.curvature, kappa, 1e-12);
      EXPECT_NEAR(out.projection_stiffness, 1 + d * kappa, 1e-12);
      EXPECT_EQ(out.projection.inside, std::abs(xi0) <= 1);
      EXPECT_LE(out.projection.iterations, 12);
    }
  }
}

TEST(SegmentGeometry, CircleArcByThreeNodes) {
  // Arc of a disc of radius R (the master body, convex), nodes at angles
  // θc - α, θc + α (corners, counter-clockwise) and θc (mid). A slave point at
  // radius ρ on the mid-angle projects exactly to ξ* = 0 with gap ρ - R; elsewhere
  // the gap converges to the circle's ρ - R as α^4 (interpolation error).
  const double R = 2.0, theta_c = 0.7;
  auto arc = [&](double alpha) {
    auto at = [&](double th) { return Vector2d(R * std::cos(th), R * std::sin(th)); };
    return Points{at(theta_c - alpha), at(theta_c + alpha), at(theta_c)};
  };
  auto max_gap_error = [&](double alpha) {
    const Points seg = arc(alpha);
    double err = 0;
    for (double frac : {-0.9, -0.5, -0.2, 0.3, 0.8}) {
      for (double rho : {0.8 * R, R, 1.3 * R}) {
        const double th = theta_c + frac * alpha;
        const SegmentGeometry out = segment_geometry(Vector2d(rho * std::cos(th), rho * std::sin(th)), seg);
        EXPECT_TRUE(out.projection.inside);
        err = std::max(err, std::abs(out.gap - (rho - R)));
        EXPECT_LT((out.normal - Vector2d(std::cos(th), std::sin(th))).norm(), 4 * alpha * alpha);
      }
    }
    return err;
  };
  for (double rho : {0.5 * R, R, 1.5 * R}) {
    const SegmentGeometry out =
        segment_geometry(Vector2d(rho * std::cos(theta_c), rho * std::sin(theta_c)), arc(0.4));
    EXPECT_NEAR(out.projection.xi, 0, 1e-14);
    EXPECT_NEAR(out.gap, rho - R, 1e-14);
    EXPECT_NEAR(out.curvature * R, 1, 0.05);  // parabola through the arc: κ ≈ 1/R
  }
  const double e1 = max_gap_error(0.4), e2 = max_gap_error(0.2);
  EXPECT_LT(e1, 2e-3 * R);
  EXPECT_GT(e1 / e2, 10.0);  // ~16 for fourth-order convergence
  std::cout << "circle arc gap error: alpha 0.4 -> " << e1 << ", alpha 0.2 -> " << e2 << "\n";
}

TEST(SegmentGeometry, ProjectionBeyondTheEndsIsFlagged) {
  const Points lin = {Vector2d(0, 0), Vector2d(2, 0)};
  const SegmentGeometry out = segment_geometry(Vector2d(2.5, -0.3), lin);
  EXPECT_NEAR(out.projection.xi, 1.5, 1e-15);
  EXPECT_FALSE(out.projection.inside);
  EXPECT_EQ(out.projection.clamped_xi, 1);
  EXPECT_NEAR(out.projection.clamped_distance, std::hypot(0.5, 0.3), 1e-15);
  EXPECT_NEAR(out.gap, 0.3, 1e-15);  // gap to the extended line
  const SegmentGeometry before = segment_geometry(Vector2d(-1, 0.2), lin);
  EXPECT_NEAR(before.projection.xi, -2, 1e-15);
  EXPECT_FALSE(before.projection.inside);
  EXPECT_EQ(before.projection.clamped_xi, -1);
  EXPECT_NEAR(before.projection.clamped_distance, std::hypot(1, 0.2), 1e-15);

  const Points quad = {Vector2d(-1, 1), Vector2d(1, 1), Vector2d(0, 0)};  // y = (ξ, ξ²)
  const SegmentGeometry q = segment_geometry(Vector2d(1.2, 1.44) + 0.1 * Vector2d(2.4, -1).normalized(), quad);
  EXPECT_NEAR(q.projection.xi, 1.2, 1e-13);
  EXPECT_FALSE(q.projection.inside);
  EXPECT_EQ(q.projection.clamped_xi, 1);
}

TEST(SegmentGeometry, SlaveOnSharedNodeIsInsideBothNeighbours) {
  const Points left = {Vector2d(0, 0), Vector2d(1, 0.3)}, right = {Vector2d(1, 0.3), Vector2d(2.1, 0.1)};
  const SegmentGeometry a = segment_geometry(left[1], left), b = segment_geometry(left[1], right);
  EXPECT_NEAR(a.projection.xi, 1, 1e-15);
  EXPECT_NEAR(b.projection.xi, -1, 1e-15);
  EXPECT_TRUE(a.projection.inside);
  EXPECT_TRUE(b.projection.inside);
  EXPECT_NEAR(a.gap, 0, 1e-15);
  EXPECT_NEAR(b.gap, 0, 1e-15);
  EXPECT_NEAR(a.projection.clamped_distance, 0, 1e-15);
}

TEST(SegmentGeometry, DegenerateAndInvalidSegments) {
  const Points collapsed = {Vector2d(1, 1), Vector2d(1, 1)};
  EXPECT_EQ(segment_geometry(Vector2d(0, 0), collapsed).projection.status, ProjectionStatus::degenerate);
  const Points collapsed3 = {Vector2d(1, 1), Vector2d(1, 1), Vector2d(1, 1)};
  EXPECT_EQ(segment_geometry(Vector2d(0, 0), collapsed3).projection.status, ProjectionStatus::degenerate);
  const Points one = {Vector2d(0, 0)};
  EXPECT_THROW(segment_geometry(Vector2d(0, 0), one), std::invalid_argument);
}

TEST(SegmentGeometry, CentreOfCurvatureIsReportedSingular) {
  // y = (ξ, ξ²): radius of curvature 1/2 at ξ = 0; the point (0, 0.5) is the centre.
  const Points quad = {Vector2d(-1, 1), Vector2d(1, 1), Vector2d(0, 0)};
  EXPECT_NEAR(segment_geometry(Vector2d(0, 0.5), quad).projection_stiffness, 0, 1e-14);
  EXPECT_GT(segment_geometry(Vector2d(0, 0.3), quad).projection_stiffness, 0);
}

// --- derivatives --------------------------------------------------------

void check_random_derivatives(int n_nodes, unsigned seed) {
  std::mt19937 rng(seed);
  constexpr double kTol = 1e-6;  // relative, see relative()
  int checked = 0, max_iterations = 0;
  DerivativeErrors worst;
  for (int trial = 0; trial < 300; ++trial) {
    const Points p = random_configuration(rng, n_nodes);
    const SegmentGeometry g = geometry_of(p);
    ASSERT_EQ(g.projection.status, ProjectionStatus::converged);
    max_iterations = std::max(max_iterations, g.projection.iterations);
    if (g.projection_stiffness < 0.2) continue;  // too close to the centre of curvature for FD
    const DerivativeErrors e = derivative_errors(p, 1e-6);
    EXPECT_LT(e.gap_gradient, kTol) << trial;
    EXPECT_LT(e.xi_gradient, kTol) << trial;
    EXPECT_LT(e.metric_gradient, kTol) << trial;
    EXPECT_LT(e.gap_hessian, kTol) << trial;
    EXPECT_LT(e.xi_hessian, kTol) << trial;
    worst.gap_gradient = std::max(worst.gap_gradient, e.gap_gradient);
    worst.gap_hessian = std::max(worst.gap_hessian, e.gap_hessian);
    worst.xi_hessian = std::max(worst.xi_hessian, e.xi_hessian);
    EXPECT_LT((g.gap_hessian - g.gap_hessian.transpose()).norm(), 1e-12);
    ++checked;
  }
  EXPECT_GT(checked, 250);
  std::cout << n_nodes << "-node segments: " << checked << " configurations, worst relative error gap gradient "
            << worst.gap_gradient << ", gap Hessian " << worst.gap_hessian << ", xi Hessian " << worst.xi_hessian
            << ", most projection iterations " << max_iterations << "\n";
}

TEST(SegmentGeometry, LinearDerivativesMatchFiniteDifferences) { check_random_derivatives(2, 11); }
TEST(SegmentGeometry, QuadraticDerivativesMatchFiniteDifferences) { check_random_derivatives(3, 12); }

TEST(SegmentGeometry, GapGradientIsNormalTimesShapeFunctions) {
  // ∂g/∂ξ = 0 at ξ* on any segment (y_s - y = g n, n unit), so
  // ∂g/∂y_s = n and ∂g/∂y^a = -N_a(ξ*) n.
  const Points lin = {Vector2d(0.4, 0.9), Vector2d(-0.3, 0.1), Vector2d(1.2, 0.5)};
  const Points quad = {Vector2d(0.4, 0.9), Vector2d(-0.3, 0.1), Vector2d(1.2, 0.5), Vector2d(0.5, 0.6)};
  for (const Points* p : {&lin, &quad}) {
    const SegmentGeometry g = geometry_of(*p);
    const int m = static_cast<int>(p->size()) - 1;
    const double xi = g.projection.xi;
    const Eigen::Vector3d N = m == 2 ? Eigen::Vector3d(0.5 * (1 - xi), 0.5 * (1 + xi), 0)
                                     : Eigen::Vector3d(0.5 * xi * (xi - 1), 0.5 * xi * (xi + 1), 1 - xi * xi);
    Eigen::VectorXd expected(g.n_dofs);
    expected.head<2>() = g.normal;
    for (int k = 0; k < m; ++k) expected.segment<2>(2 + 2 * k) = -N[k] * g.normal;
    EXPECT_LT((g.gap_gradient - expected).norm(), 1e-14) << m;
  }
}

TEST(SegmentGeometry, LinearHessianClassicClosedForm) {
  // Straight segment, l = |y^2 - y^1|: with T = [t; -N1 t; -N2 t] and C = [0; -n; n]
  // (C·δx = n·δ(y^2 - y^1)): ∂ξ*/∂x = (2/l) T + (2 g/l²) C and
  // ∂²g/∂x² = -(C Tᵀ + T Cᵀ)/l - (g/l²) C Cᵀ.
  std::mt19937 rng(21);
  for (int trial = 0; trial < 20; ++trial) {
    const Points p = random_configuration(rng, 2);
    const SegmentGeometry g = geometry_of(p);
    const double l = (p[2] - p[1]).norm(), xi = g.projection.xi;
    Eigen::Matrix<double, 6, 1> T, C;
    T << g.tangent, -0.5 * (1 - xi) * g.tangent, -0.5 * (1 + xi) * g.tangent;
    C << 0, 0, -g.normal, g.normal;
    const Eigen::Matrix<double, 6, 6> H = -(C * T.transpose() + T * C.transpose()) / l - (g.gap / (l * l)) * C * C.transpose();
    EXPECT_LT((g.gap_hessian - H).norm(), 1e-12 * (1 + H.norm())) << trial;
    EXPECT_LT((g.xi_gradient - (2 / l) * T - (2 * g.gap / (l * l)) * C).norm(), 1e-12) << trial;
  }
}

TEST(SegmentGeometry, InvariantUnderRigidMotion) {
  std::mt19937 rng(5);
  for (int n_nodes : {2, 3}) {
    for (int trial = 0; trial < 20; ++trial) {
      const Points p = random_configuration(rng, n_nodes);
      const double angle = 0.9 + 1.3 * trial;
      const Eigen::Matrix2d R = rotation(angle);
      const Vector2d shift(3.0 - trial, 0.5 * trial);
      Points q = p;
      for (auto& x : q) x = R * x + shift;
      const SegmentGeometry a = geometry_of(p), b = geometry_of(q);
      EXPECT_NEAR(a.projection.xi, b.projection.xi, 1e-12);
      EXPECT_NEAR(a.gap, b.gap, 1e-12);
      EXPECT_NEAR(a.curvature, b.curvature, 1e-10);
      EXPECT_TRUE((R * a.normal).isApprox(b.normal, 1e-12));
      // block-diagonal rotation of the dofs: gradients rotate, Hessians R H Rᵀ
      const int n = a.n_dofs;
      Eigen::MatrixXd Q = Eigen::MatrixXd::Zero(n, n);
      for (int k = 0; k < n / 2; ++k) Q.block<2, 2>(2 * k, 2 * k) = R;
      EXPECT_LT((Q * a.gap_gradient - b.gap_gradient).norm(), 1e-11);
      EXPECT_LT((Q * a.xi_gradient - b.xi_gradient).norm(), 1e-10);
      EXPECT_LT((Q * a.gap_hessian * Q.transpose() - b.gap_hessian).norm(), 1e-9 * (1 + a.gap_hessian.norm()));
    }
  }
}

TEST(SegmentGeometry, SlipIncrement) {
  // Straight segment: sliding the slave by δ along t gives Δs = δ exactly.
  const Points seg = {Vector2d(0, 0), Vector2d(3, 4)};
  const Vector2d t(0.6, 0.8), n(0.8, -0.6);
  const Vector2d start = Vector2d(1.5, 2) + 0.2 * n, end = start + 0.7 * t;
  const SegmentGeometry before = segment_geometry(start, seg);
  const SegmentGeometry after = segment_geometry(end, seg);
  EXPECT_NEAR(slip_increment(end, seg, after, seg, before.projection.xi).value, 0.7, 1e-14);
  EXPECT_NEAR(slip_increment(start, seg, before, seg, after.projection.xi).value, -0.7, 1e-14);
  // Handed over to the collinear next segment (and back): the same distance.
  const Points next = {Vector2d(3, 4), Vector2d(6, 8)};
  const Vector2d far = start + 3.1 * t;
  const SegmentGeometry on_next = segment_geometry(far, next);
  EXPECT_NEAR(slip_increment(far, next, on_next, seg, before.projection.xi).value, 3.1, 1e-14);
  EXPECT_NEAR(slip_increment(start, seg, before, next, on_next.projection.xi).value, -3.1, 1e-14);
}

TEST(SegmentGeometry, SlipIncrementOnACurveIsTheArcLengthToSecondOrder) {
  // Parabola y(ξ) = (ξ, 0.3 ξ²) as a 3-node segment: the error of Δs
  // against the arc length from ξ_c to ξ* falls as Δξ³ (ratio ~8 per halving).
  const Points seg = {Vector2d(-1, 0.3), Vector2d(1, 0.3), Vector2d(0, 0)};
  const auto arc = [](double a, double b) {  // ∫ sqrt(1 + (0.6 ξ)²) dξ, Simpson, 2000 panels
    double sum = 0;
    const int n = 2000;
    for (int k = 0; k <= n; ++k) {
      const double x = a + (b - a) * k / n;
      sum += (k == 0 || k == n ? 1 : (k % 2 ? 4 : 2)) * std::sqrt(1 + 0.36 * x * x);
    }
    return sum * (b - a) / (3 * n);
  };
  double previous = 0;
  for (double d : {0.2, 0.1, 0.05}) {
    const double xi_c = 0.1, xi = xi_c + d;
    const Vector2d y(xi, 0.3 * xi * xi), normal = Vector2d(0.6 * xi, -1).normalized();  // outward: below
    const Vector2d slave = y + 0.05 * normal;
    const SegmentGeometry g = segment_geometry(slave, seg);
    ASSERT_NEAR(g.projection.xi, xi, 1e-12);
    const double error = std::abs(slip_increment(slave, seg, g, seg, xi_c).value - arc(xi_c, xi));
    std::printf("[ slip ] dxi %.3f: |ds - arc length| = %.3e\n", d, error);
    if (previous > 0) EXPECT_GT(previous / error, 6.0) << d;
    previous = error;
  }
}

TEST(SegmentGeometry, SlipIncrementGradientMatchesFiniteDifferences) {
  // Random curved or straight current segments, committed on the same
  // segment or on another random one (a hand-over): the gradient over
  // [slave, segment, committed segment] against central differences.
  std::mt19937 rng(3);
  double worst = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const int m = trial % 2 ? 3 : 2, m_c = trial % 4 < 2 ? 2 : 3;
    Points p = random_configuration(rng, m);
    const Points other = random_configuration(rng, m_c);
    const bool same = trial % 5 == 0;
    if (!same) p.insert(p.end(), other.begin() + 1, other.end());
    const double xi_c = same ? 0.3 : -0.7;
    const auto slip = [&](const Points& q) {
      const std::span<const Vector2d> segment(q.data() + 1, static_cast<std::size_t>(m));
      const std::span<const Vector2d> committed = same ? segment : std::span<const Vector2d>(q.data() + 1 + m, q.size() - 1 - m);
      return slip_increment(q[0], segment, segment_geometry(q[0], segment, ContactDerivatives::gradient), committed, xi_c);
    };
    SlipVector grad = slip(p).gradient;
    if (same) {  // fold the committed part onto the segment's nodes
      grad.segment(2, 2 * m) += grad.tail(2 * m);
      grad.conservativeResize(2 * (1 + m));
    }
    ASSERT_EQ(grad.size(), 2 * static_cast<Eigen::Index>(p.size()));
    Eigen::VectorXd fd(grad.size());
    for (int j = 0; j < grad.size(); ++j)
      fd[j] = (slip(perturbed(p, j, 1e-6)).value - slip(perturbed(p, j, -1e-6)).value) / 2e-6;
    const double error = relative(grad, fd);
    worst = std::max(worst, error);
    EXPECT_LT(error, 1e-7) << trial;
  }
  std::printf("[ slip ] gradient vs central differences: worst relative error %.2e\n", worst);
}

TEST(SegmentGeometry, EvaluationTime) {
  // Not a benchmark: a rough wall-clock figure for one projection + gradient +
  // Hessian, printed for the record (no assertion on time).
  std::mt19937 rng(9);
  for (int n_nodes : {2, 3}) {
    std::vector<Points> configs;
    for (int i = 0; i < 64; ++i) configs.push_back(random_configuration(rng, n_nodes));
    constexpr int kRepeats = 200000;
    double sink = 0;
    const std::clock_t start = std::clock();  // CPU time: the test machine may be shared
    for (int i = 0; i < kRepeats; ++i) {
      const Points& p = configs[i % configs.size()];
      sink += segment_geometry(p[0], segment_of(p)).gap_hessian(0, 1);
    }
    const double ns = 1e9 * static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
    std::cout << n_nodes << "-node segment: " << ns / kRepeats << " ns (CPU) per projection+gradient+Hessian (sink "
              << sink << ")\n";
  }
}

}  // namespace
