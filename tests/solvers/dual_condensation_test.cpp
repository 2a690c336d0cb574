// DualCondensedSolver: eliminating the mortar multipliers with one pivot
// displacement each (a banded coupling block, as once the normals and the
// segmentation are linearised) gives the solution of the full saddle-point
// system to round-off; the condensed matrix of a symmetric system with only
// closed and open mortar multipliers has none left (Cholesky); a multiplier
// row with a diagonal (open) is eliminated alone.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <Eigen/LU>

#include "tether/solvers/dual_condensation.hpp"

using namespace tether;

namespace {

constexpr int kChain = 40;          ///< displacement unknowns: 2 per node of a chain of 20 nodes
constexpr int kMultipliers = 8;     ///< on the nodes 4..11 ("slave" nodes)
constexpr int kOpen = 3;            ///< the last kOpen multipliers are open (row -λ/c only)

/// A chain of springs (two components per node, each coupled to both of the
/// neighbour's) held at its first node, with the multiplier columns
/// -∇g̃_j = D_j n_j on node j's components plus small terms on nodes j ± 1
/// (the linearisation), symmetric; open rows have -1/c on the diagonal only.
Eigen::MatrixXd saddle_matrix() {
  const int n = kChain + kMultipliers;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  for (int node = 0; node + 1 < kChain / 2; ++node)
    for (int c = 0; c < 2; ++c)
      for (int d = 0; d < 2; ++d) {
        const int p = 2 * node + c, q = 2 * (node + 1) + d;
        const double k = c == d ? 100.0 + node : 7.0;
        a(p, p) += k, a(q, q) += k, a(p, q) -= k, a(q, p) -= k;
      }
  a(0, 0) += 1e3, a(1, 1) += 1e3;
  for (int j = 0; j < kMultipliers; ++j) {
    const int m = kChain + j, node = 4 + j;
    if (j >= kMultipliers - kOpen) {
      a(m, m) = -1e-3;
      continue;
    }
    const double nx = 0.3 + 0.05 * j, ny = -1.0;
    const double D = 0.5 + 0.01 * j;
    const auto couple = [&](int eq, double v) { a(eq, m) = v, a(m, eq) = v; };
    couple(2 * node, D * nx);
    couple(2 * node + 1, D * ny);
    couple(2 * (node - 1) + 1, 0.02 * D);  // linearisation terms on the neighbours
    couple(2 * (node + 1) + 1, -0.03 * D);
    couple(2 * (node + 1), 0.01 * D);
  }
  return a;
}

std::vector<DualNodeEquations> mortar_nodes() {
  std::vector<DualNodeEquations> nodes;
  for (int j = 0; j < kMultipliers; ++j) nodes.push_back({kChain + j, {2 * (4 + j), 2 * (4 + j) + 1}});
  return nodes;
}

TEST(DualCondensation, EqualsTheFullSolveAndLeavesAPositiveDefiniteMatrix) {
  const Eigen::MatrixXd dense = saddle_matrix();
  const SparseMatrix a = dense.sparseView();
  Eigen::VectorXd b(dense.rows());
  for (Eigen::Index i = 0; i < b.size(); ++i) b[i] = std::sin(1.0 + 0.7 * static_cast<double>(i));
  const Eigen::VectorXd exact = dense.fullPivLu().solve(b);
  DualCondensedSolver solver(mortar_nodes(), make_linear_solver(SolverKind::Auto));
  solver.analyze(a);
  solver.factorize(a, true);
  Eigen::VectorXd x;
  solver.solve(b, x);
  EXPECT_LT((x - exact).norm(), 1e-12 * exact.norm());
  EXPECT_EQ(solver.statistics().closed, kMultipliers - kOpen);
  EXPECT_EQ(solver.statistics().diagonal, kOpen);
  EXPECT_FALSE(solver.statistics().full);
  EXPECT_EQ(solver.statistics().condensed_equations, kChain - (kMultipliers - kOpen));
  // No multiplier is left: the symmetric condensed matrix is positive definite.
  EXPECT_NE(solver.name().find("CHOLMOD"), std::string::npos) << solver.name();
  // A second factorization with other values of the same pattern.
  Eigen::MatrixXd dense2 = dense;
  for (int i = 0; i < kChain; ++i) dense2(i, i) *= 1.5;
  const SparseMatrix a2 = dense2.sparseView();
  solver.factorize(a2, true);
  solver.solve(b, x);
  const Eigen::VectorXd exact2 = dense2.fullPivLu().solve(b);
  EXPECT_LT((x - exact2).norm(), 1e-12 * exact2.norm());
}

TEST(DualCondensation, UnsymmetricCouplingStillExact) {
  Eigen::MatrixXd dense = saddle_matrix();
  // Friction-like: the constraint rows differ from the force columns.
  for (int j = 0; j < kMultipliers - kOpen; ++j) dense(kChain + j, 2 * (4 + j)) *= 1.3;
  const SparseMatrix a = dense.sparseView();
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(dense.rows(), -1, 2);
  DualCondensedSolver solver(mortar_nodes(), make_linear_solver(SolverKind::Auto));
  solver.analyze(a);
  solver.factorize(a, false);
  Eigen::VectorXd x;
  solver.solve(b, x);
  const Eigen::VectorXd exact = dense.fullPivLu().solve(b);
  EXPECT_LT((x - exact).norm(), 1e-12 * exact.norm());
  EXPECT_EQ(solver.statistics().closed, kMultipliers - kOpen);
}

}  // namespace

