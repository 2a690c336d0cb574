#pragma once
/// \file What every implicit procedure (static, implicit dynamic) does with
/// one attempt: Newton, then the contributions' acceptance of its solution;
/// the attempt's outcome and report; the stamp of its results; the time
/// average of Newton's force scale over the step.

#include <vector>

#include "tether/analysis/analysis_observer.hpp"
#include "tether/analysis/increment_problem.hpp"
#include "tether/analysis/newton.hpp"
#include "tether/analysis/procedure.hpp"
#include "tether/model/restart_state.hpp"

namespace tether {

/// Solves `problem` by `newton`, then asks every contribution whether it
/// accepts the converged state (augmented-Lagrangian updates and contact
/// guards may ask for another pass): another Newton pass while one asks for
/// it, at most 50. A ModelError from a contribution's acceptance ends the
/// attempt as an element failure. Adds the iterations of every pass to
/// `iterations`; reports iterations and repeated passes to `observer`.
NewtonOutcome solve_with_acceptance(NewtonSolver& newton, IncrementProblem& problem,
                                    const std::vector<Contribution*>& contributions, AnalysisObserver& observer,
                                    double averaged_force, int n_averaged, int& iterations);

/// The outcome of an attempt whose Newton ended with `newton` after `iterations` in all.
IncrementOutcome outcome_of(const NewtonOutcome& newton, int iterations);

/// The report of that attempt (AnalysisObserver::on_increment).
IncrementReport report_of(const IncrementAttempt& attempt, const NewtonOutcome& newton, int iterations);

/// Sets the step, increment, times and iterations of a converged attempt's results.
void stamp(IncrementResults& results, const IncrementAttempt& attempt, int iterations);

/// The time average of Newton's force scale q over the step's converged
/// increments (Newton's convergence test uses it), saved for a restart.
struct ForceAverage {
  double value = 0;
  int n = 0;
  void add(double q) {
    value = (value * n + q) / (n + 1);
    ++n;
  }
  void save(RestartState& state) const { state.averaged_force = value, state.n_averaged = n; }
  void restore(const RestartState& state) { value = state.averaged_force, n = state.n_averaged; }
};

}  // namespace tether
