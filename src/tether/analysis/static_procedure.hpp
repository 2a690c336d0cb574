#pragma once
/// \file The increment of a `*STATIC` step: equilibrium at the end of the
/// increment by Newton's method.
///
/// An attempt sets the prescribed values, nodal forces and pressures to their
/// magnitudes at the end of the increment, solves the IncrementProblem by
/// Newton, and asks every contribution whether it accepts the converged state
/// (augmented-Lagrangian updates and contact guards may ask for another
/// Newton pass). A converged increment's results are built, then the
/// contributions commit their history. Newton's convergence test uses the
/// time average of the force scale over the step's increments, which the
/// procedure keeps (and saves for a restart).
///
/// Predictor: an attempt starts from the converged state moved on by the
/// last converged increment of the step scaled to the new increment size
/// (linear extrapolation of the displacements, as ABAQUS's *STATIC does by
/// default); the first increment of a step starts from the converged state
/// moved by the start tangent applied to the prescribed values' change
/// (start_tangent_predictor.hpp).
/// The prescribed values then overwrite their dofs. Multipliers are not
/// extrapolated. See docs/theory/newton.md.

#include <Eigen/Core>

#include "tether/analysis/analysis_observer.hpp"
#include "tether/analysis/implicit_attempt.hpp"
#include "tether/analysis/increment_problem.hpp"
#include "tether/analysis/procedure.hpp"
#include "tether/analysis/step_system.hpp"

namespace tether {

class StaticProcedure final : public Procedure {
 public:
  /// `system` and `observer` must outlive the procedure. `stream_results`:
  /// AnalysisOptions::stream_element_results.
  StaticProcedure(StepSystem& system, AnalysisObserver& observer, bool stream_results);

  [[nodiscard]] std::string keyword() const override { return "*STATIC"; }
  IncrementOutcome solve_increment(const IncrementAttempt& attempt, Eigen::VectorXd& u) override;
  [[nodiscard]] SolveTiming timing() const override;
  /// The time-averaged force scale and the number of increments in it, and
  /// the predictor's last increment.
  void save(RestartState& state) const override;
  void restore(const RestartState& state) override;

 private:
  /// A converged attempt: results, commit of the history, the force average, on_results.
  void complete(const IncrementAttempt& attempt, const IncrementProblem& problem, int iterations,
                double force_scale);

  StepSystem& system_;
  AnalysisObserver& observer_;
  bool stream_results_;
  NewtonSolver newton_;
  Eigen::VectorXd external_;  ///< nodal forces at the end of the increment, over all dofs
  ForceAverage force_average_;
  double output_seconds_ = 0;  ///< results and observer (on_results) in this step
  /// The predictor: displacement change of the step's last converged
  /// increment (displacement dofs only; empty before one) and its size.
  Eigen::VectorXd last_increment_;
  double last_dt_ = 0;
};

}  // namespace tether
