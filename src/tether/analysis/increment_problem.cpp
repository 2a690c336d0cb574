#include "tether/analysis/increment_problem.hpp"

#include <chrono>
#include <cmath>

#include "tether/contact/contact_pair.hpp"
#include "tether/contact/mortar_pair.hpp"

namespace tether {

IncrementProblem::IncrementProblem(Assembler& assembler, const DofMap& dofs, Eigen::VectorXd& u,
                                   const Eigen::VectorXd& u_start, const Eigen::VectorXd& external,
                                   std::vector<const Contribution*> loads, IncrementTime time, bool symmetric,
                                   const std::vector<std::unique_ptr<ContactPair>>* contact,
                                   const std::vector<std::unique_ptr<MortarPair>>* mortar)
    : assembler_(assembler),
      dofs_(dofs),
      u_(u),
      u_start_(u_start),
      external_(external),
      loads_(std::move(loads)),
      time_(time),
      symmetric_(symmetric),
      contact_(contact && !contact->empty() ? contact : nullptr),
      mortar_(mortar && !mortar->empty() ? mortar : nullptr) {}

IncrementProblem::~IncrementProblem() { assembler_.enable_residual_updates(false); }

EvaluationState IncrementProblem::state() const {
  return EvaluationState{u_, u_start_, time_.step_time, time_.total_time, time_.dt, time_.nlgeom};
}

bool IncrementProblem::evaluate(Eigen::VectorXd& residual, bool with_tangent, IterationNorms& norms,
                                double& force_scale) {
  const EvaluationState s = state();
  const auto t0 = std::chrono::steady_clock::now();
  const bool changed = assembler_.update_connectivity(s);
  const auto t1 = std::chrono::steady_clock::now();
  assembler_.assemble(s, full_, with_tangent);
  full_ -= external_;
  search_seconds_ = std::chrono::duration<double>(t1 - t0).count();
  assembly_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();

  const EquationMap& eqs = assembler_.equations();
  const int n_disp = dofs_.n_displacement_dofs();
  eqs.reduce(full_, residual);
  // Local accumulators: stored through `norms` at every equation, the
  // maxima were a chain of stores and loads (the compiler cannot keep them
  // in registers while `residual` might alias them). Same values: a NaN
  // makes the force residual NaN, as std::max kept it before.
  double force = 0, multiplier = 0;
  bool not_a_number = false;
  for (int e = 0; e < eqs.n_equations(); ++e) {
    const double a = std::abs(residual[e]);
    if (std::isnan(a)) {
      not_a_number = true;
      continue;
    }
    if (dofs_.is_multiplier(eqs.dof(e)))
      multiplier = std::max(multiplier, a);
    else
      force = std::max(force, a);  // forces (and moments at rotations)
  }
  norms.force_residual = not_a_number ? NAN : force;
  norms.multiplier_residual = multiplier;
  norms.increment = (u_.head(n_disp) - u_start_.head(n_disp)).cwiseAbs().maxCoeff();
  norms.contact_closed = contact_ || mortar_ ? 0 : -1;
  norms.contact_changes = norms.contact_repaired = norms.contact_held = 0;
  if (contact_)
    for (const auto& pair : *contact_) {
      const ContactIterationStatistics& c = pair->statistics();
      norms.contact_closed += c.closed;
      norms.contact_changes += c.status_changes;
      norms.contact_repaired += c.repaired;
      norms.contact_held += c.held_closed;
    }
  if (mortar_)
    for (const auto& pair : *mortar_) {
      const MortarIterationStatistics& c = pair->statistics();
      norms.contact_closed += c.closed;
      norms.contact_changes += c.status_changes;
      norms.contact_repaired += c.repaired;
      norms.contact_held += c.held;
    }

  force_scale = force_scale_of(s, n_disp);
  return changed;
}

double IncrementProblem::force_scale_of(const EvaluationState& s, int n_disp) const {
  // Force scale q: mean magnitude of the nonzero nodal forces (reactions at
  // prescribed dofs, applied forces and pressure resultants elsewhere).
  // (A buffer kept between calls would stay alive through the bulk's
  // factorization and add a vector of the displacement dofs to the peak memory.)
  const EquationMap& eqs = assembler_.equations();
  Eigen::VectorXd magnitude = external_.head(n_disp).cwiseAbs();
  LocalSystem local;
  for (const Contribution* load : loads_) {
    const auto dofs = load->dofs();
    local.reset(static_cast<Eigen::Index>(dofs.size()));
    load->evaluate(s, local, false);
    for (std::size_t a = 0; a < dofs.size(); ++a)
      if (dofs[a] < n_disp) magnitude[dofs[a]] += std::abs(local.residual[static_cast<Eigen::Index>(a)]);
  }
  for (int d = 0; d < n_disp; ++d)
    if (eqs.is_prescribed(d)) magnitude[d] = std::abs(full_[d]);
  const double largest = magnitude.size() ? magnitude.maxCoeff() : 0.0;
  double sum = 0;
  int count = 0;
  const double floor = 1e-10 * largest;
  for (int d = 0; d < n_disp; ++d)
    if (magnitude[d] > floor) sum += magnitude[d], ++count;
  return count ? sum / count : 0.0;
}

void IncrementProblem::apply_correction(const Eigen::VectorXd& correction, double alpha) {
  const EquationMap& eqs = assembler_.equations();
  for (int e = 0; e < eqs.n_equations(); ++e) u_[eqs.dof(e)] += alpha * correction[e];
  eqs.update_dependents(u_);
}

double IncrementProblem::displacement_norm(const Eigen::VectorXd& correction) const {
  const EquationMap& eqs = assembler_.equations();
  double m = 0;
  for (int e = 0; e < eqs.n_equations(); ++e)
    if (!dofs_.is_multiplier(eqs.dof(e))) m = std::max(m, std::abs(correction[e]));
  return m;
}

bool IncrementProblem::is_multiplier_equation(int eq) const {
  const EquationMap& eqs = assembler_.equations();
  return eq >= 0 && eq < eqs.n_equations() && dofs_.is_multiplier(eqs.dof(eq));
}

std::string IncrementProblem::describe_equation(int eq) const {
  const EquationMap& eqs = assembler_.equations();
  if (eq < 0 || eq >= eqs.n_equations()) return "equation " + std::to_string(eq);
  return dofs_.describe(eqs.dof(eq));
}

}  // namespace tether
