#include "tether/constraints/constraint_element.hpp"

#include <limits>
#include <stdexcept>

#include "tether/assembly/saved_state.hpp"
#include "tether/core/error.hpp"
#include "tether/dofs/dof_map.hpp"

namespace tether {

namespace {
constexpr double kStateTag = 1001;  ///< first value of a saved ConstraintElement state
}  // namespace

std::string to_string(Enforcement::Method method) {
  switch (method) {
    case Enforcement::Method::Lagrange: return "LAGRANGE";
    case Enforcement::Method::Penalty: return "PENALTY";
    case Enforcement::Method::Augmented: return "AUGMENTED LAGRANGE";
    case Enforcement::Method::Elimination: return "ELIMINATION";
  }
  return "?";
}

ConstraintElement::ConstraintElement(std::unique_ptr<ConstraintFunction> function, Enforcement enforcement,
                                     int first_multiplier, std::string name, std::vector<int> nodes)
    : function_(std::move(function)), enforcement_(enforcement), name_(std::move(name)), nodes_(std::move(nodes)) {
  if (enforcement_.method == Enforcement::Method::Elimination)
    throw std::invalid_argument(name_ + ": elimination is applied to the equations, not as an element");
  const auto fd = function_->dofs();
  n_ = static_cast<int>(fd.size());
  m_ = function_->n_equations();
  dofs_.assign(fd.begin(), fd.end());
  if (enforcement_.method == Enforcement::Method::Lagrange)
    for (int k = 0; k < m_; ++k) dofs_.push_back(first_multiplier + k);
  lambda_bar_.setZero(m_);
}

ConstraintInput ConstraintElement::gather(const EvaluationState& state) const {
  ConstraintInput in;
  in.u.resize(n_);
  in.u_start.resize(n_);
  for (int i = 0; i < n_; ++i) in.u[i] = state.u[dofs_[i]], in.u_start[i] = state.u_start[dofs_[i]];
  in.step_time = state.step_time;
  in.total_time = state.total_time;
  return in;
}

void ConstraintElement::evaluate(const EvaluationState& state, LocalSystem& out, bool need_tangent) const {
  const ConstraintInput in = gather(state);
  ConstraintOutput c;
  const bool nonlinear = !function_->linear();
  c.reset(m_, n_, need_tangent && nonlinear);
  function_->evaluate(in, c, need_tangent && nonlinear);
  const Eigen::MatrixXd& g = c.gradient;

  auto add_curvature = [&](const Eigen::VectorXd& weights) {
    if (!need_tangent || !nonlinear) return;
    for (int k = 0; k < m_; ++k) out.tangent.topLeftCorner(n_, n_) += weights[k] * c.hessian[k];
  };

  switch (enforcement_.method) {
    case Enforcement::Method::Lagrange: {
      Eigen::VectorXd lambda(m_);
      for (int k = 0; k < m_; ++k) lambda[k] = state.u[dofs_[n_ + k]];
      out.residual.head(n_) = g.transpose() * lambda;
      out.residual.tail(m_) = c.f - enforcement_.epsilon * lambda;
      if (!need_tangent) return;
      add_curvature(lambda);
      out.tangent.topRightCorner(n_, m_) = g.transpose();
      out.tangent.bottomLeftCorner(m_, n_) = g;
      out.tangent.bottomRightCorner(m_, m_).diagonal().setConstant(-enforcement_.epsilon);
      return;
    }
    case Enforcement::Method::Penalty: {
      const double rho = enforcement_.penalty;
      out.residual = rho * g.transpose() * c.f;
      if (!need_tangent) return;
      out.tangent = rho * g.transpose() * g;
      add_curvature(rho * c.f);
      return;
    }
    case Enforcement::Method::Augmented: {
      const double rho = enforcement_.penalty;
      const Eigen::VectorXd force = lambda_bar_ + rho * c.f;
      out.residual = g.transpose() * force;
      if (!need_tangent) return;
      out.tangent = rho * g.transpose() * g;
      add_curvature(force);
      return;
    }
    case Enforcement::Method::Elimination: break;
  }
}

Acceptance ConstraintElement::on_converged(const EvaluationState& state) {
  if (enforcement_.method != Enforcement::Method::Augmented) return Acceptance::Accept;
  ConstraintOutput c;
  c.reset(m_, n_, false);
  function_->evaluate(gather(state), c, false);
  if (c.f.cwiseAbs().maxCoeff() <= enforcement_.tolerance) return Acceptance::Accept;
  if (updates_in_increment_ >= enforcement_.max_updates)
    throw ModelError(name_ + ": augmented Lagrangian did not reach |f| <= " + std::to_string(enforcement_.tolerance) +
                     " in " + std::to_string(enforcement_.max_updates) + " updates of one increment (|f| = " +
                     std::to_string(c.f.cwiseAbs().maxCoeff()) + "); raise the penalty");
  lambda_bar_ += enforcement_.penalty * c.f;
  ++updates_;
  ++updates_in_increment_;
  return Acceptance::Iterate;
}

void ConstraintElement::commit(const EvaluationState& /*state*/) { updates_in_increment_ = 0; }

void ConstraintElement::save_state(std::vector<double>& out) const {
  if (enforcement_.method != Enforcement::Method::Augmented) return;
  out.push_back(kStateTag);
  out.push_back(m_);
  out.push_back(updates_);
  out.insert(out.end(), lambda_bar_.data(), lambda_bar_.data() + m_);
}

void ConstraintElement::load_state(std::span<const double>& in) {
  if (enforcement_.method != Enforcement::Method::Augmented) return;
  saved_state::expect_tag(in, kStateTag, "constraint element");
  saved_state::take_int(in, m_, m_, "number of equations");
  const int updates = saved_state::take_int(in, 0, std::numeric_limits<int>::max(), "update count");
  Eigen::VectorXd lambda_bar(m_);
  for (int k = 0; k < m_; ++k) lambda_bar[k] = saved_state::take(in);
  updates_ = updates;
  lambda_bar_ = lambda_bar;
}

MultiplierValues ConstraintElement::values(const EvaluationState& state, const DofMap& dofs) const {
  ConstraintOutput c;
  c.reset(m_, n_, false);
  function_->evaluate(gather(state), c, false);
  MultiplierValues v;
  v.owner = name_;
  v.nodes = nodes_;
  v.constraint.assign(c.f.data(), c.f.data() + m_);
  v.value.resize(m_);
  for (int k = 0; k < m_; ++k) {
    switch (enforcement_.method) {
      case Enforcement::Method::Lagrange: v.value[k] = state.u[dofs_[n_ + k]]; break;
      case Enforcement::Method::Penalty: v.value[k] = enforcement_.penalty * c.f[k]; break;
      case Enforcement::Method::Augmented: v.value[k] = lambda_bar_[k] + enforcement_.penalty * c.f[k]; break;
      case Enforcement::Method::Elimination: v.value[k] = 0; break;
    }
  }
  // Force on dof i: -sum_k lambda_k df_k/du_i, gathered per node; on a
  // rotation (BEAM reference node) it is the moment on the node.
  const Eigen::VectorXd force = -(c.gradient.transpose() * Eigen::Map<const Eigen::VectorXd>(v.value.data(), m_));
  for (int i = 0; i < n_; ++i) {
    const int node = dofs.node_of(dofs_[i]), component = dofs.component_of(dofs_[i]);
    std::size_t a = 0;
    while (a < v.nodal_force.size() && v.nodal_force[a].node != node) ++a;
    if (a == v.nodal_force.size()) v.nodal_force.push_back({node, Eigen::Vector2d::Zero(), std::nullopt});
    if (component < kDofsPerNode)
      v.nodal_force[a].force[component] += force[i];
    else
      v.nodal_force[a].moment = v.nodal_force[a].moment.value_or(0.0) + force[i];
  }
  return v;
}

}  // namespace tether
