#include "tether/analysis/static_procedure.hpp"

#include <chrono>

#include "tether/analysis/amplitude.hpp"
#include "tether/analysis/results_builder.hpp"
#include "tether/core/error.hpp"

namespace tether {

namespace {

/// Newton passes of one attempt before the contributions must accept its solution.
constexpr int kMaxAcceptancePasses = 50;

}  // namespace

StaticProcedure::StaticProcedure(StepSystem& system, AnalysisObserver& observer, bool stream_results)
    : system_(system),
      observer_(observer),
      stream_results_(stream_results),
      newton_(system.solver(), system.step().controls, system.discretization().length_scale()),
      external_(Eigen::VectorXd::Zero(system.discretization().dofs().n_dofs())) {}

IncrementOutcome StaticProcedure::solve_increment(const IncrementAttempt& attempt, Eigen::VectorXd& u) {
  const IncrementTimes& t = attempt.time;
  const Discretization& disc = system_.discretization();
  const Eigen::VectorXd u_start = u;
  apply_loads(t, u);
  IncrementProblem problem(system_.assembler(), disc.dofs(), u, u_start, external_, system_.load_contributions(),
                           IncrementTime{t.step_time, t.total_time, t.dt, system_.step().nlgeom}, system_.symmetric(),
                           &disc.contact_pairs());
  int iterations = 0;
  const NewtonOutcome newton = solve_with_acceptance(problem, iterations);

  IncrementOutcome out;
  out.converged = newton.status == NewtonOutcome::Status::Converged;
  out.iterations = iterations;
  out.message = newton.message;
  out.singular_at_start = newton.status == NewtonOutcome::Status::SingularMatrix && newton.singular_at_start;
  out.singular_multiplier = newton.singular_multiplier;

  IncrementReport report;
  report.step = attempt.step;
  report.increment = attempt.increment;
  report.attempt = attempt.attempt;
  report.iterations = iterations;
  report.total_iterations = attempt.prior_iterations + iterations;
  report.step_time = t.step_time;
  report.total_time = t.total_time;
  report.increment_size = t.dt;
  report.residual = newton.force_residual;
  report.converged = out.converged;
  report.note = newton.message;
  observer_.on_increment(report);

  if (out.converged)
    complete(attempt, problem, iterations, newton.force_scale);
  else
    u = u_start;  // restore the converged state
  return out;
}

void StaticProcedure::apply_loads(const IncrementTimes& t, Eigen::VectorXd& u) {
  const Model& model = system_.discretization().model();
  const StepLoads& loads = system_.loads();
  const auto magnitude = [&](const RampedValue& v) {
    return step_magnitude(model, v.amplitude, v.start, v.target, t.step_time, t.period, t.total_time);
  };
  for (const auto& [dof, v] : loads.prescribed) u[dof] = magnitude(v);
  system_.equations().update_dependents(u);
  external_.setZero();
  for (const auto& [dof, v] : loads.forces) external_[dof] += magnitude(v);
  const auto& pressures = system_.pressures();
  for (std::size_t k = 0; k < pressures.size(); ++k) pressures[k]->set_pressure(magnitude(loads.pressure_values[k]));
  system_.body_forces().set_time(t.step_time, t.period, t.total_time);
}

NewtonOutcome StaticProcedure::solve_with_acceptance(IncrementProblem& problem, int& iterations) {
  NewtonOutcome outcome;
  for (int pass = 0; pass < kMaxAcceptancePasses; ++pass) {
    outcome = newton_.solve(problem, averaged_force_, n_averaged_,
                            [&](int it, const IterationNorms& n) { observer_.on_iteration(it, n); });
    iterations += outcome.iterations;
    if (outcome.status != NewtonOutcome::Status::Converged) break;
    bool again = false;
    std::string iterating;
    const EvaluationState s = problem.state();
    try {
      for (Contribution* c : system_.contributions())
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
    observer_.on_message("converged state not accepted by " + iterating + " (augmented Lagrangian update or "
                         "contact nodes released by a contact guard): Newton pass " + std::to_string(pass + 2));
  }
  return outcome;
}

void StaticProcedure::complete(const IncrementAttempt& attempt, const IncrementProblem& problem, int iterations,
                               double force_scale) {
  const Discretization& disc = system_.discretization();
  const EvaluationState s = problem.state();
  const auto output_start = std::chrono::steady_clock::now();
  // Results first: they describe the increment (contact slip since the
  // last converged state), which commit() then makes history.
  // Streamed element values are computed from s.u during on_results,
  // after commit(): elements keep no history, so they are the same.
  const DiscretizationPoints point_source(disc, s);
  IncrementResults results = build_results(disc, s, problem.full_residual(), system_.equations(),
                                           stream_results_ ? &point_source : nullptr);
  for (Contribution* c : system_.contributions()) c->commit(s);
  averaged_force_ = (averaged_force_ * n_averaged_ + force_scale) / (n_averaged_ + 1);
  ++n_averaged_;

  results.step = attempt.step;
  results.increment = attempt.increment;
  results.step_time = attempt.time.step_time;
  results.total_time = attempt.time.total_time;
  results.iterations = iterations;
  observer_.on_results(results, system_.step(), attempt.time.ends_step);
  output_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - output_start).count();
}

SolveTiming StaticProcedure::timing() const {
  SolveTiming t = newton_.timing();
  t.output += output_seconds_;
  return t;
}

void StaticProcedure::save(RestartState& state) const {
  state.averaged_force = averaged_force_;
  state.n_averaged = n_averaged_;
}

void StaticProcedure::restore(const RestartState& state) {
  averaged_force_ = state.averaged_force;
  n_averaged_ = state.n_averaged;
}

}  // namespace tether
