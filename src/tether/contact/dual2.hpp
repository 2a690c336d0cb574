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
/// Gradient and Hessian live inside the object (at most kDual2MaxVariables
/// variables, no heap allocation; a copy moves only the n and n² entries in
/// use): the mortar kinematics create millions of temporaries per Newton
/// iteration, and allocating each one took about half of their time.

#include <Eigen/Core>
#include <cmath>
#include <stdexcept>
#include <string>

namespace tether {

/// Largest number of independent variables of a Dual2: a mortar term of a
/// 3-node slave face with both neighbours (7 slave nodes) and a 3-node master
/// face is 20; MortarPair refuses a slave surface whose terms would need more.
inline constexpr int kDual2MaxVariables = 24;

class Dual2 {
 public:
  /// Gradient and Hessian storage: dynamic size up to kDual2MaxVariables, in place.
  using Gradient = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kDual2MaxVariables, 1>;
  using Hessian = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kDual2MaxVariables, kDual2MaxVariables>;

  /// A constant 0. User-provided, so that value-initialization (`T{}`,
  /// `std::vector<Dual2>(n)`, the members of MortarTerm) does not zero the
  /// whole in-place storage (about 4.8 kB) before the constructor runs: that
  /// memset was a tenth of the mortar kinematics' instructions.
  Dual2() noexcept {}  // NOLINT(modernize-use-equals-default): see above
  Dual2(double value) : v_(value) {}  // NOLINT: constants mix freely with variables
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
    if (hessian) d.h_ = Hessian::Zero(n, n);
    return d;
  }

  [[nodiscard]] double value() const { return v_; }
  /// Gradient (empty for a constant).
  [[nodiscard]] const Gradient& gradient() const { return g_; }
  /// Hessian (empty for a constant or a first-order value).
  [[nodiscard]] const Hessian& hessian() const { return h_; }
  [[nodiscard]] bool constant() const { return g_.size() == 0; }

  /// f(this) given f, f' and f'' at the value (chain rule to second order).
  [[nodiscard]] Dual2 chain(double f, double df, double ddf) const {
    Dual2 r(f);
    if (constant()) return r;
    r.g_ = df * g_;
    if (second()) r.h_ = df * h_ + ddf * g_ * g_.transpose();
    return r;
  }

  Dual2& operator+=(const Dual2& b) {
    v_ += b.v_;
    if (b.constant()) return *this;
    if (constant()) {
      g_ = b.g_;
      h_ = b.h_;
    } else {
      g_ += b.g_;
      if (second()) h_ += b.h_;
    }
    return *this;
  }
  Dual2& operator-=(const Dual2& b) {
    v_ -= b.v_;
    if (b.constant()) return *this;
    if (constant()) {
      g_ = -b.g_;
      h_ = -b.h_;
    } else {
      g_ -= b.g_;
      if (second()) h_ -= b.h_;
    }
    return *this;
  }
  Dual2& operator*=(const Dual2& b) {
    if (b.constant()) {
      v_ *= b.v_;
      if (!constant()) g_ *= b.v_, h_ *= b.v_;
      return *this;
    }
    if (constant()) {
      const double a = v_;
      *this = b;
      v_ *= a;
      g_ *= a;
      h_ *= a;
      return *this;
    }
    if (second()) {
      // h = h b + a H_b + g_a g_bᵀ + g_b g_aᵀ in one pass, the terms added
      // in that order (the same rounding as four separate passes).
      const Eigen::Index n = g_.size();
      for (Eigen::Index j = 0; j < n; ++j) {
        const double ga_j = g_[j], gb_j = b.g_[j];
        double* h = h_.col(j).data();
        const double* hb = b.h_.col(j).data();
        for (Eigen::Index i = 0; i < n; ++i) h[i] = ((h[i] * b.v_ + v_ * hb[i]) + g_[i] * gb_j) + b.g_[i] * ga_j;
      }
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
    if (fresh) g_.resize(n), h_.resize(n, n);
    v_ += s * (a.v_ * b.v_);
    for (Eigen::Index i = 0; i < n; ++i) {
      const double t = a.v_ * b.g_[i] + b.v_ * a.g_[i];
      g_[i] = fresh ? s * t : g_[i] + s * t;
    }
    for (Eigen::Index j = 0; j < n; ++j) {
      const double ga_j = a.g_[j], gb_j = b.g_[j];
      double* h = h_.col(j).data();
      const double* ha = a.h_.col(j).data();
      const double* hb = b.h_.col(j).data();
      for (Eigen::Index i = 0; i < n; ++i) {
        const double t = ((ha[i] * b.v_ + a.v_ * hb[i]) + a.g_[i] * gb_j) + b.g_[i] * ga_j;
        h[i] = fresh ? s * t : h[i] + s * t;
      }
    }
  }

  [[nodiscard]] Dual2 inverse() const { return chain(1 / v_, -1 / (v_ * v_), 2 / (v_ * v_ * v_)); }
  friend Dual2 operator-(Dual2 a) {
    a.v_ = -a.v_;
    if (!a.constant()) a.g_ = -a.g_, a.h_ = -a.h_;
    return a;
  }
  /// Carries a Hessian (second-order variables).
  [[nodiscard]] bool second() const { return h_.size() > 0; }
  friend Dual2 operator+(Dual2 a, const Dual2& b) { return a += b; }
  friend Dual2 operator-(Dual2 a, const Dual2& b) { return a -= b; }
  /// a b, written into the result directly when both carry Hessians over the
  /// same variables (no copy of a first); the same operations in the same
  /// order as `Dual2(a) *= b`, so the same bits.
  friend Dual2 operator*(const Dual2& a, const Dual2& b) {
    const Eigen::Index n = a.g_.size();
    if (!(a.second() && b.second() && b.g_.size() == n)) {
      Dual2 r(a);
      return r *= b;
    }
    Dual2 r(a.v_ * b.v_);
    r.h_.resize(n, n);
    for (Eigen::Index j = 0; j < n; ++j) {
      const double ga_j = a.g_[j], gb_j = b.g_[j];
      double* h = r.h_.col(j).data();
      const double* ha = a.h_.col(j).data();
      const double* hb = b.h_.col(j).data();
      for (Eigen::Index i = 0; i < n; ++i) h[i] = ((ha[i] * b.v_ + a.v_ * hb[i]) + a.g_[i] * gb_j) + b.g_[i] * ga_j;
    }
    r.g_ = a.v_ * b.g_ + b.v_ * a.g_;
    return r;
  }
  friend Dual2 operator/(Dual2 a, const Dual2& b) { return a /= b; }
  friend bool operator<(const Dual2& a, const Dual2& b) { return a.v_ < b.v_; }
  friend bool operator>(const Dual2& a, const Dual2& b) { return a.v_ > b.v_; }
  friend bool operator<=(const Dual2& a, const Dual2& b) { return a.v_ <= b.v_; }
  friend bool operator>=(const Dual2& a, const Dual2& b) { return a.v_ >= b.v_; }

 private:
  double v_ = 0;
  Gradient g_;
  Hessian h_;
};

inline Dual2 sqrt(const Dual2& a) {
  const double s = std::sqrt(a.value());
  return a.chain(s, 0.5 / s, -0.25 / (s * a.value()));
}

/// The value of a double or a Dual2 (for decisions: branches, clipping).
inline double value_of(double a) { return a; }
inline double value_of(const Dual2& a) { return a.value(); }

}  // namespace tether
