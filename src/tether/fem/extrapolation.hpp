#pragma once
/// \file Extrapolation of integration-point values to element nodes.
///
/// ABAQUS-like: the point values are fitted exactly by a polynomial in the
/// reference coordinates with as many terms as there are points (constant for
/// 1 point, linear for the 3-point triangle, bilinear for 2x2, biquadratic
/// Lagrange for 3x3); the polynomial is evaluated at the element's nodes.
/// Mid-side nodes of 6- and 8-node elements integrated with fewer points
/// therefore get the average of their corner values.

#include <Eigen/Core>

#include "tether/fem/quadrature.hpp"
#include "tether/model/element_type.hpp"

namespace tether {

/// Matrix E (n_nodes(shape) x number of points of `rule`) with
/// nodal value = E * point values. `rule` must integrate over the same
/// reference shape (triangle or quadrilateral) as `shape`. Thread-safe;
/// the matrices are built once.
const Eigen::MatrixXd& extrapolation_matrix(Shape shape, QuadratureRule rule);

}  // namespace tether
