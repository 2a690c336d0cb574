#pragma once
/// \file The node-to-segment contact element of one slave node: normal
/// contact (HARD by a multiplier and a semi-smooth Newton complementarity
/// function, or a soft pressure-overclosure law) and Coulomb friction (exact
/// stick by a multiplier, or a stick penalty), with the consistent tangent of
/// finite sliding.
///
/// Local unknowns: [slave x, y, segment node 1 x, y, ..., (with friction after
/// a hand-over: the committed segment's other nodes), λn (HARD), λt (exact
/// stick)]; a slave with no master segment keeps only its multipliers, driven
/// to zero. Residual contributions (r = f_int - f_ext + ..., K = dr/du):
///
///   normal:   r_u += -N_λ ∇g,  HARD: N_λ = λn and
///             r_λn = -g (closed: λn - c g >= 0)  or  -λn/c (open);
///             soft: N = A p(-g), no multiplier;
///   friction: r_u += T F, F = |y'| ∂ξ*/∂x (T at the contact point y(ξ*)
///             along t), exact stick: T = λt and
///             r_λt = Δs (stick: |λt + c Δs| < μN), -(λt - μN sgn(λt + cΔs))/c (slip),
///             -λt/c (open); penalty: T = return map of T_old + k Δs onto |T| <= μN.
///
/// g is the normal gap (> 0 open), Δs = (y_s - ȳ_c)·t the slip increment along
/// the master tangent since the last converged increment (ȳ_c: the committed
/// master point at current positions; slip_increment()), N >= 0 the normal
/// force, c the pair's complementarity stiffness. Derivations:
/// docs/theory/contact.md.

#include "tether/assembly/contribution.hpp"
#include "tether/model/results.hpp"

namespace tether {

class ContactPair;

/// Contact state of a slave node.
enum class ContactStatus { Open, Stick, Slip };  ///< closed frictionless nodes are Slip

/// The branch of the piecewise-smooth residual a slave node takes at a state:
/// its part of the active set of the semi-smooth Newton method. Two states
/// with the same branch (and pairing) have the same smooth residual function.
struct ContactBranch {
  ContactStatus status = ContactStatus::Open;
  /// Slip with friction: the direction the friction force is driven to (+1 or
  /// -1 along the master tangent, the sign of λt + cΔs or of the trial force); 0 otherwise.
  int direction = 0;
  /// With friction: the node carries a normal force (N > 0), so its friction
  /// row is the stick or slip one. A node that has just closed (λn = 0
  /// exactly, set by the open row of the previous iteration) is closed but
  /// still has the open friction row; it is reported as Slip all the same.
  bool friction_active = false;
  friend bool operator==(const ContactBranch&, const ContactBranch&) = default;
};

class ContactNode final : public Contribution {
 public:
  ContactNode(const ContactPair& pair, int slave) : pair_(pair), slave_(slave) {}

  [[nodiscard]] std::span<const int> dofs() const override;
  void evaluate(const EvaluationState& state, LocalSystem& out, bool need_tangent) const override;
  [[nodiscard]] std::string describe() const override;
  /// Symmetric without friction (the normal part derives from a potential);
  /// Coulomb friction makes it unsymmetric.
  [[nodiscard]] bool symmetric_tangent(bool /*nlgeom*/) const override;
  /// false: the active set and the pairing change with u.
  [[nodiscard]] bool linear_in_u(bool /*nlgeom*/) const override { return false; }

  /// Status at the state (as the residual sees it).
  [[nodiscard]] ContactStatus status(const EvaluationState& state) const { return branch(state).status; }
  /// The residual's branch at the state: status, slip direction, friction row.
  [[nodiscard]] ContactBranch branch(const EvaluationState& state) const;

  /// Output values at the state (status, gap, forces, slip).
  [[nodiscard]] ContactNodeValues values(const EvaluationState& state) const;

 private:
  struct Point;
  /// Evaluates everything; fills `out` when it is not null.
  Point compute(const EvaluationState& state, LocalSystem* out, bool need_tangent) const;

  const ContactPair& pair_;
  int slave_;
};

}  // namespace tether
