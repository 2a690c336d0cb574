#include "tether/analysis/constraint_checks.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "tether/core/error.hpp"

namespace tether {

namespace {

/// A linear constraint row restricted to the free dofs, scaled so that its
/// first coefficient is 1 (rounded), as a key for duplicate detection.
std::vector<std::pair<int, long long>> signature(const Eigen::RowVectorXd& g, std::span<const int> dofs,
                                                 const EquationMap& equations) {
  std::vector<std::pair<int, long long>> key;
  double first = 0;
  for (Eigen::Index j = 0; j < g.size(); ++j) {
    if (g[j] == 0 || equations.is_prescribed(dofs[j])) continue;
    if (first == 0) first = g[j];
    key.emplace_back(dofs[j], std::llround(g[j] / first * 1e9));
  }
  std::sort(key.begin(), key.end());
  return key;
}

}  // namespace

void check_constraints(const Discretization& discretization, const EquationMap& equations,
                       const EvaluationState& state) {
  int n_rows = 0;
  std::map<std::vector<std::pair<int, long long>>, std::string> seen;
  for (const auto& c : discretization.constraints()) {
    if (c->enforcement().method != Enforcement::Method::Lagrange) continue;
    const ConstraintFunction& f = c->function();
    const auto dofs = f.dofs();
    ConstraintInput in;
    in.u.resize(static_cast<Eigen::Index>(dofs.size()));
    for (std::size_t i = 0; i < dofs.size(); ++i) in.u[static_cast<Eigen::Index>(i)] = state.u[dofs[i]];
    in.u_start = in.u;
    in.step_time = state.step_time;
    in.total_time = state.total_time;
    ConstraintOutput out;
    out.reset(f.n_equations(), static_cast<Eigen::Index>(dofs.size()), false);
    f.evaluate(in, out, false);
    for (int k = 0; k < f.n_equations(); ++k) {
      ++n_rows;
      double norm = 0;
      for (std::size_t j = 0; j < dofs.size(); ++j)
        if (!equations.is_prescribed(dofs[j])) norm += std::abs(out.gradient(k, static_cast<Eigen::Index>(j)));
      const std::string row = f.n_equations() > 1 ? " (equation " + std::to_string(k + 1) + ")" : "";
      if (norm == 0 && c->enforcement().epsilon == 0)
        throw ModelError(f.describe() + row +
                         ": its gradient vanishes on the free dofs (all its dofs are prescribed, or f does not "
                         "change with them here), so its multiplier is undetermined; remove the constraint or "
                         "regularise it with EPSILON");
      if (!f.linear() || c->enforcement().epsilon != 0) continue;
      auto key = signature(out.gradient.row(k), dofs, equations);
      const auto [it, fresh] = seen.emplace(std::move(key), f.describe() + row);
      if (!fresh)
        throw ModelError(f.describe() + row + " repeats " + it->second +
                         " (the same equation on the free dofs): remove one of them");
    }
  }
  int free_displacements = 0;
  for (int e = 0; e < equations.n_equations(); ++e)
    free_displacements += !discretization.dofs().is_multiplier(equations.dof(e));
  if (n_rows > free_displacements)
    throw ModelError(std::to_string(n_rows) + " constraint equations act on only " +
                     std::to_string(free_displacements) +
                     " free displacement dofs: the constraints cannot all be independent");
}

}  // namespace tether
