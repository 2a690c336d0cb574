#include "tether/analysis/static_analysis.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

#include "tether/analysis/amplitude.hpp"
#include "tether/analysis/increment_controller.hpp"
#include "tether/analysis/explicit_dynamic_procedure.hpp"
#include "tether/analysis/implicit_dynamic_procedure.hpp"
#include "tether/analysis/static_procedure.hpp"
#include "tether/analysis/step_system.hpp"
#include "tether/core/error.hpp"
#include "tether/solvers/condensed_solver.hpp"

namespace tether {

namespace {

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

/// Why a matrix singular at the first iteration of an attempt stops the step:
/// a redundant constraint, or a body the model does not restrain.
std::string singular_explanation(const IncrementOutcome& outcome, const Discretization& disc) {
  return outcome.message +
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
                                       "move it into contact with a prescribed displacement first")));
}

/// The procedure of a step.
std::unique_ptr<Procedure> make_procedure(StepSystem& system, AnalysisObserver& observer,
                                          const AnalysisOptions& options, MotionState& motion,
                                          const Eigen::VectorXd& u) {
  switch (system.step().procedure) {
    case StepProcedure::ImplicitDynamic:
      return std::make_unique<ImplicitDynamicProcedure>(system, observer, options.stream_element_results, motion);
    case StepProcedure::ExplicitDynamic:
      return std::make_unique<ExplicitDynamicProcedure>(system, observer, options.stream_element_results, motion, u);
    case StepProcedure::Static:
      break;
  }
  return std::make_unique<StaticProcedure>(system, observer, options.stream_element_results);
}

/// At every exit of a step (completed, stopped, or a thrown error): adds the
/// step's timing to the summary and says how the linear solver went (factors
/// kept on disk; the condensed solver's statistics).
/// "; dense system ..." for the step's condensation message: the size of the
/// last dense system factorized, how, and the smallest reciprocal condition
/// number estimate of the step's (equilibrated, 1-norm).
std::string dense_system(const CondensationStatistics& c) {
  if (c.dense_equations == 0) return "";
  char rcond[32];
  std::snprintf(rcond, sizeof rcond, "%.1e", c.smallest_dense_rcond);
  return "; dense system " + std::to_string(c.dense_equations) + " equations" +
         (c.dual_eliminations > 0 ? " after the dual elimination of the contact multipliers (" +
                                        std::to_string(c.dual_eliminations) + " factorizations, " +
                                        std::to_string(c.dual_closed) + " closed in the last)"
                                  : "") +
         ", " + (c.dense_cholesky ? "Cholesky" : "LU") + ", reciprocal condition >= " + rcond;
}

class StepEndReport {
 public:
  StepEndReport(AnalysisSummary& summary, const Procedure& procedure, const StepSystem& system,
                AnalysisObserver& observer, double memory_budget_mb, int step)
      : summary_(summary), procedure_(procedure), system_(system), observer_(observer),
        memory_budget_mb_(memory_budget_mb), step_(step) {}
  StepEndReport(const StepEndReport&) = delete;
  StepEndReport& operator=(const StepEndReport&) = delete;
  ~StepEndReport() {
    const SolveTiming t = procedure_.timing();
    SolveTiming& s = summary_.timing;
    s.contact_search += t.contact_search, s.assembly += t.assembly, s.analyse += t.analyse;
    s.factorize += t.factorize, s.solve += t.solve, s.factorizations += t.factorizations;
    s.reused_factorizations += t.reused_factorizations;
    if (system_.has_assembler()) {
      s.held_tangents += system_.assembler().linear_reuse().reused;
      s.full_tangents += system_.assembler().linear_reuse().full;
      s.residual_updates += system_.assembler().linear_reuse().residual_updates;
    }
    s.output += t.output;
    const CondensedSolver* condensed = system_.condensed();
    const LinearSolver& solver = system_.solver();
    if (!condensed && solver.out_of_core_factorizations() > 0)
      observer_.on_message("step " + std::to_string(step_) + ": the factors of " +
                           std::to_string(solver.out_of_core_factorizations()) + " of " +
                           std::to_string(t.factorizations) +
                           " factorization(s) were kept on disk in the temporary directory (memory budget " +
                           std::to_string(static_cast<long long>(memory_budget_mb_)) + " MB)");
    if (!condensed || t.factorizations == 0) return;
    const CondensationStatistics& c = condensed->statistics();
    s.sparse_factorizations += c.sparse_factorizations;
    observer_.on_message("step " + std::to_string(step_) + ": linear solver condensed onto " +
                         std::to_string(c.interface_equations) + " contact equations: " +
                         std::to_string(c.sparse_factorizations) + " sparse factorization(s), " +
                         std::to_string(c.reuses) + " reuse(s), " + std::to_string(c.fallbacks) +
                         " full factorization(s); bulk factors " +
                         std::to_string(static_cast<long long>(c.factor_entries)) + " entries, " +
                         std::to_string(c.factor_memory_mb) + " MB" + (c.out_of_core ? " in core, the factors on disk" : "") +
                         dense_system(c) +
                         (c.gave_up ? " (stopped condensing: the matrix outside the contact equations changed twice in a row or is singular)"
                                    : ""));
  }

