#include "tether/analysis/explicit_constraints.hpp"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <cmath>

#include "tether/constraints/constraint_element.hpp"
#include "tether/constraints/user_constraint_element.hpp"
#include "tether/core/error.hpp"

namespace tether {

namespace {

constexpr int kMaxPasses = 20;

}  // namespace

ExplicitConstraints::ExplicitConstraints(const Discretization& discretization, const Eigen::VectorXd& u)
    : discretization_(discretization) {
  for (const auto& c : discretization.constraints()) constraints_.push_back(c.get());
  for (const auto& c : discretization.user_constraints()) constraints_.push_back(c.get());
  const DofMap& dofs = discretization.dofs();
  const std::string refuse = "*DYNAMIC, EXPLICIT corrects constraints with exact Lagrange multipliers only: ";
  LocalSystem local;
  const EvaluationState s{u, u, 0, 0, 0, false};
  for (const Contribution* c : constraints_) {
    const auto d = c->dofs();
    bool any_multiplier = false;
    for (int dof : d) {
      if (dofs.is_rotation(dof)) throw ModelError(refuse + c->describe() + " has rotation unknowns (*MPC BEAM)");
      any_multiplier = any_multiplier || dofs.is_multiplier(dof);
    }
    if (!any_multiplier) throw ModelError(refuse + c->describe() + " is enforced without a multiplier (PENALTY or AUGMENTED)");
    local.reset(static_cast<Eigen::Index>(d.size()));
    c->evaluate(s, local, true);
    for (std::size_t i = 0; i < d.size(); ++i)
      if (dofs.is_multiplier(d[i]) && local.tangent(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(i)) != 0)
        throw ModelError(refuse + c->describe() + " is regularised (EPSILON > 0)");
  }
  tolerance_ = 1e-12 * discretization.length_scale();
}

void ExplicitConstraints::linearize(const Eigen::VectorXd& u) {
  const DofMap& dofs = discretization_.dofs();
  rows_.clear(), gradients_.clear();
  std::vector<double> values;
  LocalSystem local;
  const EvaluationState s{u, u, 0, 0, 0, false};
  for (const Contribution* c : constraints_) {
    const auto d = c->dofs();
    local.reset(static_cast<Eigen::Index>(d.size()));
    c->evaluate(s, local, true);
    for (std::size_t i = 0; i < d.size(); ++i) {
      if (!dofs.is_multiplier(d[i])) continue;
      rows_.push_back(d[i]);
      values.push_back(local.residual[static_cast<Eigen::Index>(i)]);
      auto& row = gradients_.emplace_back();
      for (std::size_t j = 0; j < d.size(); ++j) {
        const double g = local.tangent(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
        if (!dofs.is_multiplier(d[j]) && g != 0) row.emplace_back(d[j], g);
      }
    }
  }
  values_ = Eigen::Map<const Eigen::VectorXd>(values.data(), static_cast<Eigen::Index>(values.size()));
}

void ExplicitConstraints::correct(const Eigen::VectorXd& u, const Eigen::VectorXd& inverse_mass, double c,
                                  Eigen::VectorXd& force, Eigen::VectorXd& multipliers_out) {
  force.setZero(u.size());
  scratch_ = u;
  for (int dof = 0; dof < u.size(); ++dof)
    if (discretization_.dofs().is_multiplier(dof)) scratch_[dof] = 0;  // f - 0 * lambda: the constraint's value
  Eigen::VectorXd mu;
  for (int pass = 0; pass < kMaxPasses; ++pass) {
    linearize(scratch_);
    const auto m = static_cast<Eigen::Index>(rows_.size());
    if (mu.size() != m) mu = Eigen::VectorXd::Zero(m);
    if (values_.cwiseAbs().maxCoeff() <= tolerance_) break;
    if (pass + 1 == kMaxPasses)
      throw ModelError("*DYNAMIC, EXPLICIT: the constraint correction did not converge in " +
                       std::to_string(kMaxPasses) + " passes (largest violation " +
                       std::to_string(values_.cwiseAbs().maxCoeff()) + ")");
    std::vector<Eigen::Triplet<double>> entries;
    for (Eigen::Index r = 0; r < m; ++r) {
      bool moves = false;
      for (const auto& [dof, g] : gradients_[static_cast<std::size_t>(r)])
        if (inverse_mass[dof] > 0) entries.emplace_back(r, dof, g * std::sqrt(c * inverse_mass[dof])), moves = true;
      if (moves) continue;
      if (std::abs(values_[r]) > tolerance_)
        throw ModelError("*DYNAMIC, EXPLICIT: a constraint on held dofs only is violated by " +
                         std::to_string(values_[r]) + " (its multiplier is " +
                         discretization_.dofs().describe(rows_[static_cast<std::size_t>(r)]) + ")");
      entries.emplace_back(r, rows_[static_cast<std::size_t>(r)], 1.0);  // a row of its own: lambda = 0
      values_[r] = 0;
    }
    Eigen::SparseMatrix<double> scaled(m, u.size());
    scaled.setFromTriplets(entries.begin(), entries.end());
    const Eigen::SparseMatrix<double> system = scaled * scaled.transpose();
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(system);
    if (ldlt.info() != Eigen::Success || !(ldlt.vectorD().array() > 0).all())
      throw ModelError("*DYNAMIC, EXPLICIT: the constraints are redundant or act on held dofs only (their "
                       "correction matrix is singular)");
    const Eigen::VectorXd step = ldlt.solve(-values_);
    mu += step;
    for (Eigen::Index r = 0; r < m; ++r)
      for (const auto& [dof, g] : gradients_[static_cast<std::size_t>(r)]) {
        force[dof] += g * step[r];
        scratch_[dof] += c * inverse_mass[dof] * g * step[r];
      }
  }
  for (std::size_t r = 0; r < rows_.size(); ++r) multipliers_out[rows_[r]] = -mu[static_cast<Eigen::Index>(r)];
}

}  // namespace tether
