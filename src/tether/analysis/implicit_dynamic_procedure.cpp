#include "tether/analysis/implicit_dynamic_procedure.hpp"

#include "tether/analysis/amplitude.hpp"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <unordered_map>

#include "tether/analysis/amplitude.hpp"
#include "tether/analysis/implicit_attempt.hpp"
#include "tether/analysis/results_builder.hpp"
#include "tether/contact/contact_pair.hpp"
#include "tether/output/output_schedule.hpp"
#include "tether/core/error.hpp"

namespace tether {

namespace {

/// Scatters a contribution's local residual into a global vector.
void scatter(const Contribution& c, const Eigen::VectorXd& local, Eigen::VectorXd& out) {
  const auto dofs = c.dofs();
  for (std::size_t i = 0; i < dofs.size(); ++i) out[dofs[i]] += local[static_cast<Eigen::Index>(i)];
}

/// The diagonal of the assembled mass matrix, over all dofs [mass].
Eigen::VectorXd mass_diagonal(const StepSystem& system) {
  Eigen::VectorXd diagonal = Eigen::VectorXd::Zero(system.discretization().dofs().n_dofs());
  for (const auto& m : system.inertia()) {
    const auto d = m->dofs();
    for (std::size_t i = 0; i < d.size(); ++i)
      diagonal[d[i]] += m->mass_entry(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(i));
  }
  return diagonal;
}

/// Solves M a = f over the free displacement equations of `system` that
/// carry mass (a = 0 at prescribed, dependent and multiplier dofs, and at
/// massless contact-surface nodes). Constraints do not enter: the
/// accelerations at the start ignore them (docs/theory/dynamics.md).
Eigen::VectorXd solve_mass(const StepSystem& system, const Eigen::VectorXd& f) {
  const EquationMap& eqs = system.equations();
  const DofMap& dofs = system.discretization().dofs();
  const Eigen::VectorXd diagonal = mass_diagonal(system);
  std::unordered_map<int, int> index;
  std::vector<int> free;
  for (int e = 0; e < eqs.n_equations(); ++e)
    if (!dofs.is_multiplier(eqs.dof(e)) && diagonal[eqs.dof(e)] > 0)
      index[eqs.dof(e)] = static_cast<int>(free.size()), free.push_back(eqs.dof(e));
  std::vector<Eigen::Triplet<double>> entries;
  for (const auto& m : system.inertia()) {
    const auto d = m->dofs();
    for (std::size_t i = 0; i < d.size(); ++i)
      for (std::size_t j = 0; j < d.size(); ++j) {
        const auto fi = index.find(d[i]), fj = index.find(d[j]);
        const double v = m->mass_entry(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
        if (fi != index.end() && fj != index.end() && v != 0) entries.emplace_back(fi->second, fj->second, v);
      }
  }
  const auto n = static_cast<Eigen::Index>(free.size());
  Eigen::SparseMatrix<double> mass(n, n);
  mass.setFromTriplets(entries.begin(), entries.end());
  Eigen::VectorXd rhs(n);
  for (Eigen::Index k = 0; k < n; ++k) rhs[k] = f[free[static_cast<std::size_t>(k)]];
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(mass);
  if (ldlt.info() != Eigen::Success) throw ModelError("the mass matrix is singular: a free node carries no mass");
  const Eigen::VectorXd a_free = ldlt.solve(rhs);
  Eigen::VectorXd a = Eigen::VectorXd::Zero(f.size());
  for (Eigen::Index k = 0; k < n; ++k) a[free[static_cast<std::size_t>(k)]] = a_free[k];
  return a;
}

}  // namespace

ImplicitDynamicProcedure::ImplicitDynamicProcedure(StepSystem& system, AnalysisObserver& observer,
                                                   bool stream_results, MotionState& motion)
    : system_(system),
      observer_(observer),
      stream_results_(stream_results),
      motion_(motion),
      newton_(system.solver(), system.step().controls, system.discretization().length_scale()),
      alpha_(system.step().dynamic.alpha),
      beta_((1 - alpha_) * (1 - alpha_) / 4),
      gamma_(0.5 - alpha_) {
  if (!system.step().dynamic.redistribute_contact_mass) return;
  contact_mass_ = redistribute_contact_mass(system.discretization(), system.inertia());
  if (contact_mass_.nodes == 0) return;
  const Eigen::VectorXd diagonal = mass_diagonal(system);
  for (int d = 0; d < system.discretization().dofs().n_displacement_dofs(); ++d)
    if (diagonal[d] == 0) massless_.push_back(d);  // M is positive semi-definite: its row is zero
}

void ImplicitDynamicProcedure::start_step(const IncrementTimes& first, Eigen::VectorXd& u) {
  const Discretization& disc = system_.discretization();
  const DofMap& dofs = disc.dofs();
  const auto n = static_cast<Eigen::Index>(dofs.n_dofs());
  if (!motion_.started) {
    motion_.v = Eigen::VectorXd::Zero(n);
    for (const auto& iv : disc.model().initial_velocities) motion_.v[dofs.displacement(iv.node, iv.dof)] = iv.value;
  }
  motion_.a = Eigen::VectorXd::Zero(n);
  NewmarkIncrement& nm = system_.newmark();
  nm.v_start = &motion_.v;
  nm.a_start = &motion_.a;
  nm.dt = 1, nm.beta = beta_, nm.gamma = gamma_, nm.scale = 0;  // inertia silent: the static part only
  const IncrementTimes start{0, first.total_time - first.step_time, 0, first.period, false};
  const Step& step = system_.step();
  observer_.on_message("*DYNAMIC step " + step.name + ": HHT alpha " + std::to_string(alpha_) + " (Newmark beta " +
                       std::to_string(beta_) + ", gamma " + std::to_string(gamma_) + "), " +
                       (step.dynamic.lumped_mass ? "lumped" : "consistent") + " mass; loads without an amplitude " +
                       (step.ramp_loads ? "ramped over the step (AMPLITUDE=RAMP)"
                                        : "applied at the step's start and held (AMPLITUDE=STEP, the default of "
                                          "dynamic steps)"));
  if (!contact_mass_.describe().empty()) observer_.on_message(contact_mass_.describe());
  system_.apply_loads(start, u, cloads_);
  const EvaluationState s{u, u, 0, start.total_time, 0, system_.step().nlgeom};
  const Eigen::VectorXd r0 = static_residual(s);
  motion_.damping_force = Eigen::VectorXd::Zero(n);
  for (const auto& m : system_.inertia()) m->add_damping_force(s, motion_.v, motion_.damping_force);
  motion_.a = solve_mass(system_, -r0 - motion_.damping_force);
  follow_prescribed_velocities(first.total_time - first.step_time, 0, 0);
  motion_.static_residual = r0;
  Eigen::VectorXd reaction = r0 + motion_.damping_force;
  for (const auto& m : system_.inertia()) m->add_mass_times(motion_.a, reaction);
  motion_.work_force = work_force(s, reaction);
  if (!motion_.started) {
    EnergyTotals& e = motion_.energy;
    e = EnergyTotals{};
    for (const auto& m : system_.inertia()) e.kinetic += m->kinetic_energy(motion_.v);
    for (const auto& el : disc.elements()) e.strain += el->strain_energy(s);
    e.total = motion_.balance_start = e.kinetic + e.strain;
    motion_.started = true;
  }
}

void ImplicitDynamicProcedure::follow_prescribed_velocities(double step_start, double step_time, double dt) {
  const Model& model = system_.discretization().model();
  const double period = system_.step().period;
  const auto velocity = [&](const RampedValue& v, double t) {
    return step_magnitude(model, v.amplitude, v.start, v.target, t, period, step_start + t);
  };
  for (const auto& [dof, v] : system_.loads().prescribed) {
    if (!v.velocity) continue;
    const double now = velocity(v, step_time);
    motion_.a[dof] = dt > 0 ? (now - velocity(v, step_time - dt)) / dt : 0.0;
    motion_.v[dof] = now;
  }
}

Eigen::VectorXd ImplicitDynamicProcedure::static_residual(const EvaluationState& s) {
  Assembler& assembler = system_.assembler();
  assembler.update_connectivity(s);
  Eigen::VectorXd full;
  assembler.assemble(s, full, false);  // the inertia is silent (scale 0)
  return full - cloads_;
}

Eigen::VectorXd ImplicitDynamicProcedure::inertia_force(const EvaluationState& s) const {
  Eigen::VectorXd out = Eigen::VectorXd::Zero(s.u.size());
  LocalSystem local;
  for (const auto& m : system_.inertia()) {
    local.reset(static_cast<Eigen::Index>(m->dofs().size()));
    m->evaluate(s, local, false);
    scatter(*m, local.residual, out);
  }
  return out;
}

Eigen::VectorXd ImplicitDynamicProcedure::work_force(const EvaluationState& s, const Eigen::VectorXd& reaction) const {
  Eigen::VectorXd force = cloads_;
  LocalSystem local;
  for (const Contribution* p : system_.load_contributions()) {  // pressures and body forces
    local.reset(static_cast<Eigen::Index>(p->dofs().size()));
    p->evaluate(s, local, false);
    scatter(*p, -local.residual, force);
  }
  const EquationMap& eqs = system_.equations();
  const int n_disp = system_.discretization().dofs().n_displacement_dofs();
  for (int d = 0; d < n_disp; ++d)
    if (eqs.is_prescribed(d)) force[d] += reaction[d];
  return force;
}

void ImplicitDynamicProcedure::predict(double dt, Eigen::VectorXd& u) const {
  const EquationMap& eqs = system_.equations();
  const DofMap& dofs = system_.discretization().dofs();
  for (int e = 0; e < eqs.n_equations(); ++e) {
    const int d = eqs.dof(e);
    if (!dofs.is_multiplier(d)) u[d] += dt * motion_.v[d] + 0.5 * dt * dt * motion_.a[d];
  }
  eqs.update_dependents(u);
}

IncrementOutcome ImplicitDynamicProcedure::solve_increment(const IncrementAttempt& attempt, Eigen::VectorXd& u) {
  const IncrementTimes& t = attempt.time;
  const Discretization& disc = system_.discretization();
  if (!started_) start_step(t, u), started_ = true;
  const Eigen::VectorXd u_start = u;
  NewmarkIncrement& nm = system_.newmark();
  nm.v_start = &motion_.v, nm.a_start = &motion_.a;
  nm.dt = t.dt, nm.beta = beta_, nm.gamma = gamma_, nm.scale = 1 / (1 + alpha_);
  system_.apply_loads(t, u, cloads_);
  const int n_disp = disc.dofs().n_displacement_dofs();
  external_ = cloads_;
  external_.head(n_disp) += (alpha_ / (1 + alpha_)) * motion_.static_residual.head(n_disp);
  predict(t.dt, u);
  // The force scale counts the inertia forces too (a free body has no reactions).
  std::vector<const Contribution*> scale(system_.load_contributions());
  for (const auto& m : system_.inertia()) scale.push_back(m.get());
  IncrementProblem problem(system_.assembler(), disc.dofs(), u, u_start, external_, std::move(scale),
                           IncrementTime{t.step_time, t.total_time, t.dt, system_.step().nlgeom}, system_.symmetric(),
                           &disc.contact_pairs());
  int iterations = 0;
  const NewtonOutcome newton = solve_with_acceptance(newton_, problem, system_.contributions(), observer_,
                                                     force_average_.value, force_average_.n, iterations);
  IncrementOutcome out = outcome_of(newton, iterations);
  IncrementReport report = report_of(attempt, newton, iterations);
  if (out.converged && system_.step().dynamic.half_increment_tolerance > 0) judge_half_increment(t, problem, out, report);
  observer_.on_increment(report);
  if (out.converged)
    complete(attempt, problem, iterations, newton.force_scale);
  else
    u = u_start;
  return out;
}

void ImplicitDynamicProcedure::judge_half_increment(const IncrementTimes& t, const IncrementProblem& problem,
                                                    IncrementOutcome& out, IncrementReport& report) {
  const double tolerance = system_.step().dynamic.half_increment_tolerance;
  const double r = half_increment_residual(t, problem.state());
  const double ratio = r / tolerance;
  const double estimate = 0.85 / std::sqrt(std::max(ratio, 1e-12));  // the residual grows as dt^2
  if (ratio > 1) {
    out.converged = false;
    out.increment_scale = std::clamp(estimate, 0.25, 0.75);
    out.message = "half-increment residual " + format_time(r) + " above HAFTOL=" + format_time(tolerance);
    report.converged = false;
    report.note = out.message;
    return;
  }
  out.increment_scale = ratio < 0.5 ? std::max(1.0, estimate) : 1.0;
}

double ImplicitDynamicProcedure::half_increment_residual(const IncrementTimes& t, const EvaluationState& end) {
  const Discretization& disc = system_.discretization();
  const DofMap& dofs = disc.dofs();
  const EquationMap& eqs = system_.equations();
  NewmarkIncrement& nm = system_.newmark();
  const double h = 0.5 * t.dt;
  const auto n = end.u.size();
  Eigen::VectorXd u_h = 0.5 * (end.u_start + end.u), v_h = Eigen::VectorXd::Zero(n), a_h = Eigen::VectorXd::Zero(n);
  for (int d = 0; d < dofs.n_displacement_dofs(); ++d) {
    const double v_n = motion_.v[d], a_n = motion_.a[d];
    a_h[d] = 0.5 * (a_n + nm.acceleration(end.u[d], end.u_start[d], v_n, a_n));
    v_h[d] = v_n + h * ((1 - gamma_) * a_n + gamma_ * a_h[d]);
    u_h[d] = end.u_start[d] + h * v_n + h * h * ((0.5 - beta_) * a_n + beta_ * a_h[d]);
  }
  const IncrementTimes middle{t.step_time - h, t.total_time - h, h, t.period, false};
  Eigen::VectorXd forces;
  system_.apply_loads(middle, u_h, forces);  // prescribed values and loads at the middle
  const double scale = nm.scale;
  nm.scale = 0;  // the inertia is added below with the middle's accelerations
  Assembler& assembler = system_.assembler();
  const EvaluationState s_h{u_h, end.u_start, end.step_time - h, end.total_time - h, h, end.nlgeom};
  assembler.update_connectivity(s_h);
  Eigen::VectorXd residual;
  assembler.assemble(s_h, residual, false);
  residual -= forces;
  for (const auto& m : system_.inertia()) {
    m->add_mass_times(a_h, residual);
    m->add_damping_force(s_h, v_h, residual);
  }
  // Back to the increment's end: its loads, pairing and contact status.
  Eigen::VectorXd u_end = end.u, unused;
  system_.apply_loads(t, u_end, unused);
  nm.scale = scale;
  assembler.update_connectivity(end);
  assembler.assemble(end, unused, false);
  double largest = 0;
  for (int e = 0; e < eqs.n_equations(); ++e)
    if (!dofs.is_multiplier(eqs.dof(e))) largest = std::max(largest, std::abs(residual[eqs.dof(e)]));
  return largest;
}

void ImplicitDynamicProcedure::complete(const IncrementAttempt& attempt, const IncrementProblem& problem,
                                        int iterations, double force_scale) {
  const Discretization& disc = system_.discretization();
  const DofMap& dofs = disc.dofs();
  const EvaluationState s = problem.state();
  const auto output_start = std::chrono::steady_clock::now();
  // full = I + S - f - alpha/(1+alpha) r_n with I the scaled inertia, so the
  // new static residual is S - f = full + (external - f) - I.
  const Eigen::VectorXd inertia = inertia_force(s);
  const Eigen::VectorXd r_new = problem.full_residual() + external_ - cloads_ - inertia;
  const Eigen::VectorXd reaction = r_new + (1 + alpha_) * inertia;  // S - f + M a + C v
  const NewmarkIncrement& nm = system_.newmark();
  for (int d = 0; d < dofs.n_displacement_dofs(); ++d) {
    const double a = nm.acceleration(s.u[d], s.u_start[d], motion_.v[d], motion_.a[d]);
    motion_.v[d] = nm.velocity(a, motion_.v[d], motion_.a[d]);
    motion_.a[d] = a;
  }
  // A massless dof's Newmark recursion is not damped by its equation of
  // motion; under the trapezoidal rule its a grows from increment to
  // increment and the next predictor throws its node far off (inverting
  // elements). Its v and a do not enter M a, so take the increment's mean
  // velocity and no acceleration: the predictor extrapolates linearly.
  for (int d : massless_) motion_.v[d] = (s.u[d] - s.u_start[d]) / attempt.time.dt, motion_.a[d] = 0;
  follow_prescribed_velocities(attempt.time.total_time - attempt.time.step_time, attempt.time.step_time,
                               attempt.time.dt);
  motion_.static_residual = r_new;

  // As in static steps (StaticProcedure::complete), streamed results build the
  // element fields (extrapolations, nodal averages) only when the result files
  // are due; the .dat's element prints read their points from the source.
  IncrementResults when;
  stamp(when, attempt, iterations);
  const bool element_fields =
      !stream_results_ ||
      files_due(system_.step().outputs, StepProcedure::ImplicitDynamic, when, attempt.time.ends_step);
  const DiscretizationPoints point_source(disc, s);
  IncrementResults results = build_results(disc, s, reaction, system_.equations(),
                                           stream_results_ ? &point_source : nullptr, element_fields);
  results.velocity.resize(static_cast<std::size_t>(dofs.n_nodes()));
  results.acceleration.resize(results.velocity.size());
  for (int i = 0; i < dofs.n_nodes(); ++i)
    for (int c = 0; c < kDofsPerNode; ++c) {
      results.velocity[static_cast<std::size_t>(i)][c] = motion_.v[dofs.displacement(i, c)];
      results.acceleration[static_cast<std::size_t>(i)][c] = motion_.a[dofs.displacement(i, c)];
    }
  update_energy(s, work_force(s, reaction), results);
  results.energy = motion_.energy;
  for (Contribution* c : system_.contributions()) c->commit(s);
  force_average_.add(force_scale);
  stamp(results, attempt, iterations);
  observer_.on_results(results, system_.step(), attempt.time.ends_step);
  output_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - output_start).count();
}

void ImplicitDynamicProcedure::update_energy(const EvaluationState& s, const Eigen::VectorXd& force,
                                             const IncrementResults& results) {
  const int n_disp = system_.discretization().dofs().n_displacement_dofs();
  EnergyTotals& e = motion_.energy;
  e.work += 0.5 * (motion_.work_force + force).head(n_disp).dot((s.u - s.u_start).head(n_disp));
  motion_.work_force = force;
  Eigen::VectorXd damping = Eigen::VectorXd::Zero(s.u.size());
  for (const auto& m : system_.inertia()) m->add_damping_force(s, motion_.v, damping);
  e.viscous += 0.5 * (motion_.damping_force + damping).head(n_disp).dot((s.u - s.u_start).head(n_disp));
  motion_.damping_force = std::move(damping);
  e.kinetic = 0;
  for (const auto& m : system_.inertia()) e.kinetic += m->kinetic_energy(motion_.v);
  e.strain = 0;
  for (const auto& el : system_.discretization().elements()) e.strain += el->strain_energy(s);
  e.friction = 0;
  for (const ContactPairValues& pair : results.contact) e.friction += pair.dissipation;
  e.plastic = results.plastic_dissipation.value_or(0.0);
  e.total = e.kinetic + e.strain + e.viscous + e.friction + e.plastic - e.work;
  e.numerical = motion_.balance_start - e.total;
}

SolveTiming ImplicitDynamicProcedure::timing() const {
  SolveTiming t = newton_.timing();
  t.output += output_seconds_;
  return t;
}

void ImplicitDynamicProcedure::save(RestartState& state) const { force_average_.save(state); }

void ImplicitDynamicProcedure::restore(const RestartState& state) {
  force_average_.restore(state);
  started_ = true;  // the step's start (initial accelerations) lies before the saved state
}

}  // namespace tether
