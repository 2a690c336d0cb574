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
/// Scope: HARD by exact multipliers or a soft pressure-overclosure law,
/// frictionless or Coulomb friction with exact stick; linear and quadratic faces; finite sliding and finite
/// strain. Theory: docs/theory/mortar.md.

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "tether/assembly/contribution.hpp"
#include "tether/contact/mortar_terms.hpp"
#include "tether/model/contact_data.hpp"
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
  /// The user's name of each slave node (label_text(): `UPPER-1.3`, `17`),
  /// in the order of slave_nodes_of(slave_faces), for messages; empty:
  /// messages give the node index.
  std::vector<std::string> slave_names;
  /// Node indices of each master face, face_nodes() order.
  std::vector<std::vector<int>> master_faces;
  /// (element id, face number 1..4) of each master face, for output.
  std::vector<std::pair<int, int>> master_face_labels;
  /// Master faces farther than this from a slave face (bounding boxes,
  /// current positions) are not candidates for its segmentation [length], > 0.
  double search_radius = 0;
  /// Coulomb friction coefficient (0: frictionless); exact stick by a
  /// tangential multiplier per slave node.
  double mu = 0;
  /// Pressure-overclosure law: HARD (exact, by the multipliers) or a soft
  /// law p(h) of the mean overclosure h_j = -g̃_j / D_j (the multiplier then
  /// carries p(h_j); mortar_node.hpp). Its enforcement is not used.
  PressureOverclosure law;
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
  int tangent_multiplier = -1;  ///< global index of λt_j (tangential traction; friction only)
  double total_slip = 0;   ///< Σ |ũ_j / D_j| over the slipping increments [length]
  double dissipation = 0;  ///< Σ |λt_j ũ_j| over the slipping increments [force × length]
  /// Slave faces containing the node, with the node's position in each (0, 1: corners; 2: mid-side).
  std::vector<std::pair<int, int>> faces;
  /// Real nodes the weighted gap depends on: slave nodes (the faces', and
  /// their neighbours' for the averaged normals), then master nodes of the
  /// overlapped master faces (with friction also those overlapped at the
  /// last commit). Node a owns dofs[2a], dofs[2a + 1].
  std::vector<int> nodes;
  int n_slave_nodes = 0;  ///< the first n_slave_nodes of `nodes` are slave nodes
  std::vector<int> dofs;  ///< displacement dofs of `nodes`, then λ_j (and λt_j)
  bool closed = false;    ///< status at the last update_connectivity
  bool stick = false;     ///< with friction: sticking at the last update_connectivity
  int direction = 0;      ///< with friction: slip direction at the last update_connectivity (0: stick or open)
  int switches = 0;       ///< changes of the friction branch within the increment attempt
  /// Friction guard: held in stick until Newton converges, after
  /// kMaxFrictionSwitches changes of its branch in one attempt.
  bool held_stick = false;
};

/// Work of the last update_connectivity (for the iteration log).
struct MortarIterationStatistics {
  int closed = 0;          ///< slave nodes in contact
  int status_changes = 0;  ///< nodes that opened or closed since the previous iteration
  int repaired = 0;        ///< slave faces whose set of overlapped master faces changed
  int held = 0;            ///< nodes held in stick by the friction guard
};

class MortarPair final : public Contribution {
 public:
  /// `reference`: reference coordinates of all nodes (must outlive the pair).
  /// `first_multiplier`: global index of the first of multipliers_per_slave()
  /// × slave nodes multipliers (λ_j, then λt_j with friction, node by node).
  MortarPair(MortarPairSetup setup, const std::vector<Eigen::Vector2d>& reference, int first_multiplier);
  ~MortarPair() override;

  /// Multipliers per slave node: 1, 2 with friction.
  static int multipliers_per_slave(double mu) { return mu > 0 ? 2 : 1; }

  /// The slave nodes of `faces` (sorted, unique).
  static std::vector<int> slave_nodes_of(const std::vector<std::vector<int>>& faces);

