#pragma once
/// \file The increment of an implicit `*DYNAMIC` step: HHT-alpha with Newton.
///
/// The equation of motion at the end of the increment, divided by (1 + alpha),
///   M a / (1 + alpha) + C v + S(u) - f(t) - alpha / (1 + alpha) (S_n - f_n) = 0,
/// is solved for u by the same Newton and contributions as a static step, the
/// inertia and damping being one more contribution per element
/// (ElementInertia) with Newmark's a(u), v(u), beta = (1 - alpha)^2 / 4 and
/// gamma = 1/2 - alpha. S collects every other contribution (elements,
/// constraints with their multipliers, contact, pressures). At the step's
/// start the accelerations come from M a0 = f(0) - S(u0) (free dofs). After
/// each converged increment the velocities, accelerations, reactions (with
/// inertia) and energies are reported. See docs/theory/dynamics.md.

#include <Eigen/Core>

#include "tether/analysis/analysis_observer.hpp"
#include "tether/analysis/contact_mass.hpp"
#include "tether/analysis/implicit_attempt.hpp"
#include "tether/analysis/increment_problem.hpp"
#include "tether/analysis/motion_state.hpp"
#include "tether/analysis/procedure.hpp"
#include "tether/analysis/step_system.hpp"

namespace tether {

class ImplicitDynamicProcedure final : public Procedure {
 public:
  /// `system`, `observer` and `motion` must outlive the procedure; `motion`
  /// carries velocities and energies between steps.
  ImplicitDynamicProcedure(StepSystem& system, AnalysisObserver& observer, bool stream_results, MotionState& motion);

  [[nodiscard]] std::string keyword() const override { return "*DYNAMIC"; }
  IncrementOutcome solve_increment(const IncrementAttempt& attempt, Eigen::VectorXd& u) override;
  [[nodiscard]] SolveTiming timing() const override;
  void save(RestartState& state) const override;
  void restore(const RestartState& state) override;

 private:
  /// At the first attempt of the step: initial velocities (first dynamic
  /// step), the loads at the step's start, the initial accelerations, HHT's
  /// start residual and the energy baseline.
  void start_step(const IncrementTimes& first, Eigen::VectorXd& u);
  /// Prescribed values, nodal forces and pressures at time `t`; `cloads_` the nodal forces.
  void apply_loads(double step_time, double period, double total_time, Eigen::VectorXd& u);
  /// Free displacement dofs move by the constant-acceleration guess u_n + dt v_n + dt^2/2 a_n.
  void predict(double dt, Eigen::VectorXd& u) const;
  /// Residual of the contributions other than inertia, minus the nodal forces, at `s`.
  Eigen::VectorXd static_residual(const EvaluationState& s);
  /// Sum of the inertia contributions' residuals at `s` (scaled by 1 / (1 + alpha)).
  Eigen::VectorXd inertia_force(const EvaluationState& s) const;
  /// Applied forces (nodal and pressures) at `s` plus `reaction` at prescribed dofs.
  Eigen::VectorXd work_force(const EvaluationState& s, const Eigen::VectorXd& reaction) const;
  /// Energies at `s` with velocities motion_.v, given the new work force:
  /// work and viscous dissipation by the trapezoidal rule in u (force times
  /// displacement increment), friction from the contact results.
  void update_energy(const EvaluationState& s, const Eigen::VectorXd& force, const IncrementResults& results);
  /// HAFTOL: rejects a converged attempt whose half_increment_residual()
  /// exceeds the tolerance, with a cut-back estimate 0.85 sqrt(HAFTOL / r)
  /// in [0.25, 0.75]; after an accepted one the next increment grows by that
  /// estimate (within the growth factor) when r < HAFTOL / 2, else stays.
  void judge_half_increment(const IncrementTimes& t, const IncrementProblem& problem, IncrementOutcome& out,
                            IncrementReport& report);
  /// Largest residual [force] of the equation of motion M a + C v + S(u) - f
  /// over the free displacement equations at the middle of the converged
  /// increment ending at `end`: u, v, a at t_n + dt/2 by Newmark's relations
  /// over dt/2 with a(t_n + dt/2) = (a_n + a_n+1)/2, multipliers the mean of
  /// both ends, loads and prescribed values at the middle. Leaves the loads,
  /// pairing and contact status of `end` in place afterwards.
  double half_increment_residual(const IncrementTimes& t, const EvaluationState& end);
  void complete(const IncrementAttempt& attempt, const IncrementProblem& problem, int iterations,
                double force_scale);
  /// Dofs with a prescribed velocity (*BOUNDARY, TYPE=VELOCITY) take it as
  /// their v at `step_time` and its mean rate over the last `dt` as their a
  /// (0 at the step's start), rather than Newmark's recursion, which rings
  /// after a velocity jump. `step_start` is the total time at the step's start.
  void follow_prescribed_velocities(double step_start, double step_time, double dt);

  StepSystem& system_;
  AnalysisObserver& observer_;
  bool stream_results_;
  MotionState& motion_;
  NewtonSolver newton_;
  double alpha_, beta_, gamma_;
  bool started_ = false;
  Eigen::VectorXd cloads_;     ///< nodal forces at the attempt's end time, over all dofs
  Eigen::VectorXd external_;   ///< cloads_ + alpha/(1+alpha) * the previous static residual
  ForceAverage force_average_;
  ContactMassSummary contact_mass_;
  /// Displacement dofs whose mass was moved away (zero row of M): their
  /// Newmark v and a are not set by the equation of motion (see complete()).
  std::vector<int> massless_;
  double output_seconds_ = 0;
};

}  // namespace tether
