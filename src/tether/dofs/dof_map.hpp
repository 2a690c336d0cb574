#pragma once
/// \file Numbering of the global unknowns.
///
/// Displacement dofs come first (node i, component c -> 2*i + c), then blocks
/// of Lagrange multipliers in the order they were added. A block is reserved
/// once (for a constraint or a contact pair) and keeps its numbers for the whole
/// analysis, so the matrix is never renumbered when contact status changes.

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

  [[nodiscard]] int n_nodes() const { return static_cast<int>(node_labels_.size()); }
  [[nodiscard]] int n_displacement_dofs() const { return kDofsPerNode * n_nodes(); }
  [[nodiscard]] int n_multipliers() const { return n_dofs() - n_displacement_dofs(); }
  [[nodiscard]] int n_dofs() const { return n_displacement_dofs() + n_multiplier_total_; }

  /// True when `dof` is a multiplier.
  [[nodiscard]] bool is_multiplier(int dof) const { return dof >= n_displacement_dofs(); }

  /// Node index of a displacement dof.
  [[nodiscard]] int node_of(int dof) const { return dof / kDofsPerNode; }

  /// Human-readable name: "node 17 dof 2" (1-based dof as in ABAQUS) or
  /// "multiplier 3 of constraint LINK-1".
  [[nodiscard]] std::string describe(int dof) const;

 private:
  struct Block {
    int first;
    int count;
    std::string owner;
  };
  std::vector<int> node_labels_;
  std::vector<Block> blocks_;
  int n_multiplier_total_ = 0;
};

}  // namespace tether
