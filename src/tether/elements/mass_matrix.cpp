#include "tether/elements/mass_matrix.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "tether/core/error.hpp"
#include "tether/fem/shape_functions.hpp"

namespace tether {

namespace {

/// Shape functions at the points of one mass rule (computed once per shape).
const TabulatedShapes& mass_points(Shape shape, bool axisymmetric) {
  static const auto table = [] {
    std::array<std::array<TabulatedShapes, 2>, 4> t;
    for (Shape sh : {Shape::Tri3, Shape::Quad4, Shape::Tri6, Shape::Quad8})
      for (bool axi : {false, true})
        t[static_cast<std::size_t>(sh)][axi ? 1 : 0] = tabulate_shapes(sh, mass_rule(sh, axi));
    return t;
  }();
  return table[static_cast<std::size_t>(shape)][axisymmetric ? 1 : 0];
}

}  // namespace

int mass_degree(Shape shape, bool axisymmetric) {
  // N_a N_b, det J and R in the reference coordinates (see the header).
  const int r = axisymmetric ? 1 : 0;
  switch (shape) {
    case Shape::Tri3: return 2 + 0 + r;      // linear N, constant det J, linear R
    case Shape::Quad4: return 2 + 1 + r;     // bilinear N, det J and R of degree 1 per variable
    case Shape::Tri6: return 4 + 2 + 2 * r;  // quadratic N, det J and R
    case Shape::Quad8: return 4 + 3 + 2 * r; // N degree 2 per variable, det J 3, R 2
  }
  return 0;
}

std::vector<QuadraturePoint> mass_rule(Shape shape, bool axisymmetric) {
  return exact_rule(shape, mass_degree(shape, axisymmetric));
}

Eigen::MatrixXd consistent_mass(const ElementType& type, std::span<const Eigen::Vector2d> ref_coords,
                                double density, double thickness) {
  const int n = n_nodes(type.shape);
  const bool axisymmetric = type.family == Family::Axisymmetric;
  if (static_cast<int>(ref_coords.size()) != n)
    throw ModelError(fmt::format("mass: expected {} nodes, got {}", n, ref_coords.size()));
  if (!(density > 0)) throw ModelError(fmt::format("mass: density must be positive (got {:g})", density));
  if (!axisymmetric && !(thickness > 0))
    throw ModelError(fmt::format("mass: thickness must be positive (got {:g})", thickness));

  const TabulatedShapes& pts = mass_points(type.shape, axisymmetric);
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n, n);
  for (std::size_t q = 0; q < pts.weight.size(); ++q) {
    const ShapeVector& N = pts.N[q];
    const ShapeGradient& dN = pts.dN[q];
    Eigen::Matrix2d J = Eigen::Matrix2d::Zero();  // J(i,j) = dX_i/dxi_j
    Eigen::Vector2d X = Eigen::Vector2d::Zero();
    for (int a = 0; a < n; ++a) {
      J += ref_coords[a] * dN.row(a);
      X += N(a) * ref_coords[a];
    }
    const double detJ = J.determinant();
    if (!(detJ > 0))
      throw ModelError(fmt::format("Jacobian determinant {:.3g} <= 0 at mass integration point ({:.3g}, {:.3g}) "
                                   "(distorted element or clockwise node order)",
                                   detJ, X.x(), X.y()));
    if (axisymmetric && !(X.x() > 0))
      throw ModelError(fmt::format("mass integration point at r = {:.3g} <= 0", X.x()));
    const double measure = axisymmetric ? 2 * std::numbers::pi * X.x() : thickness;
    const double dm = density * pts.weight[q] * detJ * measure;
    M.noalias() += (dm * N) * N.transpose();
  }
  return M;
}

Eigen::VectorXd lumped_mass(const ElementType& type, std::span<const Eigen::Vector2d> ref_coords, double density,
                            double thickness) {
  const Eigen::MatrixXd M = consistent_mass(type, ref_coords, density, thickness);
  if (type.shape == Shape::Tri3 || type.shape == Shape::Quad4)
    return M.rowwise().sum();  // int rho N_a dV > 0: linear N_a >= 0 on the element
  // HRZ: M_aa = int rho N_a^2 dV > 0, scaled so the masses sum to the total.
  const Eigen::VectorXd diagonal = M.diagonal();
  return diagonal * (M.sum() / diagonal.sum());
}

Eigen::MatrixXd scalar_mass(MassKind kind, const ElementType& type, std::span<const Eigen::Vector2d> ref_coords,
                            double density, double thickness) {
  if (kind == MassKind::Consistent) return consistent_mass(type, ref_coords, density, thickness);
  return lumped_mass(type, ref_coords, density, thickness).asDiagonal();
}

void expand_to_components(const Eigen::MatrixXd& scalar, int n_components, Eigen::MatrixXd& out) {
  const Eigen::Index n = scalar.rows(), c = n_components;
  out.setZero(n * c, n * c);
  for (Eigen::Index a = 0; a < n; ++a)
    for (Eigen::Index b = 0; b < n; ++b)
      for (Eigen::Index i = 0; i < c; ++i) out(c * a + i, c * b + i) = scalar(a, b);
}

Eigen::MatrixXd redistribute_mass(const Eigen::MatrixXd& mass, int n_components, const Eigen::VectorXd& node_weights,
                                  const std::vector<bool>& massless, bool diagonal) {
  const auto n = static_cast<Eigen::Index>(massless.size()), c = static_cast<Eigen::Index>(n_components);
  double kept_weight = 0;
  for (Eigen::Index a = 0; a < n; ++a)
    if (!massless[static_cast<std::size_t>(a)]) kept_weight += node_weights[a];
  if (kept_weight == 0 || std::none_of(massless.begin(), massless.end(), [](bool f) { return f; })) return mass;
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(n * c, n * c);
  for (Eigen::Index a = 0; a < n; ++a)
    for (Eigen::Index i = 0; i < c; ++i) {
      if (!massless[static_cast<std::size_t>(a)]) {
        P(c * a + i, c * a + i) = 1;
        continue;
      }
      for (Eigen::Index b = 0; b < n; ++b)
        if (!massless[static_cast<std::size_t>(b)]) P(c * a + i, c * b + i) = node_weights[b] / kept_weight;
    }
  const Eigen::MatrixXd moved = P.transpose() * mass * P;
  if (!diagonal) return moved;
  return moved.rowwise().sum().asDiagonal();
}

}  // namespace tether
