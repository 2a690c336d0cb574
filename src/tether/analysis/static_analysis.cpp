#include "tether/analysis/static_analysis.hpp"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cmath>
#include <sstream>

#include "tether/analysis/amplitude.hpp"
#include "tether/analysis/constraint_checks.hpp"
#include "tether/analysis/contact_builder.hpp"
#include "tether/analysis/increment_controller.hpp"
#include "tether/analysis/increment_problem.hpp"
#include "tether/analysis/newton.hpp"
#include "tether/analysis/restart.hpp"
#include "tether/analysis/results_builder.hpp"
#include "tether/analysis/step_loads.hpp"
#include "tether/analysis/step_system.hpp"
#include "tether/assembly/assembler.hpp"
#include "tether/core/error.hpp"
#include "tether/solvers/condensed_solver.hpp"

namespace tether {

namespace {

constexpr int kMaxAcceptancePasses = 50;

/// For a step that stopped without convergence: a known cause worth naming.
/// Coulomb friction over a faceted (unsmoothed, linear, several faces)
/// master surface stops Newton when loaded slave nodes cross the concave
/// kinks a deformable master forms at its nodes (docs/theory/contact.md,
/// "Re-pairing guard"); SMOOTH rounds those corners. Empty when no pair is
/// like that.
std::string non_convergence_hint(const Discretization& disc) {
  for (const auto& pair : disc.contact_pairs()) {
    const ContactPairSetup& p = pair->setup();
    if (pair->mu() <= 0 || p.smoothing > 0 || p.master_faces.size() < 2) continue;
    const bool linear = std::all_of(p.master_faces.begin(), p.master_faces.end(),
                                    [](const std::vector<int>& f) { return f.size() == 2; });
    if (linear)
      return "; " + p.name + " has friction over a faceted master surface, where Newton can stop as loaded slave "
             "nodes cross the master's nodes: SMOOTH=0.2 on *CONTACT PAIR (ABAQUS's default) rounds its corners, "
             "and the finer of the two surfaces should be the slave";
  }
  return "";
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
  int first = 0;
  if (resume_) {
    const RestartState& r = *resume_;
    summary.steps = r.steps_completed;
    summary.increments = r.increments;
    summary.iterations = r.iterations;
    summary.cutbacks = r.cutbacks;
    first = r.step_completed ? r.step : r.step - 1;
    observer_.on_message("restarted from " + resume_file_ + " at step " + std::to_string(r.step) + ", step time " +
                         format_time(r.step_time) + " (increment " + std::to_string(r.increment) + ", total time " +
                         format_time(r.total_time) + (r.step_completed ? ", end of the step" : "") + ")");
    if (first >= static_cast<int>(model_.steps.size()))
      observer_.on_message("the restart state is at the end of the last step: nothing left to run");
  }
  for (int s = first; s < static_cast<int>(model_.steps.size()); ++s) {
    try {
      if (!run_step(s, summary)) return summary;
    } catch (const ModelError& e) {
      // A model problem found while setting the step up (a redundant constraint, ...).
      summary.message = "step " + std::to_string(s + 1) + " cannot be solved: " + e.what() +
                        (summary.increments > 0 ? "; the last converged increment has been written" : "");
      return summary;
    }
    ++summary.steps;
    if (options_.stop_after_increments > 0 && run_increments_ >= options_.stop_after_increments &&
        s + 1 < static_cast<int>(model_.steps.size())) {
      summary.message = "stopped after " + std::to_string(run_increments_) + " increment(s) as requested";
      return summary;
    }
  }
  summary.completed = true;
  summary.message = "analysis complete";
  return summary;
}

std::vector<Contribution*> StaticAnalysis::stateful_order() const {
  const Discretization& disc = *discretization_;
  std::vector<Contribution*> out;
  for (const auto& e : disc.elements()) out.push_back(e.get());
  for (const auto& c : disc.constraints()) out.push_back(c.get());
  for (const auto& c : disc.user_constraints()) out.push_back(c.get());
  for (const auto& pair : disc.contact_pairs()) out.push_back(pair.get());
  return out;
}

void StaticAnalysis::resume(const RestartState& state, const std::string& file) {
  const SourceLocation where{file, 0};
  const auto refuse = [&](const std::string& why) {
    throw InputError(where, "cannot continue this deck from the restart file: " + why);
  };
  const int n_steps = static_cast<int>(model_.steps.size());
  if (state.step < 1 || state.increment < 0) refuse("bad step " + std::to_string(state.step));
  const std::vector<Contribution*> order = stateful_order();
  const RestartFingerprint deck =
      restart_fingerprint(model_, *discretization_, static_cast<int>(order.size()), state.step);
  if (const std::string diff = fingerprint_differences(deck, state.fingerprint); !diff.empty())
    refuse("it was written for another model (" + (state.deck.empty() ? std::string("?") : state.deck) + "): " + diff);
  if (state.step > n_steps || state.fingerprint.history_steps != state.step)
    refuse("inconsistent step " + std::to_string(state.step) + " (the deck has " + std::to_string(n_steps) + ")");
  if (model_.restart_read && model_.restart_read->step > 0) {
    const RestartRead& want = *model_.restart_read;
    if (want.step != state.step || (want.increment > 0 && want.increment != state.increment))
      throw InputError(want.where,
                       "*RESTART, READ asks for step " + std::to_string(want.step) +
                           (want.increment > 0 ? " increment " + std::to_string(want.increment) : std::string()) +
                           ", but " + file + " holds step " + std::to_string(state.step) + " increment " +
                           std::to_string(state.increment) +
                           " (only the last state written is kept: OVERLAY); restart from that one or rerun");
  }
  const auto n = static_cast<std::size_t>(discretization_->dofs().n_dofs());
  if (state.u.size() != n)
    refuse("it holds " + std::to_string(state.u.size()) + " unknowns, the model has " + std::to_string(n));
  if (!state.step_completed) {
    const Step& step = model_.steps[static_cast<std::size_t>(state.step - 1)];
    if (state.u_step_start.size() != n) refuse("the unknowns at the start of the step are missing");
    if (!(state.dt > 0) || !std::isfinite(state.dt) || !(state.step_time >= 0) || state.step_time > step.period ||
        state.n_averaged < 0 || state.easy_in_row < 0)
      refuse("bad time-stepping state (step time " + format_time(state.step_time) + ", increment " +
             format_time(state.dt) + ")");
  }
  for (const auto* loads : {&state.cload_end, &state.pressure_end})
    for (const CarriedLoad& l : *loads)
      if (l.first < 0 || l.first > INT32_MAX || l.second < 0 || l.second > INT32_MAX) refuse("bad carried load");

  // Contribution states: the file must have one record for each contribution
  // that has a history in this model, and none for others.
  std::vector<Contribution*> expected;
  std::vector<double> probe;
  for (Contribution* c : order) {
    probe.clear();
    c->save_state(probe);
    expected.push_back(probe.empty() ? nullptr : c);
  }
  std::size_t next = 0;
  for (const ContributionState& record : state.contributions) {
    if (record.index < 0 || record.index >= static_cast<std::int64_t>(order.size()))
      refuse("a contribution state refers to #" + std::to_string(record.index));
    const auto k = static_cast<std::size_t>(record.index);
    if (k < next) refuse("contribution states out of order");
    for (; next < k; ++next)
      if (expected[next]) refuse("no saved state for " + expected[next]->describe());
    if (!expected[k]) refuse("a saved state for " + order[k]->describe() + ", which has none in this deck");
    next = k + 1;
  }
  for (; next < order.size(); ++next)
    if (expected[next]) refuse("no saved state for " + expected[next]->describe());

  // Everything checked: load (a contribution may still refuse its record;
  // the ones loaded before it then get their previous state back).
  std::vector<std::vector<double>> previous;
  for (const ContributionState& record : state.contributions) {
    Contribution* c = order[static_cast<std::size_t>(record.index)];
    previous.emplace_back();
    c->save_state(previous.back());
    std::span<const double> in(record.values);
    std::string error;
    try {
      c->load_state(in);
      if (!in.empty()) error = std::to_string(in.size()) + " values too many in its saved state";
    } catch (const std::exception& e) {
      error = e.what();
    }
    if (!error.empty()) {
      for (std::size_t k = 0; k < previous.size(); ++k) {
        std::span<const double> back(previous[k]);
        order[static_cast<std::size_t>(state.contributions[k].index)]->load_state(back);
      }
      refuse(c->describe() + ": " + error);
    }
  }
  u_ = Eigen::Map<const Eigen::VectorXd>(state.u.data(), static_cast<Eigen::Index>(n));
  total_time_ = state.total_time;
  cload_end_.clear();
  for (const CarriedLoad& l : state.cload_end)
    cload_end_[{static_cast<int>(l.first), static_cast<int>(l.second)}] = l.value;
  pressure_end_.clear();
  for (const CarriedLoad& l : state.pressure_end)
    pressure_end_[{static_cast<int>(l.first), static_cast<int>(l.second)}] = l.value;
  resume_ = std::make_unique<RestartState>(state);
  resume_->u.clear();
  resume_file_ = file;
}

bool StaticAnalysis::run_step(int index, AnalysisSummary& summary) {
  const Step& step = model_.steps[index];
  const Discretization& disc = *discretization_;
  const DofMap& dofs = disc.dofs();
  // A restart within this step continues its time stepping; the loads ramp
  // from the values at the step's start, as in the run that saved the state.
  std::unique_ptr<RestartState> resumed;
  if (resume_ && !resume_->step_completed && resume_->step == index + 1) resumed = std::move(resume_);
  resume_.reset();
  const Eigen::VectorXd u_step_start =
      resumed ? Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(resumed->u_step_start.data(), u_.size())) : u_;
  StepSystem system(disc, step, make_step_loads(step, dofs, u_step_start, cload_end_, pressure_end_), u_, total_time_,
                    SolverSettings{options_.solver, options_.condense_contact, options_.memory_budget_mb},
                    [&](const std::string& m) {
                      if (index == 0) observer_.on_message(m);
                    });
  const StepLoads& loads = system.loads();
  const auto& pressures = system.pressures();
  const std::vector<Contribution*>& contributions = system.contributions();
  Assembler& assembler = system.assembler();
  const CondensedSolver* condensed = system.condensed();
  LinearSolver& solver = system.solver();
  NewtonSolver newton(solver, step.controls, disc.length_scale());
  const bool symmetric = system.symmetric();

