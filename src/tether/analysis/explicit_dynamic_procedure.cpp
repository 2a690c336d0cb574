#include "tether/analysis/explicit_dynamic_procedure.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#include "tether/analysis/amplitude.hpp"
#include "tether/analysis/results_builder.hpp"
#include "tether/core/error.hpp"
#include "tether/output/output_schedule.hpp"

namespace tether {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// Adds a contribution's local residual times `factor` into a global vector.
void scatter(const Contribution& c, const Eigen::VectorXd& local, double factor, Eigen::VectorXd& out) {
  const auto dofs = c.dofs();
  for (std::size_t i = 0; i < dofs.size(); ++i) out[dofs[i]] += factor * local[static_cast<Eigen::Index>(i)];
}

}  // namespace

ExplicitDynamicProcedure::ExplicitDynamicProcedure(StepSystem& system, AnalysisObserver& observer,
                                                   bool stream_results, MotionState& motion, const Eigen::VectorXd& u)
    : system_(system), observer_(observer), stream_results_(stream_results), motion_(motion) {
  check_supported();
  if (!system.discretization().contact_pairs().empty())
    contact_ = std::make_unique<ExplicitContact>(system.discretization());
  if (!system.discretization().constraints().empty() || !system.discretization().user_constraints().empty())
    constraints_ = std::make_unique<ExplicitConstraints>(system.discretization(), u);
  update_limit(u, 0, true);
  plan_reports();
}

void ExplicitDynamicProcedure::plan_reports() {
  const Step& step = system_.step();
  const double period = step.period > 0 ? step.period : 1;
  // Above kReportIntervals, a multiple of it: the energy reports fall on hundredths of the period.
  nominal_total_ = static_cast<long>(std::max(1.0, std::ceil(period / limit_ - 1e-9)));
  if (nominal_total_ > kReportIntervals)
    nominal_total_ = kReportIntervals * static_cast<long>(std::ceil(period / (kReportIntervals * limit_) - 1e-9));
  nominal_ = period / static_cast<double>(nominal_total_);
  OutputRequest energies;
  energies.number_interval = static_cast<int>(std::min<long>(kReportIntervals, nominal_total_));
  report_marks_ = explicit_marks(energies, nominal_total_, period);
  const auto add = [&](const OutputRequest& r) {
    const std::vector<long> marks = explicit_marks(r, nominal_total_, period);
    report_marks_.insert(report_marks_.end(), marks.begin(), marks.end());
  };
  for (const OutputRequest& r : step.outputs) add(r);
  if (std::none_of(step.outputs.begin(), step.outputs.end(), is_file_request))
    add(default_file_request(StepProcedure::ExplicitDynamic));
  std::sort(report_marks_.begin(), report_marks_.end());
  report_marks_.erase(std::unique(report_marks_.begin(), report_marks_.end()), report_marks_.end());
}

bool ExplicitDynamicProcedure::output_due(const IncrementResults::ExplicitSpan& span, bool last_in_step) const {
  IncrementResults probe;
  probe.explicit_span = span;
  probe.period = system_.step().period > 0 ? system_.step().period : 1;
  const auto& outputs = system_.step().outputs;
  const auto due = [&](const OutputRequest& r) { return is_due(r, probe, last_in_step); };
  const bool default_files = std::none_of(outputs.begin(), outputs.end(), is_file_request);
  return last_in_step || std::any_of(outputs.begin(), outputs.end(), due) ||
         (default_files && due(default_file_request(StepProcedure::ExplicitDynamic)));
}

void ExplicitDynamicProcedure::check_supported() const {
  const Discretization& disc = system_.discretization();
  const std::string scheme = "*DYNAMIC, EXPLICIT (step " + system_.step().name + ") does not support ";
  if (!disc.mortar_pairs().empty())
    throw ModelError(scheme + "mortar (SURFACE TO SURFACE) contact yet: " + disc.mortar_pairs().front()->describe() +
                     "; use TYPE=NODE TO SURFACE in explicit steps");
  if (!disc.elimination_rows().empty())
    throw ModelError(scheme + "eliminated dofs (*EQUATION, *MPC, *TIE by elimination) yet: " +
                     std::to_string(disc.elimination_rows().size()) + " dependent dof(s)");
  if (system_.inertia().empty()) throw ModelError(scheme + "a model without elements");
}

