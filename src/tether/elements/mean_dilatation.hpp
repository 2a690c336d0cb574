#pragma once
/// \file Kinematics of the mean-dilatation (Q1P0) hybrid elements CPE4H and CAX4H.
///
/// Pure functions of one integration point's reference geometry and the
/// element displacements. Under NLGEOM a point of the element sees
/// F_bar = (theta/J)^(1/3) F, theta = v/V the element's current over reference
/// volume; for small strain eps_bar = eps + (e_bar - tr eps)/3 * (1,1,1,0),
/// e_bar the element mean of tr eps (B-bar). Axisymmetric volumes carry the
/// 2 pi r weight and the hoop stretch F33 = r/R is inside J. The tangent that
/// uses these is derived in docs/theory/elements.md (mean dilatation).

#include <Eigen/Core>

#include "tether/fem/shape_functions.hpp"

namespace tether {

inline constexpr int kMaxElementDofs = 2 * kMaxElementNodes;
/// A vector over an element's displacement dofs (u_0x, u_0y, u_1x, ...), no heap.
using ElementVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxElementDofs, 1>;
/// A matrix over an element's displacement dofs, no heap.
using ElementMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxElementDofs, kMaxElementDofs>;

/// Reference geometry of one integration point as the kernels below need it.
struct PointShape {
  const ShapeVector& N;    ///< shape functions (n nodes)
  const ShapeGradient& G;  ///< dN/dX (n x 2)
  double R;                ///< radius of the point (used for axisymmetry only) [length]
  bool axisymmetric;
};

/// Volume change of one point under finite strain.
struct VolumePoint {
  Eigen::Matrix2d F = Eigen::Matrix2d::Identity();  ///< in-plane deformation gradient I + dU/dX
  double F33 = 1;      ///< hoop stretch 1 + U_r/R (axisymmetric), else 1
  double J = 1;        ///< det F * F33
  ElementVector dlnJ;  ///< d ln J / du over the element dofs
};

/// F, F33, J and d ln J/du of a point, from the element displacements ue
/// (2n values, node-major). Throws ModelError when J <= 0 (inverted point).
VolumePoint volume_point(const PointShape& p, const double* ue);

/// out += w * d^2 ln J / du^2 at the point (symmetric, 2n x 2n):
/// -(F^-T G_b)_i (F^-T G_a)_k for the (a i, b k) entry, and for axisymmetry
/// -N_a N_b / (R F33)^2 on the radial-radial entries.
void add_log_volume_hessian(const PointShape& p, const VolumePoint& v, double w, ElementMatrix& out);

/// Small strain: d(tr eps)/du of the point, (G_a,x, G_a,y) per node plus
/// N_a / R on the radial dof for axisymmetry.
ElementVector volumetric_row(const PointShape& p);

/// Rows (11, 22, 33, 2*12) of the Green-Lagrange strain variation at the
/// point for the deformation gradient (F, F33): dE = B du (F = I, F33 = 1:
/// the small-strain B).
Eigen::Matrix<double, 4, Eigen::Dynamic, 0, 4, kMaxElementDofs> strain_rows(const PointShape& p,
                                                                            const Eigen::Matrix2d& F, double F33);

/// out += S : d^2 E / du^2 for the stress S = (S11, S22, S33, S12) (already
/// times the point's volume): the geometric stiffness of the point.
void add_geometric_stiffness(const PointShape& p, const Eigen::Vector4d& S, ElementMatrix& out);

/// The scale alpha = (theta/J)^(1/3) with F_bar = alpha F, F33_bar = alpha F33.
double dilatation_scale(double theta, double J);

/// Small strain with the element mean e_bar [-] as volumetric part:
/// eps + (e_bar - (eps_11 + eps_22 + eps_33)) / 3 on the normal components.
Eigen::Matrix<double, 6, 1> mean_dilatation_strain(const Eigen::Matrix<double, 6, 1>& strain, double e_bar);

}  // namespace tether
