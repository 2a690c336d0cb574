#pragma once
/// \file Numbering of the global unknowns.
///
/// Displacement dofs come first (node i, component c -> 2*i + c), then blocks
/// of extra unknowns in the order they were added: Lagrange multipliers
/// (reserved once for a constraint or a contact pair, kept for the whole
/// analysis, so the matrix is never renumbered when contact status changes)
/// and in-plane rotations of reference nodes (ABAQUS dof 6, for *MPC BEAM).
///
/// DofMap is the one place that maps a global unknown to its (node,
/// component) and back: a rotation lies past the displacements, so no
/// `dof / 2` elsewhere gives its node.

#include <string>
#include <utility>
#include <vector>

#include "tether/model/part_instance.hpp"

namespace tether {

/// Dimension of the displacement field per node (2D solids).
inline constexpr int kDofsPerNode = 2;

/// Component number (0-based, as DofMap::component_of returns it) of the
/// in-plane rotation: ABAQUS dof 6, the rotation about z, minus 1.
inline constexpr int kRotationComponent = 5;

class DofMap {
 public:
  /// `node_labels[i]` is the user id of node i, used in describe();
  /// `instances` (an ABAQUS/CAE deck's) name it `INSTANCE.label` there.
  explicit DofMap(std::vector<int> node_labels, std::vector<PartInstance> instances = {});

  /// Global index of displacement component `component` (0: x, 1: y) of node
  /// index `node`. The displacement block comes first and has this layout in
  /// every map, so it needs no map object (contact pairs, which hold none,
  /// number their slave and master nodes with it too).
  [[nodiscard]] static constexpr int displacement(int node, int component) {
    return kDofsPerNode * node + component;
  }

  /// Reserves `count` multiplier unknowns owned by `owner` (for messages, e.g.
  /// "constraint LINK-1"). Returns the global index of the first one.
  int add_multipliers(int count, std::string owner);

  /// The in-plane rotation unknown of node `node` [rad], created on first use.
  int add_rotation(int node);
  /// The rotation unknown of `node`, or -1 when it has none.
  [[nodiscard]] int rotation(int node) const;

  [[nodiscard]] int n_nodes() const { return static_cast<int>(node_labels_.size()); }
  /// User label of node index `node`.
  [[nodiscard]] int label(int node) const { return node_labels_[static_cast<std::size_t>(node)]; }
  /// Node index `node` as the user knows it (label_text(): `UPPER-1.3` or `17`).
  [[nodiscard]] std::string node_name(int node) const { return label_text(instances_, label(node)); }
  [[nodiscard]] int n_displacement_dofs() const { return kDofsPerNode * n_nodes(); }
  [[nodiscard]] int n_multipliers() const { return n_multiplier_total_; }
  [[nodiscard]] int n_dofs() const { return n_displacement_dofs() + static_cast<int>(extra_node_.size()); }

  /// True when `dof` is a multiplier (not a displacement or a rotation).
  [[nodiscard]] bool is_multiplier(int dof) const {
    return dof >= n_displacement_dofs() && extra_node_[static_cast<std::size_t>(dof - n_displacement_dofs())] < 0;
  }
  /// True when `dof` is the in-plane rotation of a node (add_rotation).
  [[nodiscard]] bool is_rotation(int dof) const {
    return dof >= n_displacement_dofs() && dof < n_dofs() && !is_multiplier(dof);
  }

  /// Node index of a nodal unknown: a displacement dof or a rotation.
  /// std::invalid_argument for a multiplier or an index outside [0, n_dofs()).
  [[nodiscard]] int node_of(int dof) const {
    if (dof >= 0 && dof < n_displacement_dofs()) return dof / kDofsPerNode;
    return extra_node_of(dof, "node_of");
  }

  /// Component of a nodal unknown: 0 (x) or 1 (y) for a displacement,
  /// kRotationComponent (5, ABAQUS dof 6) for a rotation. Same errors as node_of().
  [[nodiscard]] int component_of(int dof) const {
    if (dof >= 0 && dof < n_displacement_dofs()) return dof % kDofsPerNode;
    static_cast<void>(extra_node_of(dof, "component_of"));  // throws unless a rotation
    return kRotationComponent;
  }

  /// Human-readable name: "node 17 dof 2" (1-based dof as in ABAQUS),
  /// "node 100 dof 6 (rotation)" or "multiplier 3 of constraint LINK-1".
  [[nodiscard]] std::string describe(int dof) const;

 private:
  /// Node of rotation `dof`; throws (naming `caller`) for anything else past the displacements.
  [[nodiscard]] int extra_node_of(int dof, const char* caller) const;

  struct Block {
    int first;
    int count;
    std::string owner;
  };
  std::vector<int> node_labels_;
  std::vector<PartInstance> instances_;
  std::vector<Block> blocks_;
  /// Per unknown after the displacements: the node index of a rotation, -1 for a multiplier.
  std::vector<int> extra_node_;
  std::vector<std::pair<int, int>> rotations_;  ///< (node, dof), for rotation(): searches the rotations only
  int n_multiplier_total_ = 0;
};

}  // namespace tether