 private:
  AnalysisSummary& summary_;
  const Procedure& procedure_;
  const StepSystem& system_;
  AnalysisObserver& observer_;
  double memory_budget_mb_;
  int step_;
};

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

bool StaticAnalysis::run_step(int index, AnalysisSummary& summary) {
  const Step& step = model_.steps[index];
  const Discretization& disc = *discretization_;
  // A restart within this step continues its time stepping; the loads ramp
  // from the values at the step's start, as in the run that saved the state.
  std::unique_ptr<RestartState> resumed;
  if (resume_ && !resume_->step_completed && resume_->step == index + 1) resumed = std::move(resume_);
  resume_.reset();
  // The unknowns at the step's start: the loads ramp from them, and the
  // restart states saved within the step hold them. Without restart output
  // (and not resumed) no copy is kept: u_ is the start when the loads are
  // made, and nothing reads it later (a vector of all dofs less in memory
  // through the step).
  Eigen::VectorXd u_step_start;
  if (resumed)
    u_step_start = Eigen::Map<const Eigen::VectorXd>(resumed->u_step_start.data(), u_.size());
  else if (step.restart_frequency > 0)
    u_step_start = u_;
  StepSystem system(disc, step,
                    make_step_loads(step, disc.dofs(), u_step_start.size() > 0 ? u_step_start : u_, cload_end_,
                                    pressure_end_),
                    u_,
                    total_time_, SolverSettings{options_.solver, options_.condense_contact, options_.memory_budget_mb,
                                   options_.reuse_linear_bulk, options_.mortar_condensation,
                                   options_.condense_any_size},
                    [&](const std::string& m) {
                      if (index == 0) observer_.on_message(m);
                    });
  const std::unique_ptr<Procedure> procedure = make_procedure(system, observer_, options_, motion_, u_);
  IncrementController clock(procedure->time_stepping(step), total_time_);
  if (resumed) {
    clock.restore(*resumed);
    procedure->restore(*resumed);
  }
  const StepEndReport step_end(summary, *procedure, system, observer_, options_.memory_budget_mb, index + 1);
  const auto stop = [&](const std::string& why) {
    summary.message = "step " + std::to_string(index + 1) + " stopped at step time " + format_time(clock.step_time()) +
                      ": " + why +
                      (summary.increments > 0 ? "; the last converged increment has been written"
                                              : "; no increment converged, so there are no results");
    return false;
  };

  while (!clock.finished()) {
    if (clock.out_of_increments())
      return stop("the maximum number of increments (INC=" + std::to_string(clock.max_increments()) +
                  ") was reached" + non_convergence_hint(disc));
    const IncrementAttempt attempt{index + 1, clock.increment() + 1, clock.attempt(), clock.next_attempt(),
                                   summary.iterations};
    const IncrementOutcome outcome = procedure->solve_increment(attempt, u_);
    summary.iterations += outcome.iterations;
    if (outcome.converged) {
      if (!after_converged(index, attempt, outcome, summary, clock, *procedure, u_step_start)) return false;
      // A restart state was saved: go on as a run resumed from it (bit for bit).
      if (system.has_assembler() && !attempt.time.ends_step && restart_due(step, clock))
        system.assembler().restart_point();
      continue;
    }
    ++summary.cutbacks;
    if (outcome.singular_at_start) return stop(singular_explanation(outcome, disc));
    const IncrementController::CutBack cut = clock.cut_back(outcome.increment_scale);
    if (cut != IncrementController::CutBack::Retry)
      return stop(outcome.message + clock.stop_reason(cut, procedure->keyword()) + non_convergence_hint(disc));
    observer_.on_message("cut back to increment " + format_time(clock.dt()) + ": " + outcome.message);
  }
  carry_loads(system.loads(), clock.period());
  if (step.restart_frequency > 0)
    observer_.on_restart_state(restart_state(index, true, summary, clock, *procedure, u_step_start));
  return true;
}

bool StaticAnalysis::restart_due(const Step& step, const IncrementController& clock) {
  return step.restart_frequency > 0 && clock.increment() % step.restart_frequency == 0;
}

bool StaticAnalysis::after_converged(int index, const IncrementAttempt& attempt, const IncrementOutcome& outcome,
                                     AnalysisSummary& summary, IncrementController& clock, const Procedure& procedure,
                                     const Eigen::VectorXd& u_step_start) {
  clock.accept(attempt.time, outcome.iterations, outcome.increment_scale);
  total_time_ = attempt.time.total_time;
  ++summary.increments;
  ++run_increments_;
  if (attempt.time.ends_step) return true;  // the end of the step is saved after the step
  const Step& step = model_.steps[index];
  if (restart_due(step, clock))
    observer_.on_restart_state(restart_state(index, false, summary, clock, procedure, u_step_start));
  if (options_.stop_after_increments > 0 && run_increments_ >= options_.stop_after_increments) {
    summary.message = "stopped after " + std::to_string(run_increments_) + " increment(s) as requested";
    return false;
  }
  return true;
}

void StaticAnalysis::carry_loads(const StepLoads& loads, double period) {
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
}

}  // namespace tether
