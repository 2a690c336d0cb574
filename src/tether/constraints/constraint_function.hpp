#pragma once
/// \file A (vector) constraint f(u) = 0 over a list of displacement dofs.
///
/// A constraint function knows only its dofs, their current values and time;
/// how it is enforced (multipliers, penalty, augmented Lagrangian,
/// elimination) is ConstraintElement's business. Reference geometry a
/// function needs (a link's length, a tie's shape-function weights) is
/// captured when it is built.

#include <Eigen/Core>
#include <span>
#include <string>
#include <vector>

namespace tether {

/// What a constraint function reads.
struct ConstraintInput {
  Eigen::VectorXd u;        ///< total displacement at each of the function's dofs [length]
  Eigen::VectorXd u_start;  ///< the same at the start of the increment
  double step_time = 0;
  double total_time = 0;
};

/// What it returns: f (m), its gradient G = df/du (m x n) and, when asked,
/// the Hessians d2f_k/du2 (m matrices n x n).
struct ConstraintOutput {
  Eigen::VectorXd f;
  Eigen::MatrixXd gradient;
  std::vector<Eigen::MatrixXd> hessian;

  /// Sizes everything for m equations over n dofs and zeroes it.
  void reset(Eigen::Index m, Eigen::Index n, bool with_hessian) {
    f.setZero(m);
    gradient.setZero(m, n);
    hessian.assign(with_hessian ? static_cast<std::size_t>(m) : 0, Eigen::MatrixXd::Zero(n, n));
  }
};

class ConstraintFunction {
 public:
  virtual ~ConstraintFunction() = default;

  /// Global displacement dofs the function depends on, in local order (n).
  [[nodiscard]] virtual std::span<const int> dofs() const = 0;

  /// Number of scalar equations m (= number of multipliers).
  [[nodiscard]] virtual int n_equations() const = 0;

  /// f, G and (if `need_hessian`) the Hessians at `in`. `out` is already reset.
  virtual void evaluate(const ConstraintInput& in, ConstraintOutput& out, bool need_hessian) const = 0;

  /// True when f is affine in u with a constant gradient (elimination allowed).
  [[nodiscard]] virtual bool linear() const { return false; }

  /// True when the Hessians evaluate() returns may be taken as symmetric
  /// (exact second derivatives are), so that a constraint element built on
  /// the function has a symmetric tangent.
  [[nodiscard]] virtual bool symmetric_hessian() const { return true; }

  /// Short description for messages, e.g. "*MPC LINK 3-7".
  [[nodiscard]] virtual std::string describe() const = 0;
};

}  // namespace tether
