#include "tether/constraints/distance_constraint.hpp"

#include <stdexcept>

namespace tether {

DistanceConstraint::DistanceConstraint(std::array<int, 4> dofs, Eigen::Vector2d x_a, Eigen::Vector2d x_b,
                                       std::string description)
    : dofs_(dofs), x_a_(x_a), x_b_(x_b), length_((x_b - x_a).norm()), description_(std::move(description)) {
  if (!(length_ > 0)) throw std::invalid_argument(description_ + ": the two nodes coincide");
}

void DistanceConstraint::evaluate(const ConstraintInput& in, ConstraintOutput& out, bool need_hessian) const {
  const Eigen::Vector2d d = (x_b_ + in.u.segment<2>(2)) - (x_a_ + in.u.segment<2>(0));
  const double len = d.norm();
  out.f[0] = len - length_;
  if (len == 0) return;  // gradient undefined: leave zero, diagnosed as a vanishing gradient
  const Eigen::Vector2d n = d / len;
  out.gradient.block<1, 2>(0, 0) = -n.transpose();
  out.gradient.block<1, 2>(0, 2) = n.transpose();
  if (!need_hessian) return;
  const Eigen::Matrix2d a = (Eigen::Matrix2d::Identity() - n * n.transpose()) / len;
  Eigen::MatrixXd& h = out.hessian[0];
  h.block<2, 2>(0, 0) = a;
  h.block<2, 2>(2, 2) = a;
  h.block<2, 2>(0, 2) = -a;
  h.block<2, 2>(2, 0) = -a;
}

SliderConstraint::SliderConstraint(std::array<int, 6> dofs, Eigen::Vector2d x_a, Eigen::Vector2d x_b,
                                   Eigen::Vector2d x_c, std::string description)
    : dofs_(dofs), x_{x_a, x_b, x_c}, scale_((x_c - x_b).norm()), description_(std::move(description)) {
  if (!(scale_ > 0)) throw std::invalid_argument(description_ + ": nodes b and c coincide");
}

void SliderConstraint::evaluate(const ConstraintInput& in, ConstraintOutput& out, bool need_hessian) const {
  const Eigen::Vector2d a = x_[0] + in.u.segment<2>(0);
  const Eigen::Vector2d b = x_[1] + in.u.segment<2>(2);
  const Eigen::Vector2d c = x_[2] + in.u.segment<2>(4);
  const Eigen::Vector2d p = a - b, q = c - b;
  // f = (p_x q_y - p_y q_x) / s
  out.f[0] = (p.x() * q.y() - p.y() * q.x()) / scale_;
  // df/dp = ( q_y, -q_x)/s, df/dq = (-p_y, p_x)/s; a -> p, b -> -(p + q), c -> q
  const Eigen::Vector2d dp(q.y() / scale_, -q.x() / scale_), dq(-p.y() / scale_, p.x() / scale_);
  out.gradient.block<1, 2>(0, 0) = dp.transpose();
  out.gradient.block<1, 2>(0, 2) = (-dp - dq).transpose();
  out.gradient.block<1, 2>(0, 4) = dq.transpose();
  if (!need_hessian) return;
  // d2f/dp dq = J / s with J = [[0, 1], [-1, 0]] (row p, column q); d2f/dp2 = d2f/dq2 = 0.
  Eigen::Matrix2d j;
  j << 0, 1, -1, 0;
  j /= scale_;
  // Node maps: a = +p, b = -p - q, c = +q. H_ij = sum over (p,q) blocks.
  const double ca[3] = {1, -1, 0};  // dp/dx_node
  const double cq[3] = {0, -1, 1};  // dq/dx_node
  Eigen::MatrixXd& h = out.hessian[0];
  for (int r = 0; r < 3; ++r)
    for (int s = 0; s < 3; ++s)
      h.block<2, 2>(2 * r, 2 * s) = ca[r] * cq[s] * j + cq[r] * ca[s] * j.transpose();
}

}  // namespace tether
