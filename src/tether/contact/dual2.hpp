#pragma once
/// \file Second-order forward automatic differentiation: a scalar that carries
/// its value, gradient and Hessian with respect to n independent variables.
///
/// Used by the mortar contact kinematics, whose weighted gaps depend on the
/// slave normals, the projections and the segmentation in ways too long to
/// differentiate twice by hand: the same templated code runs on double (value
/// only) and on Dual2 (value, exact gradient and Hessian). A Dual2 with an
/// empty gradient is a constant. Cost of a product: O(n²).
///
/// The Hessian is symmetric: only its lower triangle is stored and computed
/// (n(n+1)/2 entries, packed column by column), and hessian() mirrors it,
/// so the Hessian handed out is symmetric bit for bit. A product's entry
/// (i >= j) is (H_a,ij b + a H_b,ij) + (g_a,i g_b,j + g_b,i g_a,j). This
/// is about half the work of the dense n × n arithmetic it replaced (whose
/// two triangles differed in the last bits: the results differ from it by
/// round-off).
///
/// Gradient and Hessian live inside the object (at most kDual2MaxVariables
/// variables, no heap allocation; a copy moves only the entries in use):
/// the mortar kinematics create millions of temporaries per Newton
/// iteration, and allocating each one took about half of their time.
///
/// A Hessian known to be zero (a variable, a constant times one, sums of
/// such: "flat") is neither stored, copied nor read: products with a flat
/// operand drop exactly the products that are zero (the sum without them
/// is the same, but for the sign of an entry that is zero either way).

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <stdexcept>
#include <string>

namespace tether {

/// Largest number of independent variables of a Dual2: a mortar term of a
/// 3-node slave face with both neighbours (7 slave nodes) and a 3-node master
/// face is 20; MortarPair refuses a slave surface whose terms would need more.
inline constexpr int kDual2MaxVariables = 24;

class Dual2 {
 public:
  /// Gradient storage: dynamic size up to kDual2MaxVariables, in place.
  using Gradient = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kDual2MaxVariables, 1>;
  /// The full Hessian, as hessian() returns it.
  using Hessian = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kDual2MaxVariables, kDual2MaxVariables>;

  /// A constant 0. User-provided, so that value-initialization (`T{}`,
  /// `std::vector<Dual2>(n)`, the members of MortarTerm) does not zero the
  /// whole in-place storage before the constructor runs: that memset was a
  /// tenth of the mortar kinematics' instructions.
  Dual2() noexcept {}  // NOLINT(modernize-use-equals-default): see above
  Dual2(double value) : v_(value) {}  // NOLINT: constants mix freely with variables
  /// Copies the Hessian's entries only when they are not known to be zero.
  Dual2(const Dual2& b) : v_(b.v_), g_(b.g_), flat_(b.flat_) { copy_hessian(b); }
  Dual2& operator=(const Dual2& b) {
    if (this == &b) return *this;
    v_ = b.v_, g_ = b.g_, flat_ = b.flat_;
    copy_hessian(b);
    return *this;
  }
  ~Dual2() = default;

  /// The independent variable `index` of `n` (n <= kDual2MaxVariables,
  /// else std::length_error), with the given value.
  /// `hessian` false: first derivatives only (every result of such
  /// variables has an empty Hessian; do not mix with second-order ones).
  static Dual2 variable(double value, int index, int n, bool hessian = true) {
    if (n > kDual2MaxVariables)
      throw std::length_error("Dual2: " + std::to_string(n) + " variables, at most " +
                              std::to_string(kDual2MaxVariables));
    Dual2 d(value);
    d.g_ = Gradient::Zero(n);
    d.g_[index] = 1;
    if (hessian) d.h_.resize(packed_size(n)), d.flat_ = true;  // zero: not stored
    return d;
  }

  [[nodiscard]] double value() const { return v_; }
  /// Gradient (empty for a constant).
  [[nodiscard]] const Gradient& gradient() const { return g_; }
  /// The full (symmetric) Hessian; empty for a constant or a first-order value.
  [[nodiscard]] Hessian hessian() const {
    if (!second()) return Hessian(0, 0);
    const Eigen::Index n = g_.size();
    Hessian h(n, n);
    if (flat_) return h.setZero();
    const double* p = h_.data();
    for (Eigen::Index j = 0; j < n; ++j)
      for (Eigen::Index i = j; i < n; ++i) h(i, j) = h(j, i) = *p++;
    return h;
  }
  [[nodiscard]] bool constant() const { return g_.size() == 0; }
  /// Carries a Hessian (second-order variables).
  [[nodiscard]] bool second() const { return h_.size() > 0; }

