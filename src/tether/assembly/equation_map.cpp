#include "tether/assembly/equation_map.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "tether/core/error.hpp"

namespace tether {

namespace {

/// Relative size below which a substituted coefficient counts as zero.
constexpr double kZero = 1e-12;

}  // namespace

EquationMap::EquationMap(const std::vector<bool>& prescribed, std::vector<EliminationRow> rows)
    : equation_(prescribed.size(), -1), prescribed_(prescribed), rows_(std::move(rows)) {
  const int n = static_cast<int>(prescribed.size());
  if (!rows_.empty()) dependent_index_.assign(prescribed.size(), -1);

  // Eliminate row by row, keeping every expansion in terms of independent dofs.
  for (const EliminationRow& row : rows_) {
    std::map<int, double> terms;  // independent dof -> coefficient
    double rhs = row.rhs;
    for (const auto& [dof, c] : row.terms) {
      if (dof < 0 || dof >= n) throw ModelError(row.owner + ": dof " + std::to_string(dof) + " out of range");
      const int k = dependent_index_[dof];
      if (k < 0) {
        terms[dof] += c;
        continue;
      }
      for (const auto& [m, cm] : dependents_[k].expansion) terms[m] += c * cm;
      rhs -= c * dependents_[k].rhs;
    }
    double largest = 0;
    for (const auto& [dof, c] : terms) largest = std::max(largest, std::abs(c));
    int pivot = -1;
    double best = 0;
    for (const auto& [dof, c] : terms)
      if (!prescribed_[dof] && std::abs(c) > kZero * largest && std::abs(c) > best) best = std::abs(c), pivot = dof;
    if (pivot < 0)
      throw ModelError(row.owner + ": cannot be eliminated: after substituting the constraints eliminated before "
                                   "it and the prescribed dofs, no free dof is left (the constraint is redundant or "
                                   "conflicts with other constraints or *BOUNDARY conditions)");
    const double cp = terms.at(pivot);
    Dependent dep{pivot, {}, rhs / cp};
    for (const auto& [dof, c] : terms)
      if (dof != pivot && std::abs(c) > kZero * largest) dep.expansion.emplace_back(dof, -c / cp);
    // Earlier expansions that use the new dependent dof: substitute it.
    for (Dependent& other : dependents_) {
      auto it = std::find_if(other.expansion.begin(), other.expansion.end(),
                             [&](const auto& t) { return t.first == pivot; });
      if (it == other.expansion.end()) continue;
      const double w = it->second;
      other.expansion.erase(it);
      std::map<int, double> merged(other.expansion.begin(), other.expansion.end());
      for (const auto& [m, cm] : dep.expansion) merged[m] += w * cm;
      other.expansion.assign(merged.begin(), merged.end());
      other.rhs += w * dep.rhs;
    }
    dependent_index_[pivot] = static_cast<int>(dependents_.size());
    row_dependent_.push_back(pivot);
    dependents_.push_back(std::move(dep));
  }

  const auto n_prescribed = static_cast<std::size_t>(std::count(prescribed_.begin(), prescribed_.end(), true));
  dof_.reserve(prescribed.size() - n_prescribed - dependents_.size());
  for (int d = 0; d < n; ++d) {
    if (prescribed_[d] || is_dependent(d)) continue;
    equation_[d] = static_cast<int>(dof_.size());
    dof_.push_back(d);
  }

  // T's rows of the dependent dofs, in the order of dependents_.
  if (dependents_.empty()) return;
  weight_offset_.assign(dependents_.size() + 1, 0);
  for (std::size_t k = 0; k < dependents_.size(); ++k) {
    for (const auto& [m, c] : dependents_[k].expansion)
      if (equation_[m] >= 0) weights_.push_back({equation_[m], c});
    weight_offset_[k + 1] = static_cast<int>(weights_.size());
  }
}

void EquationMap::update_dependents(Eigen::VectorXd& u) const {
  for (const Dependent& dep : dependents_) {
    double v = dep.rhs;
    for (const auto& [m, c] : dep.expansion) v += c * u[m];
    u[dep.dof] = v;
  }
}

void EquationMap::reduce(const Eigen::VectorXd& full, Eigen::VectorXd& reduced) const {
  reduced.setZero(n_equations());
  for (int e = 0; e < n_equations(); ++e) reduced[e] = full[dof_[e]];
  for (const Dependent& dep : dependents_)
    for (const EquationWeight& w : weights(dep.dof)) reduced[w.equation] += w.weight * full[dep.dof];
}

}  // namespace tether