void ExplicitDynamicProcedure::update_limit(const Eigen::VectorXd& u, double total_time, bool report) {
  const Step& step = system_.step();
  const EquationMap& equations = system_.equations();
  stable_ = stable_increment(system_.inertia(), EvaluationState{u, u, 0, total_time, 0, step.nlgeom},
                             [&equations](int dof) { return equations.is_prescribed(dof); });
  if (stable_.element < 0)
    throw ModelError("*DYNAMIC, EXPLICIT (step " + step.name + "): every dof of every element is held: nothing moves");
  const std::string where =
      system_.inertia()[static_cast<std::size_t>(stable_.element)]->element().describe();
  if (step.direct) {
    limit_ = step.initial_increment;
    if (report && limit_ > stable_.dt)
      observer_.on_message("warning: step " + step.name + ": the DIRECT increment " + format_time(limit_) +
                           " exceeds the stable time increment " + format_time(stable_.dt) + " (set by " + where +
                           "): the central differences will likely diverge");
  } else {
    limit_ = kSafetyFactor * stable_.dt;
  }
  if (report)
    observer_.on_message("step " + step.name + ": stable time increment " + format_time(stable_.dt) + " (2/omega_max, " +
                         where + "); explicit increment " + format_time(limit_) +
                         (step.direct ? " (DIRECT)" : " (safety factor " + format_time(kSafetyFactor) + ")"));
}

Step ExplicitDynamicProcedure::time_stepping(const Step& step) const {
  Step s = step;
  const double period = step.period > 0 ? step.period : 1;
  s.direct = true;
  s.period = period;
  s.initial_increment = period;  // every increment ends on the next report mark
  s.min_increment = 0;
  s.max_increment = 0;
  s.time_points.clear();
  for (long k : report_marks_)
    if (k < nominal_total_) s.time_points.push_back(static_cast<double>(k) * nominal_);
  s.max_increments = static_cast<int>(report_marks_.size()) + 2;
  return s;
}

void ExplicitDynamicProcedure::start_step(const IncrementTimes& first, Eigen::VectorXd& u) {
  const Discretization& disc = system_.discretization();
  const DofMap& dofs = disc.dofs();
  const auto n = static_cast<Eigen::Index>(dofs.n_dofs());
  if (!motion_.started) {
    motion_.v = Eigen::VectorXd::Zero(n);
    for (const auto& iv : disc.model().initial_velocities) motion_.v[dofs.displacement(iv.node, iv.dof)] = iv.value;
  }
  mass_ = Eigen::VectorXd::Zero(n);
  for (const auto& m : system_.inertia()) {
    const auto d = m->dofs();
    for (std::size_t i = 0; i < d.size(); ++i) mass_[d[i]] += m->mass_entry(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(i));
  }
  inverse_mass_ = Eigen::VectorXd::Zero(n);
  free_.clear(), prescribed_.clear();
  for (int d = 0; d < dofs.n_displacement_dofs(); ++d) {
    if (system_.equations().is_prescribed(d)) {
      prescribed_.push_back(d);
      continue;
    }
    if (!(mass_[d] > 0))
      throw ModelError("*DYNAMIC, EXPLICIT: " + dofs.describe(d) + " is free but carries no mass");
    free_.push_back(d);
    inverse_mass_[d] = 1 / mass_[d];
  }
  const double step_start = first.total_time - first.step_time;
  system_.apply_loads(IncrementTimes{0, step_start, 0, first.period, false}, u, cloads_);
  half_velocity_ = motion_.v;
  accel_ = Eigen::VectorXd::Zero(n);
  u_previous_ = u;
  force_previous_ = force_ = step_u_ = Eigen::VectorXd::Zero(n);
  h_previous_ = 0;
  sort_elements();
  setup_damping(EvaluationState{u, u, 0, step_start, 0, system_.step().nlgeom});
  residual_.resize(0), held_residual_.resize(0);
  evaluate_held(EvaluationState{u, u, 0, step_start, 0, system_.step().nlgeom});
  evaluate_forces(EvaluationState{u, u, 0, step_start, 0, system_.step().nlgeom});
  if (!motion_.started) {
    EnergyTotals& e = motion_.energy;
    e = EnergyTotals{};
    for (int d : free_) e.kinetic += 0.5 * mass_[d] * motion_.v[d] * motion_.v[d];
    const EvaluationState s{u, u, 0, step_start, 0, system_.step().nlgeom};
    for (const auto& el : disc.elements()) e.strain += el->strain_energy(s);
    e.total = motion_.balance_start = e.kinetic + e.strain;
    motion_.started = true;
  }
  work_ = motion_.energy.work;
  friction_start_ = motion_.energy.friction;
  viscous_ = motion_.energy.viscous;
}

