#include "tether/constraints/external_constraint_function.hpp"

#include <stdexcept>

#include "tether/core/error.hpp"

namespace tether {

ExternalConstraintFunction::ExternalConstraintFunction(std::shared_ptr<const ExternalConstraint> function,
                                                       std::vector<int> dofs, Eigen::VectorXd reference,
                                                       std::string description)
    : function_(std::move(function)),
      dofs_(std::move(dofs)),
      reference_(std::move(reference)),
      description_(std::move(description)) {
  if (!function_) throw std::invalid_argument(description_ + ": no constraint function");
  if (reference_.size() != static_cast<Eigen::Index>(dofs_.size()))
    throw std::invalid_argument(description_ + ": " + std::to_string(dofs_.size()) + " dofs but " +
                                std::to_string(reference_.size()) + " reference coordinates");
  m_ = function_->n_equations();
  if (m_ <= 0) throw std::invalid_argument(description_ + ": the constraint has no equation");
}

void ExternalConstraintFunction::evaluate(const ConstraintInput& in, ConstraintOutput& out, bool need_hessian) const {
  function_->evaluate(in.u, reference_, in.step_time, in.total_time, out.f, out.gradient,
                      need_hessian ? &out.hessian : nullptr);
  bool finite = out.f.allFinite() && out.gradient.allFinite();
  for (const Eigen::MatrixXd& h : out.hessian) finite = finite && h.allFinite();
  if (!finite) throw ModelError(description_ + ": the constraint function returned a value that is not finite");
}

}  // namespace tether
