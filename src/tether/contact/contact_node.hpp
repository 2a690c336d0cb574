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
///   friction: r_u += T ∇Δs,  exact stick: T = λt and
///             r_λt = Δs (stick: |λt + c Δs| < μN), -(λt - μN sgn(λt + cΔs))/c (slip),
///             -λt/c (open); penalty: T = return map of T_old + k Δs onto |T| <= μN.
///
/// g is the normal gap (> 0 open), Δs = (y_s - ȳ_c)·t the slip increment along
/// the master tangent since the last converged increment (ȳ_c: the committed
/// master point at current positions; slip_increment()), N >= 0 the normal
/// force, c the pair's complementarity stiffness. Derivations:
/// docs/theory/contact.md.

#include <utility>

#include "tether/assembly/contribution.hpp"
#include "tether/model/results.hpp"

namespace tether {

class ContactPair;

/// Contact state of a slave node.
enum class ContactStatus { Open, Stick, Slip };  ///< closed frictionless nodes are Slip

class ContactNode final : public Contribution {
 public:
  ContactNode(const ContactPair& pair, int slave) : pair_(pair), slave_(slave) {}

  [[nodiscard]] std::span<const int> dofs() const override;
  void evaluate(const EvaluationState& state, LocalSystem& out, bool need_tangent) const override;
  [[nodiscard]] std::string describe() const override;

  /// Status at the state (as the residual sees it).
  [[nodiscard]] ContactStatus status(const EvaluationState& state) const { return status_and_direction(state).first; }
  /// Status and, for a slipping node with friction, the direction of the
  /// friction force (+1 or -1 along the master tangent; 0 otherwise).
  [[nodiscard]] std::pair<ContactStatus, int> status_and_direction(const EvaluationState& state) const;

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