  /// f(this) given f, f' and f'' at the value (chain rule to second order).
  [[nodiscard]] Dual2 chain(double f, double df, double ddf) const {
    Dual2 r(f);
    if (constant()) return r;
    r.g_ = df * g_;
    if (!second()) return r;
    r.h_.resize(h_.size());
    const Eigen::Index n = g_.size();
    const double* g = g_.data();
    double* out = r.h_.data();
    if (flat_) {  // df H + (ddf g_i) g_j with H = 0
      for (Eigen::Index j = 0; j < n; ++j)
        for (Eigen::Index i = j; i < n; ++i) *out++ = (ddf * g[i]) * g[j];
    } else {
      const double* h = h_.data();
      for (Eigen::Index j = 0; j < n; ++j)
        for (Eigen::Index i = j; i < n; ++i) *out++ = df * *h++ + (ddf * g[i]) * g[j];
    }
    return r;
  }

  /// The root ξ(p) of F(ξ, p) = 0 with the derivatives the implicit
  /// function theorem gives: `f` = F and `df` = ∂F/∂ξ at the root as Dual2
  /// over p (ξ held fixed), `ddf` = ∂²F/∂ξ² there, `value` the root. With
  /// g = ∇ξ = -∇F / F_ξ:
  ///   ∇²ξ = -(∇²F + ∇F_ξ gᵀ + g ∇F_ξᵀ + F_ξξ g gᵀ) / F_ξ.
  /// Exact when F(value) = 0; F's value is not used. One pass over the
  /// Hessian, where Newton steps on Dual2 took two full steps (products of
  /// Dual2 ξ) to make it exact.
  [[nodiscard]] static Dual2 implicit_root(double value, const Dual2& f, const Dual2& df, double ddf) {
    Dual2 r(value);
    if (f.constant()) return r;  // F does not depend on p: neither does ξ
    const Eigen::Index n = f.g_.size();
    const double scale = -1 / df.v_;
    r.g_ = f.g_ * scale;
    if (!f.second()) return r;
    const bool with_df = !df.constant();
    r.h_.resize(packed_size(n));
    const double* g = r.g_.data();
    const double* dg = with_df ? df.g_.data() : nullptr;
    const double* fh = f.flat_ ? nullptr : f.h_.data();
    double* out = r.h_.data();
    for (Eigen::Index j = 0; j < n; ++j)
      for (Eigen::Index i = j; i < n; ++i, ++out) {
        double t = ddf * g[i] * g[j];
        if (with_df) t += dg[i] * g[j] + g[i] * dg[j];
        if (fh) t += *fh++;
        *out = scale * t;
      }
    return r;
  }

  /// A linear combination of the derivatives of p_1..p_K with symmetric
  /// outer products, in one pass over the Hessian:
  ///   value:    `value`,
  ///   gradient: Σ_k a_k ∇p_k, or `gradient` when given (the same sum
  ///             accumulated otherwise, e.g. point by point in the order of
  ///             the code it replaces, so that its bits are kept),
  ///   Hessian:  Σ_k a_k ∇²p_k + Σ_l (∇q_l w_lᵀ + w_l ∇q_lᵀ),  w_l = Σ_k b_lk ∇p_k.
  /// This is what a sum over many points of the implicit-function roots of
  /// equations linear in p reduces to (the weights a, b summed over the
  /// points in double): one pass where each point took several. Constant
  /// operands contribute nothing; the others must share one number of
  /// variables and one order (std::invalid_argument otherwise). The result
  /// is second order when they are.
  template <std::size_t K, std::size_t L>
  [[nodiscard]] static Dual2 combination(double value, const std::array<const Dual2*, K>& p,
                                         const std::array<double, K>& a, const std::array<const Dual2*, L>& q,
                                         const std::array<std::array<double, K>, L>& b,
                                         const Gradient* gradient = nullptr) {
    Dual2 r(value);
    const Dual2* first = nullptr;
    for (const Dual2* d : p)
      if (!d->constant()) {
        first = d;
        break;
      }
    if (!first) return r;
    const Eigen::Index n = first->g_.size();
    const bool second = first->second();
    const auto same = [&](const Dual2* d) { return d->constant() || (d->g_.size() == n && d->second() == second); };
    for (const Dual2* d : p)
      if (!same(d)) throw std::invalid_argument("Dual2::combination: operands over different variables");
    for (const Dual2* d : q)
      if (!same(d)) throw std::invalid_argument("Dual2::combination: operands over different variables");
    if (gradient) {
      if (gradient->size() != n) throw std::invalid_argument("Dual2::combination: gradient of another size");
      r.g_ = *gradient;
    } else {
      r.g_ = Gradient::Zero(n);
      for (std::size_t k = 0; k < K; ++k)
        if (!p[k]->constant()) r.g_ += a[k] * p[k]->g_;
    }
    if (!second) return r;
    std::array<Gradient, L> w;
    for (std::size_t l = 0; l < L; ++l) {
      w[l] = Gradient::Zero(n);
      for (std::size_t k = 0; k < K; ++k)
        if (!p[k]->constant()) w[l] += b[l][k] * p[k]->g_;
    }
    r.h_.resize(packed_size(n));
    r.h_.setZero();
    for (std::size_t l = 0; l < L; ++l) {
      if (q[l]->constant()) continue;
      const double* gq = q[l]->g_.data();
      const double* wl = w[l].data();
      double* out = r.h_.data();
      for (Eigen::Index j = 0; j < n; ++j)
        for (Eigen::Index i = j; i < n; ++i) *out++ += gq[i] * wl[j] + wl[i] * gq[j];
    }
    for (std::size_t k = 0; k < K; ++k)
      if (!p[k]->constant() && !p[k]->flat_) r.h_ += a[k] * p[k]->h_;
    r.flat_ = false;
    return r;
  }

