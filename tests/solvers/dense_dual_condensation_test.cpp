// The dual mortar multipliers eliminated from the dense interface system of
// CondensedSolver (DenseDualCondensation): the answer is that of a dense
// solve of the full system to round-off, for closed multipliers with a
// banded coupling (the linearised normals and segmentation), open ones
// (a tiny diagonal only), soft-law ones (a diagonal and a coupling), with a
// symmetric system (the rest is displacements only: Cholesky) and an
// unsymmetric one (LU); and the dense system factorized is the smaller one.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include <Eigen/LU>

#include "tether/solvers/condensed_solver.hpp"
#include "tether/solvers/dense_dual_condensation.hpp"

using namespace tether;

namespace {

constexpr int kGrid = 10;                       ///< grid of kGrid × kGrid nodes, two components each
constexpr int kDisplacements = 2 * kGrid * kGrid;
constexpr int kSlaves = 8;                      ///< multipliers on the surface nodes 1..kSlaves
constexpr int kMultipliers = kSlaves;

/// Equation of component c of grid node (i, j).
int equation(int i, int j, int c) { return 2 * (i * kGrid + j) + c; }
/// The surface (the last grid row) node k.
int surface(int k, int c) { return equation(kGrid - 1, k, c); }

enum class Law { Closed, Open, Soft };

/// The laws of the slave nodes for `seed`: at least two closed, one open, and a soft one on odd seeds.
std::vector<Law> laws(unsigned seed) {
  std::vector<Law> out(kSlaves, Law::Closed);
  out[static_cast<std::size_t>(seed % kSlaves)] = Law::Open;
  out[static_cast<std::size_t>((seed + 3) % kSlaves)] = Law::Open;
  if (seed % 2 == 1) out[static_cast<std::size_t>((seed + 5) % kSlaves)] = Law::Soft;
  return out;
}

/// A plane-strain-like grid (springs between neighbours on both components,
/// coupled, SPD with the bottom row held by springs) with mortar-like
/// multiplier columns: -∇g̃_j = D_j n_j on slave node j's components and
/// small linearisation terms on its neighbours, random; open rows -1e-13 or
/// -1e-6 on the diagonal only; soft rows -1e-3 and the coupling. `symmetric`: the
/// multiplier rows are the columns' transposes, else perturbed (friction-like).
Eigen::MatrixXd system_matrix(unsigned seed, bool symmetric) {
  std::mt19937 rng(seed), bulk_rng(42);  // the bulk is the same for every seed
  std::uniform_real_distribution<double> u(-1, 1);
  const int n = kDisplacements + kMultipliers;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  const auto spring = [&](int p, int q, double k) { a(p, p) += k, a(q, q) += k, a(p, q) -= k, a(q, p) -= k; };
  for (int i = 0; i < kGrid; ++i)
    for (int j = 0; j < kGrid; ++j)
      for (int c = 0; c < 2; ++c) {
        if (i + 1 < kGrid) spring(equation(i, j, c), equation(i + 1, j, c), 200 * (1 + 0.3 * u(bulk_rng)));
        if (j + 1 < kGrid) spring(equation(i, j, c), equation(i, j + 1, c), 200 * (1 + 0.3 * u(bulk_rng)));
        if (j + 1 < kGrid) spring(equation(i, j, c), equation(i, j + 1, 1 - c), 30);
        if (i == 0) a(equation(i, j, c), equation(i, j, c)) += 500;
      }
  for (int k = 0; k < kGrid; ++k)  // a seed-dependent stiffness on the surface (the interface block)
    for (int c = 0; c < 2; ++c) a(surface(k, c), surface(k, c)) += 50 * std::abs(u(rng));
  const std::vector<Law> law = laws(seed);
  for (int k = 0; k < kSlaves; ++k) {
    const int m = kDisplacements + k, node = k + 1;
    if (law[static_cast<std::size_t>(k)] == Law::Open) {
      // -1/c_j: below the equilibration's notice (1e-14 of the largest diagonal) or not
      a(m, m) = seed % 2 == 0 ? -1e-13 : -1e-6;
      continue;
    }
    const double angle = 0.4 * u(rng), D = 0.5 * (1 + 0.2 * u(rng));
    const auto couple = [&](int eq, double v) { a(eq, m) = v, a(m, eq) = symmetric ? v : v * (1 + 0.2 * u(rng)); };
    couple(surface(node, 0), D * std::sin(angle));
    couple(surface(node, 1), -D * std::cos(angle));
    couple(surface(node - 1, 1), 0.03 * D * u(rng));
    couple(surface(node + 1, 1), 0.03 * D * u(rng));
    couple(surface(node + 1, 0), 0.02 * D * u(rng));
    if (law[static_cast<std::size_t>(k)] == Law::Soft) a(m, m) = -1e-3;
  }
  return a;
}

std::vector<DualNodeEquations> mortar_nodes() {
  std::vector<DualNodeEquations> nodes;
  for (int k = 0; k < kSlaves; ++k)
    nodes.push_back({kDisplacements + k, {surface(k + 1, 0), surface(k + 1, 1)}});
  return nodes;
}

/// The interface: both components of the surface row, and the multipliers.
std::vector<int> interface_equations() {
  std::vector<int> out;
  for (int k = 0; k < kGrid; ++k) out.push_back(surface(k, 0)), out.push_back(surface(k, 1));
  for (int k = 0; k < kMultipliers; ++k) out.push_back(kDisplacements + k);
  return out;
}

Eigen::VectorXd load(Eigen::Index n, unsigned seed) {
  std::mt19937 rng(100 + seed);
  std::normal_distribution<double> g;
  Eigen::VectorXd b(n);
  for (Eigen::Index i = 0; i < n; ++i) b[i] = g(rng);
  return b;
}

int count(const std::vector<Law>& law, Law which) {
  return static_cast<int>(std::count(law.begin(), law.end(), which));
}

}  // namespace

