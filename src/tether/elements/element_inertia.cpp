#include "tether/elements/element_inertia.hpp"

#include <algorithm>

namespace tether {

ElementInertia::ElementInertia(const ContinuumElement& element, MassKind kind, double damping_alpha,
                               double damping_beta, const NewmarkIncrement& increment)
    : element_(element), increment_(increment), kind_(kind), damping_alpha_(damping_alpha), damping_beta_(damping_beta) {
  Eigen::MatrixXd full;
  element_.mass(kind, full);  // (c n) x (c n), node by node (expand_to_components)
  const auto n = static_cast<Eigen::Index>(element_.nodes().size());
  components_ = full.rows() / n;
  nodal_.resize(n, kind == MassKind::Lumped ? 1 : n);
  for (Eigen::Index a = 0; a < n; ++a)
    for (Eigen::Index b = 0; b < nodal_.cols(); ++b)
      nodal_(a, b) = full(components_ * a, components_ * (kind == MassKind::Lumped ? a : b));
}

void ElementInertia::expanded_mass(Eigen::MatrixXd& out) const {
  if (moved_) {
    out = *moved_;
  } else if (kind_ == MassKind::Lumped) {
    const Eigen::MatrixXd diagonal = nodal_.col(0).asDiagonal();
    expand_to_components(diagonal, static_cast<int>(components_), out);
  } else {
    expand_to_components(nodal_, static_cast<int>(components_), out);
  }
}

Eigen::MatrixXd ElementInertia::mass() const {
  Eigen::MatrixXd out;
  expanded_mass(out);
  return out;
}

double ElementInertia::mass_entry(Eigen::Index i, Eigen::Index j) const {
  if (moved_) return (*moved_)(i, j);
  const Eigen::Index c = components_;
  if (i % c != j % c) return 0;  // local dofs node by node: component i % c of node i / c
  if (kind_ == MassKind::Lumped) return i == j ? nodal_(i / c, 0) : 0;
  return nodal_(i / c, j / c);
}

Eigen::VectorXd ElementInertia::mass_diagonal() const {
  const Eigen::Index size = components_ * nodal_.rows();
  Eigen::VectorXd out(size);
  for (Eigen::Index i = 0; i < size; ++i) out[i] = mass_entry(i, i);
  return out;
}

Eigen::Index ElementInertia::stored_mass_values() const { return moved_ ? moved_->size() : nodal_.size(); }

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
  Eigen::MatrixXd mass;
  expanded_mass(mass);
  out.residual.noalias() = n.scale * (mass * (a + damping_alpha_ * v));
  if (need_tangent) out.tangent.noalias() = (n.scale * (c_u + c_v * damping_alpha_)) * mass;
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
  const Eigen::Index c = components_;
  Eigen::VectorXd weights(n);
  for (Eigen::Index a = 0; a < n; ++a) weights[a] = lumped(c * a, c * a);
  moved_ = std::make_unique<Eigen::MatrixXd>(
      redistribute_mass(mass(), static_cast<int>(c), weights, massless, kind_ == MassKind::Lumped));
  return true;
}

double ElementInertia::kinetic_energy(const Eigen::VectorXd& v) const {
  const auto dofs = element_.dofs();
  Eigen::VectorXd ve(static_cast<Eigen::Index>(dofs.size()));
  for (std::size_t i = 0; i < dofs.size(); ++i) ve[static_cast<Eigen::Index>(i)] = v[dofs[i]];
  return 0.5 * ve.dot(mass() * ve);
}

void ElementInertia::add_damping_force(const EvaluationState& s, const Eigen::VectorXd& v, Eigen::VectorXd& out) const {
  if (!damped()) return;
  const auto dofs = element_.dofs();
  const auto size = static_cast<Eigen::Index>(dofs.size());
  Eigen::VectorXd ve(size);
  for (Eigen::Index i = 0; i < size; ++i) ve[i] = v[dofs[static_cast<std::size_t>(i)]];
  Eigen::VectorXd f = damping_alpha_ * (mass() * ve);
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
  const Eigen::VectorXd y = mass() * xe;
  for (Eigen::Index i = 0; i < size; ++i) out[dofs[static_cast<std::size_t>(i)]] += y[i];
}

}  // namespace tether