  /// This Dual2 over more variables: its variable i becomes variable
  /// to[i] of n (to: distinct indices < n, one per variable; the others'
  /// derivatives are zero). A value computed over the few variables it
  /// depends on and then embedded with `to` increasing has the entries of
  /// the same computation over all n bit for bit (the same operations on the
  /// same numbers; only the zeros' signs may differ), at the cost of the
  /// few; in another order, the same to round-off (the chain rule's
  /// (f'' g_i) g_j then multiplies in the other order).
  [[nodiscard]] Dual2 embedded(std::span<const int> to, int n) const {
    Dual2 r(v_);
    if (constant()) return r;
    if (static_cast<Eigen::Index>(to.size()) != g_.size() || n > kDual2MaxVariables)
      throw std::invalid_argument("Dual2::embedded: " + std::to_string(to.size()) + " indices for " +
                                  std::to_string(g_.size()) + " variables, into " + std::to_string(n));
    r.g_ = Gradient::Zero(n);
    for (std::size_t i = 0; i < to.size(); ++i) r.g_[to[i]] = g_[static_cast<Eigen::Index>(i)];
    if (!second()) return r;
    r.h_.resize(packed_size(n));
    r.flat_ = flat_;
    if (flat_) return r;
    r.h_.setZero();
    const Eigen::Index m = g_.size();
    const double* p = h_.data();
    for (Eigen::Index j = 0; j < m; ++j)
      for (Eigen::Index i = j; i < m; ++i) {
        const Eigen::Index ti = to[static_cast<std::size_t>(i)], tj = to[static_cast<std::size_t>(j)];
        const Eigen::Index a = std::max(ti, tj), b = std::min(ti, tj);  // lower triangle: row a >= column b
        r.h_[b * n - b * (b - 1) / 2 + (a - b)] = *p++;
      }
    return r;
  }

  /// The value `value` with slope × this Dual2's derivatives, in one pass:
  /// the derivatives of c + slope x for any c, e.g. 0.5 (1 - x) with slope
  /// -0.5.
  [[nodiscard]] Dual2 affine(double value, double slope) const {
    Dual2 r;
    r.set_affine(*this, value, slope);
    return r;
  }
  /// *this = x.affine(value, slope), written in place (x is not *this).
  void set_affine(const Dual2& x, double value, double slope) {
    v_ = value;
    if (x.constant()) {
      g_.resize(0), h_.resize(0), flat_ = false;
      return;
    }
    g_ = x.g_ * slope;
    scale_hessian_of(x, slope);
  }

