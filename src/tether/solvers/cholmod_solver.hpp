#pragma once
/// \file SuiteSparse CHOLMOD supernodal Cholesky behind LinearSolver (SPD systems).

#include <memory>

#include "tether/solvers/linear_solver.hpp"

namespace tether {

class CholmodSolver final : public LinearSolver {
 public:
  CholmodSolver();
  ~CholmodSolver() override;
  CholmodSolver(const CholmodSolver&) = delete;
  CholmodSolver& operator=(const CholmodSolver&) = delete;

  /// Uses the lower triangle of `a` only; the upper one is ignored.
  void analyze(const SparseMatrix& a) override;
  /// Throws SolverError when `a` is not positive definite, naming the column
  /// where the factorization stopped.
  void factorize(const SparseMatrix& a, bool symmetric) override;
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override;
  [[nodiscard]] std::string name() const override { return "CHOLMOD"; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tether
