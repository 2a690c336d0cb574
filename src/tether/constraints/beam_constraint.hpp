#pragma once
/// \file MPC BEAM: node a moves rigidly with reference node b, including
/// b's in-plane rotation (finite rotation).
///
/// f = (X_a + u_a) - (X_b + u_b) - R(theta_b) (X_a - X_b) = 0 (two equations),
/// with theta_b the rotation unknown of node b (ABAQUS dof 6). Gradients:
/// df/du_a = I, df/du_b = -I, df/dtheta = -R'(theta) d0; the only nonzero
/// second derivative is d2f/dtheta2 = R(theta) d0 (since R'' = -R).

#include <Eigen/Core>
#include <array>

#include "tether/constraints/constraint_function.hpp"

namespace tether {

class BeamConstraint final : public ConstraintFunction {
 public:
  /// `dofs` = {x_a, y_a, x_b, y_b, theta_b}; reference positions of a and b.
  BeamConstraint(std::array<int, 5> dofs, Eigen::Vector2d x_a, Eigen::Vector2d x_b, std::string description);

  [[nodiscard]] std::span<const int> dofs() const override { return dofs_; }
  [[nodiscard]] int n_equations() const override { return 2; }
  void evaluate(const ConstraintInput& in, ConstraintOutput& out, bool need_hessian) const override;
  [[nodiscard]] std::string describe() const override { return description_; }

 private:
  std::array<int, 5> dofs_;
  Eigen::Vector2d offset_;  ///< X_a - X_b
  std::string description_;
};

}  // namespace tether
