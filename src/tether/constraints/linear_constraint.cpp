#include "tether/constraints/linear_constraint.hpp"

#include <algorithm>
#include <stdexcept>

namespace tether {

LinearConstraint::LinearConstraint(std::vector<std::vector<LinearTerm>> rows, std::string description,
                                   std::vector<double> rhs)
    : description_(std::move(description)) {
  for (const auto& row : rows)
    for (const auto& t : row) dofs_.push_back(t.dof);
  std::sort(dofs_.begin(), dofs_.end());
  dofs_.erase(std::unique(dofs_.begin(), dofs_.end()), dofs_.end());
  gradient_.setZero(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(dofs_.size()));
  for (std::size_t r = 0; r < rows.size(); ++r)
    for (const auto& t : rows[r]) {
      const auto col = std::lower_bound(dofs_.begin(), dofs_.end(), t.dof) - dofs_.begin();
      gradient_(static_cast<Eigen::Index>(r), col) += t.coefficient;
    }
  rhs_.setZero(gradient_.rows());
  if (!rhs.empty()) {
    if (rhs.size() != rows.size()) throw std::invalid_argument("LinearConstraint: rhs size differs from rows");
    rhs_ = Eigen::Map<const Eigen::VectorXd>(rhs.data(), static_cast<Eigen::Index>(rhs.size()));
  }
}

void LinearConstraint::evaluate(const ConstraintInput& in, ConstraintOutput& out, bool /*need_hessian*/) const {
  out.f = gradient_ * in.u - rhs_;
  out.gradient = gradient_;
}

}  // namespace tether
