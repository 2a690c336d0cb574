#pragma once
/// \file Shape functions of the 2D reference elements and of their faces.
///
/// Reference elements (ABAQUS node order, corners counter-clockwise first,
/// then mid-side nodes starting on edge 1-2):
///  - triangles: xi, eta in the unit triangle, corners (0,0), (1,0), (0,1);
///  - quadrilaterals: xi, eta in [-1,1]^2, corners (-1,-1), (1,-1), (1,1), (-1,1).
/// Faces are parametrised by s in [-1,1]: first corner at s = -1, second at
/// s = +1, mid-side node (3-node faces) at s = 0, the same order as face_nodes().

#include <Eigen/Core>

#include <span>
#include <vector>

#include "tether/fem/quadrature.hpp"
#include "tether/model/element_type.hpp"

namespace tether {

/// Largest number of nodes of a 2D element tether supports.
inline constexpr int kMaxElementNodes = 8;

/// Shape function values N_a, one per node (no heap allocation).
using ShapeVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxElementNodes, 1>;
/// Shape function derivatives dN_a/dxi_j: row a = node, column j = xi or eta.
using ShapeGradient = Eigen::Matrix<double, Eigen::Dynamic, 2, 0, kMaxElementNodes, 2>;

/// Number of nodes of a shape: 3, 4, 6 or 8.
int n_nodes(Shape shape);

/// Evaluates N and dN/dxi of `shape` at reference coordinates `xi`.
/// Resizes N to n_nodes(shape) and dN to n_nodes(shape) x 2.
void shape_functions(Shape shape, const Eigen::Vector2d& xi, ShapeVector& N, ShapeGradient& dN);

/// Reference coordinates of local node `node` (0-based) of `shape`.
Eigen::Vector2d reference_node(Shape shape, int node);

/// Shape functions of a face with `n_face_nodes` (2 or 3) nodes at s in [-1,1]:
/// values N[0..n) and derivatives dN/ds. Entry 2 is zero for 2-node faces.
void face_shape_functions(int n_face_nodes, double s, Eigen::Vector3d& N, Eigen::Vector3d& dN);

/// N and dN/dxi of a shape at the points of a rule, with the weights: the
/// same for every element of the shape, so callers tabulate them once.
struct TabulatedShapes {
  std::vector<ShapeVector> N;
  std::vector<ShapeGradient> dN;
  std::vector<double> weight;
};

/// Evaluates `shape`'s functions at every point of `points`.
TabulatedShapes tabulate_shapes(Shape shape, std::span<const QuadraturePoint> points);

}  // namespace tether