  IncrementController clock(step, total_time_);
  const double period = clock.period();

  Eigen::VectorXd external = Eigen::VectorXd::Zero(dofs.n_dofs());
  double averaged_force = 0;
  int n_averaged = 0;
  if (resumed) {
    clock.restore(*resumed);
    averaged_force = resumed->averaged_force;
    n_averaged = resumed->n_averaged;
  }

  // The state *RESTART, WRITE saves: this step's progress, or (completed) its end.
  const auto save_restart = [&](bool completed) {
    RestartState r;
    r.written_by = std::string("tether ") + TETHER_VERSION;
    r.deck = model_.deck_path;
    const std::vector<Contribution*> order = stateful_order();
    r.fingerprint = restart_fingerprint(model_, disc, static_cast<int>(order.size()), index + 1);
    r.step = index + 1;
    clock.save(r);
    r.step_completed = completed;
    r.total_time = total_time_;
    r.averaged_force = averaged_force;
    r.n_averaged = n_averaged;
    r.steps_completed = summary.steps + (completed ? 1 : 0);
    r.increments = summary.increments;
    r.iterations = summary.iterations;
    r.cutbacks = summary.cutbacks;
    r.u.assign(u_.data(), u_.data() + u_.size());
    if (!completed) r.u_step_start.assign(u_step_start.data(), u_step_start.data() + u_step_start.size());
    for (const auto& [key, value] : cload_end_) r.cload_end.push_back({key.first, key.second, value});
    for (const auto& [key, value] : pressure_end_) r.pressure_end.push_back({key.first, key.second, value});
    for (std::size_t k = 0; k < order.size(); ++k) {
      ContributionState c;
      c.index = static_cast<std::int64_t>(k);
      order[k]->save_state(c.values);
      if (!c.values.empty()) r.contributions.push_back(std::move(c));
    }
    observer_.on_restart_state(r);
  };

