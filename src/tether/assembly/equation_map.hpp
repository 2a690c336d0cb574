#pragma once
/// \file Which global unknowns are solved for, which are prescribed and which
/// are eliminated by linear constraints.
///
/// Every global dof is one of:
/// - free: it has an equation number 0..n-1 (free displacements, all multipliers);
/// - prescribed (Dirichlet): its value is set in the global vector, no equation;
/// - dependent: eliminated by a linear constraint, u_d = sum_k c_k u_k + g,
///   where every u_k is free or prescribed (chains are resolved).
///
/// The reduced system is T^T K T du = -T^T r with T the map from free
/// equations to all dofs: a free dof maps to itself with weight 1, a dependent
/// one to the free dofs of its expansion with their coefficients.

#include <Eigen/Core>
#include <span>
#include <string>
#include <vector>

namespace tether {

/// One row of a linear constraint to eliminate: sum_k coefficient_k u[dof_k] = rhs.
struct EliminationRow {
  std::vector<std::pair<int, double>> terms;  ///< (global dof, coefficient)
  double rhs = 0;
  std::string owner;                          ///< constraint name, for messages
};

/// A (equation, weight) pair of the map T.
struct EquationWeight {
  int equation;
  double weight;
};

class EquationMap {
 public:
  EquationMap() = default;

  /// `prescribed[d]` is true for Dirichlet dof d; size = number of global dofs.
  /// `rows` are eliminated in order: each picks as dependent the dof of largest
  /// |coefficient| that is neither prescribed nor already dependent (so the
  /// answer does not depend on the order the terms were written). Throws
  /// ModelError naming the constraint when a row is redundant or conflicting
  /// (nothing left to eliminate after substituting earlier rows and
  /// prescribed dofs).
  explicit EquationMap(const std::vector<bool>& prescribed, std::vector<EliminationRow> rows = {});

  /// Equation of global dof d, or -1 when d is prescribed or dependent.
  [[nodiscard]] int equation(int dof) const { return equation_[dof]; }
  /// Global dof of equation e.
  [[nodiscard]] int dof(int eq) const { return dof_[eq]; }
  [[nodiscard]] int n_equations() const { return static_cast<int>(dof_.size()); }
  [[nodiscard]] int n_dofs() const { return static_cast<int>(equation_.size()); }
  [[nodiscard]] bool is_prescribed(int dof) const { return prescribed_[dof]; }
  [[nodiscard]] bool is_dependent(int dof) const { return dependent_index_[dof] >= 0; }
  [[nodiscard]] bool has_dependents() const { return !dependents_.empty(); }

  /// Row of T for global dof d: its equations and weights (empty for prescribed dofs).
  [[nodiscard]] std::span<const EquationWeight> weights(int dof) const;

  /// Sets every dependent dof from its expansion (call after changing free or
  /// prescribed values).
  void update_dependents(Eigen::VectorXd& u) const;

  /// Reduced residual T^T r from the residual over all dofs.
  void reduce(const Eigen::VectorXd& full, Eigen::VectorXd& reduced) const;

  /// The dependent dof chosen for elimination row k (in the order given).
  [[nodiscard]] int dependent_of_row(int k) const { return row_dependent_[k]; }
  /// The rows as given (for multiplier recovery).
  [[nodiscard]] const std::vector<EliminationRow>& rows() const { return rows_; }

 private:
  struct Dependent {
    int dof;
    std::vector<std::pair<int, double>> expansion;  ///< over free and prescribed dofs
    double rhs;
  };
  std::vector<int> equation_;
  std::vector<int> dof_;
  std::vector<bool> prescribed_;
  std::vector<int> dependent_index_;     ///< per dof: index into dependents_ or -1
  std::vector<Dependent> dependents_;
  std::vector<EquationWeight> weights_;  ///< T rows, flattened
  std::vector<int> weight_offset_;       ///< per dof, into weights_ (size n_dofs + 1)
  std::vector<EliminationRow> rows_;
  std::vector<int> row_dependent_;
};

}  // namespace tether
