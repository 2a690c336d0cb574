#include "tether/analysis/static_analysis.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "tether/analysis/amplitude.hpp"
#include "tether/analysis/constraint_checks.hpp"
#include "tether/analysis/increment_problem.hpp"
#include "tether/analysis/newton.hpp"
#include "tether/analysis/results_builder.hpp"
#include "tether/analysis/step_loads.hpp"
#include "tether/assembly/assembler.hpp"
#include "tether/core/error.hpp"

namespace tether {

namespace {

constexpr int kMaxAcceptancePasses = 50;

std::string format_time(double t) {
  std::ostringstream s;
  s.precision(6);
  s << t;
  return s.str();
}

}  // namespace

StaticAnalysis::StaticAnalysis(const Model& model, AnalysisObserver& observer, AnalysisOptions options)
    : model_(model),
      observer_(observer),
      options_(options),
      discretization_(std::make_unique<Discretization>(model)),
      u_(Eigen::VectorXd::Zero(discretization_->dofs().n_dofs())) {}

StaticAnalysis::~StaticAnalysis() = default;

AnalysisSummary StaticAnalysis::run() {
  AnalysisSummary summary;
  if (model_.steps.empty()) {
    summary.message = "the deck defines no *STEP";
    return summary;
  }
  for (int s = 0; s < static_cast<int>(model_.steps.size()); ++s) {
    try {
      if (!run_step(s, summary)) return summary;
    } catch (const ModelError& e) {
      // A model problem found while setting the step up (a redundant constraint, ...).
      summary.message = "step " + std::to_string(s + 1) + " cannot be solved: " + e.what() +
                        (summary.increments > 0 ? "; the last converged increment has been written" : "");
      return summary;
    }
    ++summary.steps;
  }
  summary.completed = true;
  summary.message = "analysis complete";
  return summary;
}

bool StaticAnalysis::run_step(int index, AnalysisSummary& summary) {
  const Step& step = model_.steps[index];
  const Discretization& disc = *discretization_;
  const DofMap& dofs = disc.dofs();
  const StepLoads loads = make_step_loads(step, dofs, u_, cload_end_, pressure_end_);

  // Contributions of this step: every element, then the pressure loads.
  auto pressures = disc.make_pressures(loads.pressures);
  std::vector<Contribution*> contributions;
  contributions.reserve(disc.elements().size() + disc.constraints().size() + disc.user_constraints().size() +
                        pressures.size());
  for (const auto& e : disc.elements()) contributions.push_back(e.get());
  for (const auto& c : disc.constraints()) contributions.push_back(c.get());
  for (const auto& c : disc.user_constraints()) contributions.push_back(c.get());
  for (const auto& pair : disc.contact_pairs()) {
    contributions.push_back(pair.get());  // searches before its nodes are evaluated
    for (Contribution* node : pair->nodes()) contributions.push_back(node);
  }
  std::vector<const Contribution*> load_contributions;
  for (const auto& p : pressures) contributions.push_back(p.get()), load_contributions.push_back(p.get());

  std::vector<bool> prescribed(dofs.n_dofs(), false);
  for (const auto& [dof, value] : loads.prescribed) prescribed[dof] = true;
  // Nodes no element or constraint uses have no dofs (as in ABAQUS): their
  // displacements are held at zero instead of making the matrix singular.
  std::vector<bool> used(dofs.n_dofs(), false);
  for (const Contribution* c : contributions)
    for (int d : c->dofs()) used[d] = true;
  for (const auto& row : disc.elimination_rows())
    for (const auto& term : row.terms) used[term.first] = true;
  int unused_nodes = 0;
  for (int node = 0; node < dofs.n_nodes(); ++node) {
    bool any = false;
    for (int c = 0; c < kDofsPerNode; ++c) any = any || used[dofs.displacement(node, c)];
    if (any) continue;
    ++unused_nodes;
    for (int c = 0; c < kDofsPerNode; ++c) prescribed[dofs.displacement(node, c)] = true;
  }
  if (unused_nodes > 0 && index == 0)
    observer_.on_message(std::to_string(unused_nodes) +
                         " node(s) belong to no element; they get no degrees of freedom");
  Assembler assembler(contributions, EquationMap(prescribed, disc.elimination_rows()));
  check_constraints(disc, assembler.equations(), EvaluationState{u_, u_, 0, total_time_, 0, step.nlgeom});
  auto solver = make_linear_solver(options_.solver);
  NewtonSolver newton(*solver, step.controls, disc.length_scale());
  // The tangent is symmetric unless follower pressure, friction or a user
  // routine (its Hessian comes from finite differences) makes it otherwise;
  // the solver then picks Cholesky (positive definite) or LDLT (multipliers).
  bool unsymmetric = step.nlgeom && !pressures.empty();
  for (const auto& pair : disc.contact_pairs()) unsymmetric = unsymmetric || pair->mu() > 0;
  unsymmetric = unsymmetric || !disc.user_constraints().empty();
  for (const ConstraintData& c : model_.constraints) unsymmetric = unsymmetric || c.kind == ConstraintData::Kind::UserMpc;
  const bool symmetric = !unsymmetric;

  const double period = step.period > 0 ? step.period : 1.0;
  const double max_dt = step.max_increment > 0 ? step.max_increment : period;
  double dt = std::min(step.initial_increment > 0 ? step.initial_increment : period, max_dt);
  const double min_dt = step.min_increment > 0 ? step.min_increment : std::min(1e-5 * period, dt);
  const Controls& controls = step.controls;

  Eigen::VectorXd external = Eigen::VectorXd::Zero(dofs.n_dofs());
  double step_time = 0;
  int increment = 0, attempt = 1, easy_in_row = 0;
  double averaged_force = 0;
  int n_averaged = 0;
  const double step_start_time = total_time_;

  double output_seconds = 0;
  // Adds this step's timing to the summary (at every exit of the step).
  struct TimingGuard {
    AnalysisSummary& summary;
    const NewtonSolver& newton;
    const double& output;
    ~TimingGuard() {
      const SolveTiming& t = newton.timing();
      SolveTiming& s = summary.timing;
      s.contact_search += t.contact_search, s.assembly += t.assembly, s.analyse += t.analyse;
      s.factorize += t.factorize, s.solve += t.solve, s.factorizations += t.factorizations;
      s.output += output;
    }
  } timing_guard{summary, newton, output_seconds};

  auto stop = [&](const std::string& why) {
    summary.message = "step " + std::to_string(index + 1) + " stopped at step time " + format_time(step_time) +
                      ": " + why +
                      (summary.increments > 0 ? "; the last converged increment has been written"
                                              : "; no increment converged, so there are no results");
    return false;
  };

  while (step_time < period * (1 - 1e-12)) {
    if (increment >= step.max_increments)
      return stop("the maximum number of increments (INC=" + std::to_string(step.max_increments) + ") was reached");
    dt = std::min(dt, period - step_time);
    if (period - step_time - dt < 1e-9 * period) dt = period - step_time;
    const double t_new = step_time + dt;
    const double total_new = step_start_time + t_new;

    // Apply the state at the end of the increment.
    const Eigen::VectorXd u_start = u_;
    for (const auto& [dof, v] : loads.prescribed)
      u_[dof] = step_magnitude(model_, v.amplitude, v.start, v.target, t_new, period, total_new);
    assembler.equations().update_dependents(u_);
    external.setZero();
    for (const auto& [dof, v] : loads.forces)
      external[dof] += step_magnitude(model_, v.amplitude, v.start, v.target, t_new, period, total_new);
    for (std::size_t k = 0; k < pressures.size(); ++k) {
      const RampedValue& v = loads.pressure_values[k];
      pressures[k]->set_pressure(step_magnitude(model_, v.amplitude, v.start, v.target, t_new, period, total_new));
    }

    IncrementProblem problem(assembler, dofs, u_, u_start, external, load_contributions,
                             IncrementTime{t_new, total_new, dt, step.nlgeom}, symmetric);
    NewtonOutcome outcome;
    int iterations = 0;
    for (int pass = 0; pass < kMaxAcceptancePasses; ++pass) {
      outcome = newton.solve(problem, averaged_force, n_averaged,
                             [&](int it, const IterationNorms& n) {
                               if (disc.contact_pairs().empty()) return observer_.on_iteration(it, n);
                               IterationNorms with_contact = n;
                               with_contact.contact_closed = 0;
                               for (const auto& pair : disc.contact_pairs()) {
                                 const ContactIterationStatistics& c = pair->statistics();
                                 with_contact.contact_closed += c.closed;
                                 with_contact.contact_changes += c.status_changes;
                                 with_contact.contact_repaired += c.repaired;
                                 with_contact.contact_held += c.held_closed;
                               }
                               observer_.on_iteration(it, with_contact);
                             });
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
      observer_.on_message("converged state not accepted by " + iterating + " (augmented Lagrangian update or "
                           "contact nodes released by the chattering guard): Newton pass " + std::to_string(pass + 2));
    }
    summary.iterations += iterations;

    IncrementReport report;
    report.step = index + 1;
    report.increment = increment + 1;
    report.attempt = attempt;
    report.iterations = iterations;
    report.total_iterations = summary.iterations;
    report.step_time = t_new;
    report.total_time = total_new;
    report.increment_size = dt;
    report.residual = outcome.force_residual;
    report.converged = outcome.status == NewtonOutcome::Status::Converged;
    report.note = outcome.message;
    observer_.on_increment(report);

    if (report.converged) {
      const EvaluationState s = problem.state();
      const auto output_start = std::chrono::steady_clock::now();
      // Results first: they describe the increment (contact slip since the
      // last converged state), which commit() then makes history.
      IncrementResults results = build_results(disc, s, problem.full_residual(), assembler.equations());
      for (Contribution* c : contributions) c->commit(s);
      step_time = t_new;
      total_time_ = total_new;
      ++increment;
      ++summary.increments;
      averaged_force = (averaged_force * n_averaged + outcome.force_scale) / (n_averaged + 1);
      ++n_averaged;
      attempt = 1;

      results.step = index + 1;
      results.increment = increment;
      results.step_time = step_time;
      results.total_time = total_time_;
      results.iterations = iterations;
      observer_.on_results(results, step, step_time >= period * (1 - 1e-12));
      output_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - output_start).count();

      if (!step.direct) {
        easy_in_row = iterations <= controls.easy_iterations ? easy_in_row + 1 : 0;
        if (easy_in_row >= 2) {
          dt = std::min(dt * controls.growth_factor, max_dt);
          easy_in_row = 0;
        }
      }
      continue;
    }

    // Failed attempt: restore the converged state.
    u_ = u_start;
    ++summary.cutbacks;
    if (outcome.status == NewtonOutcome::Status::SingularMatrix && outcome.singular_at_start)
      return stop(outcome.message +
                  (outcome.singular_multiplier
                       ? " — this constraint is redundant or conflicts with others: it repeats other constraints "
                         "or *BOUNDARY conditions, or its gradient vanishes on the free dofs; remove it, or "
                         "regularise it with EPSILON"
                       : " — the model is not restrained there (a rigid-body mode, or a dof that no element "
                         "or constraint stiffens); add *BOUNDARY conditions or check the connectivity" +
                             (disc.contact_pairs().empty()
                                  ? std::string()
                                  : std::string("; a body held only by contact floats while its contact is "
                                                "open: let it start touching (a gap of exactly 0 counts as "
                                                "closed), close initial gaps with ADJUST= on *CONTACT PAIR, or "
                                                "move it into contact with a prescribed displacement first"))));
    if (step.direct) return stop(outcome.message + " with fixed increments (*STATIC, DIRECT)");
    if (attempt > controls.max_cutbacks)
      return stop(outcome.message + " after " + std::to_string(controls.max_cutbacks) + " cut-backs");
    dt *= controls.cutback_factor;
    easy_in_row = 0;
    ++attempt;
    if (dt < min_dt * (1 - 1e-12))
      return stop(outcome.message + "; the increment would fall below the minimum " + format_time(min_dt));
    observer_.on_message("cut back to increment " + format_time(dt) + ": " + outcome.message);
  }

  // Remember the load magnitudes at the end of the step.
  cload_end_.clear();
  for (std::size_t k = 0; k < loads.forces.size(); ++k) {
    const RampedValue& v = loads.forces[k].second;
    cload_end_[loads.force_keys[k]] = step_magnitude(model_, v.amplitude, v.start, v.target, period, period, total_time_);
  }
  pressure_end_.clear();
  for (std::size_t k = 0; k < loads.pressures.size(); ++k) {
    const RampedValue& v = loads.pressure_values[k];
    pressure_end_[{loads.pressures[k].face.element, loads.pressures[k].face.face}] =
        step_magnitude(model_, v.amplitude, v.start, v.target, period, period, total_time_);
  }
  return true;
}

}  // namespace tether
