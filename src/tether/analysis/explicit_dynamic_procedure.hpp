#pragma once
/// \file The increment of a `*DYNAMIC, EXPLICIT` step: central differences
/// with the lumped mass, no Newton and no linear solver.
///
/// Each explicit increment h (velocity Verlet form of central differences):
///   v_{n+1/2} = v_{n-1/2} + (h_{n-1/2} + h_{n+1/2}) / 2 a_n,  u_{n+1} = u_n + h v_{n+1/2},
///   a_{n+1} = M^-1 (f_ext(t_{n+1}) - f_int(u_{n+1}))  at free dofs,
/// with f_int the elements' residuals evaluated without tangent (elements
/// whose every dof is held at a constant value: once per report interval,
/// not per increment; their forces only enter the reactions). Prescribed
/// dofs follow their values (and amplitudes): their half-step velocity is the
/// difference of the prescribed values, their acceleration the difference of
/// those velocities. Full-step velocities v_n = v_{n-1/2} + h/2 a_n are what
/// the results, the kinetic energy and the next step see.
///
/// Rayleigh damping (*DAMPING ALPHA, BETA): the mass-proportional part is
/// integrated exactly per dof, v_{n+1/2} = e^{-alpha h} v_{n-1/2} + (1 - e^{-alpha h})/alpha a_n
/// (every mode's amplitude decays as e^{-alpha t / 2}, and the stable increment
/// is not lowered); the stiffness-proportional part is the force beta K_e v_{n-1/2}
/// with the lagged velocity, as ABAQUS/Explicit does it, which lowers the stable
/// increment to (2/omega)(sqrt(1 + xi^2) - xi), xi = beta omega / 2 (stable_increment.hpp).
///
/// Constraints and contact: ExplicitConstraints' and ExplicitContact's
/// predictor–corrector add their forces at t_n before the velocities and
/// positions are advanced (constraints first, contact from the constrained
/// prediction; the two are not iterated together).
///
/// Time stepping: the explicit increment is the data line's increment with
/// DIRECT (used as given, with a warning above the stable estimate) and
/// otherwise kSafetyFactor times the element-by-element stable increment
/// (stable_increment.hpp), recomputed at every report under NLGEOM. The
/// step's period is divided into N = ceil(period / limit) nominal explicit
/// increments h0 = period / N. Reports (status line, energies, and results
/// when an output request is due) end on nominal increments: the union of
/// kReportIntervals equal intervals (the energy history; every increment when
/// there are fewer) and the marks of the step's output requests
/// (output_schedule.hpp: FREQUENCY counts explicit increments, NUMBER and
/// TIME INTERVAL marks are rounded to h0). Each increment of the step loop is
/// one report interval of k = (its nominal increments) equal explicit
/// increments, more when NLGEOM has lowered the limit below h0. At a report
/// where no request is due only the nodal values and energies are built. See
/// docs/theory/explicit_dynamics.md.

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "tether/analysis/explicit_constraints.hpp"
#include "tether/analysis/explicit_contact.hpp"
#include "tether/analysis/analysis_observer.hpp"
#include "tether/analysis/motion_state.hpp"
#include "tether/analysis/procedure.hpp"
#include "tether/analysis/results_builder.hpp"
#include "tether/analysis/stable_increment.hpp"
#include "tether/analysis/step_system.hpp"

namespace tether {

class ExplicitDynamicProcedure final : public Procedure {
 public:
  /// Fraction of the stable increment used without DIRECT.
  static constexpr double kSafetyFactor = 0.9;
  /// Energy reports per step (fewer when the step has fewer explicit
  /// increments); output requests add their own marks.
  static constexpr int kReportIntervals = 100;
  /// A report whose ALLKE + ALLSE exceeds this multiple of the energy put in
  /// stops the step as diverged (an increment above the stable one). Below
  /// the limit the full-step energy of a mode stays under 1 / (1 - (omega h / 2)^2)
  /// times its share: the guard cannot fire for h < (1 - 5e-7) 2 / omega_max.
  static constexpr double kEnergyGrowthLimit = 1e6;

