#pragma once
/// \file Mass of one 2D continuum element: pure functions of the element's
/// type, reference coordinates, density and thickness (no mesh, no dofs).
///
/// The mass is a scalar n x n matrix over the element's nodes, the same for
/// every displacement component; `expand_to_components` turns it into the
/// block matrix over the element's local dofs (u_1x, u_1y, u_2x, ...), with as
/// many components per node as the caller's dimension. It is integrated over
/// the *reference* configuration (total Lagrangian), so it is constant under
/// NLGEOM. Axisymmetric masses are totals over 2 pi radians (dV = 2 pi R dA),
/// as tether's forces. See docs/theory/elements.md, section "Mass".

#include <Eigen/Core>
#include <span>
#include <vector>

#include "tether/fem/quadrature.hpp"
#include "tether/model/element_type.hpp"

namespace tether {

/// How an element's mass is distributed over its nodes.
enum class MassKind {
  /// M_ab = integral of rho N_a N_b dV: symmetric positive definite, exact
  /// kinetic energy of every velocity field the element can represent.
  Consistent,
  /// Diagonal: the row sum of the consistent matrix for 3- and 4-node
  /// elements; HRZ (Hinton-Rock-Zienkiewicz: the consistent diagonal scaled
  /// to the element's mass) for 6- and 8-node elements, where the row sum
  /// gives zero (Tri6) or negative (Quad8) corner masses. Every nodal mass
  /// is > 0 for every element with det J > 0 (and R > 0 for CAX).
  Lumped,
};

/// Polynomial degree of rho N_a N_b det J (times R for axisymmetry) in the
/// reference coordinates, which is what the mass rule integrates exactly for
/// any isoparametric element, curved edges included (det J is a polynomial:
/// no inverse is needed). Triangles: total degree; quadrilaterals: degree in
/// each variable. Tri3 2 (CAX 3), Quad4 3 (4), Tri6 6 (8), Quad8 7 (9).
int mass_degree(Shape shape, bool axisymmetric);

/// Integration points of the mass: exact_rule(shape, mass_degree(...)):
/// Tri3 4 (CAX 6) points, Quad4 2x2 (3x3), Tri6 16 (25), Quad8 4x4 (5x5).
std::vector<QuadraturePoint> mass_rule(Shape shape, bool axisymmetric);

/// Consistent mass over the nodes [mass], n x n with n = n_nodes(type.shape):
/// M_ab = sum_q rho N_a N_b det J w_q * (thickness, or 2 pi R_q for CAX).
/// ref_coords: reference coordinates [length], ABAQUS node order; density
/// rho [mass/volume] > 0; thickness [length] > 0 for plane elements, ignored
/// for axisymmetric ones. Reduced (8R) types have the mass of the full ones.
/// Throws ModelError (without the element's name: the caller adds it) for a
/// wrong node count, a non-positive density or thickness, det J <= 0 or (CAX)
/// R <= 0 at a point of the mass rule.
Eigen::MatrixXd consistent_mass(const ElementType& type, std::span<const Eigen::Vector2d> ref_coords,
                                double density, double thickness);

/// Lumped nodal masses [mass], one per node (see MassKind::Lumped); they sum
/// to the element's mass sum_ab M_ab and are all > 0. Same arguments and
/// errors as consistent_mass().
Eigen::VectorXd lumped_mass(const ElementType& type, std::span<const Eigen::Vector2d> ref_coords,
                            double density, double thickness);

/// The n x n matrix of `kind` (lumped: diagonal).
Eigen::MatrixXd scalar_mass(MassKind kind, const ElementType& type, std::span<const Eigen::Vector2d> ref_coords,
                            double density, double thickness);

/// Block expansion of a scalar n x n mass into the (n c) x (n c) matrix over
/// local dofs ordered node by node, c = n_components (2 in 2D) components per
/// node: out(c a + i, c b + j) = delta_ij scalar(a, b).
void expand_to_components(const Eigen::MatrixXd& scalar, int n_components, Eigen::MatrixXd& out);

/// Mass redistribution away from contact surfaces (Khenous, Laborde & Renard
/// 2008), used by implicit dynamics with contact: the nodes flagged in
/// `massless` carry no mass afterwards. For the kinetic energy, a flagged
/// node moves with the weighted mean of the element's other nodes
/// (weights w_j = node_weights_j / their sum), i.e. M' = P^T M P with P the
/// identity on unflagged nodes and the row w on flagged ones (per component).
/// Keeps the element's total mass and the kinetic energy of every rigid
/// translation; moves its centre of mass towards the unflagged nodes.
/// `mass`: (n c) x (n c) over local dofs node by node (expand_to_components);
/// `n_components` c >= 1; `node_weights`: n values > 0 (the lumped nodal
/// masses); `diagonal`: keep a diagonal (lumped) matrix diagonal by taking
/// the row sums of P^T M P. Returns `mass` unchanged when no node or every
/// node is flagged.
Eigen::MatrixXd redistribute_mass(const Eigen::MatrixXd& mass, int n_components, const Eigen::VectorXd& node_weights,
                                  const std::vector<bool>& massless, bool diagonal);

}  // namespace tether
