#include "tether/analysis/static_procedure.hpp"

#include <chrono>

#include "tether/analysis/implicit_attempt.hpp"
#include "tether/analysis/results_builder.hpp"
#include "tether/analysis/start_tangent_predictor.hpp"
#include "tether/core/error.hpp"
#include "tether/output/output_schedule.hpp"

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
  const Eigen::Index nd = disc.dofs().n_displacement_dofs();
  // Linear extrapolation of the last increment: without it the first
  // iteration starts from the converged state with only the prescribed dofs
  // moved, and its tangent is taken where the elements next to them are
  // strained by the whole increment (a necking bar's ends yield far more than
  // the bar does), so the first correction is a poor one.
  bool predict = system_.step().extrapolate && last_dt_ > 0 && last_increment_.size() == nd;
  for (;;) {
    if (predict) u.head(nd) += (t.dt / last_dt_) * last_increment_;
    system_.apply_loads(t, u, external_);
    const IncrementTime time{t.step_time, t.total_time, t.dt, system_.step().nlgeom};
    // Without an extrapolation (a step's first increment), the free dofs
    // follow the prescribed values' change by the start tangent, as CalculiX
    // and ABAQUS start an increment (docs/theory/newton.md).
    NewtonOutcome newton;
    int iterations = 0;
    try {
      if (!predict && start_tangent_predictor_applies(system_))
        apply_start_tangent_predictor(system_, time, u_start, external_, u);
    } catch (const ModelError& e) {
      newton.status = NewtonOutcome::Status::ElementFailure;
      newton.message = e.what();
    }
    IncrementProblem problem(system_.assembler(), disc.dofs(), u, u_start, external_, system_.load_contributions(),
                             time, system_.symmetric(), &disc.contact_pairs(), &disc.mortar_pairs());
    if (newton.status != NewtonOutcome::Status::ElementFailure)
      newton = solve_with_acceptance(newton_, problem, system_.contributions(), observer_, force_average_.value,
                                     force_average_.n, iterations);
    const IncrementOutcome out = outcome_of(newton, iterations);
    if (!out.converged) u = u_start;  // restore the converged state
    // A matrix singular at the predicted start (a body the extrapolation
    // moved out of its contact floats) says nothing about the increment,
    // which a singular start would end: solve it again from the converged state.
    if (!out.converged && predict && out.singular_at_start) {
      predict = false;
      continue;
    }
    observer_.on_increment(report_of(attempt, newton, iterations));
    if (out.converged) {
      last_increment_ = (u - u_start).head(nd);
      last_dt_ = t.dt;
      complete(attempt, problem, iterations, newton.force_scale);
    }
    return out;
  }
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
  // What the results hold follows what is written (see IncrementResults::element_fields):
  // stored results (a Job keeping its increments, Python) hold everything; streamed ones
  // (the writers of `tether run`) build the element fields -- every element's
  // extrapolation and nodal averages -- only when the result files are due, the one
  // output that reads them. The .dat's element prints take their own elements' points
  // from the point source; the node, contact, multiplier, energy and restart output
  // read node and contact values, which are always built.
  IncrementResults when;
  stamp(when, attempt, iterations);
  const bool element_fields =
      !stream_results_ ||
      files_due(system_.step().outputs, StepProcedure::Static, when, attempt.time.ends_step);
  const DiscretizationPoints point_source(disc, s);
  IncrementResults results = build_results(disc, s, problem.full_residual(), system_.equations(),
                                           stream_results_ ? &point_source : nullptr, element_fields);
  for (Contribution* c : system_.contributions()) c->commit(s);
  force_average_.add(force_scale);
  stamp(results, attempt, iterations);
  observer_.on_results(results, system_.step(), attempt.time.ends_step);
  output_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - output_start).count();
}

SolveTiming StaticProcedure::timing() const {
  SolveTiming t = newton_.timing();
  t.output += output_seconds_;
  return t;
}

void StaticProcedure::save(RestartState& state) const {
  force_average_.save(state);
  state.predictor_increment.assign(last_increment_.data(), last_increment_.data() + last_increment_.size());
  state.predictor_dt = last_dt_;
}

void StaticProcedure::restore(const RestartState& state) {
  force_average_.restore(state);
  last_increment_ = Eigen::Map<const Eigen::VectorXd>(state.predictor_increment.data(),
                                                      static_cast<Eigen::Index>(state.predictor_increment.size()));
  last_dt_ = state.predictor_dt;
}

}  // namespace tether