  Dual2& operator+=(const Dual2& b) {
    v_ += b.v_;
    if (b.constant()) return *this;
    if (constant()) {
      g_ = b.g_;
      flat_ = b.flat_;
      copy_hessian(b);
    } else {
      g_ += b.g_;
      if (second() && !b.flat_) {
        if (flat_)
          h_ = b.h_, flat_ = false;
        else
          h_ += b.h_;
      }
    }
    return *this;
  }
  Dual2& operator-=(const Dual2& b) {
    v_ -= b.v_;
    if (b.constant()) return *this;
    if (constant()) {
      g_ = -b.g_;
      scale_hessian_of(b, -1.0);
    } else {
      g_ -= b.g_;
      if (second() && !b.flat_) {
        if (flat_)
          h_ = -b.h_, flat_ = false;
        else
          h_ -= b.h_;
      }
    }
    return *this;
  }
  Dual2& operator*=(const Dual2& b) {
    if (b.constant()) {
      v_ *= b.v_;
      if (!constant()) {
        g_ *= b.v_;
        if (!flat_) h_ *= b.v_;
      }
      return *this;
    }
    if (constant()) {  // b a in one pass
      const double a = v_;
      v_ = b.v_ * a;
      g_ = b.g_ * a;
      scale_hessian_of(b, a);
      return *this;
    }
    if (second()) {
      product_hessian(*this, b, h_.data(), [](double& h, double t) { h = t; });
      flat_ = false;
    }
    g_ = v_ * b.g_ + b.v_ * g_;
    v_ *= b.v_;
    return *this;
  }
  Dual2& operator/=(const Dual2& b) { return *this *= b.inverse(); }

  /// *this += a b (`subtract`: *this -= a b) without a temporary: the same
  /// operations, in the same order, as `*this += a * b`, so the same bits.
  void add_product(const Dual2& a, const Dual2& b, bool subtract = false) {
    const Eigen::Index n = a.g_.size();
    const bool fused = a.second() && b.second() && b.g_.size() == n && (constant() || (second() && g_.size() == n));
    if (!fused) {
      if (subtract)
        *this -= a * b;
      else
        *this += a * b;
      return;
    }
    const double s = subtract ? -1.0 : 1.0;
    const bool fresh = constant();
    if (fresh) g_.resize(n), h_.resize(packed_size(n));
    v_ += s * (a.v_ * b.v_);
    for (Eigen::Index i = 0; i < n; ++i) {
      const double t = a.v_ * b.g_[i] + b.v_ * a.g_[i];
      g_[i] = fresh ? s * t : g_[i] + s * t;
    }
    // A zero Hessian (fresh or flat) takes s t (0 + s t: the same but for
    // the sign of a zero).
    if (fresh || flat_)
      product_hessian(a, b, h_.data(), [s](double& h, double t) { h = s * t; });
    else
      product_hessian(a, b, h_.data(), [s](double& h, double t) { h = h + s * t; });
    flat_ = false;
  }

  [[nodiscard]] Dual2 inverse() const { return chain(1 / v_, -1 / (v_ * v_), 2 / (v_ * v_ * v_)); }
  friend Dual2 operator-(const Dual2& a) {
    Dual2 r(-a.v_);
    if (a.constant()) return r;
    r.g_ = -a.g_;
    r.scale_hessian_of(a, -1.0);
    return r;
  }
  /// a ± b written into the result in one pass (no copy of a first; the
  /// same operations as `Dual2(a) += b`, so the same bits).
  friend Dual2 operator+(const Dual2& a, const Dual2& b) { return sum(a, b, false); }
  friend Dual2 operator-(const Dual2& a, const Dual2& b) { return sum(a, b, true); }
  /// a b, written into the result directly when both carry Hessians over the
  /// same variables (no copy of a first); the same operations in the same
  /// order as `Dual2(a) *= b`, so the same bits.
  friend Dual2 operator*(const Dual2& a, const Dual2& b) {
    const Eigen::Index n = a.g_.size();
    if (!(a.second() && b.second() && b.g_.size() == n)) {
      // A constant factor scales the other in one pass (no copy first).
      const bool scale_b = a.constant() && !b.constant(), scale_a = b.constant() && !a.constant();
      if (scale_a || scale_b) {
        const Dual2& d = scale_b ? b : a;
        const double s = scale_b ? a.v_ : b.v_;
        Dual2 r(d.v_ * s);
        r.g_ = d.g_ * s;
        r.scale_hessian_of(d, s);
        return r;
      }
      Dual2 r(a);
      return r *= b;
    }
    Dual2 r(a.v_ * b.v_);
    r.h_.resize(packed_size(n));
    product_hessian(a, b, r.h_.data(), [](double& h, double t) { h = t; });
    r.g_ = a.v_ * b.g_ + b.v_ * a.g_;
    return r;
  }
  friend Dual2 operator/(Dual2 a, const Dual2& b) { return a /= b; }
  friend bool operator<(const Dual2& a, const Dual2& b) { return a.v_ < b.v_; }
  friend bool operator>(const Dual2& a, const Dual2& b) { return a.v_ > b.v_; }
  friend bool operator<=(const Dual2& a, const Dual2& b) { return a.v_ <= b.v_; }
  friend bool operator>=(const Dual2& a, const Dual2& b) { return a.v_ >= b.v_; }

