#pragma once
/// \file A constraint f(u) = 0 computed by the program that built the model
/// (the Python module: callables), held by the model like a deck's constraint.

#include <Eigen/Core>
#include <string>
#include <vector>

namespace tether {

/// f(u) = 0 over the x, y displacements of a list of nodes
/// (ConstraintData::nodes): u = (u_x, u_y) of the first node, then of the
/// second, ... (n = 2 * nodes). Enforced like any other constraint
/// (ConstraintData::enforcement: multipliers, penalty, augmented Lagrangian).
class ExternalConstraint {
 public:
  virtual ~ExternalConstraint() = default;

  /// Number of scalar equations m (> 0).
  [[nodiscard]] virtual int n_equations() const = 0;

  /// f (m), the gradient df/du (m x n) and, when `hessian` is given, the
  /// Hessians d2f_k/du2 (m matrices n x n) at the displacements `u` (n) of
  /// nodes whose reference coordinates are `reference` (n, same layout), at
  /// the given step and total time. The outputs arrive sized and zeroed.
  /// Throws what it likes; ModelError makes Newton cut the increment back.
  virtual void evaluate(const Eigen::VectorXd& u, const Eigen::VectorXd& reference, double step_time,
                        double total_time, Eigen::VectorXd& f, Eigen::MatrixXd& gradient,
                        std::vector<Eigen::MatrixXd>* hessian) const = 0;

  /// True when the Hessians are symmetric (exact second derivatives are).
  [[nodiscard]] virtual bool symmetric_hessian() const { return true; }
};

}  // namespace tether
