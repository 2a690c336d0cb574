#pragma once
/// \file The Lagrange-multiplier constraint element (and its penalty and
/// augmented-Lagrangian variants) as a Contribution.
///
/// For f(u) = 0 with m equations over n displacement dofs, G = df/du:
///
/// - Lagrange: unknowns [u (n), lambda (m)],
///     r = [G^T lambda ; f - eps lambda],
///     K = [[sum_k lambda_k H_k, G^T], [G, -eps I]];
/// - Penalty: unknowns u, r = rho G^T f, K = rho (G^T G + sum_k f_k H_k);
/// - Augmented: unknowns u, r = G^T (lambda_bar + rho f),
///     K = rho G^T G + sum_k (lambda_bar_k + rho f_k) H_k, and after Newton
///     converges lambda_bar += rho f until max |f| <= tolerance.
///
/// The multiplier lambda is the generalised force the constraint exerts: the
/// force on dof i is -lambda * df/du_i.

#include <memory>

#include "tether/assembly/contribution.hpp"
#include "tether/constraints/constraint_function.hpp"
#include "tether/constraints/enforcement.hpp"
#include "tether/model/results.hpp"

namespace tether {

class DofMap;

class ConstraintElement final : public Contribution {
 public:
  /// `first_multiplier` is the global index of the first of the function's m
  /// multipliers (reserved with DofMap::add_multipliers) for Lagrange; ignored
  /// otherwise. `nodes` are the node indices the constraint acts on (output).
  ConstraintElement(std::unique_ptr<ConstraintFunction> function, Enforcement enforcement, int first_multiplier,
                    std::string name, std::vector<int> nodes);

  [[nodiscard]] std::span<const int> dofs() const override { return dofs_; }
  void evaluate(const EvaluationState& state, LocalSystem& out, bool need_tangent) const override;
  Acceptance on_converged(const EvaluationState& state) override;
  [[nodiscard]] std::string describe() const override { return name_; }
  /// Symmetric when the function's Hessians are (every enforcement keeps the
  /// coupling blocks G and G^T, or rho G^T G, symmetric).
  [[nodiscard]] bool symmetric_tangent(bool /*nlgeom*/) const override { return function_->symmetric_hessian(); }
  /// Linear when the function is (a constant gradient: the tangent of every
  /// enforcement is then constant; an Uzawa update changes the residual only).
  [[nodiscard]] bool linear_in_u(bool /*nlgeom*/) const override { return function_->linear(); }
  /// Augmented: the Uzawa multipliers and the update count (nothing otherwise).
  void save_state(std::vector<double>& out) const override;
  void load_state(std::span<const double>& in) override;

  /// Multiplier (constraint force) values and f at the state, for output;
  /// `dofs` (the map the function's dofs were numbered by) names the node of
  /// each dof for the nodal forces.
  [[nodiscard]] MultiplierValues values(const EvaluationState& state, const DofMap& dofs) const;

  [[nodiscard]] const ConstraintFunction& function() const { return *function_; }
  [[nodiscard]] const Enforcement& enforcement() const { return enforcement_; }
  /// Uzawa updates done so far (Augmented).
  [[nodiscard]] int n_updates() const { return updates_; }
  /// Starts a new count of Uzawa updates (max_updates holds per increment).
  void commit(const EvaluationState& state) override;

 private:
  ConstraintInput gather(const EvaluationState& state) const;

  std::unique_ptr<ConstraintFunction> function_;
  Enforcement enforcement_;
  std::string name_;
  std::vector<int> nodes_;
  std::vector<int> dofs_;          ///< function dofs, then multipliers (Lagrange)
  int n_ = 0, m_ = 0;
  Eigen::VectorXd lambda_bar_;     ///< Augmented: current Uzawa multipliers
  int updates_ = 0;               ///< Uzawa updates over the analysis
  int updates_in_increment_ = 0;  ///< since the last converged increment (cut-back attempts included)
};

}  // namespace tether