  /// `system`, `observer` and `motion` must outlive the procedure; `u` is the
  /// state at the step's start (for the stable increment). Throws ModelError
  /// for what the explicit scheme does not support (eliminated dofs, damping;
  /// constraints without exact multipliers; contact other than hard), naming it.
  ExplicitDynamicProcedure(StepSystem& system, AnalysisObserver& observer, bool stream_results, MotionState& motion,
                           const Eigen::VectorXd& u);

  [[nodiscard]] std::string keyword() const override { return "*DYNAMIC, EXPLICIT"; }
  /// The step as the step loop's IncrementController should step it: one
  /// increment per report interval, ending on the report marks (time points).
  [[nodiscard]] Step time_stepping(const Step& step) const override;
  IncrementOutcome solve_increment(const IncrementAttempt& attempt, Eigen::VectorXd& u) override;
  [[nodiscard]] SolveTiming timing() const override;
  void save(RestartState& state) const override;
  void restore(const RestartState& state) override;

  /// The explicit increment limit in force [time] (DIRECT's, or the safety times the stable estimate).
  [[nodiscard]] double increment_limit() const { return limit_; }
  /// The last element-by-element estimate (without the safety factor).
  [[nodiscard]] const StableIncrement& stable() const { return stable_; }

 private:
  /// Refuses the contributions the scheme does not support.
  void check_supported() const;
  /// The nominal explicit increment and the report marks of the step (from limit_).
  void plan_reports();
  /// Some output request of the step (or the result files' default) writes the report ending at `span`.
  [[nodiscard]] bool output_due(const IncrementResults::ExplicitSpan& span, bool last_in_step) const;
  /// Sets limit_ from DIRECT or the stable increment at `u` and time
  /// `total_time`; `report`: tells the observer (and warns when DIRECT exceeds it).
  void update_limit(const Eigen::VectorXd& u, double total_time, bool report);
  /// At the first increment of the step: velocities, masses, forces and accelerations at the step's start.
  void start_step(const IncrementTimes& first, Eigen::VectorXd& u);
  /// r = f_int(u) - f_ext at step time `t` (loads applied by the caller), and a = -r / m at free dofs.
  void evaluate_forces(const EvaluationState& s);
  /// Sorts the elements into moving ones and held ones (every dof held at a
  /// constant value over the step: their forces do not change as the scheme moves).
  void sort_elements();
  /// The held elements' forces at state `s` into held_residual_ (once per report interval), and their commit.
  void evaluate_held(const EvaluationState& s);
  /// Accelerations at the prescribed dofs at step time `t` (state `u`) from
  /// their values at t + h (the central difference of the prescribed motion).
  void prescribed_accelerations(const Eigen::VectorXd& u, double t, double h);
  /// Rayleigh damping of the step: alpha per free dof (mass-proportional, from
  /// the elements' alpha m), and beta_e K_e per damped element at the state `s`.
  void setup_damping(const EvaluationState& s);
  /// decay_ = exp(-alpha h_average) and gain_ = (1 - decay_) / (alpha h_average) per dof, and
  /// effective_inverse_mass_ = gain_ / m (all 1 and 1 / m without mass-proportional damping).
  void set_damping_factors(double h_average);
  /// Forces doing work: applied forces at free dofs, the reactions r + m a at prescribed ones.
  void work_force(Eigen::VectorXd& out) const;
  /// The constraint and contact forces at t_n (ExplicitConstraints and
  /// ExplicitContact::correct) for the positions the next increment h would
  /// predict from the state `u`, half_velocity_, accel_; the constraints'
  /// multipliers are written into `u`.
  void correction_force(Eigen::VectorXd& u, double h, Eigen::VectorXd& force);
  /// v_{n+1/2} and u_{n+1} at the displacement dofs (u_previous_ = u_n,
  /// step_u_ = u_{n+1} - u_n there); returns the viscous power of the damping
  /// forces at t_n over the increment (0 undamped).
  double move(Eigen::VectorXd& u, double h, double h_average);
  /// Rayleigh damping in the step (mass- or stiffness-proportional).
  [[nodiscard]] bool damped() const { return mass_damping_.size() > 0 || !stiffness_damping_.empty(); }
  /// One explicit increment h from step time t to t + h.
  void advance(Eigen::VectorXd& u, double t, double h);
  /// Results and energies at the end of an interval, state `s`, spanning
  /// `span` (also sets the motion state); `points` (may be null) streams
  /// element values and must outlive the results. Without `output_due` only
  /// the nodal values, contact values and energies (energies_only).
  IncrementResults interval_results(const IncrementAttempt& attempt, const EvaluationState& s,
                                    const ElementPointSource* points, const IncrementResults::ExplicitSpan& span,
                                    bool output_due);
  /// The energy in the model (ALLKE + ALLSE) is not finite or more than
  /// kEnergyGrowthLimit times what was put in (the balance's start plus |ALLWK|
  /// plus h |F_n . v_n|, the work of the next increment).
  [[nodiscard]] bool diverged(const EnergyTotals& e) const;

