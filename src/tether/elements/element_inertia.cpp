#include "tether/elements/element_inertia.hpp"

#include <algorithm>

namespace tether {

ElementInertia::ElementInertia(const ContinuumElement& element, MassKind kind, double damping_alpha,
                               double damping_beta, const NewmarkIncrement& increment)
    : element_(element), increment_(increment), kind_(kind), damping_alpha_(damping_alpha), damping_beta_(damping_beta) {
  element_.mass(kind, mass_);
}

void ElementInertia::evaluate(const EvaluationState& s, LocalSystem& out, bool need_tangent) const {
  const NewmarkIncrement& n = increment_;
  const auto dofs = element_.dofs();
  const auto size = static_cast<Eigen::Index>(dofs.size());
  Eigen::VectorXd a(size), v(size);
  for (Eigen::Index i = 0; i < size; ++i) {
    const int d = dofs[static_cast<std::size_t>(i)];
    const double v_n = (*n.v_start)[d], a_n = (*n.a_start)[d];
    a[i] = n.acceleration(s.u[d], s.u_start[d], v_n, a_n);
    v[i] = n.velocity(a[i], v_n, a_n);
  }
  const double c_u = 1 / (n.beta * n.dt * n.dt), c_v = n.gamma / (n.beta * n.dt);
  out.residual.noalias() = n.scale * (mass_ * (a + damping_alpha_ * v));
  if (need_tangent) out.tangent.noalias() = (n.scale * (c_u + c_v * damping_alpha_)) * mass_;
  if (damping_beta_ == 0) return;
  LocalSystem k;
  k.reset(size);
  element_.evaluate(s, k, true);
  out.residual.noalias() += (n.scale * damping_beta_) * (k.tangent * v);
  if (need_tangent) out.tangent += (n.scale * damping_beta_ * c_v) * k.tangent;
}

bool ElementInertia::redistribute(const std::vector<bool>& massless) {
  if (std::all_of(massless.begin(), massless.end(), [](bool f) { return f; })) return false;
  Eigen::MatrixXd lumped;
  element_.mass(MassKind::Lumped, lumped);
  const auto n = static_cast<Eigen::Index>(massless.size());
  const Eigen::Index c = mass_.rows() / n;  // components per node of the element's local dofs
  Eigen::VectorXd weights(n);
  for (Eigen::Index a = 0; a < n; ++a) weights[a] = lumped(c * a, c * a);
  mass_ = redistribute_mass(mass_, static_cast<int>(c), weights, massless, kind_ == MassKind::Lumped);
  return true;
}

double ElementInertia::kinetic_energy(const Eigen::VectorXd& v) const {
  const auto dofs = element_.dofs();
  Eigen::VectorXd ve(static_cast<Eigen::Index>(dofs.size()));
  for (std::size_t i = 0; i < dofs.size(); ++i) ve[static_cast<Eigen::Index>(i)] = v[dofs[i]];
  return 0.5 * ve.dot(mass_ * ve);
}

void ElementInertia::add_damping_force(const EvaluationState& s, const Eigen::VectorXd& v, Eigen::VectorXd& out) const {
  if (!damped()) return;
  const auto dofs = element_.dofs();
  const auto size = static_cast<Eigen::Index>(dofs.size());
  Eigen::VectorXd ve(size);
  for (Eigen::Index i = 0; i < size; ++i) ve[i] = v[dofs[static_cast<std::size_t>(i)]];
  Eigen::VectorXd f = damping_alpha_ * (mass_ * ve);
  if (damping_beta_ > 0) {
    LocalSystem k;
    k.reset(size);
    element_.evaluate(s, k, true);
    f += damping_beta_ * (k.tangent * ve);
  }
  for (Eigen::Index i = 0; i < size; ++i) out[dofs[static_cast<std::size_t>(i)]] += f[i];
}

void ElementInertia::add_mass_times(const Eigen::VectorXd& x, Eigen::VectorXd& out) const {
  const auto dofs = element_.dofs();
  const auto size = static_cast<Eigen::Index>(dofs.size());
  Eigen::VectorXd xe(size);
  for (Eigen::Index i = 0; i < size; ++i) xe[i] = x[dofs[static_cast<std::size_t>(i)]];
  const Eigen::VectorXd y = mass_ * xe;
  for (Eigen::Index i = 0; i < size; ++i) out[dofs[static_cast<std::size_t>(i)]] += y[i];
}

}  // namespace tether
