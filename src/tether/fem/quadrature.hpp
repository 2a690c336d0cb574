#pragma once
/// \file Gauss integration rules of the 2D reference elements and of faces.
///
/// Point order follows ABAQUS: for quadrilaterals xi varies fastest, from
/// negative to positive, then eta; triangles use the 1-point centroid rule and
/// the 3-point rule with points at (1/6,1/6), (2/3,1/6), (1/6,2/3).
/// Weights integrate over the reference element: they sum to 1/2 on the
/// triangle, 4 on the square and 2 on the line [-1,1].

#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <vector>

#include "tether/model/element_type.hpp"

namespace tether {

/// Integration rules of the 2D reference elements.
enum class QuadratureRule : std::uint8_t {
  Triangle1,  ///< centroid, exact for degree 1
  Triangle3,  ///< interior 3-point rule, exact for degree 2
  Quad2x2,    ///< 2x2 Gauss, exact for degree 3 in each direction
  Quad3x3,    ///< 3x3 Gauss, exact for degree 5 in each direction
};

/// One integration point: reference coordinates and weight.
struct QuadraturePoint {
  Eigen::Vector2d xi;
  double weight;
};

/// One point of a rule on the line s in [-1,1].
struct LinePoint {
  double s;
  double weight;
};

/// Points of `rule`, in ABAQUS order.
std::span<const QuadraturePoint> quadrature_points(QuadratureRule rule);

/// Shape the rule integrates over.
Shape rule_shape(QuadratureRule rule);

/// Rule tether uses for an element type: CPE3/CPS3/CAX3 1 point, 4-node 2x2,
/// 6-node 3 points, 8-node 3x3 (full) or 2x2 (reduced, R suffix).
QuadratureRule default_rule(const ElementType& type);

/// Gauss-Legendre rule with `n_points` (2 or 3) on [-1,1].
std::span<const LinePoint> line_points(int n_points);

/// Gauss-Legendre rule with `n_points` (1 to 20) on [-1,1], points ascending,
/// computed by Newton's method on the Legendre polynomial (to about 1e-15).
/// Exact for polynomials of degree 2 n_points - 1.
std::vector<LinePoint> gauss_legendre(int n_points);

/// A rule on the reference element of `shape` (the triangle for Tri3/Tri6,
/// the square for Quad4/Quad8) that integrates every polynomial of degree
/// `degree` (0 to 37) exactly:
///  - square: degree in each variable separately (xi^d eta^d included);
///    tensor Gauss with ceil((degree+1)/2) points per direction, xi fastest;
///  - triangle: total degree; the collapsed ("Duffy") product of Gauss rules,
///    xi = u, eta = v (1 - u) with u, v in [0,1] and weight factor (1 - u):
///    a monomial of total degree d becomes degree d+1 in u (with the factor)
///    and d in v, so ceil((degree+2)/2) points in u and ceil((degree+1)/2) in v.
///    Points are interior but not symmetric under the triangle's rotations.
/// Meant for integrals evaluated once per element (e.g. mass), not hot loops.
std::vector<QuadraturePoint> exact_rule(Shape shape, int degree);

}  // namespace tether
