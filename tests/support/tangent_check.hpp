#pragma once
// Test helper: finite-difference check of a contribution's tangent.

#include <algorithm>

#include "tether/assembly/contribution.hpp"

namespace tether::testing {

/// Max |analytic tangent - central finite difference of the residual| over the
/// contribution's dofs, relative to max(1, largest analytic entry). Only u is
/// perturbed (step h); u_start and the times are those of `state`.
inline double tangent_error(const Contribution& c, const EvaluationState& state, double h = 1e-6) {
  const auto dofs = c.dofs();
  const auto n = static_cast<Eigen::Index>(dofs.size());
  LocalSystem at;
  at.reset(n);
  c.evaluate(state, at, true);
  Eigen::MatrixXd fd(n, n);
  for (Eigen::Index j = 0; j < n; ++j) {
    Eigen::VectorXd up = state.u, um = state.u;
    up[dofs[j]] += h;
    um[dofs[j]] -= h;
    LocalSystem p, m;
    p.reset(n);
    m.reset(n);
    c.evaluate(EvaluationState{up, state.u_start, state.step_time, state.total_time, state.dt, state.nlgeom}, p, false);
    c.evaluate(EvaluationState{um, state.u_start, state.step_time, state.total_time, state.dt, state.nlgeom}, m, false);
    fd.col(j) = (p.residual - m.residual) / (2 * h);
  }
  return (at.tangent - fd).cwiseAbs().maxCoeff() / std::max(1.0, at.tangent.cwiseAbs().maxCoeff());
}

}  // namespace tether::testing
