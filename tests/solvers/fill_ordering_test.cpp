// nested_dissection_last: a permutation with the chosen equations last and a
// node's dofs together, less fill than minimum degree on a grid, and MumpsSchur
// above its threshold (where it uses this ordering) solving exactly.

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <vector>

#include "tether/solvers/fill_ordering.hpp"
#include "tether/solvers/mumps_schur.hpp"

using namespace tether;

namespace {

/// SPD matrix of a `side` x `side` grid of nodes with 2 dofs each, coupled as
/// bilinear quadrilaterals couple them (a node to its 8 neighbours, both dofs),
/// with slightly different values per entry so that no two are alike.
/// `unsymmetric_by`: added to the upper entries only. `lower_only`: keep the
/// lower triangle.
SparseMatrix grid_matrix(int side, double unsymmetric_by = 0, bool lower_only = false) {
  const int n = 2 * side * side;
  std::vector<Eigen::Triplet<double>> t;
  const auto node = [&](int i, int j) { return i * side + j; };
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j)
      for (int di = -1; di <= 1; ++di)
        for (int dj = -1; dj <= 1; ++dj) {
          if (i + di < 0 || i + di >= side || j + dj < 0 || j + dj >= side) continue;
          const int p = node(i, j), q = node(i + di, j + dj);
          for (int a = 0; a < 2; ++a)
            for (int b = 0; b < 2; ++b) {
              const int r = 2 * p + a, c = 2 * q + b;
              if (lower_only && r < c) continue;
              const double base = r == c ? 20.0 : -1.0 + 0.1 * std::sin(0.37 * std::min(r, c) + 0.11 * std::max(r, c));
              t.emplace_back(r, c, base + (r < c ? unsymmetric_by : 0.0));
            }
        }
  SparseMatrix a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  a.makeCompressed();
  return a;
}

/// Every `stride`-th node's two dofs, as an interface.
std::vector<char> interface_flags(int n, int stride) {
  std::vector<char> in(static_cast<std::size_t>(n), 0);
  for (int e = 0; e < n; e += 2 * stride) in[static_cast<std::size_t>(e)] = in[static_cast<std::size_t>(e) + 1] = 1;
  return in;
}

}  // namespace

TEST(FillOrdering, IsAPermutationWithTheLastEquationsLastAndEachNodesDofsTogether) {
  const SparseMatrix a = grid_matrix(30);
  const int n = static_cast<int>(a.rows());
  const std::vector<char> last = interface_flags(n, 37);
  const int m = static_cast<int>(std::count(last.begin(), last.end(), 1));
  ASSERT_GT(m, 10);
  const std::vector<int> perm = nested_dissection_last(a, last);
  ASSERT_EQ(perm.size(), static_cast<std::size_t>(n));
  std::vector<int> at(static_cast<std::size_t>(n), -1);  // equation at each position
  for (int e = 0; e < n; ++e) {
    const int p = perm[static_cast<std::size_t>(e)];
    ASSERT_GE(p, 1);
    ASSERT_LE(p, n);
    ASSERT_EQ(at[static_cast<std::size_t>(p - 1)], -1) << "position " << p << " taken twice";
    at[static_cast<std::size_t>(p - 1)] = e;
  }
  int previous_last = -1;
  for (int k = n - m; k < n; ++k) {  // the interface, ascending, at the end
    const int e = at[static_cast<std::size_t>(k)];
    EXPECT_TRUE(last[static_cast<std::size_t>(e)]) << "position " << k + 1;
    EXPECT_GT(e, previous_last);
    previous_last = e;
  }
  for (int e = 0; e < n; e += 2)  // x and y of a node next to each other
    if (!last[static_cast<std::size_t>(e)])
      EXPECT_EQ(perm[static_cast<std::size_t>(e) + 1], perm[static_cast<std::size_t>(e)] + 1) << "node " << e / 2;
  // One triangle or both, symmetric or not: the same graph, the same order.
  EXPECT_EQ(nested_dissection_last(grid_matrix(30, 0, true), last), perm);
  EXPECT_EQ(nested_dissection_last(grid_matrix(30, 0.3), last), perm);
}

TEST(FillOrdering, FillsLessThanMinimumDegreeOnAGrid) {
  // 100 x 100 nodes (20000 equations): the Cholesky factor after nested
  // dissection against Eigen's AMD, both symbolic counts of the same matrix.
  const SparseMatrix a = grid_matrix(100);
  const std::vector<char> none(static_cast<std::size_t>(a.rows()), 0);
  const std::vector<int> perm = nested_dissection_last(a, none);
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> p(a.rows());
  for (Eigen::Index e = 0; e < a.rows(); ++e) p.indices()[e] = perm[static_cast<std::size_t>(e)] - 1;
  SparseMatrix permuted;
  permuted = a.twistedBy(p);
  Eigen::SimplicialLLT<SparseMatrix, Eigen::Lower, Eigen::NaturalOrdering<int>> nested(permuted);
  Eigen::SimplicialLLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>> amd(a);
  ASSERT_EQ(nested.info(), Eigen::Success);
  ASSERT_EQ(amd.info(), Eigen::Success);
  const double nd_entries = static_cast<double>(SparseMatrix(nested.matrixL()).nonZeros());
  const double amd_entries = static_cast<double>(SparseMatrix(amd.matrixL()).nonZeros());
  // Measured 1 239 660 against 1 280 356 (-3.2 %); on the graded Hertz mesh
  // of 231k equations the gain is 11 % (docs/performance.md).
  EXPECT_LT(nd_entries, 0.99 * amd_entries) << nd_entries << " against AMD's " << amd_entries;
}

TEST(FillOrdering, MumpsSchurAboveItsThresholdSolvesExactly) {
  // 225 x 225 nodes = 101250 equations, above MumpsSchur's 100000: the
  // analysis takes this ordering. Solve A x = b by condensation (the dense
  // interface system solved here) and compare the residual; LDLT and LU.
  for (const bool symmetric : {true, false}) {
    const SparseMatrix a = grid_matrix(225, symmetric ? 0.0 : 0.05);
    const int n = static_cast<int>(a.rows());
    const std::vector<char> in = interface_flags(n, 4001);
    std::vector<int> interface;
    for (int e = 0; e < n; ++e)
      if (in[static_cast<std::size_t>(e)]) interface.push_back(e);
    MumpsSchur schur;
    schur.factorize(a, interface, in, symmetric);
    Eigen::VectorXd b(n), reduced, x;
    for (int e = 0; e < n; ++e) b[e] = std::cos(0.001 * e);
    schur.reduce(b, reduced);
    // Interface system: (A_II + S) x_I = b_I + reduced.
    const auto m = static_cast<Eigen::Index>(interface.size());
    Eigen::MatrixXd system = schur.schur();
    Eigen::VectorXd rhs(m);
    for (Eigen::Index r = 0; r < m; ++r) {
      rhs[r] = b[interface[static_cast<std::size_t>(r)]] + reduced[r];
      for (Eigen::Index c = 0; c < m; ++c) system(r, c) += a.coeff(interface[static_cast<std::size_t>(r)], interface[static_cast<std::size_t>(c)]);
    }
    schur.expand(system.partialPivLu().solve(rhs), x);
    EXPECT_LT((a * x - b).norm() / b.norm(), 1e-12) << symmetric;
    EXPECT_GT(schur.factor_entries(), 0);
  }
}
