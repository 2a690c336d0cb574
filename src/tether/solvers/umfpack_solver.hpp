#pragma once
/// \file SuiteSparse UMFPACK (LU with partial pivoting) behind LinearSolver.
///
/// Uses the 64-bit `umfpack_dl_*` routines: the 32-bit ones run out of index
/// range (reported as out of memory) near a million dofs. The matrix's 32-bit
/// index arrays are copied to 64-bit once per pattern. Systems above
/// kMetisThreshold equations are ordered with METIS (less fill than AMD).

#include <cstdint>
#include <vector>

#include "tether/solvers/linear_solver.hpp"

namespace tether {

class UmfpackSolver final : public LinearSolver {
 public:
  /// Equations above which METIS orders the matrix.
  static constexpr int kMetisThreshold = 100000;

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

  /// 64-bit copies of the analysed matrix's index arrays.
  std::vector<std::int64_t> outer_, inner_;
  void* symbolic_ = nullptr;
  void* numeric_ = nullptr;
  double control_[20]{};
  const SparseMatrix* matrix_ = nullptr;  ///< last factorized (needed by solve)
};

}  // namespace tether
