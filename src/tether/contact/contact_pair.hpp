#pragma once
/// \file One `*CONTACT PAIR` of 2D node-to-segment contact: the slave nodes,
/// the master surface, their pairing (search) and history, and one
/// ContactNode contribution per slave node.
///
/// The pair is itself a Contribution without unknowns: its
/// update_connectivity() runs the search before each Newton iteration (a full
/// search at the first iteration of every increment attempt, the incremental
/// walk afterwards; SMALL SLIDING keeps the first pairing) and hands the new
/// pairings to its ContactNodes, whose dof lists change accordingly. The
/// multipliers are reserved once per slave node and never renumbered.
/// It must come before its nodes in the assembler's list.
///
/// Theory, choices and limits: docs/theory/contact.md.

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tether/assembly/contribution.hpp"
#include "tether/contact/calculix_area.hpp"
#include "tether/contact/contact_node.hpp"
#include "tether/contact/contact_search.hpp"
#include "tether/contact/master_segments.hpp"
#include "tether/model/contact_data.hpp"
#include "tether/model/results.hpp"

namespace tether {

/// A pair resolved to node indices (built by the analysis from the model).
struct ContactPairSetup {
  std::string name;  ///< for messages and output, e.g. "CONTACT PAIR SLAVE-MASTER"
  /// Node indices of each master segment, face_nodes() order (counter-clockwise around its element).
  std::vector<std::vector<int>> master_faces;
  /// (element id, face number 1..4) of each master segment, for output.
  std::vector<std::pair<int, int>> master_face_labels;
  std::vector<int> slave_nodes;    ///< node indices
  /// The user's name of each slave node (label_text(): `UPPER-1.3`, `17`),
  /// parallel to slave_nodes, for messages; empty: messages give the index.
  std::vector<std::string> slave_names;
  /// Tributary area of each slave node [length × thickness] (1 per node for a
  /// node-based slave surface, as in ABAQUS); pressure = normal force / area.
  std::vector<double> slave_area;
  /// The slave surface is node-based (*SURFACE, TYPE=NODE): its areas are the
  /// ones given per node (default 1), so "pressure" is force / that area.
  bool node_based_slave = false;
  /// Dialect calculix, node-based slave: per master face, the rule of
  /// CalculiX's area (calculix_area.hpp). Each slave node's area is then the
  /// master face's at its projection on the current face (slave_area holds
  /// it in the reference configuration, for the reach and for messages);
  /// pressure = normal force / that current area. Empty: the areas are
  /// slave_area, fixed. Needs unsmoothed faces (smoothing 0).
  std::vector<MasterFaceArea> calculix_face_areas;
  PressureOverclosure law;               ///< HARD: exact (multipliers); else a soft law
  std::optional<FrictionData> friction;  ///< none or mu = 0: frictionless
  bool small_sliding = false;
  /// SMOOTH fraction s of the corners of a linear master surface: 0 (the
  /// faces as they are) or 0 < s <= 0.5 (MasterSegments; linear faces only).
  double smoothing = 0;
  double search_radius = 0;  ///< [length], > 0
  /// c of the complementarity functions min(λ/c, g) [force/length]: decides
  /// the active set between iterations only; the converged answer does not
  /// depend on it. Order of the slave body's E × thickness.
  double complementarity_stiffness = 1;
  /// Changes of status of one slave node within an increment attempt after
  /// which it is held closed until Newton converges (chattering guard).
  /// 5: with 4 the 3 mm ironing test (friction at the contact point) held,
  /// then released, a node in one slide increment: 9 iterations with one
  /// thread (7 with 5; every other test unchanged).
  int max_status_changes = 5;
  /// Reversals of the slip direction of one node within an attempt after
  /// which it is held in stick until Newton converges (friction guard).
  int max_direction_flips = 3;
  /// Switches of one closed node between stick and slip on the same segment
  /// within an attempt after which it is held in stick until Newton converges.
  int max_stick_slip_switches = 4;
};

/// Per-slave record: pairing, dofs, committed history.
struct ContactSlave {
  int node = 0;
  double area = 1;
  int normal_multiplier = -1;      ///< global index (HARD), -1 otherwise
  int tangent_multiplier = -1;     ///< global index (exact stick), -1 otherwise
  ContactPairing pairing;          ///< current pairing; segment -1: free
  /// [slave x, y, segment nodes x, y ..., committed segment's other nodes x, y ..., λn?, λt?]
  /// (the committed segment's nodes not already listed, with friction after a hand-over only).
  std::vector<int> dofs;
  /// The real nodes whose displacements head `dofs`: node a owns its x, y at
  /// dofs[2a], dofs[2a + 1] (slave, segment nodes, committed segment's others).
  std::vector<int> nodes;
  /// With friction: paired with another segment than at the last converged
  /// increment when the dofs were built, so the slip increment depends on the
  /// committed segment's nodes too (they are in `dofs`).
  bool handed_over = false;
  // History at the last converged increment.
  int committed_segment = -1;      ///< segment of the last converged pairing (-1: none)
  double committed_xi = 0;         ///< ξ* there
  double committed_tangential_force = 0;  ///< T [force] (penalty stick)
  double total_slip = 0;           ///< Σ |Δs| over slipping increments [length]
  double dissipation = 0;          ///< Σ T Δs over slipping increments [force × length]
  double lambda_bar = 0;           ///< HARD, AUGMENTED: Uzawa normal force [force] (kept between increments)
  // Within an increment attempt.
  ContactStatus status = ContactStatus::Open;  ///< at the last update_connectivity
  int status_changes = 0;
  bool held_closed = false;        ///< chattering guard engaged
  int slip_direction = 0;          ///< friction force direction at the last update_connectivity (slip only)
  bool friction_active = false;    ///< friction row stick or slip (N > 0) at the last update_connectivity
  int direction_flips = 0;         ///< reversals of the slip direction in this attempt
  int stick_slip_switches = 0;     ///< switches between stick and slip in this attempt
  bool held_stick = false;         ///< friction guard engaged: held in stick until Newton converges
  int left_segment = -1;           ///< segment left by a re-pairing at the previous iteration (-1: none)
  int returns = 0;                 ///< returns across a concave kink to left_segment in this attempt
  bool held_segment = false;       ///< re-pairing guard engaged: kept on its segment (extended) until Newton converges
};

/// Work done by the last update_connectivity (for the iteration log).
struct ContactIterationStatistics {
  int closed = 0;         ///< slave nodes in contact (stick or slip)
  /// Nodes whose branch changed since the previous iteration: status
  /// (open/stick/slip), slip direction, or friction row (ContactBranch).
  int status_changes = 0;
  int repaired = 0;       ///< nodes paired with another segment
  int held_closed = 0;    ///< nodes held by a guard (closed, in stick, or on their segment)
};

class ContactPair final : public Contribution {
 public:
  /// `reference`: reference coordinates of all nodes (must outlive the pair).
  /// `first_multiplier`: global index of the first of multipliers_per_slave() ×
  /// slaves multipliers (DofMap::add_multipliers), -1 when there are none.
  ContactPair(ContactPairSetup setup, const std::vector<Eigen::Vector2d>& reference, int first_multiplier);
  ~ContactPair() override;