void ExplicitDynamicProcedure::setup_damping(const EvaluationState& s) {
  const auto n = static_cast<Eigen::Index>(mass_.size());
  mass_damping_.resize(0);
  stiffness_damping_.clear();
  Eigen::VectorXd alpha_mass = Eigen::VectorXd::Zero(n);
  const auto& inertia = system_.inertia();
  LocalSystem k;
  for (std::size_t e = 0; e < inertia.size(); ++e) {
    const ElementInertia& m = *inertia[e];
    const auto dofs = m.dofs();
    for (std::size_t i = 0; i < dofs.size(); ++i)
      alpha_mass[dofs[i]] += m.damping_alpha() * m.mass_entry(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(i));
    if (m.damping_beta() == 0) continue;
    k.reset(static_cast<Eigen::Index>(dofs.size()));
    m.element().evaluate(s, k, true);
    stiffness_damping_.push_back({static_cast<int>(e), m.damping_beta() * k.tangent});
  }
  if (alpha_mass.cwiseAbs().maxCoeff() > 0) {
    mass_damping_ = Eigen::VectorXd::Zero(n);
    for (Eigen::Index d = 0; d < n; ++d)
      if (mass_[d] > 0) mass_damping_[d] = alpha_mass[d] / mass_[d];
  }
  factors_h_ = -1;
  set_damping_factors(0);
}

void ExplicitDynamicProcedure::set_damping_factors(double h_average) {
  if (h_average == factors_h_) return;
  factors_h_ = h_average;
  const auto n = inverse_mass_.size();
  decay_.setOnes(n), gain_.setOnes(n);
  if (mass_damping_.size() > 0)
    for (Eigen::Index d = 0; d < n; ++d) {
      const double x = mass_damping_[d] * h_average;
      if (x == 0 || inverse_mass_[d] == 0) continue;  // prescribed dofs follow their motion
      decay_[d] = std::exp(-x);
      gain_[d] = -std::expm1(-x) / x;
    }
  if (contact_ || constraints_) effective_inverse_mass_ = gain_.cwiseProduct(inverse_mass_);  // the correction's mobility
}

void ExplicitDynamicProcedure::sort_elements() {
  const auto n = static_cast<std::size_t>(system_.discretization().dofs().n_dofs());
  std::vector<bool> constant(n, false);
  for (int d : prescribed_) constant[static_cast<std::size_t>(d)] = true;  // held dofs keep their values...
  for (const auto& [dof, v] : system_.loads().prescribed)  // ... unless the step moves them
    constant[static_cast<std::size_t>(dof)] = !prescribed_moves(v);
  moving_elements_.clear(), held_elements_.clear(), committing_elements_.clear();
  const auto& elements = system_.discretization().elements();
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const auto dofs = elements[e]->dofs();
    const bool held = std::all_of(dofs.begin(), dofs.end(), [&](int d) { return constant[static_cast<std::size_t>(d)]; });
    (held ? held_elements_ : moving_elements_).push_back(static_cast<int>(e));
    if (!held && elements[e]->has_history()) committing_elements_.push_back(static_cast<int>(e));
  }
}

