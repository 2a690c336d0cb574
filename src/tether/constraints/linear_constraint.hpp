#pragma once
/// \file Affine constraints sum_i c_i u_i = b: *EQUATION, MPC TIE/PIN, ties, periodic pairs.

#include "tether/constraints/constraint_function.hpp"

namespace tether {

/// One term c * u[dof].
struct LinearTerm {
  int dof = 0;
  double coefficient = 0;
};

class LinearConstraint final : public ConstraintFunction {
 public:
  /// One row per equation: sum of its terms = rhs[row] (rhs empty = all zero).
  /// Repeated dofs in a row are added together.
  LinearConstraint(std::vector<std::vector<LinearTerm>> rows, std::string description,
                   std::vector<double> rhs = {});

  [[nodiscard]] std::span<const int> dofs() const override { return dofs_; }
  [[nodiscard]] int n_equations() const override { return static_cast<int>(gradient_.rows()); }
  void evaluate(const ConstraintInput& in, ConstraintOutput& out, bool need_hessian) const override;
  [[nodiscard]] bool linear() const override { return true; }
  [[nodiscard]] std::string describe() const override { return description_; }

  /// The constant gradient (m x n) and right-hand side.
  [[nodiscard]] const Eigen::MatrixXd& gradient() const { return gradient_; }
  [[nodiscard]] const Eigen::VectorXd& rhs() const { return rhs_; }

 private:
  std::vector<int> dofs_;
  Eigen::MatrixXd gradient_;
  Eigen::VectorXd rhs_;
  std::string description_;
};

}  // namespace tether
