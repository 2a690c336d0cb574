#pragma once
/// \file Body force on one element: gravity and centrifugal loads (`*DLOAD`
/// GRAV, CENTRIF), as a load contribution.

#include <Eigen/Core>
#include <span>
#include <string>
#include <vector>

#include "tether/assembly/contribution.hpp"
#include "tether/dofs/dof_map.hpp"
#include "tether/model/body_load.hpp"
#include "tether/model/element_type.hpp"

namespace tether {

/// The nodal forces of a body force per unit mass b(x) on one element,
/// f_a = integral of rho N_a b dV, over the reference volume (mass is
/// conserved, so this is exact under NLGEOM too; totals over 2 pi for
/// axisymmetric elements, as tether's other forces). Both loads are affine in
/// the position, b(x) = magnitude * (g, or P (x - p) with P the projection
/// normal to the axis), and x is interpolated by the element's own shape
/// functions, so f = M b_nodes exactly, with M the consistent mass
/// (elements/mass_matrix.hpp) and b_nodes the load at the nodes. The
/// residual is -f. Gravity and small-strain centrifugal loads do not depend
/// on u; a centrifugal load under NLGEOM follows the current positions and
/// has the symmetric load stiffness -magnitude (M (x) P) ("spin softening").
/// The magnitude is set per increment (set_magnitude), so the same object
/// serves static and dynamic procedures. See docs/theory/body_loads.md.
class BodyForce final : public Contribution {
 public:
  /// element_label/type: for messages and the family; node_indices: mesh node
  /// indices, ABAQUS order; ref_coords: their reference coordinates [length];
  /// density [mass/volume] > 0; thickness [length] > 0 for plane elements
  /// (ignored for axisymmetric ones); load: its kind, direction or axis and
  /// point (its magnitude is ignored: see set_magnitude). Throws ModelError
  /// naming the element for a non-positive density or thickness, or an
  /// element whose mass cannot be integrated (det J <= 0, R <= 0).
  /// `element_name`: the element as the user knows it (label_text():
  /// `PLATE-1.12`), for messages; empty: its label.
  BodyForce(int element_label, const ElementType& type, const std::vector<int>& node_indices,
            std::vector<Eigen::Vector2d> ref_coords, double density, double thickness, const BodyLoad& load,
            const DofMap& dofs, std::string element_name = "");

  /// Sets the current magnitude: g [length/time^2] or omega^2 [1/time^2].
  void set_magnitude(double magnitude) { magnitude_ = magnitude; }
  [[nodiscard]] double magnitude() const { return magnitude_; }

  /// The element's displacement dofs (x, y per node, ABAQUS node order).
  [[nodiscard]] std::span<const int> dofs() const override { return dofs_; }
  void evaluate(const EvaluationState& s, LocalSystem& out, bool need_tangent) const override;
  /// "gravity on element 12 (CPE4)", "centrifugal load on element 12 (CAX4)".
  [[nodiscard]] std::string describe() const override;
  /// The load stiffness (CENTRIF under NLGEOM) is symmetric; otherwise it is zero.
  [[nodiscard]] bool symmetric_tangent(bool /*nlgeom*/) const override { return true; }
  /// Only a centrifugal load under NLGEOM depends on u.
  [[nodiscard]] bool linear_in_u(bool nlgeom) const override {
    return !(nlgeom && kind_ == BodyLoad::Kind::Centrifugal);
  }

  /// The nodal forces f [force] at displacements u (reference positions when
  /// !nlgeom), in the order of dofs(): the negated residual.
  [[nodiscard]] Eigen::VectorXd nodal_forces(const Eigen::VectorXd& u, bool nlgeom) const;

 private:
  std::string element_name_;  ///< for messages: the element_name given, else the label
  ElementType type_;
  BodyLoad::Kind kind_;
  std::vector<int> dofs_;
  std::vector<Eigen::Vector2d> ref_coords_;
  Eigen::MatrixXd mass_;       ///< consistent scalar mass over the nodes [mass]
  Eigen::Vector2d gravity_;    ///< in-plane unit gravity direction
  Eigen::Matrix2d projection_;  ///< in-plane part of I - a a^T (a the unit axis)
  Eigen::Vector2d axis_point_;  ///< in-plane coordinates of the axis point
  double magnitude_ = 0;
};

}  // namespace tether