void ExplicitDynamicProcedure::evaluate_held(const EvaluationState& s) {
  if (held_elements_.empty()) {  // no held element: no vector
    held_residual_.resize(0);
    return;
  }
  if (residual_.size() == s.u.size() && held_residual_.size() == s.u.size()) residual_ -= held_residual_;
  held_residual_.setZero(s.u.size());
  const auto& elements = system_.discretization().elements();
  for (int e : held_elements_) {
    const auto& el = elements[static_cast<std::size_t>(e)];
    local_.residual.setZero(static_cast<Eigen::Index>(el->dofs().size()));  // no tangent: left unsized
    el->evaluate(s, local_, false);
    scatter(*el, local_.residual, 1, held_residual_);
    el->commit(s);
  }
  if (residual_.size() == s.u.size()) residual_ += held_residual_;  // held dofs only: no free acceleration changes
}

void ExplicitDynamicProcedure::evaluate_forces(const EvaluationState& s) {
  if (held_residual_.size() == s.u.size())
    residual_ = held_residual_;
  else
    residual_.setZero(s.u.size());
  const auto& elements = system_.discretization().elements();
  for (int e : moving_elements_) {
    const auto& el = elements[static_cast<std::size_t>(e)];
    local_.residual.setZero(static_cast<Eigen::Index>(el->dofs().size()));  // no tangent: left unsized
    el->evaluate(s, local_, false);
    scatter(*el, local_.residual, 1, residual_);
  }
  external_ = cloads_;
  for (const Contribution* p : system_.load_contributions()) {  // pressures and body forces
    local_.reset(static_cast<Eigen::Index>(p->dofs().size()));
    p->evaluate(s, local_, false);
    scatter(*p, local_.residual, -1, external_);
  }
  residual_ -= external_;
  if (!damped() && damping_force_.size() == s.u.size()) {  // stays 0; r + 0 = r (r is never -0: sums from +0)
    for (int d : free_) accel_[d] = -residual_[d] * inverse_mass_[d];
    return;
  }
  damping_force_.setZero(s.u.size());
  const auto& inertia = system_.inertia();
  for (const StiffnessDamping& c : stiffness_damping_) {  // beta K_e v_{n-1/2}
    const auto dofs = inertia[static_cast<std::size_t>(c.element)]->dofs();
    for (std::size_t i = 0; i < dofs.size(); ++i) {
      double f = 0;
      for (std::size_t j = 0; j < dofs.size(); ++j)
        f += c.matrix(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) * half_velocity_[dofs[j]];
      damping_force_[dofs[i]] += f;
    }
  }
  if (mass_damping_.size() > 0)  // into the reactions (free dofs: integrated exactly in advance())
    for (int d : prescribed_) damping_force_[d] += mass_damping_[d] * mass_[d] * half_velocity_[d];
  residual_ += damping_force_;
  for (int d : free_) accel_[d] = -residual_[d] * inverse_mass_[d];
}

void ExplicitDynamicProcedure::prescribed_accelerations(const Eigen::VectorXd& u, double t, double h) {
  const Model& model = system_.discretization().model();
  const double step_start = motion_time_offset_;
  next_values_.resize(u.size());
  for (int d : prescribed_) next_values_[d] = u[d];  // held dofs (unused nodes) keep their values
  for (const auto& [dof, v] : system_.loads().prescribed)
    next_values_[dof] = prescribed_value(model, v, t + h, period_, step_start + t + h);
  const double h_average = 0.5 * (h_previous_ + h);
  for (int d : prescribed_) {
    const double v_next = (next_values_[d] - u[d]) / h;
    if (h_previous_ == 0) half_velocity_[d] = v_next;  // the prescribed motion's own velocity from the start
    accel_[d] = (v_next - half_velocity_[d]) / h_average;
  }
}

void ExplicitDynamicProcedure::work_force(Eigen::VectorXd& out) const {
  out = external_;
  for (int d : prescribed_) out[d] += residual_[d] + mass_[d] * accel_[d];
}

