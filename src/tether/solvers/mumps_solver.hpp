#pragma once
/// \file Sparse symmetric-indefinite LDLᵀ factorization by MUMPS (sequential,
/// multifrontal, with 2×2 pivoting): the solver for symmetric saddle-point
/// systems — Lagrange-multiplier constraints and frictionless contact — at
/// about half the work and memory of an LU factorization.
///
/// Only the lower triangle of the matrix is read, so the matrix must be
/// symmetric (an unsymmetric one is solved as if its upper triangle mirrored
/// the lower). Ordering: METIS above 100k equations, AMD below. A zero pivot
/// is detected (MUMPS null-pivot detection) and reported as a SolverError
/// naming the first such equation.

#include <memory>
#include <vector>

#include "tether/solvers/linear_solver.hpp"

namespace tether {

class MumpsSolver final : public LinearSolver {
 public:
  MumpsSolver();
  ~MumpsSolver() override;
  MumpsSolver(const MumpsSolver&) = delete;
  MumpsSolver& operator=(const MumpsSolver&) = delete;

  void analyze(const SparseMatrix& a) override;
  void factorize(const SparseMatrix& a, bool symmetric) override;
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override;
  [[nodiscard]] std::string name() const override { return "MUMPS LDLT"; }

  /// Memory the process may use [MB], 0 for no limit: beyond it the factors
  /// go out of core (see MumpsSchur::set_memory_budget).
  void set_memory_budget(double mb) { memory_budget_mb_ = mb; }
  [[nodiscard]] int out_of_core_factorizations() const override { return out_of_core_factorizations_; }

 private:
  struct Instance;
  std::unique_ptr<Instance> mumps_;
  std::vector<int> rows_, cols_;       ///< lower-triangle coordinates, 1-based
  std::vector<int> source_;            ///< value-array index of each lower entry
  std::vector<double> values_;
  Eigen::Index n_ = 0, nnz_ = 0;       ///< pattern analysed (size and entries of the full matrix)
  bool factorized_ = false;
  double memory_budget_mb_ = 0;
  int out_of_core_factorizations_ = 0;
};

}  // namespace tether
