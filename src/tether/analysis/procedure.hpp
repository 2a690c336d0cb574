#pragma once
/// \file What a step's procedure does with one increment: the seam between the
/// step loop and the physics of the step (static; later implicit and explicit
/// dynamics).
///
/// The step loop (StaticAnalysis) owns the time stepping (IncrementController)
/// and the analysis' counters; a Procedure solves one increment attempt over
/// the step's StepSystem and reports it. A procedure keeps what it needs
/// between increments (the static one: Newton and the time-averaged force; a
/// dynamic one: velocities and accelerations) and saves it for a restart.
/// See docs/theory/procedures.md.

#include <Eigen/Core>
#include <string>

#include "tether/analysis/increment_controller.hpp"
#include "tether/analysis/newton.hpp"
#include "tether/model/restart_state.hpp"

namespace tether {

/// One attempt of an increment, as the step loop hands it to a procedure.
struct IncrementAttempt {
  int step = 1;              ///< 1-based step number
  int increment = 1;         ///< 1-based number of the increment attempted (converged increments + 1)
  int attempt = 1;           ///< 1 = first try, > 1 after cut-backs
  IncrementTimes time;       ///< from IncrementController::next_attempt()
  int prior_iterations = 0;  ///< Newton iterations of the analysis before this attempt (reports show the total)
};

/// How an attempt ended.
struct IncrementOutcome {
  bool converged = false;
  int iterations = 0;   ///< Newton iterations (linear solves) of the attempt, over all its passes
  std::string message;  ///< why it failed (names the node, dof or contribution); may be set when converged
  /// The matrix was singular at the attempt's first iteration: the model is
  /// not restrained or a constraint is redundant; a smaller increment will not help.
  bool singular_at_start = false;
  bool singular_multiplier = false;  ///< ... and the vanishing pivot is a constraint (multiplier) row
  /// The procedure's own estimate of the next increment relative to this
  /// one (an error estimate such as HAFTOL's): > 0 overrides the controls'
  /// growth after a converged attempt and their cut-back factor after a
  /// failed one; 0: none.
  double increment_scale = 0;
};

class Procedure {
 public:
  virtual ~Procedure() = default;

  /// The deck keyword of the procedure, for messages ("*STATIC").
  [[nodiscard]] virtual std::string keyword() const = 0;

  /// Solves one attempt from the converged state in `u` (all unknowns) to the
  /// end of `attempt.time`, and reports it (AnalysisObserver::on_increment).
  /// Converged: the contributions' history is committed, the results are
  /// reported (on_results) and `u` holds the new state. Failed: `u` is back
  /// at the converged state. Exceptions from the observer propagate.
  virtual IncrementOutcome solve_increment(const IncrementAttempt& attempt, Eigen::VectorXd& u) = 0;

  /// The step as the step loop's IncrementController should step it: the
  /// step itself, unless the procedure reports at intervals of its own (the
  /// explicit one: fixed report intervals, each of many explicit increments).
  [[nodiscard]] virtual Step time_stepping(const Step& step) const { return step; }

  /// Time spent in this step so far: evaluation, linear solver, output.
  [[nodiscard]] virtual SolveTiming timing() const = 0;

  /// Restart: writes the procedure's state between increments into `state`.
  virtual void save(RestartState& state) const = 0;
  /// Restart: continues from a state save() wrote in the same step.
  virtual void restore(const RestartState& state) = 0;
};

}  // namespace tether
