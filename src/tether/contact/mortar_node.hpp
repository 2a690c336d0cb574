#pragma once
/// \file The mortar contact element of one slave node j: its weighted gap
/// g̃_j and the normal multiplier λ_j (the dual nodal contact pressure, >= 0
/// in compression), with the semi-smooth Newton complementarity function of
/// HARD contact (or a soft law's row) and the complete tangent.
///
/// Local unknowns: [the real nodes g̃_j depends on, x and y each
/// (MortarSlave::nodes), λ_j (= λn_j), with friction λt_j]. With the nodal normal n_j (averaged, unit)
/// and the mortar integrals of the slave faces around j,
///
///   g̃_j = Σ_{faces e ∋ j} n_j · (Σ_{f,a} M^e_{j,fa} y_fa - D^e_j x_j)   [length × area]
///
/// (> 0 open). The contact virtual work λ_j δg̃_j gives
///
///   closed (λ_j - c_j g̃_j >= 0):  r_u += -λ_j ∇g̃_j,  r_λ = -g̃_j,
///                                 K_uu += -λ_j ∇²g̃_j, K_uλ = K_λuᵀ = -∇g̃_j;
///   open:                         r_λ = -λ_j / c_j,   K_λλ = -1 / c_j,
///
/// with c_j = c / A_j². With Coulomb friction (μ > 0) a second multiplier
/// λt_j, the tangential traction (force on the slave -D_j λt_j τ_j, τ_j =
/// n_j turned by +90°), adds r_u += λt_j G_j with G_j = τ_j·(D_j δx_j -
/// Σ M δy) (coefficients frozen) and the row ũ_j = 0 (stick: |λt + c_j ũ_j|
/// < μ λn_j) or -(λt - μ λn sgn(λt + c_j ũ_j))/c_j (slip), -λt/c_j when
/// open; ũ_j is the objective weighted slip increment of the increment
/// (mortar_node.cpp). With a soft pressure-overclosure law, λ_j = p(h_j) of
/// the mean overclosure h_j = -g̃_j / D_j: r_u += λ_j D_j ∇h_j (the nodal
/// force on the mean gap) and r_λ = (p(h_j) - λ_j) / c_j, the tangent with
/// ∇D_j and ∇²D_j, unsymmetric; the node is in the law wherever p(h_j) > 0,
/// p'(h_j) > 0 or λ_j ≠ 0. The gradient and Hessian are exact (Dual2): they
/// include the variation of the normals, of the projections and of the
/// segmentation. A node whose faces overlap no master face (or whose
/// D_j <= 0) is free: λ_j = 0. Theory: docs/theory/mortar.md.

#include <cstdint>
#include <mutex>
#include <vector>

#include "tether/assembly/contribution.hpp"

namespace tether {

class MortarPair;

class MortarNode final : public Contribution {
 public:
  MortarNode(const MortarPair& pair, int slave) : pair_(pair), slave_(slave) {}

  [[nodiscard]] std::span<const int> dofs() const override;
  void evaluate(const EvaluationState& state, LocalSystem& out, bool need_tangent) const override;
  [[nodiscard]] std::string describe() const override;
  /// Symmetric for frictionless HARD contact: the closed rows derive from
  /// the potential λ_j g̃_j. Coulomb friction and the soft laws' rows make it
  /// unsymmetric.
  [[nodiscard]] bool symmetric_tangent(bool /*nlgeom*/) const override;
  [[nodiscard]] bool linear_in_u(bool /*nlgeom*/) const override { return false; }

  /// Weighted gap g̃_j [length × area] and D_j = Σ_e D^e_j [area] at the
  /// displacements `u`; `covered` is false when no master face overlaps the
  /// node's faces or D_j <= 0 (the node is then free). `nlgeom`: the
  /// integrals' measure dA is the current one (λ_j a Cauchy pressure);
  /// otherwise the reference one (λ_j a force per reference area, like the
  /// loads of a geometrically linear step), the rest staying current.
  struct Gap {
    double gap = 0;
    double D = 0;
    bool covered = false;
  };
  [[nodiscard]] Gap gap(const Eigen::VectorXd& u, bool nlgeom) const;

  /// Whether the node takes the closed row at the state.
  [[nodiscard]] bool closed(const EvaluationState& state) const;

  /// λn_j ∇g̃_j - λt_j G_j over the displacement dofs of dofs() (the contact
  /// forces on those nodes from this node's multipliers); zero when open.
  [[nodiscard]] Eigen::VectorXd forces(const EvaluationState& state) const;

  /// With friction: whether the node is closed, sticks (else slips: in
  /// `direction` ±1, the sign of λt + c ũ), and its weighted slip increment
  /// ũ_j [length × area] at the state. The branch the residual would take
  /// without the pair's stick guard.
  struct Friction {
    bool closed = false, stick = false;
    int direction = 0;
    double slip = 0;
  };
  [[nodiscard]] Friction friction(const EvaluationState& state) const;

 private:
  /// c_j = c / A_j² of the complementarity function.
  [[nodiscard]] double row_stiffness() const;
  /// The weighted gap and the gap the active set is decided on (zero for a
  /// touch; 0 when not covered) at the state's displacements.
  struct Decision {
    Gap gap;
    double decisive = 0;
  };
  /// decision at `state`, memoized: update_connectivity and the assembly
  /// that follows ask at the same state. A pure function of the positions of
  /// the node's nodes, of the measure and of the pair's overlaps (its
  /// overlap_version()), the memo keys on exactly those, bit for bit.
  [[nodiscard]] Decision decision(const EvaluationState& state) const;
  const MortarPair& pair_;
  int slave_;
  struct Memo {
    bool valid = false, nlgeom = false;
    std::uint64_t version = 0;
    std::vector<int> nodes;
    std::vector<double> x;  ///< positions of `nodes`, x and y
    Decision decision;
  };
  mutable std::mutex memo_mutex_;
  mutable Memo memo_;
};

}  // namespace tether
