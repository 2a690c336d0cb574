#pragma once
/// \file The step loop of an analysis: increments with automatic cut-back and growth.
///
/// For every `*STEP` the driver builds the step's StepSystem (contributions,
/// equations, assembler, solver), its IncrementController (time stepping)
/// and its Procedure (what an increment does: a `*STATIC` step solves
/// equilibrium by Newton, with the prescribed displacements and loads ramped
/// or scaled by their amplitudes over the step period). A failed attempt is
/// cut back by the controls' factor; growth follows two easy increments. When
/// the increment would fall below the minimum, or the model is singular, the
/// analysis stops: the last converged increment has already been reported and
/// the summary says why it stopped. See docs/theory/procedures.md.

#include <Eigen/Core>
#include <map>
#include <memory>
#include <string>

#include "tether/analysis/analysis_observer.hpp"
#include "tether/analysis/discretization.hpp"
#include "tether/analysis/motion_state.hpp"
#include "tether/analysis/newton.hpp"
#include "tether/solvers/dual_condensation.hpp"
#include "tether/solvers/linear_solver.hpp"

namespace tether {

struct AnalysisOptions {
  SolverKind solver = SolverKind::Auto;
  /// With the Auto solver and contact: condense the sparse system onto the
  /// contact equations and factorize the rest only when it changes
  /// (CondensedSolver; docs/theory/condensation.md). Off: every Newton
  /// iteration factorizes the whole matrix.
  bool condense_contact = true;
  /// Memory the run may use [MB] (`tether run --memory`), 0 for no limit:
  /// sparse MUMPS factors that would not fit are kept out of core.
  double memory_budget_mb = 0;
  /// A step whose bulk is linear in u (small strain, elastic) assembles its
  /// bulk's tangent once and factorizes an unchanged tangent once
  /// (SolverSettings::reuse_linear_bulk); off: at every iteration. The
  /// results are the same bit for bit.
  bool reuse_linear_bulk = true;
  /// How mortar pairs' multipliers are eliminated (MortarCondensation;
  /// `tether run --mortar-condensation`).
  MortarCondensation mortar_condensation = MortarCondensation::Dense;
  /// Condense onto the contact equations whatever their number (tests; SolverSettings::condense_any_size).
  bool condense_any_size = false;
  /// Streamed results: the IncrementResults handed to the observer carry no
  /// integration-point values (`points` empty) but each element's mean stress
  /// and a source that computes an element's points during on_results (see
  /// IncrementResults), so writing an increment takes memory per node rather
  /// than per integration point. For observers that write the results and do
  /// not keep them (`tether run`); off: every point is stored.
  bool stream_element_results = false;
  /// Tests of restart: stop (not completed) after this many converged
  /// increments of this run, as if the run had been killed there; 0 = never.
  int stop_after_increments = 0;
};

struct AnalysisSummary {
  bool completed = false;   ///< every step reached its end
  std::string message;      ///< "analysis complete" or why it stopped
  int steps = 0;            ///< steps completed
  int increments = 0;       ///< converged increments in all steps
  int iterations = 0;       ///< Newton iterations in all attempts
  int cutbacks = 0;         ///< failed attempts
  SolveTiming timing;       ///< where the time went (all steps)
};

class IncrementController;
class Procedure;
struct IncrementAttempt;
struct IncrementOutcome;
struct StepLoads;

class StaticAnalysis {
 public:
  /// The model must outlive the analysis. Throws ModelError if it cannot be discretized.
  StaticAnalysis(const Model& model, AnalysisObserver& observer, AnalysisOptions options = {});
  ~StaticAnalysis();

  /// Runs all steps (or, after resume(), the rest of the analysis). Never
  /// throws for a model that fails to converge or that a step cannot solve
  /// (singular, redundant constraints): the summary reports it.
  AnalysisSummary run();

  /// Continues from a saved state (`*RESTART, READ`, `tether run --restart`)
  /// instead of the beginning; call before run(). Checks that the state
  /// belongs to this model (node, element, dof and multiplier counts; hashes of
  /// the coordinates, the connectivity and the load history up to the saved
  /// step; the constraint and contact states) and to the STEP=/INC= of the
  /// deck's `*RESTART, READ`, and throws InputError naming `file` and what
  /// differs otherwise (nothing is changed then).
  void resume(const RestartState& state, const std::string& file);

  /// Global unknowns at the last converged increment.
  [[nodiscard]] const Eigen::VectorXd& solution() const { return u_; }
  [[nodiscard]] const Discretization& discretization() const { return *discretization_; }

 private:
  /// Runs step `index` (0-based); false when the analysis stops there (summary.message says why).
  bool run_step(int index, AnalysisSummary& summary);
  /// True when a converged increment (not the step's last) writes a restart
  /// state: every restart_frequency-th increment of the step.
  static bool restart_due(const Step& step, const IncrementController& clock);
  /// After a converged increment: the counters, a restart point, a requested
  /// stop (false).
  bool after_converged(int index, const IncrementAttempt& attempt, const IncrementOutcome& outcome,
                       AnalysisSummary& summary, IncrementController& clock, const Procedure& procedure,
                       const Eigen::VectorXd& u_step_start);
  /// Remembers the step's load magnitudes at its end (the next step ramps from them).
  void carry_loads(const StepLoads& loads, double period);
  /// Contributions with a history, in a fixed order (restart records refer to it).
  [[nodiscard]] std::vector<Contribution*> stateful_order() const;
  /// The state a restart point of step `index` saves: its progress, or (completed) its end.
  [[nodiscard]] RestartState restart_state(int index, bool completed, const AnalysisSummary& summary,
                                           const IncrementController& clock, const Procedure& procedure,
                                           const Eigen::VectorXd& u_step_start) const;

  const Model& model_;
  AnalysisObserver& observer_;
  AnalysisOptions options_;
  std::unique_ptr<Discretization> discretization_;
  Eigen::VectorXd u_;
  double total_time_ = 0;
  std::map<std::pair<int, int>, double> cload_end_;     ///< (node, dof) -> magnitude at the end of the last step
  std::map<std::pair<int, int>, double> pressure_end_;  ///< (element, face) -> magnitude at the end of the last step
  std::unique_ptr<RestartState> resume_;  ///< set by resume(): where run() continues
  std::string resume_file_;
  int run_increments_ = 0;                ///< converged increments of this run (stop_after_increments)
  MotionState motion_;                    ///< velocities and energies of dynamic steps
};

}  // namespace tether
