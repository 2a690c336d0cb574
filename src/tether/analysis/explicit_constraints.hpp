#pragma once
/// \file Constraints with Lagrange multipliers in explicit dynamics, by the
/// same forward-increment correction as contact.
///
/// Every constraint element (`*EQUATION`, `*MPC`, `*TIE`, `*CONSTRAINT`
/// expressions, user constraints) with exact multipliers gives, at the
/// predicted positions u~, its values f_j(u~) (the residual rows of its
/// multipliers) and gradients G_j = df_j/du (the coupling rows of its tangent).
/// Forces f_c = G^T mu acting at t_n move the predicted positions by
/// c M^-1 f_c (c = h_{n+1/2} (h_{n-1/2} + h_{n+1/2}) / 2), and
///     c G M^-1 G^T mu = -f(u~ + c M^-1 f_c)
/// is solved by Newton on mu (exact in one pass for linear constraints; a
/// few passes for nonlinear ones, to 1e-12 of the model's size). The forces of a
/// constraint whose f depends on differences of displacements sum to zero, so
/// they conserve linear momentum. The multiplier reported is lambda = -mu
/// (the sign of the static procedure: r_u = lambda df/du). See
/// docs/theory/explicit_dynamics.md.

#include <Eigen/Core>
#include <vector>

#include "tether/analysis/discretization.hpp"
#include "tether/assembly/contribution.hpp"

namespace tether {

class ExplicitConstraints {
 public:
  /// The constraint and user-constraint elements of `discretization` (must
  /// outlive this), checked at the state `u`. Throws ModelError naming the
  /// constraint for what the correction does not support: no multiplier
  /// (PENALTY), a regularised one (EPSILON > 0), rotation unknowns (*MPC BEAM).
  ExplicitConstraints(const Discretization& discretization, const Eigen::VectorXd& u);

  [[nodiscard]] bool empty() const { return constraints_.empty(); }

  /// Constraint forces (over all unknowns) that make the predicted
  /// displacements `u` (multiplier entries ignored) satisfy every
  /// constraint when the nodes move by c M^-1 force; writes the multipliers
  /// lambda into `multipliers_out` at the multiplier dofs. Throws ModelError
  /// when the constraints are redundant or do not converge.
  void correct(const Eigen::VectorXd& u, const Eigen::VectorXd& inverse_mass, double c, Eigen::VectorXd& force,
               Eigen::VectorXd& multipliers_out);

 private:
  /// Values f and gradients G (rows over global dofs) of every multiplier row at `u`.
  void linearize(const Eigen::VectorXd& u);

  const Discretization& discretization_;
  std::vector<const Contribution*> constraints_;
  std::vector<int> rows_;                 ///< the multiplier dof of each row
  Eigen::VectorXd values_;                ///< f per row
  std::vector<std::vector<std::pair<int, double>>> gradients_;  ///< per row: (displacement dof, df/du)
  Eigen::VectorXd scratch_;               ///< corrected positions
  double tolerance_ = 0;                  ///< |f| accepted [length-like]
};

}  // namespace tether
