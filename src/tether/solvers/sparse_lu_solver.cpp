#include "tether/solvers/sparse_lu_solver.hpp"

#include <cmath>

#include "tether/core/error.hpp"

namespace tether {

void SparseLuSolver::analyze(const SparseMatrix& a) {
  lu_.analyzePattern(a);
  analysed_ = true;
}

void SparseLuSolver::factorize(const SparseMatrix& a, bool /*symmetric*/) {
  if (!analysed_) analyze(a);
  lu_.factorize(a);
  if (lu_.info() != Eigen::Success) {
    // SparseLU reports "THE MATRIX IS STRUCTURALLY SINGULAR ... COLUMN k" (1-based, permuted).
    int column = -1;
    const std::string msg = lu_.lastErrorMessage();
    const auto pos = msg.find_last_of("0123456789");
    if (pos != std::string::npos) {
      const auto start = msg.find_last_not_of("0123456789", pos) + 1;
      const int k = std::stoi(msg.substr(start, pos - start + 1)) - 1;  // 1-based, permuted
      const auto& q = lu_.colsPermutation().indices();
      for (int j = 0; j < q.size(); ++j)
        if (q[j] == k) column = j;
    }
    throw SolverError("the stiffness matrix is singular (SparseLU: " + msg + ")", column);
  }
  // SparseLU only notices exact zero pivots. Probe for a numerical null space:
  // solve a x = a 1; for a (nearly) singular matrix x - 1 is dominated by the
  // null vector, whose largest entry names a dof without stiffness.
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(a.cols());
  const Eigen::VectorXd x = lu_.solve(a * ones);
  Eigen::Index worst = 0;
  const double error = (x - ones).cwiseAbs().maxCoeff(&worst);
  if (!std::isfinite(error) || error > 1e-3)
    throw SolverError("the stiffness matrix is numerically singular (SparseLU probe error " + std::to_string(error) + ")",
                      static_cast<int>(worst));
}

void SparseLuSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) { x = lu_.solve(b); }

}  // namespace tether
