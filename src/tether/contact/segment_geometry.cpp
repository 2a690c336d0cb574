#include "tether/contact/segment_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "tether/fem/shape_functions.hpp"

namespace tether {

namespace {

// Derivatives are first taken with respect to z = (ξ, x), x the contact dofs,
// treating ξ as independent; the implicit function theorem on the projection
// condition then gives the total derivatives (see the theory page).
constexpr int kMaxZ = 1 + kMaxContactDofs;
using ZVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxZ, 1>;
using ZMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxZ, kMaxZ>;
using ZJacobian = Eigen::Matrix<double, 2, Eigen::Dynamic, 0, 2, kMaxZ>;  // d(2-vector)/dz

void check_segment(std::span<const Eigen::Vector2d> segment) {
  if (segment.size() != 2 && segment.size() != 3) {
    throw std::invalid_argument("contact segment must have 2 or 3 nodes, got " + std::to_string(segment.size()));
  }
}

/// Point, first and second ξ-derivatives of the segment at ξ.
struct SegmentPoint {
  Eigen::Vector2d y, a, b;  // y(ξ), y'(ξ), y''(ξ)
  Eigen::Vector3d N, dN, ddN;
};

SegmentPoint evaluate(std::span<const Eigen::Vector2d> segment, double xi) {
  SegmentPoint p;
  const int m = static_cast<int>(segment.size());
  face_shape_functions(m, xi, p.N, p.dN);
  p.ddN = m == 3 ? Eigen::Vector3d(1, 1, -2) : Eigen::Vector3d::Zero();
  p.y.setZero();
  p.a.setZero();
  p.b.setZero();
  for (int k = 0; k < m; ++k) {
    p.y += p.N[k] * segment[k];
    p.a += p.dN[k] * segment[k];
    p.b += p.ddN[k] * segment[k];
  }
  return p;
}

/// Squared size of the segment, the reference for "degenerate".
double size_squared(std::span<const Eigen::Vector2d> segment) {
  double l2 = (segment[1] - segment[0]).squaredNorm();
  if (segment.size() == 3) l2 += (segment[2] - segment[0]).squaredNorm() + (segment[2] - segment[1]).squaredNorm();
  return l2;
}

bool is_degenerate(double metric_squared, double l2) { return !(metric_squared > 1e-24 * l2); }

/// Value, z-gradient and z-Hessian of a scalar.
struct Scalar {
  double value = 0;
  ZVector dz;
  ZMatrix dzz;
};

/// φ = uᵀ M v for 2-vectors u(z), v(z) with z-Jacobians and per-component z-Hessians.
Scalar bilinear(const Eigen::Vector2d& u, const ZJacobian& u_z, const ZMatrix* u_zz, const Eigen::Vector2d& v,
                const ZJacobian& v_z, const ZMatrix* v_zz, const Eigen::Matrix2d& M, bool hessian) {
  Scalar s;
  const Eigen::Vector2d Mv = M * v;
  const Eigen::Vector2d Mtu = M.transpose() * u;
  s.value = u.dot(Mv);
  s.dz = u_z.transpose() * Mv + v_z.transpose() * Mtu;
  if (hessian) {
    const ZJacobian Mv_z = M * v_z;
    s.dzz = u_z.transpose().lazyProduct(Mv_z);
    s.dzz += s.dzz.transpose().eval();
    for (int i = 0; i < 2; ++i) s.dzz += Mv[i] * u_zz[i] + Mtu[i] * v_zz[i];
  }
  return s;
}

}  // namespace

SegmentProjection project(const Eigen::Vector2d& slave, std::span<const Eigen::Vector2d> segment,
                          const ProjectionOptions& options) {
  check_segment(segment);
  SegmentProjection out;
  const double l2 = size_squared(segment);
  if (segment.size() == 2) {
    const Eigen::Vector2d mid = 0.5 * (segment[0] + segment[1]);
    const Eigen::Vector2d a = 0.5 * (segment[1] - segment[0]);
    if (is_degenerate(a.squaredNorm(), l2)) {
      out.status = ProjectionStatus::degenerate;
      return out;
    }
    out.xi = (slave - mid).dot(a) / a.squaredNorm();
  } else {
    // Start: projection on the chord between the corners, kept near the segment.
    const Eigen::Vector2d chord = segment[1] - segment[0];
    if (is_degenerate(chord.squaredNorm(), l2)) {
      out.status = ProjectionStatus::degenerate;
      return out;
    }
    double xi = std::clamp(2 * (slave - segment[0]).dot(chord) / chord.squaredNorm() - 1, -2.0, 2.0);
    out.status = ProjectionStatus::not_converged;
    for (int it = 0; it <= options.max_iterations; ++it) {
      const SegmentPoint p = evaluate(segment, xi);
      const Eigen::Vector2d r = slave - p.y;
      const double a2 = p.a.squaredNorm();
      if (is_degenerate(a2, l2)) {
        out.status = ProjectionStatus::degenerate;
        break;
      }
      const double f = r.dot(p.a);  // = -dφ/dξ, φ = ½|r|²
      if (std::abs(f) <= 1e-15 * std::sqrt(a2) * (r.norm() + std::sqrt(a2))) {
        out.status = ProjectionStatus::converged;
        break;
      }
      if (it == options.max_iterations) break;
      const double phi_xx = a2 - r.dot(p.b);  // d²φ/dξ²
      double step = phi_xx > 0 ? f / phi_xx : f / a2;  // Newton where convex, else Gauss–Newton (descent)
      step = std::clamp(step, -1.0, 1.0);
      const double phi = 0.5 * r.squaredNorm();
      for (int halving = 0; halving < 40; ++halving) {
        const double phi_new = 0.5 * (slave - evaluate(segment, xi + step).y).squaredNorm();
        if (phi_new <= phi + 1e-13 * (phi + a2)) break;
        step *= 0.5;
      }
      xi += step;
      out.iterations = it + 1;
      if (std::abs(step) <= options.xi_tolerance) {
        out.status = ProjectionStatus::converged;
        break;
      }
    }
    out.xi = xi;
  }
  if (out.status == ProjectionStatus::degenerate) return out;
  out.inside = std::abs(out.xi) <= 1 + options.end_tolerance;
  out.clamped_xi = std::clamp(out.xi, -1.0, 1.0);
  out.clamped_distance = (slave - evaluate(segment, out.clamped_xi).y).norm();
  return out;
}

SegmentGeometry segment_geometry(const Eigen::Vector2d& slave, std::span<const Eigen::Vector2d> segment,
                                 ContactDerivatives derivatives, const ProjectionOptions& options) {
  SegmentGeometry g;
  g.projection = project(slave, segment, options);
  const int m = static_cast<int>(segment.size());
  const int nd = 2 * (1 + m);
  const int nz = 1 + nd;
  g.n_dofs = nd;
  g.gap_gradient.setZero(nd);
  g.xi_gradient.setZero(nd);
  g.metric_gradient.setZero(nd);
  g.gap_hessian.setZero(nd, nd);
  g.xi_hessian.setZero(nd, nd);
  if (g.projection.status == ProjectionStatus::degenerate) return g;

  const SegmentPoint p = evaluate(segment, g.projection.xi);
  const Eigen::Vector2d r = slave - p.y;
  const double a2 = p.a.squaredNorm();
  const double q = std::sqrt(a2);
  g.point = p.y;
  g.tangent_vector = p.a;
  g.metric = q;
  g.tangent = p.a / q;
  g.normal = Eigen::Vector2d(g.tangent.y(), -g.tangent.x());
  g.gap = r.dot(g.normal);
  g.curvature = -g.normal.dot(p.b) / a2;
  const double f_xi = -a2 + r.dot(p.b);
  g.projection_stiffness = -f_xi / a2;
  if (derivatives == ContactDerivatives::none) return g;
  const bool hessian = derivatives == ContactDerivatives::hessian;

  // Coefficients over the points (slave, y^1..y^m): r = Σ cr_k p_k, a = Σ ca_k p_k, b = Σ cb_k p_k.
  Eigen::Vector4d cr, ca, cb;
  cr << 1, -p.N[0], -p.N[1], -p.N[2];
  ca << 0, p.dN[0], p.dN[1], p.dN[2];
  cb << 0, p.ddN[0], p.ddN[1], p.ddN[2];

  // z-Jacobians (column 0 = ξ) and per-component z-Hessians of r and a.
  ZJacobian r_z = ZJacobian::Zero(2, nz), a_z = ZJacobian::Zero(2, nz);
  r_z.col(0) = -p.a;
  a_z.col(0) = p.b;
  ZMatrix r_zz[2], a_zz[2];
  for (int i = 0; i < 2; ++i) {
    r_zz[i].setZero(nz, nz);
    a_zz[i].setZero(nz, nz);
    r_zz[i](0, 0) = -p.b[i];  // y''' = 0 for up to quadratic segments
  }
  for (int k = 0; k <= m; ++k) {
    for (int i = 0; i < 2; ++i) {
      const int col = 1 + 2 * k + i;
      r_z(i, col) = cr[k];
      a_z(i, col) = ca[k];
      r_zz[i](0, col) = r_zz[i](col, 0) = -ca[k];  // ∂cr_k/∂ξ = -ca_k
      a_zz[i](0, col) = a_zz[i](col, 0) = cb[k];
    }
  }

  const Eigen::Matrix2d I = Eigen::Matrix2d::Identity();
  Eigen::Matrix2d J;  // rᵀ J a = r × a = (y_s - y)·(a_y, -a_x)
  J << 0, 1, -1, 0;
  const Scalar f = bilinear(r, r_z, r_zz, p.a, a_z, a_zz, I, hessian);   // projection condition
  const Scalar h = bilinear(r, r_z, r_zz, p.a, a_z, a_zz, J, hessian);   // g_n |a|
  const Scalar s = bilinear(p.a, a_z, a_zz, p.a, a_z, a_zz, I, hessian);  // |a|²

  // |a| = sqrt(s) and g_n = h / |a| as functions of z.
  const ZVector q_z = s.dz / (2 * q);
  const ZVector g_z = h.dz / q - h.value * q_z / a2;

  // Implicit function theorem: f(ξ*(x), x) = 0  ⇒  ∂ξ*/∂x = -f_x / f_ξ.
  // E = dz/dx = [∂ξ*/∂x ; I] maps z-derivatives to total x-derivatives.
  const double fxi = f.dz[0];
  g.xi_gradient = -f.dz.tail(nd) / fxi;
  g.gap_gradient = g_z.tail(nd) + g_z[0] * g.xi_gradient;
  g.metric_gradient = q_z.tail(nd) + q_z[0] * g.xi_gradient;
  if (!hessian) return g;

  ZMatrix E = ZMatrix::Zero(nz, nd);
  E.row(0) = g.xi_gradient.transpose();
  E.bottomRows(nd).setIdentity();
  const ZMatrix q_zz = s.dzz / (2 * q) - q_z * q_z.transpose() / q;
  ZMatrix g_zz = h.dzz / q - (h.dz * q_z.transpose() + q_z * h.dz.transpose()) / a2 +
                 (2 * h.value / (a2 * q)) * q_z * q_z.transpose() - (h.value / a2) * q_zz;
  // d²/dx² of f(ξ*(x), x) = 0  ⇒  ∂²ξ*/∂x² = -Eᵀ f_zz E / f_ξ.
  // (lazy products: at most 9 x 9, far below where blocked GEMM pays off)
  const ZMatrix fE = f.dzz.lazyProduct(E), gE = g_zz.lazyProduct(E);
  g.xi_hessian = -E.transpose().lazyProduct(fE) / fxi;
  g.gap_hessian = E.transpose().lazyProduct(gE) + g_z[0] * g.xi_hessian;
  g.gap_hessian = 0.5 * (g.gap_hessian + g.gap_hessian.transpose()).eval();
  return g;
}

SlipIncrement slip_increment(const Eigen::Vector2d& slave, std::span<const Eigen::Vector2d> segment,
                             const SegmentGeometry& geometry, std::span<const Eigen::Vector2d> committed_segment,
                             double committed_xi, ContactDerivatives derivatives) {
  check_segment(segment);
  check_segment(committed_segment);
  const int m = static_cast<int>(segment.size());
  const int mc = static_cast<int>(committed_segment.size());
  SlipIncrement s;
  if (geometry.projection.status == ProjectionStatus::degenerate) {
    if (derivatives != ContactDerivatives::none) s.gradient.setZero(2 * (1 + m + mc));
    return s;
  }
  const SegmentPoint c = evaluate(committed_segment, committed_xi);
  const SegmentPoint p = evaluate(segment, geometry.projection.xi);
  // (y(ξ*) - ȳ_c)·t rather than the equal (y_s - ȳ_c)·t: exactly 0 when ξ*
  // is ξ_c on the same segment (the start of an increment), so round-off does
  // not decide between stick and slip there (|τ| = |λt| = μN).
  s.value = (p.y - c.y).dot(geometry.tangent);
  if (derivatives == ContactDerivatives::none) return s;
  s.gradient.setZero(2 * (1 + m + mc));
  // δt = n nᵀ δy' / |y'|, so d·δt = w·δy' with d = y_s - ȳ_c, w = (d·n / |y'|) n.
  const Eigen::Vector2d d = slave - c.y;
  const Eigen::Vector2d w = (d.dot(geometry.normal) / geometry.metric) * geometry.normal;
  s.gradient.head(2 * (1 + m)) = w.dot(p.b) * geometry.xi_gradient;
  s.gradient.head<2>() += geometry.tangent;
  for (int a = 0; a < m; ++a) s.gradient.segment<2>(2 + 2 * a) += p.dN[a] * w;
  for (int a = 0; a < mc; ++a) s.gradient.segment<2>(2 * (1 + m + a)) = -c.N[a] * geometry.tangent;
  return s;
}

}  // namespace tether