  double output_seconds = 0;
  // Adds this step's timing to the summary (at every exit of the step) and
  // says how the condensed solver went.
  struct TimingGuard {
    AnalysisSummary& summary;
    const NewtonSolver& newton;
    const double& output;
    const CondensedSolver* condensed;
    const LinearSolver& solver;
    double memory_budget_mb;
    AnalysisObserver& observer;
    int step;
    ~TimingGuard() {
      const SolveTiming& t = newton.timing();
      SolveTiming& s = summary.timing;
      s.contact_search += t.contact_search, s.assembly += t.assembly, s.analyse += t.analyse;
      s.factorize += t.factorize, s.solve += t.solve, s.factorizations += t.factorizations;
      s.output += output;
      if (!condensed && solver.out_of_core_factorizations() > 0)
        observer.on_message("step " + std::to_string(step) + ": the factors of " +
                            std::to_string(solver.out_of_core_factorizations()) + " of " +
                            std::to_string(t.factorizations) +
                            " factorization(s) were kept on disk in the temporary directory (memory budget " +
                            std::to_string(static_cast<long long>(memory_budget_mb)) + " MB)");
      if (!condensed || t.factorizations == 0) return;
      const CondensationStatistics& c = condensed->statistics();
      s.sparse_factorizations += c.sparse_factorizations;
      observer.on_message("step " + std::to_string(step) + ": linear solver condensed onto " +
                          std::to_string(c.interface_equations) + " contact equations: " +
                          std::to_string(c.sparse_factorizations) + " sparse factorization(s), " +
                          std::to_string(c.reuses) + " reuse(s), " + std::to_string(c.fallbacks) +
                          " full factorization(s); bulk factors " +
                          std::to_string(static_cast<long long>(c.factor_entries)) + " entries, " +
                          std::to_string(c.factor_memory_mb) + " MB" + (c.out_of_core ? " in core, the factors on disk" : "") +
                          (c.gave_up ? " (stopped condensing: the matrix outside the contact equations changed twice in a row or is singular)"
                                     : ""));
    }
  } timing_guard{summary, newton, output_seconds, condensed, solver, options_.memory_budget_mb, observer_, index + 1};

