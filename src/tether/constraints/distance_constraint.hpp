#pragma once
/// \file MPC LINK: the distance between two nodes keeps its initial value.
///
/// f = |x_b - x_a| - L0 with x = X + u and L0 = |X_b - X_a|. Nonlinear: the
/// Hessian is [[A, -A], [-A, A]] with A = (I - n n^T) / |x_b - x_a|.

#include <Eigen/Core>
#include <array>

#include "tether/constraints/constraint_function.hpp"

namespace tether {

class DistanceConstraint final : public ConstraintFunction {
 public:
  /// `dofs` = {x_a, y_a, x_b, y_b} global dofs; X_a, X_b reference positions.
  /// Throws std::invalid_argument when the nodes coincide.
  DistanceConstraint(std::array<int, 4> dofs, Eigen::Vector2d x_a, Eigen::Vector2d x_b, std::string description);

  [[nodiscard]] std::span<const int> dofs() const override { return dofs_; }
  [[nodiscard]] int n_equations() const override { return 1; }
  void evaluate(const ConstraintInput& in, ConstraintOutput& out, bool need_hessian) const override;
  [[nodiscard]] std::string describe() const override { return description_; }

 private:
  std::array<int, 4> dofs_;
  Eigen::Vector2d x_a_, x_b_;
  double length_;
  std::string description_;
};

/// MPC SLIDER: node a stays on the straight line through nodes b and c.
///
/// f = ((x_a - x_b) x (x_c - x_b)) / |X_c - X_b| (the 2D cross product scaled
/// by the reference length, so f is a distance). Nonlinear (bilinear).
class SliderConstraint final : public ConstraintFunction {
 public:
  /// `dofs` = {x_a, y_a, x_b, y_b, x_c, y_c}; reference positions of a, b, c.
  SliderConstraint(std::array<int, 6> dofs, Eigen::Vector2d x_a, Eigen::Vector2d x_b, Eigen::Vector2d x_c,
                   std::string description);

  [[nodiscard]] std::span<const int> dofs() const override { return dofs_; }
  [[nodiscard]] int n_equations() const override { return 1; }
  void evaluate(const ConstraintInput& in, ConstraintOutput& out, bool need_hessian) const override;
  [[nodiscard]] std::string describe() const override { return description_; }

 private:
  std::array<int, 6> dofs_;
  std::array<Eigen::Vector2d, 3> x_;
  double scale_;
  std::string description_;
};

}  // namespace tether
