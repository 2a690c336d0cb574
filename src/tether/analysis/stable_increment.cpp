#include "tether/analysis/stable_increment.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <sstream>

#include "tether/core/error.hpp"

namespace tether {

double largest_frequency_squared(const Eigen::MatrixXd& stiffness, const Eigen::VectorXd& lumped_mass,
                                 const std::string& what) {
  const Eigen::Index n = lumped_mass.size();
  Eigen::VectorXd scale(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    if (!(lumped_mass[i] > 0))
      throw ModelError(what + " has a lumped mass of " + std::to_string(lumped_mass[i]) +
                       " at one of its dofs: the stable increment needs a positive mass at every node");
    scale[i] = 1 / std::sqrt(lumped_mass[i]);
  }
  // M^-1/2 K M^-1/2 has the eigenvalues omega^2 of the generalized problem.
  const Eigen::MatrixXd scaled = scale.asDiagonal() * (0.5 * (stiffness + stiffness.transpose())) * scale.asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(scaled, Eigen::EigenvaluesOnly);
  if (eigen.info() != Eigen::Success) return std::numeric_limits<double>::quiet_NaN();
  return eigen.eigenvalues().maxCoeff();
}

double damped_stable_increment(double omega, double beta) {
  const double xi = 0.5 * beta * omega;
  // (2/omega)(sqrt(1 + xi^2) - xi), written without the cancellation at large xi.
  return 2 / (omega * (std::sqrt(1 + xi * xi) + xi));
}

StableIncrement stable_increment(const std::vector<std::unique_ptr<ElementInertia>>& inertia,
                                 const EvaluationState& s, const std::function<bool(int)>& held) {
  StableIncrement out;
  LocalSystem local;
  std::vector<Eigen::Index> free;
  for (std::size_t e = 0; e < inertia.size(); ++e) {
    const ElementInertia& m = *inertia[e];
    const auto dofs = m.dofs();
    free.clear();
    for (std::size_t i = 0; i < dofs.size(); ++i)
      if (!held || !held(dofs[i])) free.push_back(static_cast<Eigen::Index>(i));
    if (free.empty()) continue;
    local.reset(static_cast<Eigen::Index>(dofs.size()));
    m.element().evaluate(s, local, true);
    const std::string what = m.element().describe();
    const Eigen::VectorXd mass = m.mass_diagonal();
    const double omega2 = free.size() == dofs.size()
                              ? largest_frequency_squared(local.tangent, mass, what)
                              : largest_frequency_squared(local.tangent(free, free), mass(free), what);
    if (!(omega2 > 0) || !std::isfinite(omega2)) {
      std::ostringstream why;
      why << what << " gives a stable time increment that is not a positive number (largest omega^2 = " << omega2
          << "): the element has no stiffness, or is degenerate or inverted";
      throw ModelError(why.str());
    }
    const double omega = std::sqrt(omega2);
    out.omega_max = std::max(out.omega_max, omega);
    const double dt = damped_stable_increment(omega, m.damping_beta());
    if (dt < out.dt) out.dt = dt, out.element = static_cast<int>(e);
  }
  return out;
}

}  // namespace tether