void ExplicitDynamicProcedure::correction_force(Eigen::VectorXd& u, double h, Eigen::VectorXd& force) {
  const double h_average = 0.5 * (h_previous_ + h), c = h * h_average;
  const int n_disp = system_.discretization().dofs().n_displacement_dofs();
  set_damping_factors(h_average);
  predicted_ = u;
  for (int d = 0; d < n_disp; ++d)
    predicted_[d] += h * (decay_[d] * half_velocity_[d] + h_average * gain_[d] * accel_[d]);
  force.setZero(u.size());
  // A force f at t_n moves the predicted positions by c gain M^-1 f.
  const Eigen::VectorXd& mobility = effective_inverse_mass_;
  if (constraints_) {  // first the constraints, then contact from the constrained prediction
    constraints_->correct(predicted_, mobility, c, constraint_force_, u);
    force += constraint_force_;
    predicted_ += c * mobility.cwiseProduct(constraint_force_);
  }
  if (contact_) {
    contact_->correct(u, predicted_, mobility, c, contact_only_);
    force += contact_only_;
  }
}

double ExplicitDynamicProcedure::move(Eigen::VectorXd& u, double h, double h_average) {
  const int n_disp = system_.discretization().dofs().n_displacement_dofs();
  for (Eigen::Index d = n_disp; d < u.size(); ++d) u_previous_[d] = u[d];  // multipliers
  if (!damped()) {  // decay_ = gain_ = 1 and no damping force: the same values, fewer vectors read
    for (int d = 0; d < n_disp; ++d) {
      half_velocity_[d] = half_velocity_[d] + h_average * accel_[d];
      u_previous_[d] = u[d];
      u[d] += h * half_velocity_[d];
      step_u_[d] = u[d] - u_previous_[d];
    }
    return 0;
  }
  double viscous_power = 0;  // (the damping forces at t_n) . (u_{n+1} - u_n) / h
  for (int d = 0; d < n_disp; ++d) {
    const double undamped = half_velocity_[d] + h_average * accel_[d];
    half_velocity_[d] = decay_[d] * half_velocity_[d] + h_average * gain_[d] * accel_[d];
    u_previous_[d] = u[d];
    u[d] += h * half_velocity_[d];
    step_u_[d] = u[d] - u_previous_[d];
    viscous_power += (damping_force_[d] + mass_[d] * (undamped - half_velocity_[d]) / h_average) * half_velocity_[d];
  }
  return viscous_power;
}

void ExplicitDynamicProcedure::advance(Eigen::VectorXd& u, double t, double h) {
  prescribed_accelerations(u, t, h);
  if (contact_ || constraints_) {  // the contact and constraint forces at t_n, from the predicted positions
    correction_force(u, h, contact_force_);
    if (contact_) contact_->commit();
    accel_ += inverse_mass_.cwiseProduct(contact_force_);
    residual_ -= contact_force_;
  }
  work_force(force_);
  work_ += 0.5 * (force_previous_ + force_).dot(step_u_);
  std::swap(force_previous_, force_);
  const double h_average = 0.5 * (h_previous_ + h);
  const int n_disp = system_.discretization().dofs().n_displacement_dofs();
  set_damping_factors(h_average);
  viscous_ += h * move(u, h, h_average);
  const double t_next = t + h;
  system_.apply_loads(IncrementTimes{t_next, motion_time_offset_ + t_next, h, period_, false}, u, cloads_);
  for (const auto& [dof, v] : system_.loads().prescribed)  // the dofs apply_loads() moved
    if (dof < n_disp) step_u_[dof] = u[dof] - u_previous_[dof];
  const EvaluationState s{u, u_previous_, t_next, motion_time_offset_ + t_next, h, system_.step().nlgeom};
  evaluate_forces(s);
  for (int e : committing_elements_) system_.discretization().elements()[static_cast<std::size_t>(e)]->commit(s);
  h_previous_ = h;
  ++n_increments_;
}

