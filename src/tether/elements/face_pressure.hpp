#pragma once
/// \file Pressure on an element face (`*DLOAD` Pn / `*DSLOAD` P).

#include <Eigen/Core>
#include <span>
#include <string>
#include <vector>

#include "tether/assembly/contribution.hpp"
#include "tether/elements/continuum_element.hpp"
#include "tether/dofs/dof_map.hpp"
#include "tether/materials/constitutive_model.hpp"
#include "tether/model/element_type.hpp"

namespace tether {

/// Distributed pressure on one face (edge) of a 2D element. Positive pressure
/// pushes INTO the face: traction t = -p n with n the outward normal. The
/// residual is -f_ext on the face nodes. Under NLGEOM the load follows the
/// deformed face (follower load) and the tangent holds the load stiffness
/// -d f_ext/du (unsymmetric in general); otherwise the load acts on the
/// reference face and the tangent is zero. Plane elements multiply by the
/// thickness; axisymmetric ones by 2 pi r (totals over 2 pi, as in ABAQUS).
/// Under NLGEOM both are current: the radius of the deformed face, and for
/// plane stress the thickness h0 F33, F33 the element's thickness stretch at
/// the face point (from its material with S_33 = 0), so that the load acts on
/// the current area as on a 3D face; a plane-stress load then depends on all
/// the element's nodes. An elastic material's F33 is solved at the face point
/// from the in-plane deformation; any other material's (plastic: F33 follows
/// the history; thermal: the temperature) is the element's, interpolated from
/// its integration points (ContinuumElement::thickness_stretch; set_element()). Plane strain keeps its thickness. Faces are integrated
/// exactly in the reference length (2 Gauss points on 2-node faces, 3 on
/// 3-node faces).
class FacePressure final : public Contribution {
 public:
  /// element_label/type: of the loaded element (for messages and the family);
  /// element_node_indices/element_ref_coords: all of its nodes, ABAQUS order;
  /// face: 0-based (S1 = 0); thickness [length] for plane elements (ignored
  /// for axisymmetric ones); material: the element's (used for the thickness
  /// of plane-stress faces under NLGEOM; must outlive the load). Throws
  /// ModelError when the face does not exist, the node count does not match,
  /// or the face has zero length. `element_name`: the element as the user
  /// knows it (label_text(): `PLATE-1.12`), for messages; empty: its label.
  FacePressure(int element_label, const ElementType& type, std::vector<int> element_node_indices,
               std::vector<Eigen::Vector2d> element_ref_coords, int face, double thickness,
               const ConstitutiveModel& material, const DofMap& dofs, std::string element_name = "");

  /// The loaded element (must outlive the load; same nodes as given to the
  /// constructor): plane-stress faces of a material that is not purely
  /// elastic take their thickness stretch from it under NLGEOM. Without it
  /// such a face throws ModelError when evaluated under NLGEOM.
  void set_element(const ContinuumElement& element);

  /// Sets the current pressure magnitude p [force/area].
  void set_pressure(double p) { pressure_ = p; }
  [[nodiscard]] double pressure() const { return pressure_; }

  /// The face nodes' dofs (x, y per node, in face order); for plane stress
  /// then those of the element's other nodes.
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
  /// Plane stress: appends the element's other nodes to dofs() and stores
  /// the element's shape gradients at the face Gauss points.
  void prepare_thickness_stretch(const std::vector<int>& element_nodes,
                                 const std::vector<Eigen::Vector2d>& element_coords, const DofMap& dofs);
  /// Plane stress under NLGEOM: the thickness stretch F33 at face Gauss point
  /// `point` and its derivative over dofs() (into dF33_du, resized).
  [[nodiscard]] double thickness_stretch(const EvaluationState& s, std::size_t point, Eigen::VectorXd& dF33_du) const;

  std::string element_name_;  ///< for messages: the element_name given, else the label
  ElementType type_;
  int face_;
  double thickness_;
  std::vector<int> nodes_;
  std::vector<int> dofs_;
  std::vector<Eigen::Vector2d> ref_coords_;  ///< of the face nodes
  const ConstitutiveModel* material_;
  /// Plane stress: element shape gradients dN_a/dX at each face Gauss point
  /// (rows in the order of dofs(), node by node).
  std::vector<Eigen::MatrixX2d> element_gradients_;
  /// Plane stress: the face Gauss points in the element's reference coordinates.
  std::vector<Eigen::Vector2d> element_points_;
  /// Plane stress: element-local node of each dof pair of dofs().
  std::vector<int> element_order_;
  /// Plane stress with a material that is not an ElasticModel: the element (set_element()).
  const ContinuumElement* element_ = nullptr;
  std::vector<int> element_nodes_;  ///< plane stress: all of the element's nodes (checked by set_element())
  double pressure_ = 0;
};

}  // namespace tether
