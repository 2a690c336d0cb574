#pragma once
/// \file Pressure on an element face (`*DLOAD` Pn / `*DSLOAD` P).

#include <Eigen/Core>
#include <span>
#include <string>
#include <vector>

#include "tether/assembly/contribution.hpp"
#include "tether/dofs/dof_map.hpp"
#include "tether/model/element_type.hpp"

namespace tether {

/// Distributed pressure on one face (edge) of a 2D element. Positive pressure
/// pushes INTO the face: traction t = -p n with n the outward normal. The
/// residual is -f_ext on the face nodes. Under NLGEOM the load follows the
/// deformed face (follower load) and the tangent holds the load stiffness
/// -d f_ext/du (unsymmetric in general); otherwise the load acts on the
/// reference face and the tangent is zero. Plane elements multiply by the
/// thickness; axisymmetric ones by 2 pi r (totals over 2 pi, as in ABAQUS),
/// with the current radius under NLGEOM. Faces are integrated exactly (2
/// Gauss points on 2-node faces, 3 on 3-node faces).
class FacePressure final : public Contribution {
 public:
  /// element_label/type: of the loaded element (for messages and the family);
  /// element_node_indices/element_ref_coords: all of its nodes, ABAQUS order;
  /// face: 0-based (S1 = 0); thickness [length] for plane elements (ignored
  /// for axisymmetric ones). Throws ModelError when the face does not exist,
  /// the node count does not match, or the face has zero length.
  FacePressure(int element_label, const ElementType& type, std::vector<int> element_node_indices,
               std::vector<Eigen::Vector2d> element_ref_coords, int face, double thickness,
               const DofMap& dofs);

  /// Sets the current pressure magnitude p [force/area].
  void set_pressure(double p) { pressure_ = p; }
  [[nodiscard]] double pressure() const { return pressure_; }

  [[nodiscard]] std::span<const int> dofs() const override { return dofs_; }
  void evaluate(const EvaluationState& s, LocalSystem& out, bool need_tangent) const override;
  /// "pressure on element 12 (CPE4) face S2".
  [[nodiscard]] std::string describe() const override;
  /// Under NLGEOM the load stiffness is unsymmetric in general; otherwise the tangent is zero.
  [[nodiscard]] bool symmetric_tangent(bool nlgeom) const override { return !nlgeom; }
  /// Without NLGEOM the load acts on the reference face: independent of u.
  [[nodiscard]] bool linear_in_u(bool nlgeom) const override { return !nlgeom; }

  /// Mesh node indices of the face: two corners, then the mid-side node if any.
  [[nodiscard]] const std::vector<int>& nodes() const { return nodes_; }

 private:
  int element_label_;
  ElementType type_;
  int face_;
  double thickness_;
  std::vector<int> nodes_;
  std::vector<int> dofs_;
  std::vector<Eigen::Vector2d> ref_coords_;  ///< of the face nodes
  double pressure_ = 0;
};

}  // namespace tether
