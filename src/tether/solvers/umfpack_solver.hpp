#pragma once
/// \file SuiteSparse UMFPACK (LU with partial pivoting) behind LinearSolver.

#include "tether/solvers/linear_solver.hpp"

namespace tether {

class UmfpackSolver final : public LinearSolver {
 public:
  UmfpackSolver();
  ~UmfpackSolver() override;
  UmfpackSolver(const UmfpackSolver&) = delete;
  UmfpackSolver& operator=(const UmfpackSolver&) = delete;

  void analyze(const SparseMatrix& a) override;
  /// Throws SolverError when UMFPACK reports a singular matrix or the
  /// reciprocal condition estimate is below 1e-15 (numerically singular).
  void factorize(const SparseMatrix& a, bool symmetric) override;
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override;
  [[nodiscard]] std::string name() const override { return "UMFPACK"; }

 private:
  /// Equation (column of a) with the smallest |pivot| relative to its column.
  int weakest_equation(const SparseMatrix& a) const;
  void free_numeric();
  void free_symbolic();

  void* symbolic_ = nullptr;
  void* numeric_ = nullptr;
  double control_[20]{};
  const SparseMatrix* matrix_ = nullptr;  ///< last factorized (needed by solve)
};

}  // namespace tether