TEST(DenseDualCondensation, EqualsTheDenseSolveOfTheWholeSystem) {
  double worst = 0, worst_residual = 0;
  for (unsigned seed = 1; seed <= 6; ++seed)
    for (const bool symmetric : {true, false}) {
      const Eigen::MatrixXd a = system_matrix(seed, symmetric);
      const SparseMatrix sparse = a.sparseView();
      const DualElimination e = choose_dual_elimination(sparse, mortar_nodes());
      const std::vector<Law> law = laws(seed);
      EXPECT_EQ(e.closed, count(law, Law::Closed));
      EXPECT_EQ(e.diagonal, count(law, Law::Open) + count(law, Law::Soft));
      DenseDualCondensation dual;
      EXPECT_GT(dual.factorize(a, e, symmetric), 1e-8) << seed;
      // The kept system: the displacements less the pivots.
      EXPECT_EQ(dual.condensed_size(), kDisplacements - e.closed);
      EXPECT_EQ(dual.cholesky(), symmetric);  // soft rows are in B: no multiplier is left
      const Eigen::VectorXd b = load(a.rows(), seed);
      Eigen::VectorXd x;
      dual.solve(b, x);
      const Eigen::VectorXd exact = a.partialPivLu().solve(b);
      worst = std::max(worst, (x - exact).norm() / exact.norm());
      worst_residual = std::max(worst_residual, (a * x - b).norm() / b.norm());
      EXPECT_LT((x - exact).norm(), 1e-12 * exact.norm()) << "seed " << seed << (symmetric ? "" : ", unsymmetric");
      // Round-off: 1.0e-13 measured with one BLAS kernel, 1.02e-13 under valgrind's.
      EXPECT_LT((a * x - b).norm(), 1e-12 * b.norm()) << "seed " << seed;
    }
  std::printf("[ dense dual ] 12 systems of %d equations: max |x - x_LU| / |x_LU| = %.1e, max |Ax - b| / |b| = %.1e\n",
              kDisplacements + kMultipliers, worst, worst_residual);
}

TEST(DenseDualCondensation, SingularBlockIsReported) {
  // Two closed multipliers with the same row (a redundant constraint): B is
  // singular, factorize() says so (0) and the caller solves otherwise.
  Eigen::MatrixXd a = system_matrix(2, true);
  const int m = kDisplacements + 4;  // closed for seed 2
  ASSERT_EQ(laws(2)[4], Law::Closed);
  a.row(m) = a.row(m - 1), a.col(m) = a.col(m - 1);
  a(m, m) = 0;
  DualElimination e = choose_dual_elimination(SparseMatrix(a.sparseView()), mortar_nodes());
  DenseDualCondensation dual;
  EXPECT_EQ(dual.factorize(a, e, true), 0.0);
}

TEST(CondensedSolver, EliminatesTheDualMultipliersFromTheInterfaceSystemExactly) {
  // The bulk (the grid below the surface row) is factorized once; each
  // matrix then differs in the contact rows and columns only, and its dense
  // interface system loses its closed multipliers with their pivots and its
  // open ones: 2 kGrid + kMultipliers interface equations, 2 kGrid - closed
  // factorized (by Cholesky when symmetric).
  CondensedSolver solver(interface_equations(), make_linear_solver(SolverKind::Auto));
  solver.eliminate_dual_multipliers(mortar_nodes());
  CondensedSolver kept(interface_equations(), make_linear_solver(SolverKind::Auto));
  int factorized = 0;
  for (unsigned seed = 1; seed <= 6; ++seed) {
    const bool symmetric = seed % 3 != 0;
    const Eigen::MatrixXd a = system_matrix(seed, symmetric);  // the same outside the interface block
    SparseMatrix sparse = a.sparseView();
    sparse.makeCompressed();
    const Eigen::VectorXd b = load(a.rows(), seed);
    solver.analyze(sparse);
    solver.factorize(sparse, symmetric);
    Eigen::VectorXd x;
    solver.solve(b, x);
    const Eigen::VectorXd exact = a.partialPivLu().solve(b);
    EXPECT_LT((x - exact).norm(), 1e-12 * exact.norm()) << "seed " << seed << " via " << solver.name();
    const int closed = count(laws(seed), Law::Closed);
    const CondensationStatistics& s = solver.statistics();
    EXPECT_EQ(s.dual_closed, closed);
    EXPECT_EQ(s.dense_equations, 2 * kGrid - closed) << solver.name();
    EXPECT_EQ(s.dense_cholesky, symmetric) << solver.name();
    EXPECT_GT(s.dense_rcond, 1e-8);
    EXPECT_NE(solver.name().find("after the dual elimination"), std::string::npos) << solver.name();
    ++factorized;
    // Without the elimination (the path before): the same answer, the whole interface system by LU.
    kept.analyze(sparse);
    kept.factorize(sparse, symmetric);
    Eigen::VectorXd y;
    kept.solve(b, y);
    EXPECT_LT((x - y).norm(), 1e-12 * y.norm()) << "seed " << seed;
    EXPECT_EQ(kept.statistics().dense_equations, 2 * kGrid + kMultipliers);
    EXPECT_FALSE(kept.statistics().dense_cholesky);
  }
  EXPECT_EQ(solver.statistics().sparse_factorizations, 1);
  EXPECT_EQ(solver.statistics().reuses, factorized - 1);
  EXPECT_EQ(solver.statistics().dual_eliminations, factorized);
  EXPECT_EQ(solver.statistics().fallbacks, 0);
}
