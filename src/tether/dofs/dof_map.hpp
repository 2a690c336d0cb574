#pragma once
/// \file Numbering of the global unknowns.
///
/// Displacement dofs come first (node i, component c -> 2*i + c), then blocks
/// of extra unknowns in the order they were added: Lagrange multipliers
/// (reserved once for a constraint or a contact pair, kept for the whole
/// analysis, so the matrix is never renumbered when contact status changes)
/// and in-plane rotations of reference nodes (ABAQUS dof 6, for *MPC BEAM).

#include <string>
#include <vector>

namespace tether {

/// Dimension of the displacement field per node (2D solids).
inline constexpr int kDofsPerNode = 2;

class DofMap {
 public:
  /// `node_labels[i]` is the user id of node i, used in describe().
  explicit DofMap(std::vector<int> node_labels);

  /// Global index of displacement component `component` (0 or 1) of node `node` (index).
  [[nodiscard]] int displacement(int node, int component) const { return kDofsPerNode * node + component; }

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
  [[nodiscard]] int n_displacement_dofs() const { return kDofsPerNode * n_nodes(); }
  [[nodiscard]] int n_multipliers() const { return n_multiplier_total_; }
  [[nodiscard]] int n_dofs() const { return n_displacement_dofs() + static_cast<int>(is_multiplier_.size()); }

  /// True when `dof` is a multiplier (not a displacement or a rotation).
  [[nodiscard]] bool is_multiplier(int dof) const {
    return dof >= n_displacement_dofs() && is_multiplier_[static_cast<std::size_t>(dof - n_displacement_dofs())];
  }

  /// Node index of a displacement dof.
  [[nodiscard]] int node_of(int dof) const { return dof / kDofsPerNode; }

  /// Human-readable name: "node 17 dof 2" (1-based dof as in ABAQUS; 6 for a
  /// rotation) or "multiplier 3 of constraint LINK-1".
  [[nodiscard]] std::string describe(int dof) const;

 private:
  struct Block {
    int first;
    int count;
    std::string owner;
  };
  std::vector<int> node_labels_;
  std::vector<Block> blocks_;
  std::vector<bool> is_multiplier_;  ///< per unknown after the displacements
  std::vector<std::pair<int, int>> rotations_;  ///< (node, dof)
  int n_multiplier_total_ = 0;
};

}  // namespace tether