  auto stop = [&](const std::string& why) {
    summary.message = "step " + std::to_string(index + 1) + " stopped at step time " + format_time(clock.step_time()) +
                      ": " + why +
                      (summary.increments > 0 ? "; the last converged increment has been written"
                                              : "; no increment converged, so there are no results");
    return false;
  };

  while (!clock.finished()) {
    if (clock.out_of_increments())
      return stop("the maximum number of increments (INC=" + std::to_string(clock.max_increments()) + ") was reached" +
                  non_convergence_hint(disc));
    const IncrementTimes times = clock.next_attempt();
    const double t_new = times.step_time, total_new = times.total_time, dt = times.dt;

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

    IncrementProblem problem(assembler, dofs, u_, u_start, external, system.load_contributions(),
                             IncrementTime{t_new, total_new, dt, step.nlgeom}, symmetric, &disc.contact_pairs());
    NewtonOutcome outcome;
    int iterations = 0;
    for (int pass = 0; pass < kMaxAcceptancePasses; ++pass) {
      outcome = newton.solve(problem, averaged_force, n_averaged,
                             [&](int it, const IterationNorms& n) { observer_.on_iteration(it, n); });
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
                           "contact nodes released by a contact guard): Newton pass " + std::to_string(pass + 2));
    }
    summary.iterations += iterations;

    IncrementReport report;
    report.step = index + 1;
    report.increment = clock.increment() + 1;
    report.attempt = clock.attempt();
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
      // Streamed element values are computed from s.u during on_results,
      // after commit(): elements keep no history, so they are the same.
      const DiscretizationPoints point_source(disc, s);
      IncrementResults results = build_results(disc, s, problem.full_residual(), assembler.equations(),
                                               options_.stream_element_results ? &point_source : nullptr);
      for (Contribution* c : contributions) c->commit(s);
      clock.accept(times, iterations);
      total_time_ = total_new;
      ++summary.increments;
      averaged_force = (averaged_force * n_averaged + outcome.force_scale) / (n_averaged + 1);
      ++n_averaged;

      results.step = index + 1;
      results.increment = clock.increment();
      results.step_time = t_new;
      results.total_time = total_time_;
      results.iterations = iterations;
      observer_.on_results(results, step, times.ends_step);
      output_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - output_start).count();

      ++run_increments_;
      if (!times.ends_step) {  // the end of the step is saved after the loop
        if (step.restart_frequency > 0 && clock.increment() % step.restart_frequency == 0) save_restart(false);
        if (options_.stop_after_increments > 0 && run_increments_ >= options_.stop_after_increments) {
          summary.message = "stopped after " + std::to_string(run_increments_) + " increment(s) as requested";
          return false;
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
                                                "open: let it start touching (a gap of 0, to within "
                                                "round-off, counts as closed), close initial gaps with ADJUST= on *CONTACT PAIR, or "
                                                "move it into contact with a prescribed displacement first"))));
    const IncrementController::CutBack cut = clock.cut_back();
    if (cut != IncrementController::CutBack::Retry)
      return stop(outcome.message + clock.stop_reason(cut, "*STATIC") + non_convergence_hint(disc));
    observer_.on_message("cut back to increment " + format_time(clock.dt()) + ": " + outcome.message);
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
  if (step.restart_frequency > 0) save_restart(true);
  return true;
}

}  // namespace tether
