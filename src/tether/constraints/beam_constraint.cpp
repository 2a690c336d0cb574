#include "tether/constraints/beam_constraint.hpp"

#include <cmath>

namespace tether {

BeamConstraint::BeamConstraint(std::array<int, 5> dofs, Eigen::Vector2d x_a, Eigen::Vector2d x_b,
                               std::string description)
    : dofs_(dofs), offset_(x_a - x_b), description_(std::move(description)) {}

void BeamConstraint::evaluate(const ConstraintInput& in, ConstraintOutput& out, bool need_hessian) const {
  const double theta = in.u[4], c = std::cos(theta), s = std::sin(theta);
  Eigen::Matrix2d r, dr;
  r << c, -s, s, c;
  dr << -s, -c, c, -s;
  const Eigen::Vector2d rotated = r * offset_;
  out.f = offset_ + in.u.segment<2>(0) - in.u.segment<2>(2) - rotated;
  out.gradient.block<2, 2>(0, 0).setIdentity();
  out.gradient.block<2, 2>(0, 2) = -Eigen::Matrix2d::Identity();
  out.gradient.col(4) = -dr * offset_;
  if (!need_hessian) return;
  for (int k = 0; k < 2; ++k) out.hessian[static_cast<std::size_t>(k)](4, 4) = rotated[k];
}

}  // namespace tether