namespace {

// An open row's diagonal -1/c_j = -A_j²/(E t) is many orders below the
// stiffnesses (1e-13 here against 1e2): such rows are solved apart, and B is
// equilibrated, so that the elimination is not taken for singular (before,
// every factorization of the 25k Hertz deck went to the full matrix).
TEST(DualCondensation, TinyOpenDiagonalsDoNotMakeTheBlockLookSingular) {
  Eigen::MatrixXd dense = saddle_matrix();
  for (int j = kMultipliers - kOpen; j < kMultipliers; ++j) dense(kChain + j, kChain + j) = -1e-13;
  const SparseMatrix a = dense.sparseView();
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(dense.rows(), 1, 3);
  DualCondensedSolver solver(mortar_nodes(), make_linear_solver(SolverKind::Auto));
  solver.analyze(a);
  solver.factorize(a, true);
  EXPECT_FALSE(solver.statistics().full);
  EXPECT_EQ(solver.statistics().closed, kMultipliers - kOpen);
  Eigen::VectorXd x;
  solver.solve(b, x);
  const Eigen::VectorXd exact = dense.partialPivLu().solve(b);  // (full pivoting's rank test drops -1e-13)
  EXPECT_LT((x - exact).norm(), 1e-12 * exact.norm());
}

}  // namespace

// The choice of the eliminated equations reads each multiplier's row, its
// diagonal and whether its row or column holds anything else: for a
// symmetric matrix the lower triangle alone (the multipliers numbered after
// the displacements, their rows sit in the displacement columns) gives the
// same choice as the whole matrix, over all columns and over a subset.
TEST(DualCondensation, LowerTriangleOfASymmetricMatrixGivesTheSameChoice) {
  const Eigen::MatrixXd dense = saddle_matrix();
  const SparseMatrix whole = dense.sparseView();
  const SparseMatrix lower = Eigen::MatrixXd(dense.triangularView<Eigen::Lower>()).sparseView();
  std::vector<int> columns;
  for (int i = 2 * 2; i < kChain + kMultipliers; ++i) columns.push_back(i);  // all but the first two nodes
  const std::vector<int>* none = nullptr;
  const std::vector<int>* some = &columns;
  for (const std::vector<int>* subset : {none, some}) {
    const DualElimination w = choose_dual_elimination(whole, mortar_nodes(), subset);
    const DualElimination l = choose_dual_elimination(lower, mortar_nodes(), subset);
    EXPECT_EQ(w.eliminated, l.eliminated);
    EXPECT_EQ(w.apart, l.apart);
    EXPECT_EQ(w.closed, kMultipliers - kOpen);
    EXPECT_EQ(l.closed, w.closed);
    EXPECT_EQ(l.diagonal, w.diagonal);
  }
}
