#pragma once
/// The scalar roots of mortar segmentation: projections of a point along the
/// slave's interpolated normals onto a slave segment (SlaveRay) and along a
/// direction onto a master segment (MasterRay), found by Newton in double and
/// given their derivatives by the implicit function theorem (solve_scalar).
/// Private to src/tether/contact/mortar_segmentation.cpp (not installed);
/// split from it to keep that file about the overlaps and their integrals.

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <vector>

#include "tether/contact/dual2.hpp"
#include "tether/contact/mortar_segmentation.hpp"

namespace tether::mortar_roots {

using std::sqrt;

/// Newton steps taken on the root after the iteration has converged (three;
/// one on a 2-node master face, whose equation is linear): in double, they
/// take the root to round-off. The root's derivatives come from the
/// implicit function theorem (Dual2::implicit_root), not from these steps.
constexpr int kPolishSteps = 3;
constexpr int kMaxNewton = 50;
/// Convergence of the double Newton iteration on |Δξ|: the derivative steps
/// that follow take the root to round-off (quadratic convergence), so this
/// only has to be within their reach, and well above the round-off floor of
/// the iteration itself (a tighter test can stall and drop a projection).
constexpr double kXiTolerance = 1e-10;

template <class T>
Vec2T<double> values(const Vec2T<T>& a) {
  return {value_of(a.x), value_of(a.y)};
}

template <class T>
std::vector<Vec2T<double>> values(std::span<const Vec2T<T>> a) {
  std::vector<Vec2T<double>> out;
  out.reserve(a.size());
  for (const auto& p : a) out.push_back(values(p));
  return out;
}

/// Σ_a N_a x_a, accumulated in place (no temporaries of Vec2T<Dual2>).
template <class T>
Vec2T<T> interpolate(std::span<const Vec2T<T>> x, const std::array<T, 3>& N) {
  Vec2T<T> r{T(0.0), T(0.0)};
  for (std::size_t a = 0; a < x.size(); ++a) {
    add_product(r.x, N[a], x[a].x);
    add_product(r.y, N[a], x[a].y);
  }
  return r;
}

/// d²N/dξ² of a 2- or 3-node segment (constant).
inline void second_shapes(int n_nodes, std::array<double, 3>& ddN) {
  ddN = n_nodes == 2 ? std::array<double, 3>{0.0, 0.0, 0.0} : std::array<double, 3>{1.0, 1.0, -2.0};
}

/// f(ξ) = (p - x(ξ)) × n(ξ) and f'(ξ) on a slave segment with nodal normals.
/// The derivatives x'(ξ) and n'(ξ) of a 2-node segment do not depend on ξ:
/// they are computed once per projection (`SlaveRay`), bit for bit the same.
template <class T>
struct SlaveRay {
  const Vec2T<T>& p;
  std::span<const Vec2T<T>> x, normals;
  std::optional<Vec2T<T>> dx, dn;  ///< x', n' of a 2-node segment
  SlaveRay(const Vec2T<T>& p_, std::span<const Vec2T<T>> x_, std::span<const Vec2T<T>> normals_)
      : p(p_), x(x_), normals(normals_) {
    if (x.size() != 2) return;
    std::array<T, 3> N, dN;
    segment_shapes(2, T(0.0), N, dN);
    dx = interpolate(x, dN), dn = interpolate(normals, dN);
  }
  void operator()(const T& xi, T& f, T& df) const {
    std::array<T, 3> N, dN;
    segment_shapes(static_cast<int>(x.size()), xi, N, dN);
    const Vec2T<T> d = p - interpolate(x, N);
    const Vec2T<T> n = interpolate(normals, N);
    f = cross(d, n);
    if (dx) {
      df = cross(d, *dn) - cross(*dx, n);
      return;
    }
    const Vec2T<T> dn_xi = interpolate(normals, dN), dx_xi = interpolate(x, dN);
    df = cross(d, dn_xi) - cross(dx_xi, n);
  }
  /// f''(ξ) = (p - x) × n'' - 2 x' × n' - x'' × n (values).
  double curvature(double xi) const {
    std::array<double, 3> N, dN, ddN;
    segment_shapes(static_cast<int>(x.size()), xi, N, dN);
    second_shapes(static_cast<int>(x.size()), ddN);
    const auto at = [&](std::span<const Vec2T<T>> v, const std::array<double, 3>& w) {
      Vec2T<double> r{0.0, 0.0};
      for (std::size_t a = 0; a < v.size(); ++a) r = r + w[a] * Vec2T<double>{value_of(v[a].x), value_of(v[a].y)};
      return r;
    };
    const Vec2T<double> d = Vec2T<double>{value_of(p.x), value_of(p.y)} - at(x, N);
    return cross(d, at(normals, ddN)) - 2.0 * cross(at(x, dN), at(normals, dN)) - cross(at(x, ddN), at(normals, N));
  }
};

/// f(η) = (y(η) - p) × d and f'(η) on a master segment; f' of a 2-node
/// segment does not depend on η and is computed once per projection.
template <class T>
struct MasterRay {
  const Vec2T<T>& p;
  const Vec2T<T>& d;
  std::span<const Vec2T<T>> y;
  std::optional<T> df2;  ///< f' of a 2-node segment
  MasterRay(const Vec2T<T>& p_, const Vec2T<T>& d_, std::span<const Vec2T<T>> y_) : p(p_), d(d_), y(y_) {
    if (y.size() != 2) return;
    std::array<T, 3> N, dN;
    segment_shapes(2, T(0.0), N, dN);
    df2 = cross(interpolate(y, dN), d);
  }
  void operator()(const T& eta, T& f, T& df) const {
    std::array<T, 3> N, dN;
    segment_shapes(static_cast<int>(y.size()), eta, N, dN);
    f = cross(interpolate(y, N) - p, d);
    df = df2 ? *df2 : cross(interpolate(y, dN), d);
  }
  /// f''(η) = y''(η) × d (values).
  double curvature(double /*eta*/) const {
    std::array<double, 3> ddN;
    second_shapes(static_cast<int>(y.size()), ddN);
    Vec2T<double> ddy{0.0, 0.0};
    for (std::size_t a = 0; a < y.size(); ++a) ddy = ddy + ddN[a] * Vec2T<double>{value_of(y[a].x), value_of(y[a].y)};
    return cross(ddy, Vec2T<double>{value_of(d.x), value_of(d.y)});
  }
};

/// Newton on a scalar equation given by `residual_double(xi, f, df)`, then
/// `polish_steps` more Newton steps: the root's value as solve_scalar<T>
/// has it. The polishing steps compute t - f/f' as the Newton steps on T
/// did before (Dual2 divides by multiplying with 1/f'), so the roots'
/// values are the bits they were. None when it does not converge or leaves
/// |ξ| <= limit.
template <class T, class DoubleResidual>
std::optional<double> scalar_root(double start, double limit, DoubleResidual residual_double, int polish_steps) {
  double xi = start;
  bool converged = false;
  for (int it = 0; it < kMaxNewton; ++it) {
    double f = 0, df = 0;
    residual_double(xi, f, df);
    if (!(std::abs(df) > 0) || !std::isfinite(f)) return std::nullopt;
    const double step = f / df;
    xi -= step;
    if (!(std::abs(xi) <= limit)) return std::nullopt;
    if (std::abs(step) <= kXiTolerance) {
      converged = true;
      break;
    }
  }
  if (!converged) return std::nullopt;
  double root = xi;
  for (int k = 0; k < polish_steps; ++k) {
    double f = 0, df = 0;
    residual_double(root, f, df);
    if constexpr (std::is_same_v<T, double>)
      f /= df;
    else
      f *= 1 / df;
    root -= f;
  }
  return root;
}

/// The root of scalar_root, then (T = Dual2) its gradient and Hessian by
/// the implicit function theorem from one evaluation of `residual_t` (the
/// same equation on T) at the root, with f'' from `residual_t.curvature`
/// (exact at a root; Dual2::implicit_root).
template <class T, class DoubleResidual, class TResidual>
std::optional<T> solve_scalar(double start, double limit, DoubleResidual residual_double, TResidual residual_t,
                              int polish_steps = kPolishSteps) {
  const std::optional<double> root = scalar_root<T>(start, limit, residual_double, polish_steps);
  if (!root) return std::nullopt;
  if constexpr (std::is_same_v<T, double>) {
    return *root;
  } else {
    T f, df;
    residual_t(T(*root), f, df);
    return Dual2::implicit_root(*root, f, df, residual_t.curvature(*root));
  }
}

/// Newton's start for the projection of p along the normals of slave segment x:
/// the closest point of its chord, in [-2, 2].
inline double slave_projection_start(const Vec2T<double>& p, std::span<const Vec2T<double>> x) {
  const Vec2T<double> chord = x[1] - x[0], mid = 0.5 * (x[0] + x[1]);
  return std::clamp(2 * dot(p - mid, chord) / dot(chord, chord), -2.0, 2.0);
}

/// Polishing steps of a projection onto master segment y (its equation is linear on a 2-node one).
inline int master_polish_steps(std::size_t nodes) { return nodes == 2 ? 1 : kPolishSteps; }

}  // namespace tether::mortar_roots