IncrementOutcome ExplicitDynamicProcedure::solve_increment(const IncrementAttempt& attempt, Eigen::VectorXd& u) {
  const IncrementTimes& t = attempt.time;
  period_ = t.period;
  motion_time_offset_ = t.total_time - t.step_time;
  if (!started_) start_step(t, u), started_ = true;
  const double t_start = t.step_time - t.dt;
  if (system_.step().nlgeom && n_increments_ > 0) {
    update_limit(u, t.total_time - t.dt, false);
    if (!stiffness_damping_.empty()) setup_damping(EvaluationState{u, u, t_start, t.total_time - t.dt, 0, true});
  }
  // The report's span in nominal increments; NLGEOM may have lowered the limit below h0.
  const IncrementResults::ExplicitSpan span{std::lround(t_start / nominal_), std::lround(t.step_time / nominal_),
                                            nominal_total_};
  const long nominal_count = std::max(1L, span.end - span.start);
  const double lowered = std::ceil(t.dt / limit_ - 1e-9);
  const auto k = static_cast<int>(limit_ < nominal_ * (1 - 1e-12) ? std::max<double>(lowered, nominal_count)
                                                                  : static_cast<double>(nominal_count));
  const double h = t.dt / k;
  const Eigen::VectorXd u_start = u;
  const auto evaluation_start = Clock::now();
  if (n_increments_ > 0 && !held_elements_.empty())  // the held elements' forces of this interval
    evaluate_held(EvaluationState{u, u, t_start, t.total_time - t.dt, 0, system_.step().nlgeom});
  for (int i = 0; i < k; ++i) advance(u, i + 1 == k ? t.step_time - h : t_start + i * h, h);
  evaluation_seconds_ += seconds_since(evaluation_start);

  IncrementOutcome out;
  std::optional<IncrementResults> results;
  const auto output_start = Clock::now();
  if (u.allFinite() && accel_.allFinite()) {  // the accelerations and corrections at t_n (multipliers into u)
    prescribed_accelerations(u, t.step_time, h_previous_);
    if (contact_ || constraints_) correction_force(u, h_previous_, contact_force_);
  }
  // The results may stream element values from `points` until on_results returns.
  const EvaluationState s{u, u_previous_, t.step_time, t.total_time, h_previous_, system_.step().nlgeom};
  const DiscretizationPoints points(system_.discretization(), s);
  if (u.allFinite() && accel_.allFinite())
    results = interval_results(attempt, s, stream_results_ ? &points : nullptr, span, output_due(span, t.ends_step));
  out.converged = results && !diverged(*results->energy);
  if (!out.converged)
    out.message = std::string("the central differences diverged (") +
                  (results ? "the energy grew past " + format_time(kEnergyGrowthLimit) + " times the energy put in"
                           : "displacements not finite") +
                  ") by step time " + format_time(t.step_time) + " with explicit increments of " + format_time(h) +
                  " against a stable increment of " + format_time(stable_.dt);
  IncrementReport r;
  r.step = attempt.step, r.increment = attempt.increment, r.attempt = attempt.attempt;
  r.total_iterations = attempt.prior_iterations;
  r.step_time = t.step_time, r.total_time = t.total_time, r.increment_size = t.dt;
  r.converged = out.converged, r.note = out.message;
  observer_.on_increment(r);
  if (out.converged)
    observer_.on_results(*results, system_.step(), t.ends_step);
  else
    u = u_start;
  output_seconds_ += seconds_since(output_start);
  return out;
}

bool ExplicitDynamicProcedure::diverged(const EnergyTotals& e) const {
  // What was put in, plus what the forces at t_n put in over one increment
  // (the full-step kinetic energy runs half an increment ahead of ALLWK: a
  // model at rest loaded from t = 0 has ALLWK = 0 and ALLKE > 0 at the first report).
  const double power = std::abs(force_.dot(motion_.v));
  const double put_in = std::abs(motion_.balance_start) + std::abs(e.work) + h_previous_ * power;
  return !std::isfinite(e.total) || e.kinetic + e.strain > kEnergyGrowthLimit * put_in;
}

