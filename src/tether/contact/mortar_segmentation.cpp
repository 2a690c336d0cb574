#include "tether/contact/mortar_segmentation.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "tether/contact/mortar_roots.hpp"
#include "tether/fem/quadrature.hpp"

namespace tether {

using std::sqrt;
using namespace mortar_roots;  // the scalar roots (SlaveRay, MasterRay, solve_scalar, ...)

namespace {

/// Gauss points of the whole-segment integrals of the dual basis: exact for
/// straight segments (polynomial integrands), to about 1e-7 relative on a
/// strongly curved 3-node segment.
constexpr int kElementPoints = 8;

/// Gauss–Legendre rule with n points, 1 <= n <= 20, computed once.
const std::vector<LinePoint>& gauss_rule(int n) {
  static const std::vector<std::vector<LinePoint>> rules = [] {
    std::vector<std::vector<LinePoint>> r(21);
    for (int k = 1; k <= 20; ++k) r[static_cast<std::size_t>(k)] = gauss_legendre(k);
    return r;
  }();
  return rules.at(static_cast<std::size_t>(n));
}

/// The overlap [ξ_lo, ξ_hi] on slave segment x of master segment y: the
/// slave points whose normal ray meets y. Its ends are slave ends whose
/// nodal normal ray meets y (|η| <= 1) and projections of master ends that
/// fall on the slave (|ξ| <= 1), clipped to [-1, 1]. None when that leaves
/// no interval. The ends are chosen on the projections' values (the bits
/// the T projections have); with T = Dual2 only a chosen master end strictly
/// inside the slave is projected again for its derivatives (a slave end or
/// a clipped one is a constant, and the projections onto the master only
/// decide), so the result is the same as projecting every end in T.
template <class T>
std::optional<std::array<T, 2>> overlap_of(std::span<const Vec2T<T>> x, std::span<const Vec2T<T>> normals,
                                           std::span<const Vec2T<T>> y) {
  constexpr double inside = 1 + 1e-12;
  // The values of the positions (with T = double, the positions themselves: no copies).
  std::vector<Vec2T<double>> xv, nv, yv;
  if constexpr (!std::is_same_v<T, double>) xv = values(x), nv = values(normals), yv = values(y);
  const auto as_values = [](std::span<const Vec2T<T>> t, const std::vector<Vec2T<double>>& v) {
    if constexpr (std::is_same_v<T, double>)
      return t;
    else
      return std::span<const Vec2T<double>>(v);
  };
  const std::span<const Vec2T<double>> xd = as_values(x, xv), nd = as_values(normals, nv), yd = as_values(y, yv);
  struct End {
    double xi = 0;
    int master = -1;  ///< the master end projected, -1 for a slave end
  };
  std::vector<End> ends;
  for (int end = 0; end < 2; ++end) {
    const auto e = static_cast<std::size_t>(end);
    const std::optional<double> eta =
        scalar_root<T>(0.0, 3.0, MasterRay<double>(xd[e], nd[e], yd), master_polish_steps(yd.size()));
    if (eta && std::abs(*eta) <= inside) ends.push_back({end == 0 ? -1.0 : 1.0, -1});
    const std::optional<double> xi =
        scalar_root<T>(slave_projection_start(yd[e], xd), 3.0, SlaveRay<double>(yd[e], xd, nd), kPolishSteps);
    if (xi && std::abs(*xi) <= inside) ends.push_back({std::max(-1.0, std::min(1.0, *xi)), end});
  }
  if (ends.size() < 2) return std::nullopt;
  const auto by_xi = [](const End& a, const End& b) { return a.xi < b.xi; };
  const auto [lo, hi] = std::minmax_element(ends.begin(), ends.end(), by_xi);
  if (!(hi->xi - lo->xi > 1e-14)) return std::nullopt;
  const auto at = [&](const End& end) -> T {
    if constexpr (std::is_same_v<T, double>) {
      return end.xi;
    } else {
      if (end.master < 0 || !(end.xi > -1.0 && end.xi < 1.0)) return T(end.xi);
      return *project_along_slave_normals<T>(y[static_cast<std::size_t>(end.master)], x, normals);
    }
  };
  return std::array<T, 2>{at(*lo), at(*hi)};
}

/// dual_coefficients of the (constant) positions x, as T.
template <class T>
std::array<std::array<T, 3>, 3> constant_coefficients(std::span<const Vec2T<double>> x) {
  const std::array<std::array<double, 3>, 3> a = dual_coefficients<double>(x);
  std::array<std::array<T, 3>, 3> out;
  for (std::size_t k = 0; k < 3; ++k)
    for (std::size_t l = 0; l < 3; ++l) out[k][l] = T(a[k][l]);
  return out;
}

/// One overlap [lo, hi] of a slave segment x (nodal normals, dual
/// coefficients A, Jacobian from `jacobian_of`) with master segment y.
template <class T>
struct Overlap {
  std::span<const Vec2T<T>> x, normals, y, jacobian_of;
  const std::array<std::array<T, 3>, 3>& A;
  double thickness;
  const std::vector<LinePoint>& gauss;
  const T &lo, &hi;
};

/// Adds the overlap's ∫ Φ_k dA to D[k] and sets M[k][a] = ∫ Φ_k N_a(η) dA
/// (any segments): at each Gauss point ξ_q, η_q is the projection of x(ξ_q)
/// along n(ξ_q) onto y; points without one are skipped.
template <class T>
void integrate_overlap(const Overlap<T>& o, std::array<T, 3>& D, std::array<std::array<T, 3>, 3>& M) {
  const int n = static_cast<int>(o.x.size());
  const T half = 0.5 * (o.hi - o.lo), centre = 0.5 * (o.hi + o.lo);
  for (const LinePoint& q : o.gauss) {
    const T xi = centre + q.s * half;
    std::array<T, 3> N, dN;
    segment_shapes(n, xi, N, dN);
    const Vec2T<T> dx = interpolate(o.jacobian_of, dN);
    const T w = (q.weight * o.thickness) * half * sqrt(dot(dx, dx));
    const std::optional<T> eta = project_onto_master<T>(interpolate(o.x, N), interpolate(o.normals, N), o.y);
    if (!eta) continue;
    std::array<T, 3> Nm, dNm;
    segment_shapes(static_cast<int>(o.y.size()), *eta, Nm, dNm);
    for (int k = 0; k < n; ++k) {
      T phi(0.0);
      for (int l = 0; l < n; ++l) add_product(phi, o.A[k][l], N[l]);
      const T wphi = w * phi;
      D[k] += wphi;
      for (std::size_t m = 0; m < o.y.size(); ++m) add_product(M[k][m], wphi, Nm[m]);
    }
  }
}

/// The projections η(s) of x(s) = x_c + s x_h along n(s) = n_c + s n_h onto
/// a 2-node master segment y (y(η) = y_c + η y_d), for any s: the equation
///   f(η; s) = (y(η) - x(s)) × n(s) = F(s) + η G(s),
///   F(s) = r × n_c + s (r × n_h - x_h × n_c) - s² x_h × n_h  (r = y_c - x_c),
///   G(s) = y_d × n_c + s y_d × n_h,
/// with its five coefficients p = (f0, f1, f2, g0, g1) built once per
/// overlap. η's value comes from the same double Newton iteration as
/// project_onto_master (the same bits, the same points skipped).
///
/// Its derivatives are summed over the points in closed form. At a point,
/// with e = (1, s, s², η, sη) (so F + ηG = e·p) and G its value, the
/// implicit function theorem (f'' = 0 on a straight master) gives
///   ∇η = -(e·∇p) / G,   ∇²η = -(e·∇²p + ∇G ∇ηᵀ + ∇η ∇Gᵀ) / G,   ∇G = ∇g0 + s ∇g1,
/// so a sum Σ_q c_q η_q has
///   gradient Σ_k a_k ∇p_k,   Hessian Σ_k a_k ∇²p_k + Σ_{l=0,1} (∇g_l w_lᵀ + w_l ∇g_lᵀ),
///   a = Σ_q (-c_q/G_q) e_q,  w_0 = Σ_q (-c_q/G_q) ∇η_q,  w_1 = Σ_q (-c_q/G_q) s_q ∇η_q,
/// all weights in double: one pass over the Hessian per sum
/// (Dual2::combination), where Dual2::implicit_root and the sums took about
/// fifteen per point. The same derivatives up to round-off.
struct LinearMasterProjection {
  Vec2T<double> xc_v, xh_v, nc_v, nh_v;
  std::vector<Vec2T<double>> y_v;
  Dual2 f0, f1, f2, g0, g1;
  LinearMasterProjection(const Vec2T<Dual2>& xc, const Vec2T<Dual2>& xh, const Vec2T<Dual2>& nc,
                         const Vec2T<Dual2>& nh, std::span<const Vec2T<Dual2>> y)
      : xc_v(values(xc)), xh_v(values(xh)), nc_v(values(nc)), nh_v(values(nh)), y_v(values(y)) {
    const Vec2T<Dual2> yc{0.5 * (y[0].x + y[1].x), 0.5 * (y[0].y + y[1].y)};
    const Vec2T<Dual2> yd{0.5 * (y[1].x - y[0].x), 0.5 * (y[1].y - y[0].y)};
    const Vec2T<Dual2> r = yc - xc;
    f0 = cross(r, nc);
    f1 = cross(r, nh) - cross(xh, nc);
    f2 = -cross(xh, nh);
    g0 = cross(yd, nc);
    g1 = cross(yd, nh);
  }
  /// η's value at x(s) along n(s), or none where project_onto_master has none.
  [[nodiscard]] std::optional<double> eta(double s) const {
    // The values of x_c + s x_h and n_c + s n_h as Vec2T<Dual2> has them.
    const Vec2T<double> p{xc_v.x + s * xh_v.x, xc_v.y + s * xh_v.y}, d{nc_v.x + s * nh_v.x, nc_v.y + s * nh_v.y};
    return scalar_root<Dual2>(0.0, 3.0, MasterRay<double>(p, d, y_v), master_polish_steps(2));
  }
  /// Σ_q w_q η_q and Σ_q w_q s_q η_q over the Gauss points that project;
  /// adds Σ_q w_q and Σ_q w_q s_q over the same points to sum_w, sum_ws.
  void sums(const std::vector<LinePoint>& gauss, double& sum_w, double& sum_ws, Dual2& sum_w_eta,
            Dual2& sum_ws_eta) const {
    struct Weights {  // of one sum Σ c_q η_q
      double value = 0;
      std::array<double, 5> a{};
      std::array<std::array<double, 5>, 2> b{};
      void add(double c, double eta_q, double s, const std::array<double, 5>& e, double G) {
        value += c * eta_q;
        const double r = -c / G, to_eta = -1 / G;  // ∇η = to_eta e·∇p
        for (std::size_t k = 0; k < 5; ++k) {
          a[k] += r * e[k];
          b[0][k] += (r * to_eta) * e[k];
          b[1][k] += (r * s * to_eta) * e[k];
        }
      }
    } w_eta, ws_eta;
    // The gradients point by point, in the operations (and so the bits) of
    // the Dual2 evaluation this replaces: ∇η = (∇F + η ∇G)(-1/G) with
    // ∇F = (∇f0 + s ∇f1) + s² ∇f2, ∇G = ∇g0 + s ∇g1, added up as w ∇η.
    const Eigen::Index n = std::max({f0.gradient().size(), f1.gradient().size(), f2.gradient().size(),
                                     g0.gradient().size(), g1.gradient().size()});
    const auto grad = [n](const Dual2& d) { return d.constant() ? Dual2::Gradient(Dual2::Gradient::Zero(n)) : d.gradient(); };
    const Dual2::Gradient df0 = grad(f0), df1 = grad(f1), df2 = grad(f2), dg0 = grad(g0), dg1 = grad(g1);
    Dual2::Gradient grad_w = Dual2::Gradient::Zero(n), grad_ws = grad_w;
    for (const LinePoint& q : gauss) {
      const std::optional<double> eta_q = eta(q.s);
      if (!eta_q) continue;
      sum_w += q.weight, sum_ws += q.weight * q.s;
      const double s = q.s, G = g0.value() + s * g1.value(), to_eta = -1 / G;
      const std::array<double, 5> e{1.0, s, s * s, *eta_q, s * *eta_q};
      w_eta.add(q.weight, *eta_q, s, e, G);
      ws_eta.add(q.weight * q.s, *eta_q, s, e, G);
      for (Eigen::Index i = 0; i < n; ++i) {
        const double d_eta = (((df0[i] + df1[i] * s) + df2[i] * (s * s)) + (dg0[i] + dg1[i] * s) * *eta_q) * to_eta;
        grad_w[i] += d_eta * q.weight;
        grad_ws[i] += d_eta * (q.weight * q.s);
      }
    }
    const std::array<const Dual2*, 5> p{&f0, &f1, &f2, &g0, &g1};
    const std::array<const Dual2*, 2> g{&g0, &g1};
    sum_w_eta = Dual2::combination(w_eta.value, p, w_eta.a, g, w_eta.b, n > 0 ? &grad_w : nullptr);
    sum_ws_eta = Dual2::combination(ws_eta.value, p, ws_eta.a, g, ws_eta.b, n > 0 ? &grad_ws : nullptr);
  }
};

/// integrate_overlap for a 2-node slave and a 2-node master segment, with
/// the same Gauss points and projections but one accumulation per point.
/// There the dual basis is affine, Φ_k = α_k + β_k ξ (α_k = (A_k0 + A_k1)/2,
/// β_k = (A_k1 - A_k0)/2), the master shapes are (1 ∓ η)/2 and the
/// Jacobian J is constant, so with c = t J half and w_q the Gauss weights
/// of the points that project (ξ_q = centre + s_q half):
///   S_k = ∫ Φ_k dA   = c (α_k Σ w_q + β_k Σ w_q ξ_q),
///   E_k = ∫ Φ_k η dA = c (α_k Σ w_q η_q + β_k Σ w_q ξ_q η_q),
///   D_k += S_k,  M_k0 = (S_k - E_k)/2,  M_k1 = (S_k + E_k)/2.
/// Only η_q carries derivatives per point (Σ w_q and Σ w_q s_q are
/// numbers; with T = Dual2 the derivatives of Σ w_q η_q and Σ w_q s_q η_q
/// are summed in closed form, LinearMasterProjection::sums); the sums equal
/// integrate_overlap's up to round-off. The point x(ξ_q) and normal n(ξ_q)
/// that η_q projects are affine in s_q too:
/// x(ξ_q) = x(centre) + s_q half x', likewise n.
template <class T>
void integrate_linear_overlap(const Overlap<T>& o, std::array<T, 3>& D, std::array<std::array<T, 3>, 3>& M) {
  const T half = 0.5 * (o.hi - o.lo), centre = 0.5 * (o.hi + o.lo);
  std::array<T, 3> Nc, dNc;
  segment_shapes(2, centre, Nc, dNc);
  const Vec2T<T> xc = interpolate(o.x, Nc), nc = interpolate(o.normals, Nc);
  const Vec2T<T> xh = half * interpolate(o.x, dNc), nh = half * interpolate(o.normals, dNc);
  const auto at = [](const Vec2T<T>& c, const Vec2T<T>& h, double s) { return Vec2T<T>{c.x + s * h.x, c.y + s * h.y}; };
  double sum_w = 0, sum_ws = 0;
  T sum_w_eta(0.0), sum_ws_eta(0.0);  // Σ w_q η_q, Σ w_q s_q η_q
  if constexpr (std::is_same_v<T, Dual2>) {
    LinearMasterProjection(xc, xh, nc, nh, o.y).sums(o.gauss, sum_w, sum_ws, sum_w_eta, sum_ws_eta);
  } else {
    for (const LinePoint& q : o.gauss) {
      // project_onto_master<double> without its copy of y (the same root).
      const std::optional<double> eta =
          scalar_root<double>(0.0, 3.0, MasterRay<double>(at(xc, xh, q.s), at(nc, nh, q.s), o.y), master_polish_steps(2));
      if (!eta) continue;
      sum_w += q.weight, sum_ws += q.weight * q.s;
      add_product(sum_w_eta, T(q.weight), *eta);
      add_product(sum_ws_eta, T(q.weight * q.s), *eta);
    }
  }
  if (sum_w == 0) return;
  std::array<T, 3> N, dN;
  segment_shapes(2, T(0.0), N, dN);
  const Vec2T<T> dx = interpolate(o.jacobian_of, dN);
  const T c = (o.thickness * half) * sqrt(dot(dx, dx));
  const T w0 = c * sum_w, w1 = c * (centre * sum_w + half * sum_ws);
  const T w_eta = c * sum_w_eta, w1_eta = c * (centre * sum_w_eta + half * sum_ws_eta);
  for (int k = 0; k < 2; ++k) {
    const T alpha = 0.5 * (o.A[k][0] + o.A[k][1]), beta = 0.5 * (o.A[k][1] - o.A[k][0]);
    const T S = alpha * w0 + beta * w1, E = alpha * w_eta + beta * w1_eta;
    D[k] += S;
    M[k][0] = 0.5 * (S - E);
    M[k][1] = 0.5 * (S + E);
  }
}

}  // namespace

template <class T>
void segment_shapes(int n_nodes, const T& xi, std::array<T, 3>& N, std::array<T, 3>& dN) {
  if constexpr (std::is_same_v<T, Dual2>) {
    if (n_nodes == 2) {  // 0.5 (1 ∓ ξ) written in one pass each (the same bits)
      const double v = xi.value();
      N[0].set_affine(xi, 0.5 * (1.0 - v), -0.5);
      N[1].set_affine(xi, 0.5 * (1.0 + v), 0.5);
      N[2] = T(0.0);
      dN[0] = T(-0.5), dN[1] = T(0.5), dN[2] = T(0.0);
      return;
    }
  }
  if (n_nodes == 2) {
    N = {0.5 * (1.0 - xi), 0.5 * (1.0 + xi), T(0.0)};
    dN = {T(-0.5), T(0.5), T(0.0)};
  } else {
    N = {0.5 * xi * (xi - 1.0), 0.5 * xi * (xi + 1.0), 1.0 - xi * xi};
    dN = {xi - 0.5, xi + 0.5, -2.0 * xi};
  }
}

template <class T>
Vec2T<T> segment_normal(std::span<const Vec2T<T>> x, const T& xi) {
  std::array<T, 3> N, dN;
  segment_shapes(static_cast<int>(x.size()), xi, N, dN);
  const Vec2T<T> t = interpolate(x, dN);
  const T length = sqrt(dot(t, t));
  return {t.y / length, -t.x / length};
}

template <class T>
Vec2T<T> nodal_normal(std::span<const std::vector<Vec2T<T>>> segments, std::span<const int> at) {
  Vec2T<T> sum{T(0.0), T(0.0)};
  for (std::size_t k = 0; k < segments.size(); ++k) {
    const T xi(at[k] == 0 ? -1.0 : at[k] == 1 ? 1.0 : 0.0);
    sum = sum + segment_normal<T>(segments[k], xi);
  }
  const T length = sqrt(dot(sum, sum));
  return {sum.x / length, sum.y / length};
}

template <class T>
std::optional<T> project_along_slave_normals(const Vec2T<T>& p, std::span<const Vec2T<T>> x,
                                             std::span<const Vec2T<T>> normals) {
  const Vec2T<double> pd = values(p);
  const std::vector<Vec2T<double>> xd = values(x), nd = values(normals);
  return solve_scalar<T>(slave_projection_start(pd, xd), 3.0, SlaveRay<double>(pd, xd, nd), SlaveRay<T>(p, x, normals));
}

template <class T>
std::optional<T> project_onto_master(const Vec2T<T>& p, const Vec2T<T>& d, std::span<const Vec2T<T>> y) {
  const Vec2T<double> pd = values(p), dd = values(d);
  const std::vector<Vec2T<double>> yd = values(y);
  return solve_scalar<T>(
      0.0, 3.0, MasterRay<double>(pd, dd, yd), MasterRay<T>(p, d, y), master_polish_steps(y.size()));
}

template <class T>
std::array<std::array<T, 3>, 3> dual_coefficients(std::span<const Vec2T<T>> x) {
  const int n = static_cast<int>(x.size());
  std::array<std::array<T, 3>, 3> me{}, a{};
  std::array<T, 3> de{};
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) me[k][l] = T(0.0), a[k][l] = T(0.0);
  for (int k = 0; k < 3; ++k) de[k] = T(0.0);
  for (const LinePoint& q : gauss_rule(kElementPoints)) {
    std::array<T, 3> N, dN;
    segment_shapes(n, T(q.s), N, dN);
    const Vec2T<T> dx = interpolate(x, dN);
    const T w = q.weight * sqrt(dot(dx, dx));
    for (int k = 0; k < n; ++k) {
      de[k] += w * N[k];
      for (int l = 0; l < n; ++l) me[k][l] += w * N[k] * N[l];
    }
  }
  // A = D_e M_e⁻¹, i.e. M_e Aᵀ = D_e (M_e symmetric positive definite):
  // Gaussian elimination without pivoting on [M_e | D_e].
  std::array<std::array<T, 3>, 3> rhs{};
  for (int k = 0; k < n; ++k)
    for (int l = 0; l < n; ++l) rhs[k][l] = k == l ? de[k] : T(0.0);
  for (int p = 0; p < n; ++p)
    for (int r = p + 1; r < n; ++r) {
      const T factor = me[r][p] / me[p][p];
      for (int c = p; c < n; ++c) me[r][c] -= factor * me[p][c];
      for (int c = 0; c < n; ++c) rhs[r][c] -= factor * rhs[p][c];
    }
  for (int r = n - 1; r >= 0; --r)
    for (int c = 0; c < n; ++c) {
      T s = rhs[r][c];
      for (int k = r + 1; k < n; ++k) s -= me[r][k] * a[c][k];
      a[c][r] = s / me[r][r];  // (Aᵀ)[r][c] = A[c][r]
    }
  return a;
}

