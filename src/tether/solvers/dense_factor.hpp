#pragma once
/// \file An equilibrated dense factorization (LAPACK): the interface systems
/// of CondensedSolver, with or without the dual mortar multipliers.
///
/// The matrix A is first scaled symmetrically, D A D, with D = 1/√|a_kk| on
/// rows with a diagonal and, on rows without one (a closed HARD multiplier,
/// whose diagonal is -ε = 0), 1/max_j |a_kj d_j|, so that the condition
/// test does not depend on the units (an open contact row's -1/c is eleven
/// orders below the stiffnesses). D A D is then factorized by Cholesky
/// (dpotrf, half the flops of LU) when asked for and it succeeds, else by
/// LU with partial pivoting (dgetrf). Blocked LAPACK: OpenBLAS's kernels.

#include <vector>

#include <Eigen/Core>

namespace tether {

/// D of D A D (see the file comment); entries of A that are not finite
/// count as absent.
[[nodiscard]] Eigen::VectorXd equilibration(const Eigen::MatrixXd& a);

class DenseFactor {
 public:
  /// Factorizes `a` (square; taken over, its storage becomes the factors).
  /// `try_cholesky`: `a` is symmetric and probably positive definite:
  /// Cholesky of its lower triangle is tried first; when it meets a
  /// non-positive pivot, LU of the matrix whose lower triangle is the
  /// mirror of the upper. `scale`: equilibrate (false when the caller
  /// already did and D would be 1). Returns the reciprocal condition number
  /// estimate of the equilibrated matrix in the 1-norm (dpocon / dgecon),
  /// 0 for an exactly singular or non-finite one.
  double factorize(Eigen::MatrixXd a, bool try_cholesky, bool scale = true);
  /// b ← A⁻¹ b (in place) with the factors of the last factorize().
  void solve(Eigen::VectorXd& b) const;
  /// X ← A⁻¹ X for several right-hand sides (columns), in place.
  void solve(Eigen::MatrixXd& x) const;
  [[nodiscard]] bool cholesky() const { return cholesky_; }
  [[nodiscard]] Eigen::Index size() const { return factors_.rows(); }

 private:
  Eigen::VectorXd scale_;    ///< D
  Eigen::MatrixXd factors_;  ///< of D A D: L (Cholesky, lower) or L\U (LU)
  std::vector<int> pivots_;  ///< LU's row interchanges
  bool cholesky_ = false;
};

}  // namespace tether
