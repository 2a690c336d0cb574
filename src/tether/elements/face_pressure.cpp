#include "tether/elements/face_pressure.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <fmt/format.h>
#include <numbers>

#include "tether/core/error.hpp"
#include "tether/elements/material_point.hpp"
#include "tether/fem/quadrature.hpp"
#include "tether/fem/shape_functions.hpp"

namespace tether {

FacePressure::FacePressure(int element_label, const ElementType& type,
                           std::vector<int> element_node_indices,
                           std::vector<Eigen::Vector2d> element_ref_coords, int face,
                           double thickness, const ConstitutiveModel& material, const DofMap& dofs,
                           std::string element_name)
    : element_name_(element_name.empty() ? std::to_string(element_label) : std::move(element_name)),
      type_(type),
      face_(face),
      thickness_(thickness),
      material_(&material) {
  if (face < 0 || face >= n_faces(type.shape))
    throw ModelError(fmt::format("element {} ({}) has no face S{}", element_name_, type.name, face + 1));
  const int nn = n_nodes(type.shape);
  if (static_cast<int>(element_node_indices.size()) != nn ||
      static_cast<int>(element_ref_coords.size()) != nn)
    throw ModelError(fmt::format("element {} ({}): expected {} nodes", element_name_, type.name, nn));
  const auto local = face_nodes(type.shape, face);
  const int nf = n_face_nodes(type.shape);
  for (int k = 0; k < nf; ++k) {
    nodes_.push_back(element_node_indices[local[k]]);
    ref_coords_.push_back(element_ref_coords[local[k]]);
    dofs_.push_back(dofs.displacement(nodes_.back(), 0));
    dofs_.push_back(dofs.displacement(nodes_.back(), 1));
  }
  if (!((ref_coords_[1] - ref_coords_[0]).norm() > 0))
    throw ModelError(describe() + ": the face has zero length");
  if (type.family != Family::Axisymmetric && !(thickness > 0))
    throw ModelError(fmt::format("{}: thickness must be positive (got {:g})", describe(), thickness));
  if (type.family == Family::PlaneStress) prepare_thickness_stretch(element_node_indices, element_ref_coords, dofs);
}

void FacePressure::prepare_thickness_stretch(const std::vector<int>& element_nodes,
                                             const std::vector<Eigen::Vector2d>& element_coords, const DofMap& dofs) {
  const auto local = face_nodes(type_.shape, face_);
  const int nf = n_face_nodes(type_.shape), nn = n_nodes(type_.shape);
  std::vector<int> order(local.begin(), local.begin() + nf);  // element-local node of each dof pair
  for (int a = 0; a < nn; ++a)
    if (std::find(order.begin(), order.end(), a) == order.end()) {
      order.push_back(a);
      dofs_.push_back(dofs.displacement(element_nodes[a], 0));
      dofs_.push_back(dofs.displacement(element_nodes[a], 1));
    }
  element_order_ = order;
  element_nodes_ = element_nodes;
  Eigen::Vector3d Nf, dNf;
  ShapeVector N;
  ShapeGradient dN;
  for (const LinePoint& lp : line_points(nf)) {
    face_shape_functions(nf, lp.s, Nf, dNf);
    Eigen::Vector2d xi = Eigen::Vector2d::Zero();  // the face point in the element's reference coordinates
    for (int k = 0; k < nf; ++k) xi += Nf(k) * reference_node(type_.shape, local[k]);
    element_points_.push_back(xi);
    shape_functions(type_.shape, xi, N, dN);
    Eigen::Matrix2d J = Eigen::Matrix2d::Zero();  // J(i, j) = dX_i / dxi_j
    for (int a = 0; a < nn; ++a) J += element_coords[a] * dN.row(a);
    if (!(J.determinant() > 0)) throw ModelError(describe() + ": the element is inverted at the face");
    const ShapeGradient dN_dX = dN * J.inverse();
    Eigen::MatrixX2d g(nn, 2);
    for (int k = 0; k < nn; ++k) g.row(k) = dN_dX.row(order[k]);
    element_gradients_.push_back(std::move(g));
  }
}

void FacePressure::set_element(const ContinuumElement& element) {
  if (!std::ranges::equal(element.nodes(), element_nodes_) && !element_nodes_.empty())
    throw ModelError(describe() + ": set_element() was given another element (" + element.describe() + ")");
  element_ = &element;
}

double FacePressure::thickness_stretch(const EvaluationState& s, std::size_t point, Eigen::VectorXd& dF33_du) const {
  if (element_ != nullptr && dynamic_cast<const ElasticModel*>(material_) == nullptr) {
    // The element's points, with their history and temperature; dofs() holds
    // the element's dofs in the order element_order_.
    Eigen::VectorXd local;
    const double F33 = element_->thickness_stretch(s, element_points_[point], local);
    dF33_du.resize(static_cast<Eigen::Index>(dofs_.size()));
    for (std::size_t k = 0; k < element_order_.size(); ++k)
      dF33_du.segment<2>(2 * static_cast<Eigen::Index>(k)) = local.segment<2>(2 * element_order_[k]);
    return F33;
  }
  const Eigen::MatrixX2d& g = element_gradients_[point];
  Eigen::Matrix2d H = Eigen::Matrix2d::Zero();  // H(i, j) = dU_i / dX_j
  for (Eigen::Index k = 0; k < g.rows(); ++k)
    H += Eigen::Vector2d(s.u(dofs_[2 * k]), s.u(dofs_[2 * k + 1])) * g.row(k);
  Eigen::Matrix2d dF33_dH;
  const double F33 = plane_stress_thickness_stretch(*material_, H, dF33_dH);
  dF33_du.resize(static_cast<Eigen::Index>(dofs_.size()));
  for (Eigen::Index k = 0; k < g.rows(); ++k) dF33_du.segment<2>(2 * k) = dF33_dH * g.row(k).transpose();
  return F33;
}

std::string FacePressure::describe() const {
  return fmt::format("pressure on element {} ({}) face S{}", element_name_, type_.name, face_ + 1);
}

void FacePressure::evaluate(const EvaluationState& s, LocalSystem& out, bool need_tangent) const {
  const int nf = static_cast<int>(nodes_.size());
  const bool axisymmetric = type_.family == Family::Axisymmetric;
  Eigen::Matrix<double, 2, 3> x = Eigen::Matrix<double, 2, 3>::Zero();
  for (int b = 0; b < nf; ++b) {
    x.col(b) = ref_coords_[b];
    if (s.nlgeom) x.col(b) += Eigen::Vector2d(s.u(dofs_[2 * b]), s.u(dofs_[2 * b + 1]));
  }
  const double p = pressure_;
  const bool current_thickness = s.nlgeom && !element_gradients_.empty();
  Eigen::Vector3d N, dN;
  Eigen::VectorXd dF33_du;
  const auto points = line_points(nf);
  for (std::size_t q = 0; q < points.size(); ++q) {
    const LinePoint& lp = points[q];
    face_shape_functions(nf, lp.s, N, dN);
    const Eigen::Vector2d xs = x * dN;                       // dx/ds
    const Eigen::Vector2d normal_ds(xs.y(), -xs.x());        // outward normal * |dx/ds|
    double measure = axisymmetric ? 2 * std::numbers::pi * x.row(0).dot(N) : thickness_;
    if (current_thickness) measure *= thickness_stretch(s, q, dF33_du);
    const double w = p * lp.weight;
    // residual = -f_ext = p * int N_a * n * measure ds
    for (int a = 0; a < nf; ++a) out.residual.segment<2>(2 * a) += (w * measure * N(a)) * normal_ds;
    if (!need_tangent || !s.nlgeom) continue;
    if (current_thickness)  // d(h0 F33)/du over all the element's dofs
      for (int a = 0; a < nf; ++a)
        out.tangent.middleRows<2>(2 * a) += (w * thickness_ * N(a)) * normal_ds * dF33_du.transpose();
    // d(normal_ds)/du_b: x-component of u_b changes xs.x -> normal_ds.y by -dN_b;
    // y-component changes xs.y -> normal_ds.x by +dN_b. d(measure)/du_bx = 2 pi N_b (CAX).
    for (int a = 0; a < nf; ++a)
      for (int b = 0; b < nf; ++b) {
        const double c = w * N(a);
        out.tangent(2 * a + 1, 2 * b) += -c * measure * dN(b);
        out.tangent(2 * a, 2 * b + 1) += c * measure * dN(b);
        if (axisymmetric) {
          const double dm = 2 * std::numbers::pi * N(b);
          out.tangent(2 * a, 2 * b) += c * dm * normal_ds.x();
          out.tangent(2 * a + 1, 2 * b) += c * dm * normal_ds.y();
        }
      }
  }
}

}  // namespace tether