  StepSystem& system_;
  AnalysisObserver& observer_;
  bool stream_results_;
  MotionState& motion_;
  StableIncrement stable_;
  std::unique_ptr<ExplicitContact> contact_;          ///< null without contact pairs
  std::unique_ptr<ExplicitConstraints> constraints_;  ///< null without constraints
  Eigen::VectorXd contact_force_;  ///< constraint and contact forces at t_n
  Eigen::VectorXd predicted_, constraint_force_, contact_only_;  ///< scratch
  double limit_ = 0;
  long nominal_total_ = 1;          ///< N: nominal explicit increments in the step
  double nominal_ = 0;              ///< h0 = period / N [time]
  std::vector<long> report_marks_;  ///< reports end after these nominal increments (sorted, last = N)
  bool started_ = false;
  std::vector<int> free_, prescribed_;   ///< displacement dofs that move by the scheme / by their values
  Eigen::VectorXd mass_, inverse_mass_;  ///< lumped mass per dof (inverse 0 at prescribed dofs)
  Eigen::VectorXd cloads_;               ///< nodal forces at the current time
  Eigen::VectorXd external_;             ///< f_ext (nodal forces and pressures) at the current state
  Eigen::VectorXd residual_;             ///< f_int - f_ext at the current state
  Eigen::VectorXd next_values_;          ///< scratch: prescribed values one increment ahead
  LocalSystem local_;                    ///< scratch for one contribution
  std::vector<int> moving_elements_, held_elements_;  ///< element indices (see sort_elements())
  std::vector<int> committing_elements_;  ///< the moving elements with history (the others commit nothing)
  Eigen::VectorXd mass_damping_;         ///< alpha per dof [1/time], 0 at prescribed dofs (empty: none)
  Eigen::VectorXd decay_, gain_;         ///< see set_damping_factors()
  Eigen::VectorXd effective_inverse_mass_;  ///< see set_damping_factors() (empty without contact and constraints)
  double factors_h_ = -1;                ///< the h_average of decay_ and gain_
  struct StiffnessDamping {
    int element = 0;         ///< index in the step system's inertia()
    Eigen::MatrixXd matrix;  ///< beta_e K_e over the element's dofs [force time / length]
  };
  std::vector<StiffnessDamping> stiffness_damping_;
  Eigen::VectorXd damping_force_;        ///< beta K v_{n-1/2} (with alpha m v_{n-1/2} at prescribed dofs)
  double viscous_ = 0;                   ///< ALLVD (from the step's start value)
  Eigen::VectorXd held_residual_;        ///< the held elements' f_int at the current report interval (empty: none)
  Eigen::VectorXd half_velocity_;        ///< v_{n-1/2} (v_0 before the first increment)
  Eigen::VectorXd accel_;                ///< a_n
  Eigen::VectorXd u_previous_;           ///< u_{n-1} (evaluation state's u_start)
  Eigen::VectorXd force_previous_, force_, step_u_;  ///< work forces at n-1 and n; u_n - u_{n-1}
  double friction_start_ = 0;            ///< ALLFD at the step's start
  double work_ = 0;                      ///< ALLWK up to u_{n-1} (the last increment's share is added later)
  double period_ = 1, motion_time_offset_ = 0;  ///< the step's period and its start in total time
  double h_previous_ = 0;                ///< h_{n-1/2} (0 before the first increment)
  long long n_increments_ = 0;           ///< explicit increments in this step
  double evaluation_seconds_ = 0, output_seconds_ = 0;
};

}  // namespace tether