template <class T>
SegmentMortar<T> integrate_segment(std::span<const Vec2T<T>> x, std::span<const Vec2T<T>> normals,
                                   std::span<const std::vector<Vec2T<T>>> masters, double thickness, int n_gauss,
                                   std::span<const Vec2T<double>> measure) {
  SegmentMortar<T> out;
  const int n = static_cast<int>(x.size());
  out.n_slave = n;
  for (auto& d : out.D) d = T(0.0);
  // assign() from a default-initialized block, not resize(): value-
  // initialization would zero the in-place storage of its 9 Dual2 (43 kB).
  std::array<std::array<T, 3>, 3> blank;
  for (auto& row : blank) row.fill(T(0.0));
  out.M.assign(masters.size(), blank);
  out.overlap.assign(masters.size(), {1.0, -1.0});
  std::vector<Vec2T<T>> measure_t;
  for (const Vec2T<double>& p : measure) measure_t.push_back({T(p.x), T(p.y)});
  const std::span<const Vec2T<T>> jacobian_of = measure.empty() ? x : std::span<const Vec2T<T>>(measure_t);
  // From reference positions the coefficients are numbers: computed in
  // double (Dual2 constants took the same operations, but for divisions by
  // a reciprocal: the same to round-off).
  const std::array<std::array<T, 3>, 3> A =
      measure.empty() ? dual_coefficients<T>(x) : constant_coefficients<T>(measure);
  const std::vector<LinePoint>& gauss = gauss_rule(n_gauss);
  const Vec2T<double> slave_dir = values(x[1]) - values(x[0]);
  for (std::size_t f = 0; f < masters.size(); ++f) {
    for (auto& row : out.M[f])
      for (auto& m : row) m = T(0.0);
    const std::span<const Vec2T<T>> y(masters[f]);
    if (!(dot(values(y[1]) - values(y[0]), slave_dir) < 0)) continue;  // not facing the slave
    const std::optional<std::array<T, 2>> range = overlap_of<T>(x, normals, y);
    if (!range) continue;
    out.overlap[f] = {value_of((*range)[0]), value_of((*range)[1])};
    const Overlap<T> o{x, normals, y, jacobian_of, A, thickness, gauss, (*range)[0], (*range)[1]};
    if (n == 2 && y.size() == 2)
      integrate_linear_overlap<T>(o, out.D, out.M[f]);
    else
      integrate_overlap<T>(o, out.D, out.M[f]);
  }
  return out;
}