IncrementResults ExplicitDynamicProcedure::interval_results(const IncrementAttempt& attempt, const EvaluationState& s,
                                                            const ElementPointSource* points,
                                                            const IncrementResults::ExplicitSpan& span,
                                                            bool output_due) {
  const Eigen::VectorXd& u = s.u;
  const Discretization& disc = system_.discretization();
  const DofMap& dofs = disc.dofs();
  const IncrementTimes& t = attempt.time;
  // The state at t_n with the contact forces of t_n, as the next increment will find them.
  Eigen::VectorXd accel = accel_, residual = residual_;
  if (contact_ || constraints_) {  // correction_force() was called by solve_increment
    accel += inverse_mass_.cwiseProduct(contact_force_);
    residual -= contact_force_;
  }
  const int n_disp = dofs.n_displacement_dofs();
  motion_.v = Eigen::VectorXd::Zero(u.size());
  set_damping_factors(0.5 * h_previous_);  // v_n: half an increment from v_{n-1/2}
  motion_.v.head(n_disp) = decay_.head(n_disp).cwiseProduct(half_velocity_.head(n_disp)) +
                           (0.5 * h_previous_) * gain_.head(n_disp).cwiseProduct(accel.head(n_disp));
  motion_.a = accel;
  force_ = external_;
  for (int d : prescribed_) force_[d] += residual[d] + mass_[d] * accel[d];
  motion_.work_force = force_;
  motion_.static_residual = residual;
  motion_.damping_force = damping_force_;
  if (mass_damping_.size() > 0)
    for (int d : free_) motion_.damping_force[d] += mass_damping_[d] * mass_[d] * motion_.v[d];  // at t_n
  Eigen::VectorXd reaction = residual;
  reaction.head(n_disp) += mass_.head(n_disp).cwiseProduct(accel.head(n_disp));

  IncrementResults results = output_due ? build_results(disc, s, reaction, system_.equations(), points)
                                        : build_node_results(disc, s, reaction, system_.equations());
  results.energies_only = !output_due;
  results.explicit_span = span;
  results.increment_size = t.dt;
  results.period = t.period;
  if (contact_) results.contact = contact_->values();
  results.velocity.resize(static_cast<std::size_t>(dofs.n_nodes()));
  results.acceleration.resize(results.velocity.size());
  for (int i = 0; i < dofs.n_nodes(); ++i)
    for (int c = 0; c < kDofsPerNode; ++c) {
      results.velocity[static_cast<std::size_t>(i)][c] = motion_.v[dofs.displacement(i, c)];
      results.acceleration[static_cast<std::size_t>(i)][c] = motion_.a[dofs.displacement(i, c)];
    }
  EnergyTotals& e = motion_.energy;
  e.kinetic = 0.5 * motion_.v.head(n_disp).cwiseAbs2().dot(mass_.head(n_disp));
  // Kinematic contact removes the normal relative velocity of a slave at impact
  // (a plastic impact of the node's mass): that loss shows as numerical energy.
  e.strain = 0;
  for (const auto& el : disc.elements()) e.strain += el->strain_energy(s);
  e.work = work_ + 0.5 * (force_previous_ + force_).dot(step_u_);
  e.viscous = viscous_;
  e.friction = friction_start_ + (contact_ ? contact_->dissipation() : 0.0);
  e.plastic = results.plastic_dissipation.value_or(0.0);  // the material points' committed records
  e.total = e.kinetic + e.strain + e.viscous + e.friction + e.plastic - e.work;
  e.numerical = motion_.balance_start - e.total;
  results.energy = e;
  results.step = attempt.step;
  results.increment = attempt.increment;
  results.step_time = t.step_time;
  results.total_time = t.total_time;
  results.iterations = 0;
  return results;
}

SolveTiming ExplicitDynamicProcedure::timing() const {
  SolveTiming t;
  t.assembly = evaluation_seconds_;
  t.output = output_seconds_;
  return t;
}

// The state between report intervals is (u, v, a) at a full step, which the
// analysis saves with the motion state: a restart starts the next interval
// with v_{n+1/2} = v_n + h/2 a_n, the same increment the run would have made.
void ExplicitDynamicProcedure::save(RestartState& /*state*/) const {}

void ExplicitDynamicProcedure::restore(const RestartState& /*state*/) {}

}  // namespace tether
