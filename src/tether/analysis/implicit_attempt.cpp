#include "tether/analysis/implicit_attempt.hpp"

#include <string>

#include "tether/core/error.hpp"

namespace tether {

namespace {

/// Newton passes of one attempt before the contributions must accept its solution.
constexpr int kMaxAcceptancePasses = 50;

}  // namespace

NewtonOutcome solve_with_acceptance(NewtonSolver& newton, IncrementProblem& problem,
                                    const std::vector<Contribution*>& contributions, AnalysisObserver& observer,
                                    double averaged_force, int n_averaged, int& iterations) {
  NewtonOutcome outcome;
  for (int pass = 0; pass < kMaxAcceptancePasses; ++pass) {
    outcome = newton.solve(problem, averaged_force, n_averaged,
                           [&](int it, const IterationNorms& n) { observer.on_iteration(it, n); });
    iterations += outcome.iterations;
    if (outcome.status != NewtonOutcome::Status::Converged) break;
    bool again = false;
    std::string iterating;
    const EvaluationState s = problem.state();
    try {
      for (Contribution* c : contributions)
        if (c->on_converged(s) == Acceptance::Iterate) {
          if (!again) iterating = c->describe();
          again = true;
        }
    } catch (const ModelError& e) {
      outcome.status = NewtonOutcome::Status::ElementFailure;
      outcome.message = e.what();
      break;
    }
    if (!again) break;
    observer.on_message("converged state not accepted by " + iterating + " (augmented Lagrangian update or "
                        "contact nodes released by a contact guard): Newton pass " + std::to_string(pass + 2));
  }
  return outcome;
}

IncrementOutcome outcome_of(const NewtonOutcome& newton, int iterations) {
  IncrementOutcome out;
  out.converged = newton.status == NewtonOutcome::Status::Converged;
  out.iterations = iterations;
  out.message = newton.message;
  out.singular_at_start = newton.status == NewtonOutcome::Status::SingularMatrix && newton.singular_at_start;
  out.singular_multiplier = newton.singular_multiplier;
  return out;
}

IncrementReport report_of(const IncrementAttempt& attempt, const NewtonOutcome& newton, int iterations) {
  IncrementReport report;
  report.step = attempt.step;
  report.increment = attempt.increment;
  report.attempt = attempt.attempt;
  report.iterations = iterations;
  report.total_iterations = attempt.prior_iterations + iterations;
  report.step_time = attempt.time.step_time;
  report.total_time = attempt.time.total_time;
  report.increment_size = attempt.time.dt;
  report.residual = newton.force_residual;
  report.converged = newton.status == NewtonOutcome::Status::Converged;
  report.note = newton.message;
  return report;
}

void stamp(IncrementResults& results, const IncrementAttempt& attempt, int iterations) {
  results.step = attempt.step;
  results.increment = attempt.increment;
  results.step_time = attempt.time.step_time;
  results.total_time = attempt.time.total_time;
  results.increment_size = attempt.time.dt;
  results.period = attempt.time.period;
  results.iterations = iterations;
}

}  // namespace tether