  [[nodiscard]] std::span<const int> dofs() const override { return {}; }
  void evaluate(const EvaluationState&, LocalSystem&, bool) const override {}
  bool update_connectivity(const EvaluationState& state) override;
  [[nodiscard]] std::string describe() const override { return setup_.name; }
  /// Friction guard: a node held in stick must lie within the friction cone
  /// at convergence; otherwise it is released and Newton goes on.
  Acceptance on_converged(const EvaluationState& state) override;
  /// Commits the overlaps (friction: the slip is measured from them) and
  /// accumulates slip and dissipation of the slipping nodes.
  void commit(const EvaluationState& state) override;
  /// Symmetric for frictionless HARD contact only (friction and the soft
  /// laws' rows make the nodes' tangents unsymmetric).
  [[nodiscard]] bool symmetric_tangent(bool /*nlgeom*/) const override { return !(mu() > 0) && !soft(); }
  /// Restart: per slave node the total slip and dissipation, per slave face
  /// the master faces overlapped at the last commit, and whether the pair
  /// has searched. Loading rebuilds the nodes' dof lists.
  void save_state(std::vector<double>& out) const override;
  void load_state(std::span<const double>& in) override;
  [[nodiscard]] double mu() const { return setup_.mu; }
  /// Whether the pair has a soft pressure-overclosure law (not HARD).
  [[nodiscard]] bool soft() const { return setup_.law.law != PressureOverclosure::Law::Hard; }
  [[nodiscard]] bool linear_in_u(bool /*nlgeom*/) const override { return false; }

  /// The per-slave-node contributions (to be assembled after the pair).
  [[nodiscard]] std::vector<Contribution*> nodes() const;

  [[nodiscard]] const MortarPairSetup& setup() const { return setup_; }
  [[nodiscard]] const std::vector<Eigen::Vector2d>& reference() const { return reference_; }
  [[nodiscard]] int n_slaves() const { return static_cast<int>(slaves_.size()); }
  [[nodiscard]] const MortarSlave& slave(int i) const { return slaves_[static_cast<std::size_t>(i)]; }
  /// Master faces slave face e overlaps at the last update_connectivity.
  [[nodiscard]] const std::vector<int>& overlapped(int e) const { return overlapped_[static_cast<std::size_t>(e)]; }
  /// The master faces whose terms the kinematics of slave face e sums:
  /// overlapped(e), and with friction those overlapped at the last commit.
  [[nodiscard]] const std::vector<int>& term_faces(int e) const { return term_faces_[static_cast<std::size_t>(e)]; }
  /// Changes whenever overlapped() or term_faces() may have changed (the
  /// nodes' memo of their active-set decision keys on it).
  [[nodiscard]] std::uint64_t overlap_version() const { return overlap_version_; }
  /// Slave faces sharing a node with each slave face's nodes (for the normals), by slave node index.
  [[nodiscard]] const std::vector<std::vector<std::pair<int, int>>>& faces_of_node() const { return faces_of_node_; }
  /// The memo of the terms (slave face × master face) the nodes' kinematics
  /// share (mortar_terms.hpp); a cache of pure functions of the positions,
  /// so it is no state of the pair.
  [[nodiscard]] MortarTermCache& term_cache() const { return term_cache_; }

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
  std::vector<std::vector<int>> committed_;   ///< per slave face: overlapped at the last commit (friction)
  std::vector<std::vector<int>> term_faces_;  ///< per slave face: overlapped_ ∪ committed_
  void update_term_faces();
  std::uint64_t overlap_version_ = 0;
  bool searched_once_ = false;
  bool dofs_stale_ = false;  ///< commit() changed the term faces: rebuild the dofs at the next update
  double attempt_time_ = -1, attempt_dt_ = -1;  ///< the increment attempt the guard counts in
  int releases_ = 0;                            ///< guard releases in this attempt
  MortarIterationStatistics statistics_;
  mutable MortarTermCache term_cache_;
};

}  // namespace tether
