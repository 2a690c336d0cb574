#include "tether/elements/body_force.hpp"

#include <fmt/format.h>

#include "tether/core/error.hpp"
#include "tether/elements/mass_matrix.hpp"

namespace tether {

BodyForce::BodyForce(int element_label, const ElementType& type, const std::vector<int>& node_indices,
                     std::vector<Eigen::Vector2d> ref_coords, double density, double thickness, const BodyLoad& load,
                     const DofMap& dofs, std::string element_name)
    : element_name_(element_name.empty() ? std::to_string(element_label) : std::move(element_name)),
      type_(type),
      kind_(load.kind),
      ref_coords_(std::move(ref_coords)) {
  try {
    mass_ = consistent_mass(type, ref_coords_, density, thickness);
  } catch (const ModelError& e) {
    throw ModelError(describe() + ": " + e.what());
  }
  for (int n : node_indices) {
    dofs_.push_back(dofs.displacement(n, 0));
    dofs_.push_back(dofs.displacement(n, 1));
  }
  gravity_ = load.direction.head<2>();
  const Eigen::Matrix3d p = Eigen::Matrix3d::Identity() - load.direction * load.direction.transpose();
  projection_ = p.topLeftCorner<2, 2>();
  axis_point_ = load.point.head<2>();
}

Eigen::VectorXd BodyForce::nodal_forces(const Eigen::VectorXd& u, bool nlgeom) const {
  const auto n = static_cast<Eigen::Index>(ref_coords_.size());
  // The load per unit mass at the nodes, component by component.
  Eigen::MatrixX2d b(n, 2);
  for (Eigen::Index a = 0; a < n; ++a) {
    if (kind_ == BodyLoad::Kind::Gravity) {
      b.row(a) = magnitude_ * gravity_.transpose();
      continue;
    }
    Eigen::Vector2d x = ref_coords_[static_cast<std::size_t>(a)];
    if (nlgeom) x += Eigen::Vector2d(u[dofs_[2 * a]], u[dofs_[2 * a + 1]]);
    b.row(a) = magnitude_ * (projection_ * (x - axis_point_)).transpose();
  }
  const Eigen::MatrixX2d f = mass_ * b;  // f(a, i) = sum_b M_ab b_bi
  Eigen::VectorXd out(2 * n);
  for (Eigen::Index a = 0; a < n; ++a) out.segment<2>(2 * a) = f.row(a).transpose();
  return out;
}

void BodyForce::evaluate(const EvaluationState& s, LocalSystem& out, bool need_tangent) const {
  out.residual = -nodal_forces(s.u, s.nlgeom);
  if (!need_tangent || linear_in_u(s.nlgeom)) return;
  // d f_ai / d u_bj = magnitude M_ab P_ij.
  const auto n = mass_.rows();
  for (Eigen::Index a = 0; a < n; ++a)
    for (Eigen::Index c = 0; c < n; ++c)
      out.tangent.block<2, 2>(2 * a, 2 * c) -= magnitude_ * mass_(a, c) * projection_;
}

std::string BodyForce::describe() const {
  return fmt::format("{} on element {} ({})", kind_ == BodyLoad::Kind::Gravity ? "gravity" : "centrifugal load",
                     element_name_, type_.name);
}

}  // namespace tether
