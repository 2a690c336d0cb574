#pragma once
/// \file An ExternalConstraint (model data: e.g. Python callables) as a
/// ConstraintFunction, so that ConstraintElement enforces it like the deck's
/// constraints.

#include <memory>

#include "tether/constraints/constraint_function.hpp"
#include "tether/model/external_constraint.hpp"

namespace tether {

class ExternalConstraintFunction final : public ConstraintFunction {
 public:
  /// `dofs`: the global x, y dofs of the constraint's nodes (x, y of the first
  /// node, ...); `reference`: their reference coordinates in the same layout.
  /// std::invalid_argument when `function` is null, the sizes differ or the
  /// function has no equation.
  ExternalConstraintFunction(std::shared_ptr<const ExternalConstraint> function, std::vector<int> dofs,
                             Eigen::VectorXd reference, std::string description);

  [[nodiscard]] std::span<const int> dofs() const override { return dofs_; }
  [[nodiscard]] int n_equations() const override { return m_; }
  /// Calls the function and checks what it returns: ModelError naming the
  /// constraint when a value is not finite (Newton cuts back); the function's
  /// own exceptions pass through.
  void evaluate(const ConstraintInput& in, ConstraintOutput& out, bool need_hessian) const override;
  [[nodiscard]] bool symmetric_hessian() const override { return function_->symmetric_hessian(); }
  [[nodiscard]] std::string describe() const override { return description_; }

 private:
  std::shared_ptr<const ExternalConstraint> function_;
  std::vector<int> dofs_;
  Eigen::VectorXd reference_;
  int m_ = 0;
  std::string description_;
};

}  // namespace tether
