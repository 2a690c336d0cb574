#pragma once
/// \file One `*CONTACT PAIR, TYPE=SURFACE TO SURFACE` of 2D mortar contact:
/// the slave and master faces, the master segments each slave face currently
/// overlaps (its search), and one MortarNode contribution per slave node.
///
/// Like ContactPair, the pair is a Contribution without unknowns that runs
/// before its nodes: update_connectivity() recomputes, before every Newton
/// iteration, which master faces each slave face overlaps (projected along
/// the slave normal field) and hands the result to its nodes, whose dof lists
/// change accordingly. One normal multiplier per slave node (the dual nodal
/// contact pressure) is reserved once and never renumbered.
///
/// Scope: frictionless, HARD by exact multipliers; linear and quadratic
/// faces; finite sliding and finite strain. Theory: docs/theory/mortar.md.

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "tether/assembly/contribution.hpp"
#include "tether/model/results.hpp"

namespace tether {

class MortarNode;

/// A mortar pair resolved to node indices (built by the analysis from the model).
struct MortarPairSetup {
  std::string name;  ///< for messages and output
  /// Node indices of each slave face, face_nodes() order (counter-clockwise around its element).
  std::vector<std::vector<int>> slave_faces;
  /// Out-of-plane thickness of each slave face [length] (dA = t ds).
  std::vector<double> slave_thickness;
  /// Node indices of each master face, face_nodes() order.
  std::vector<std::vector<int>> master_faces;
  /// (element id, face number 1..4) of each master face, for output.
  std::vector<std::pair<int, int>> master_face_labels;
  /// Master faces farther than this from a slave face (bounding boxes,
  /// current positions) are not candidates for its segmentation [length], > 0.
  double search_radius = 0;
  /// c of min(λ, c g̃): a stiffness E t of the bodies [force/length]; each
  /// node's row uses c / A_j² with A_j its reference area, so that the
  /// decision compares a pressure with E × (a mean gap / a length). Decides
  /// the active set between iterations only; the converged answer does not
  /// depend on it.
  double complementarity_stiffness = 1;
};

/// Per slave node: dofs, current pairing, status.
struct MortarSlave {
  int node = 0;
  double area = 0;      ///< reference ∫ N_j dA over the slave faces [area]
  int multiplier = -1;  ///< global index of λ_j (the nodal contact pressure)
  /// Slave faces containing the node, with the node's position in each (0, 1: corners; 2: mid-side).
  std::vector<std::pair<int, int>> faces;
  /// Real nodes the weighted gap depends on: slave nodes (the faces', and
  /// their neighbours' for the averaged normals), then master nodes of the
  /// overlapped master faces. Node a owns dofs[2a], dofs[2a + 1].
  std::vector<int> nodes;
  int n_slave_nodes = 0;  ///< the first n_slave_nodes of `nodes` are slave nodes
  std::vector<int> dofs;  ///< displacement dofs of `nodes`, then λ_j
  bool closed = false;    ///< status at the last update_connectivity
};

/// Work of the last update_connectivity (for the iteration log).
struct MortarIterationStatistics {
  int closed = 0;          ///< slave nodes in contact
  int status_changes = 0;  ///< nodes that opened or closed since the previous iteration
  int repaired = 0;        ///< slave faces whose set of overlapped master faces changed
};

class MortarPair final : public Contribution {
 public:
  /// `reference`: reference coordinates of all nodes (must outlive the pair).
  /// `first_multiplier`: global index of the first of n slave nodes multipliers.
  MortarPair(MortarPairSetup setup, const std::vector<Eigen::Vector2d>& reference, int first_multiplier);
  ~MortarPair() override;

  /// The slave nodes of `faces` (sorted, unique).
  static std::vector<int> slave_nodes_of(const std::vector<std::vector<int>>& faces);

  [[nodiscard]] std::span<const int> dofs() const override { return {}; }
  void evaluate(const EvaluationState&, LocalSystem&, bool) const override {}
  bool update_connectivity(const EvaluationState& state) override;
  [[nodiscard]] std::string describe() const override { return setup_.name; }
  [[nodiscard]] bool symmetric_tangent(bool /*nlgeom*/) const override { return true; }
  [[nodiscard]] bool linear_in_u(bool /*nlgeom*/) const override { return false; }

  /// The per-slave-node contributions (to be assembled after the pair).
  [[nodiscard]] std::vector<Contribution*> nodes() const;

  [[nodiscard]] const MortarPairSetup& setup() const { return setup_; }
  [[nodiscard]] const std::vector<Eigen::Vector2d>& reference() const { return reference_; }
  [[nodiscard]] int n_slaves() const { return static_cast<int>(slaves_.size()); }
  [[nodiscard]] const MortarSlave& slave(int i) const { return slaves_[static_cast<std::size_t>(i)]; }
  /// Master faces slave face e overlaps at the last update_connectivity.
  [[nodiscard]] const std::vector<int>& overlapped(int e) const { return overlapped_[static_cast<std::size_t>(e)]; }
  /// Slave faces sharing a node with each slave face's nodes (for the normals), by slave node index.
  [[nodiscard]] const std::vector<std::vector<std::pair<int, int>>>& faces_of_node() const { return faces_of_node_; }

  /// Per-slave output at the state: status, mean gap g̃_j / D_j, pressure
  /// λ_j, normal force λ_j D_j, and the contact force on the node.
  [[nodiscard]] ContactPairValues values(const EvaluationState& state) const;
  [[nodiscard]] const MortarIterationStatistics& statistics() const { return statistics_; }

 private:
  /// Recomputes overlapped_ at displacements u; true when it changed.
  bool find_overlaps(const Eigen::VectorXd& u);
  void rebuild_dofs(MortarSlave& s);

  MortarPairSetup setup_;
  const std::vector<Eigen::Vector2d>& reference_;
  std::vector<MortarSlave> slaves_;
  std::vector<std::unique_ptr<MortarNode>> nodes_;
  /// By node index (size of reference): slave faces containing the node, with its position there.
  std::vector<std::vector<std::pair<int, int>>> faces_of_node_;
  std::vector<std::vector<int>> overlapped_;  ///< per slave face
  bool searched_once_ = false;
  MortarIterationStatistics statistics_;
};

}  // namespace tether