#define TETHER_MORTAR_INSTANTIATE(T)                                                                               \
  template void segment_shapes<T>(int, const T&, std::array<T, 3>&, std::array<T, 3>&);                            \
  template Vec2T<T> segment_normal<T>(std::span<const Vec2T<T>>, const T&);                                        \
  template Vec2T<T> nodal_normal<T>(std::span<const std::vector<Vec2T<T>>>, std::span<const int>);                 \
  template std::optional<T> project_along_slave_normals<T>(const Vec2T<T>&, std::span<const Vec2T<T>>,              \
                                                           std::span<const Vec2T<T>>);                             \
  template std::optional<T> project_onto_master<T>(const Vec2T<T>&, const Vec2T<T>&, std::span<const Vec2T<T>>);  \
  template std::array<std::array<T, 3>, 3> dual_coefficients<T>(std::span<const Vec2T<T>>);                        \
  template SegmentMortar<T> integrate_segment<T>(std::span<const Vec2T<T>>, std::span<const Vec2T<T>>,             \
                                                 std::span<const std::vector<Vec2T<T>>>, double, int,             \
                                                 std::span<const Vec2T<double>>);

TETHER_MORTAR_INSTANTIATE(double)
TETHER_MORTAR_INSTANTIATE(Dual2)

}  // namespace tether
