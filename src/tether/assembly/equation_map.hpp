#pragma once
/// \file Which global unknowns are solved for and which are prescribed.
///
/// Prescribed displacement dofs (Dirichlet conditions) are eliminated: they are
/// given values in the global vector and get no equation. Every other unknown
/// (free displacements and all multipliers) gets an equation number 0..n-1.

#include <vector>

namespace tether {

class EquationMap {
 public:
  EquationMap() = default;
  /// `prescribed[d]` is true for eliminated dof d; size = number of global dofs.
  explicit EquationMap(const std::vector<bool>& prescribed);

  /// Equation of global dof d, or -1 when d is prescribed.
  [[nodiscard]] int equation(int dof) const { return equation_[dof]; }
  /// Global dof of equation e.
  [[nodiscard]] int dof(int eq) const { return dof_[eq]; }
  [[nodiscard]] int n_equations() const { return static_cast<int>(dof_.size()); }
  [[nodiscard]] int n_dofs() const { return static_cast<int>(equation_.size()); }
  [[nodiscard]] bool is_prescribed(int dof) const { return equation_[dof] < 0; }

 private:
  std::vector<int> equation_;
  std::vector<int> dof_;
};

}  // namespace tether
