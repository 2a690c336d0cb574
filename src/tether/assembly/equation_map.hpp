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
///
/// Memory: T's rows are stored for the dependent dofs only (a free dof's
/// row, (its equation, 1), is made when asked for), and the per-dof index of
/// the dependents only when there are any: a model without *EQUATION, *MPC
/// or *TIE keeps 8 bytes per dof (equation and dof numbers) and a bit.

#include <Eigen/Core>
#include <cstddef>
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

/// One row of T (EquationMap::weights), iterated like a span: a view of a
/// dependent dof's stored row, or a free dof's one pair held by value. The
/// pairs it hands out live as long as the WeightRow: keep it alive while
/// they are read (a range-for over `map.weights(d)` does).
class WeightRow {
 public:
  WeightRow() = default;  ///< empty (a prescribed dof)
  /// A free dof's row: the single pair (equation, 1).
  explicit WeightRow(int equation) : single_{equation, 1.0}, size_(1) {}
  /// A stored row of `size` pairs from `data` (which outlives this row).
  WeightRow(const EquationWeight* data, std::size_t size) : data_(data), size_(size) {}

  [[nodiscard]] const EquationWeight* begin() const { return data_ != nullptr ? data_ : &single_; }
  [[nodiscard]] const EquationWeight* end() const { return begin() + size_; }
  [[nodiscard]] std::size_t size() const { return size_; }
  [[nodiscard]] bool empty() const { return size_ == 0; }
  [[nodiscard]] const EquationWeight& operator[](std::size_t k) const { return begin()[k]; }

 private:
  const EquationWeight* data_ = nullptr;  ///< null: the row is single_ (or empty)
  EquationWeight single_{-1, 0.0};
  std::size_t size_ = 0;
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
  [[nodiscard]] bool is_dependent(int dof) const { return !dependent_index_.empty() && dependent_index_[dof] >= 0; }
  [[nodiscard]] bool has_dependents() const { return !dependents_.empty(); }

  /// Row of T for global dof d: its equations and weights ((equation, 1) for
  /// a free dof, empty for a prescribed one).
  [[nodiscard]] WeightRow weights(int dof) const {
    if (!dependent_index_.empty())
      if (const int k = dependent_index_[dof]; k >= 0)
        return {weights_.data() + weight_offset_[k], static_cast<std::size_t>(weight_offset_[k + 1] - weight_offset_[k])};
    const int e = equation_[dof];
    return e >= 0 ? WeightRow(e) : WeightRow();
  }

  /// Pairs of T stored (those of the dependent dofs' rows; 16 bytes each).
  [[nodiscard]] std::size_t n_stored_weights() const { return weights_.size(); }

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
  std::vector<int> dependent_index_;     ///< per dof: index into dependents_ or -1; empty without dependents
  std::vector<Dependent> dependents_;
  std::vector<EquationWeight> weights_;  ///< T rows of the dependent dofs, flattened
  std::vector<int> weight_offset_;       ///< per dependent, into weights_ (size dependents_.size() + 1)
  std::vector<EliminationRow> rows_;
  std::vector<int> row_dependent_;
};

}  // namespace tether
