#include "tether/analysis/static_procedure.hpp"

#include <chrono>

#include "tether/analysis/acceptance.hpp"
#include "tether/analysis/results_builder.hpp"
#include "tether/core/error.hpp"

namespace tether {

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
  system_.apply_loads(t, u, external_);
  IncrementProblem problem(system_.assembler(), disc.dofs(), u, u_start, external_, system_.load_contributions(),
                           IncrementTime{t.step_time, t.total_time, t.dt, system_.step().nlgeom}, system_.symmetric(),
                           &disc.contact_pairs());
  int iterations = 0;
  const NewtonOutcome newton = solve_with_acceptance(newton_, problem, system_.contributions(), observer_,
                                                     averaged_force_, n_averaged_, iterations);

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

void StaticProcedure::complete(const IncrementAttempt& attempt, const IncrementProblem& problem, int iterations,
                               double force_scale) {
  const Discretization& disc = system_.discretization();
  const EvaluationState s = problem.state();
  const auto output_start = std::chrono::steady_clock::now();
  // Results first: they describe the increment (contact slip since the
  // last converged state), which commit() then makes history.
  // Streamed element values are computed from s.u during on_results,
  // after commit(): an element with material history then reads the records
  // commit() stamped with s.u (ContinuumElement::point_values), so both are
  // the converged trial state of s.u, bit for bit.
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
