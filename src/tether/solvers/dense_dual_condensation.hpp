#pragma once
/// \file Exact elimination of the dual mortar multipliers from a dense
/// system: CondensedSolver's interface system A_II + C (|I| × |I|).
///
/// The equations are split as DualCondensedSolver splits the whole matrix
/// (choose_dual_elimination): Z, the closed multipliers with their pivot
/// displacements and the soft-law multipliers; O, the open multipliers,
/// whose rows and columns hold their diagonal only; K, the rest (the
/// interface displacements, friction multipliers). With B = S_ZZ,
///
///     S_K = S_KK - S_KZ B⁻¹ S_ZK,      S_K x_K = b_K - S_KZ B⁻¹ b_Z,
///     x_Z = B⁻¹ (b_Z - S_ZK x_K),      x_O = b_O / s_OO.
///
/// B (|Z| = 2 × closed + soft-law nodes) by a dense LU; S_K, which for a
/// frictionless HARD pair holds displacements only (the reduced Hessian on
/// the constraints' null space, symmetric positive definite when the
/// problem is), by Cholesky when the system is symmetric, LU otherwise
/// (DenseFactor, equilibrated again). The products are BLAS (dgemm). solve()
/// ends with one step of iterative refinement on S. Nothing is
/// approximated: x is S⁻¹ b to round-off. Theory: docs/theory/mortar.md
/// ("Condensation of the multipliers").

#include <utility>
#include <vector>

#include <Eigen/Core>

#include "tether/solvers/dense_factor.hpp"
#include "tether/solvers/dual_condensation.hpp"

namespace tether {

class DenseDualCondensation {
 public:
  /// Factorizes `s` (square, best equilibrated: D S D; taken over and kept
  /// for the refinement) with `elimination`'s equations, given as indices
  /// of s, eliminated (the open rows' diagonals are read from s). `symmetric`: s is symmetric, so S_K is too and
  /// Cholesky is tried. Returns the reciprocal condition number estimate
  /// of the equilibrated S_K (DenseFactor), 0 when B is numerically
  /// singular (reciprocal condition below 1e-14) or S_K is exactly; the
  /// caller then solves s otherwise.
  double factorize(Eigen::MatrixXd s, const DualElimination& elimination, bool symmetric);
  /// S as given to the last factorize() (unchanged by it), moved out: for
  /// the caller's other factorization when this one failed. solve() may not
  /// be called afterwards.
  [[nodiscard]] Eigen::MatrixXd release_matrix() { return std::move(s_); }
  /// x = S⁻¹ b (condensed solve, then one step of iterative refinement on S).
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const;
  /// |K|: the size of the dense system factorized.
  [[nodiscard]] Eigen::Index condensed_size() const { return condensed_.size(); }
  [[nodiscard]] bool cholesky() const { return condensed_.cholesky(); }

 private:
  void solve_condensed(const Eigen::VectorXd& b, Eigen::VectorXd& x) const;

  Eigen::MatrixXd s_;                          ///< S, for the refinement
  std::vector<int> z_, k_;                     ///< indices of S: eliminated (B's order), kept (S_K's order)
  std::vector<std::pair<int, double>> apart_;  ///< O: index and diagonal
  DenseFactor b_;                              ///< LU of B
  Eigen::MatrixXd w_;                          ///< B⁻¹ S_ZK
  Eigen::MatrixXd s_kz_;                       ///< S_KZ
  DenseFactor condensed_;                      ///< of S_K
};

}  // namespace tether
