#pragma once
/// \file The one interface every contributor to the equilibrium equations implements.
///
/// A contribution (continuum element, pressure load, Lagrange-multiplier
/// constraint, contact element) names a list of global unknowns and, given the
/// current state, returns a residual vector and a tangent matrix over that list.
///
/// Sign convention: the residual is the out-of-balance force
///   r(u) = f_int(u) - f_ext(u) (+ constraint terms lambda * df/du, f),
/// and the tangent is K = dr/du. Newton solves K du = -r.
/// A Lagrange-multiplier constraint f(u) = 0 contributes r_u = lambda df/du,
/// r_lambda = f (or f - eps*lambda) and K = [[lambda d2f/du2, df/du^T], [df/du, -eps]].

#include <Eigen/Core>
#include <span>
#include <string>
#include <vector>

namespace tether {

/// What a contribution may read when it is evaluated. All vectors are global,
/// indexed by the numbering of DofMap (displacements, then multipliers).
struct EvaluationState {
  const Eigen::VectorXd& u;        ///< current iterate: total displacements and multipliers
  const Eigen::VectorXd& u_start;  ///< converged values at the start of the increment
  double step_time = 0;            ///< time within the step at the end of the increment
  double total_time = 0;           ///< total time at the end of the increment
  double dt = 0;                   ///< increment size
  bool nlgeom = false;             ///< finite-strain kinematics requested by the step
};

/// Residual and tangent of one contribution over its local dof list.
struct LocalSystem {
  Eigen::VectorXd residual;  ///< size n
  Eigen::MatrixXd tangent;   ///< n x n, d residual / d u (may be unsymmetric)

  /// Resizes to n and zeroes both.
  void reset(Eigen::Index n) {
    residual.setZero(n);
    tangent.setZero(n, n);
  }
};

/// How a contribution judges a converged Newton solution (augmented Lagrange
/// updates, active-set checks): accept it, or ask for another Newton pass.
enum class Acceptance { Accept, Iterate };

/// An element-like contributor to the global equations.
class Contribution {
 public:
  virtual ~Contribution() = default;

  /// Global unknowns this contribution couples, in local order. Stable between
  /// calls to update_connectivity().
  [[nodiscard]] virtual std::span<const int> dofs() const = 0;

  /// Fills `out` (already sized by the caller to dofs().size() and zeroed).
  /// When `need_tangent` is false the tangent may be left untouched.
  virtual void evaluate(const EvaluationState& state, LocalSystem& out, bool need_tangent) const = 0;

  /// True when the tangent evaluate() returns may be taken as symmetric at
  /// every state of a step with this NLGEOM setting: the step's solver may
  /// then factorize it by Cholesky or LDLT, which read one triangle only.
  /// False when it is unsymmetric or tether cannot vouch for it (a user
  /// routine's own tangent).
  [[nodiscard]] virtual bool symmetric_tangent(bool nlgeom) const = 0;

  /// True when, in a step with this NLGEOM setting, the residual is affine in
  /// u with a tangent that is the same matrix over the same dofs at every
  /// state of the step (the residual may still change with time, e.g. a ramped
  /// load, or with history updated between Newton passes, e.g. an Uzawa
  /// update). Such contributions need to be assembled and factorized only once per step.
  [[nodiscard]] virtual bool linear_in_u(bool nlgeom) const = 0;

  /// False only when, within one step, the residual at a given u is always
  /// the same vector: evaluate() reads nothing of `state` but u (and nlgeom)
  /// — not the times, dt or u_start — and nothing that changes between its
  /// evaluations (a magnitude set per increment, an amplitude, temperatures,
  /// history or multipliers stored by on_converged() or commit(), user code).
  /// The assembler then keeps the residual of a linear contribution recorded
  /// at one state for the rest of the step (Assembler::enable_residual_updates).
  /// True (the default) when it may change or tether cannot vouch for it.
  [[nodiscard]] virtual bool residual_depends_on_time() const { return true; }

  /// Called before each Newton iteration (not once held linear: Assembler::set_linear); may change
  /// dofs() (contact re-pairing). Returns true when dofs() changed so the assembler rebuilds its pattern.
  virtual bool update_connectivity(const EvaluationState& /*state*/) { return false; }

  /// Called when Newton has converged; Iterate asks for another Newton pass
  /// with the internal state this call updated (e.g. an Uzawa multiplier update).
  virtual Acceptance on_converged(const EvaluationState& /*state*/) { return Acceptance::Accept; }

  /// Called once the increment is accepted: store history (friction slip, ...).
  virtual void commit(const EvaluationState& /*state*/) {}

  /// Restart: appends the history kept between increments (what commit() and
  /// on_converged() store) to `out`, so that load_state() on the same
  /// contribution of the same model continues the analysis identically.
  /// Values are copied bitwise (integers as exact doubles). Empty default:
  /// stateless contributions save nothing.
  virtual void save_state(std::vector<double>& /*out*/) const {}

  /// Restart: reads back what save_state() wrote from the front of `in` and
  /// advances `in` past it. Throws std::runtime_error when `in` does not hold
  /// such a state (too short, wrong kind or sizes): the file belongs to another model.
  virtual void load_state(std::span<const double>& /*in*/) {}

  /// Short description for messages, e.g. "element 12 (CPE4)".
  [[nodiscard]] virtual std::string describe() const = 0;
};

}  // namespace tether