 private:
  /// Packed lower triangle: column j holds rows j..n-1.
  using Packed = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kDual2MaxVariables*(kDual2MaxVariables + 1) / 2, 1>;
  static Eigen::Index packed_size(Eigen::Index n) { return n * (n + 1) / 2; }

  /// put(h_ij, t_ij), i >= j, for t = (H_a b + a H_b) + (g_a,i g_b,j + g_b,i g_a,j)
  /// (both second order over the same n variables), into packed storage h
  /// (h may be a's). A flat Hessian is not read: its products are zeros,
  /// and the sum without them is the same (but for the sign of a zero).
  template <class Put>
  static void product_hessian(const Dual2& a, const Dual2& b, double* h, Put put) {
    if (!a.flat_ && !b.flat_)
      product_columns<false, false>(a, b, h, put);
    else if (!a.flat_)
      product_columns<false, true>(a, b, h, put);
    else if (!b.flat_)
      product_columns<true, false>(a, b, h, put);
    else
      product_columns<true, true>(a, b, h, put);
  }
  template <bool AFlat, bool BFlat, class Put>
  static void product_columns(const Dual2& a, const Dual2& b, double* h, Put put) {
    const Eigen::Index n = a.g_.size();
    const double av = a.v_, bv = b.v_;
    const double* ga = a.g_.data();
    const double* gb = b.g_.data();
    const double* ha = a.h_.data();
    const double* hb = b.h_.data();
    Eigen::Index p = 0;
    for (Eigen::Index j = 0; j < n; ++j) {
      const double ga_j = ga[j], gb_j = gb[j];
      for (Eigen::Index i = j; i < n; ++i, ++p) {
        const double outer = ga[i] * gb_j + gb[i] * ga_j;
        double t;
        if constexpr (!AFlat && !BFlat)
          t = (ha[p] * bv + av * hb[p]) + outer;
        else if constexpr (!AFlat)
          t = ha[p] * bv + outer;
        else if constexpr (!BFlat)
          t = av * hb[p] + outer;
        else
          t = outer;
        put(h[p], t);
      }
    }
  }

  /// The Hessian of b (its storage skipped when flat).
  void copy_hessian(const Dual2& b) {
    if (b.flat_)
      h_.resize(b.h_.size());
    else
      h_ = b.h_;
  }
  /// The Hessian of b times s (s = -1: exactly -H_b).
  void scale_hessian_of(const Dual2& b, double s) {
    flat_ = b.flat_;
    if (b.flat_)
      h_.resize(b.h_.size());
    else
      h_ = b.h_ * s;
  }

  static Dual2 sum(const Dual2& a, const Dual2& b, bool subtract) {
    const bool same = !a.constant() && !b.constant() && a.second() == b.second() && a.g_.size() == b.g_.size() &&
                      !a.flat_ && !b.flat_;
    if (!same) {
      Dual2 r(a);
      return subtract ? r -= b : r += b;
    }
    Dual2 r(subtract ? a.v_ - b.v_ : a.v_ + b.v_);
    if (subtract) {
      r.g_ = a.g_ - b.g_;
      if (a.second()) r.h_ = a.h_ - b.h_;
    } else {
      r.g_ = a.g_ + b.g_;
      if (a.second()) r.h_ = a.h_ + b.h_;
    }
    return r;
  }

  double v_ = 0;
  Gradient g_;
  /// The lower triangle of the Hessian, packed by columns (n(n+1)/2 for n
  /// the gradient's size) when second order. With flat_ the Hessian is zero
  /// and the stored entries are not set.
  Packed h_;
  bool flat_ = false;
};

inline Dual2 sqrt(const Dual2& a) {
  const double s = std::sqrt(a.value());
  return a.chain(s, 0.5 / s, -0.25 / (s * a.value()));
}

/// The value of a double or a Dual2 (for decisions: branches, clipping).
inline double value_of(double a) { return a; }
inline double value_of(const Dual2& a) { return a.value(); }

}  // namespace tether
