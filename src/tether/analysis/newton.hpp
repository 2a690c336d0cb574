#pragma once
/// \file Newton–Raphson iterations for one increment attempt.
///
/// Newton sees the problem only through NewtonProblem (assemble, apply a
/// correction, norms). Convergence is judged by ConvergenceCriteria; an
/// optional backtracking line search shortens a correction that increases the
/// residual.

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <string>

#include "tether/analysis/convergence.hpp"
#include "tether/solvers/linear_solver.hpp"

namespace tether {

/// Wall-clock seconds spent in the parts of the solution (summed over calls).
struct SolveTiming {
  double contact_search = 0;  ///< update_connectivity: contact search and pattern rebuilds
  double assembly = 0;        ///< residual and tangent (elements, constraints, contact)
  double analyse = 0;         ///< symbolic analysis (ordering) of the linear solver
  double factorize = 0;       ///< numeric factorization
  double solve = 0;           ///< triangular solves
  double output = 0;          ///< results and writers (set by the analysis)
  int factorizations = 0;
  /// Iterations that solved with the factorization of the previous one,
  /// the tangent being the same matrix (all of it linear in u and held).
  int reused_factorizations = 0;
  /// Tangent assemblies that held the linear bulk's tangent, and those that
  /// assembled it in full, in steps that hold it (Assembler::linear_reuse).
  int held_tangents = 0, full_tangents = 0;
  /// Evaluations whose linear bulk's residual came from the held tangent
  /// (Assembler::enable_residual_updates) instead of the elements.
  int residual_updates = 0;
  /// Of those, sparse factorizations of the bulk by the condensed solver (the
  /// rest reused it); 0 when the solver did not condense.
  int sparse_factorizations = 0;
};

/// The nonlinear system of one increment, in terms of its free equations.
class NewtonProblem {
 public:
  virtual ~NewtonProblem() = default;
  /// Called at the start of every NewtonSolver::solve(): the loads and the
  /// contributions' internal state may have changed since the last
  /// evaluate() (a new increment, a contribution that asked for another
  /// pass), so nothing evaluated before may be reused.
  virtual void begin_solve() {}
  /// Residual over the free equations and, when `with_tangent`, the tangent
  /// (tangent(); unchanged otherwise). Returns true when the matrix pattern
  /// changed since the last call. Fills `norms` (all but correction /
  /// previous residual) and the force scale q.
  virtual bool evaluate(Eigen::VectorXd& residual, bool with_tangent, IterationNorms& norms,
                        double& force_scale) = 0;
  /// The tangent of the last evaluate() with `with_tangent`, owned by the
  /// problem (so the matrix exists once, not also as the caller's copy).
  [[nodiscard]] virtual const SparseMatrix& tangent() const = 0;
  /// u_free += alpha * correction.
  virtual void apply_correction(const Eigen::VectorXd& correction, double alpha) = 0;
  /// Largest |correction| over displacement equations.
  [[nodiscard]] virtual double displacement_norm(const Eigen::VectorXd& correction) const = 0;
  /// True when the tangent is known to be symmetric (lets the solver use Cholesky).
  [[nodiscard]] virtual bool symmetric() const = 0;
  /// Names the unknown of free equation `eq` for messages ("node 12 dof 2").
  [[nodiscard]] virtual std::string describe_equation(int eq) const = 0;
  /// True when free equation `eq` is a constraint (multiplier) row.
  [[nodiscard]] virtual bool is_multiplier_equation(int eq) const = 0;
  /// Adds the time of the last evaluate() to `timing` (search and assembly).
  virtual void add_evaluation_time(SolveTiming& /*timing*/) const {}
  /// Identifies the tangent's values: equal non-zero revisions mean the same
  /// matrix (Assembler::tangent_revision), whose factorization Newton then
  /// reuses; 0: unknown, factorize at every iteration.
  [[nodiscard]] virtual std::uint64_t tangent_revision() const { return 0; }
  /// Likewise for the tangent's entries outside the reserved (contact) block
  /// (Assembler::outer_revision): equal non-zero values between two
  /// factorizations let a condensing solver skip comparing them.
  [[nodiscard]] virtual std::uint64_t outer_revision() const { return 0; }
};

/// How an attempt ended.
struct NewtonOutcome {
  enum class Status { Converged, Diverged, TooManyIterations, SingularMatrix, ElementFailure };
  Status status = Status::Converged;
  int iterations = 0;          ///< linear solves done
  double force_residual = 0;   ///< final max |r| over force rows
  double force_scale = 0;      ///< q used for the final test
  std::string message;         ///< why it failed (names the node/dof/element)
  bool singular_at_start = false;  ///< singular already at the first iteration
  bool singular_multiplier = false;  ///< the vanishing pivot belongs to a constraint row
};

/// Called after each iteration (iteration number, norms) for logs.
using IterationListener = std::function<void(int, const IterationNorms&)>;

class NewtonSolver {
 public:
  NewtonSolver(LinearSolver& solver, const Controls& controls, double length_scale);

  /// Iterates from the problem's current state. `averaged_force` is the time
  /// average of q over earlier increments (0 when none); `n_averaged` how many.
  NewtonOutcome solve(NewtonProblem& problem, double averaged_force, int n_averaged,
                      const IterationListener& listener = {});

  /// Time spent so far in the problem's evaluations and in the linear solver.
  [[nodiscard]] const SolveTiming& timing() const { return timing_; }

 private:
  LinearSolver& solver_;
  Controls controls_;
  ConvergenceCriteria criteria_;
  bool analysed_ = false;
  /// The tangent revision the solver holds a factorization of (0: none known).
  std::uint64_t factorized_revision_ = 0;
  std::uint64_t factorized_outer_revision_ = 0;  ///< likewise for outer_revision()
  SolveTiming timing_;
};

}  // namespace tether
