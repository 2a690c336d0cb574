#pragma once
/// \file Eigen's SparseLU (COLAMD ordering) behind LinearSolver: the fallback.

#include <Eigen/SparseLU>

#include "tether/solvers/linear_solver.hpp"

namespace tether {

class SparseLuSolver final : public LinearSolver {
 public:
  void analyze(const SparseMatrix& a) override;
  /// Throws SolverError on a structurally or numerically zero pivot.
  void factorize(const SparseMatrix& a, bool symmetric) override;
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override;
  [[nodiscard]] std::string name() const override { return "SparseLU"; }

 private:
  Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> lu_;
  bool analysed_ = false;
};

}  // namespace tether