  /// Multipliers per slave node: 1 for HARD (normal force), +1 for friction
  /// with exact stick (no stick slope or elastic slip given).
  static int multipliers_per_slave(const PressureOverclosure& law, const std::optional<FrictionData>& friction);

  [[nodiscard]] std::span<const int> dofs() const override { return {}; }
  void evaluate(const EvaluationState&, LocalSystem&, bool) const override {}
  bool update_connectivity(const EvaluationState& state) override;
  Acceptance on_converged(const EvaluationState& state) override;
  void commit(const EvaluationState& state) override;
  [[nodiscard]] std::string describe() const override { return setup_.name; }
  /// The pair assembles nothing itself; it declares what its nodes do
  /// (unsymmetric with friction).
  [[nodiscard]] bool symmetric_tangent(bool /*nlgeom*/) const override { return mu() <= 0; }
  /// false: it re-pairs its nodes as u changes.
  [[nodiscard]] bool linear_in_u(bool /*nlgeom*/) const override { return false; }
  /// Restart: per slave the pairing, status and committed history (segment,
  /// ξ, tangential force, total slip, dissipation, Uzawa λ̄), and whether the
  /// pair has searched yet. Loading re-pairs the slaves (their dof lists).
  void save_state(std::vector<double>& out) const override;
  void load_state(std::span<const double>& in) override;

  /// The per-slave contributions (to be assembled after the pair).
  [[nodiscard]] std::vector<Contribution*> nodes() const;

  [[nodiscard]] const ContactPairSetup& setup() const { return setup_; }
  /// The segments slave nodes are paired with (the faces, or the smoothed surface).
  [[nodiscard]] const MasterSegments& segments() const { return segments_; }
  /// Search topology over the segments (segments().surface()).
  [[nodiscard]] const MasterSurface& surface() const { return segments_.surface(); }
  /// Current virtual node positions of segment k at displacements `u` (the
  /// real node positions for an unsmoothed surface), 2 or 3 points.
  [[nodiscard]] std::vector<Eigen::Vector2d> segment_points(int k, const Eigen::VectorXd& u) const;
  [[nodiscard]] const ContactSlave& slave(int i) const { return slaves_[static_cast<std::size_t>(i)]; }
  [[nodiscard]] int n_slaves() const { return static_cast<int>(slaves_.size()); }
  [[nodiscard]] const std::vector<Eigen::Vector2d>& reference() const { return reference_; }
  [[nodiscard]] bool exact_stick() const;
  [[nodiscard]] double mu() const { return setup_.friction ? setup_.friction->mu : 0.0; }

  /// Per-slave output at the state (status, gap, pressure, friction, pairing).
  [[nodiscard]] ContactPairValues values(const EvaluationState& state) const;
  [[nodiscard]] const ContactIterationStatistics& statistics() const { return statistics_; }

 private:
  void set_pairing(ContactSlave& s, const ContactPairing& p);
  void start_attempt(const EvaluationState& state);

  ContactPairSetup setup_;
  const std::vector<Eigen::Vector2d>& reference_;
  MasterSegments segments_;
  std::vector<ContactSlave> slaves_;
  std::vector<std::unique_ptr<ContactNode>> nodes_;
  /// Updates positions_ (and points_ when smoothed) to `u`; returns the search's points.
  const std::vector<Eigen::Vector2d>& search_points(const Eigen::VectorXd& u);
  std::vector<Eigen::Vector2d> positions_;  ///< current positions by node index (master nodes kept current)
  std::vector<Eigen::Vector2d> points_;     ///< current positions of the search's points (segments_.point_positions)
  bool searched_once_ = false;
  double attempt_time_ = -1, attempt_dt_ = -1;
  int releases_ = 0;  ///< chattering-guard releases in this attempt
  int uzawa_updates_ = 0;  ///< augmented-Lagrangian updates in this attempt
  ContactIterationStatistics statistics_;
};

}  // namespace tether
