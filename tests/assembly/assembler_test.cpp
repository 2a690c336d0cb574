#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cstring>
#include <string>

#include "tether/assembly/assembler.hpp"
#include "test_contributions.hpp"

using namespace tether;
using tether::testing::DenseBlock;
using tether::testing::grid_list;
using tether::testing::grid_prescribed;
using tether::testing::grid_quads;
using tether::testing::Rewiring;
using tether::testing::Spring;

TEST(Assembler, MatchesDenseAssemblyOfSpringChain) {
  const int n = 50;
  std::vector<Spring> springs;
  springs.reserve(n - 1);
  for (int i = 0; i + 1 < n; ++i) springs.emplace_back(i, i + 1, 1.0 + i);
  std::vector<Contribution*> list;
  for (auto& s : springs) list.push_back(&s);
  std::vector<bool> prescribed(n, false);
  prescribed[0] = true;
  Assembler assembler(list, EquationMap(prescribed));
  EXPECT_LE(assembler.n_colours(), 2);

  Eigen::VectorXd u = Eigen::VectorXd::LinSpaced(n, 0.0, 1.0).array().square();
  EvaluationState state{u, u};
  Eigen::VectorXd r;
  SparseMatrix k;
  assembler.assemble(state, r, &k);

  Eigen::MatrixXd kd = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd rd = Eigen::VectorXd::Zero(n);
  for (int i = 0; i + 1 < n; ++i) {
    const double ki = 1.0 + i, f = ki * (u[i] - u[i + 1]);
    rd[i] += f;
    rd[i + 1] -= f;
    kd(i, i) += ki, kd(i + 1, i + 1) += ki, kd(i, i + 1) -= ki, kd(i + 1, i) -= ki;
  }
  EXPECT_LT((r - rd).norm(), 1e-12);
  EXPECT_LT((Eigen::MatrixXd(k) - kd.bottomRightCorner(n - 1, n - 1)).norm(), 1e-12);
}

TEST(Assembler, NodeBlockScatterMatchesDenseAssembly) {
  // A 5 x 3 grid of nodes (dofs 2i, 2i+1; node = 5 row + column), 4 x 2
  // "quads" of 8 dofs. Node 0 fully prescribed (its blocks skipped); node 10
  // with x prescribed only, a spring in x only between nodes 12 and 14 (their
  // x and y columns differ) and one quad listing a node's dofs y before x:
  // those quads keep full positions. Blocked: the three quads of the first row
  // with normal order.
  const int nx = 5, ny = 3, n_nodes = nx * ny, n = 2 * n_nodes;
  std::vector<DenseBlock> quads = grid_quads(nx, ny);
  Spring spring(2 * 12, 2 * 14, 5.0);
  const std::vector<Contribution*> list = grid_list(quads, spring);
  const std::vector<bool> prescribed = grid_prescribed(n);
  const EquationMap map(prescribed);
  Assembler assembler(list, map);
  EXPECT_EQ(assembler.n_blocked(), 3);

  Eigen::VectorXd u = Eigen::VectorXd::LinSpaced(n, 0.1, 2.0);
  const EvaluationState state{u, u};
  Eigen::VectorXd r;
  SparseMatrix k;
  assembler.assemble(state, r, &k);

  Eigen::MatrixXd full = Eigen::MatrixXd::Zero(n, n);
  for (const auto& q : quads) {
    const auto dofs = q.dofs();
    for (std::size_t b = 0; b < dofs.size(); ++b)
      for (std::size_t a = 0; a < dofs.size(); ++a)
        full(dofs[a], dofs[b]) += q.matrix()(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b));
  }
  full(24, 24) += 5, full(28, 28) += 5, full(24, 28) -= 5, full(28, 24) -= 5;
  Eigen::MatrixXd expected(map.n_equations(), map.n_equations());
  for (int j = 0; j < map.n_equations(); ++j)
    for (int i = 0; i < map.n_equations(); ++i) expected(i, j) = full(map.dof(i), map.dof(j));
  EXPECT_EQ(Eigen::MatrixXd(k), expected);
}

TEST(Assembler, LowerTriangleIsTheFullTangentsLowerTriangleBitForBit) {
  // The grid of NodeBlockScatterMatchesDenseAssembly (blocked quads, quads
  // with full positions, a spring, prescribed dofs) and a tie making dof 15
  // dependent (its quads scatter through T). The quads' matrices are not
  // symmetric, so an entry taken from the wrong side of the diagonal, or
  // placed at the wrong position of a lower column, changes the result.
  const int nx = 5, ny = 3, n_nodes = nx * ny, n = 2 * n_nodes;
  std::vector<DenseBlock> quads = grid_quads(nx, ny);
  Spring spring(2 * 12, 2 * 14, 5.0);
  const std::vector<Contribution*> list = grid_list(quads, spring);
  const std::vector<bool> prescribed = grid_prescribed(n);
  EliminationRow tie;
  tie.terms = {{15, 2.0}, {2 * 9, -0.5}};
  tie.owner = "tie";
  Assembler full(list, EquationMap(prescribed, {tie})), lower(list, EquationMap(prescribed, {tie}), {}, true);
  EXPECT_TRUE(lower.lower_triangle());
  EXPECT_EQ(lower.n_blocked(), full.n_blocked());  // blocking (a quarter of the positions) kept
  EXPECT_GT(lower.n_blocked(), 0);
  Eigen::VectorXd u = Eigen::VectorXd::LinSpaced(n, 0.1, 2.0), r_full, r_lower;
  const EvaluationState state{u, u};
  full.assemble(state, r_full, true);
  lower.assemble(state, r_lower, true);
  EXPECT_EQ(r_lower, r_full);
  const SparseMatrix expected = full.tangent().triangularView<Eigen::Lower>();
  const SparseMatrix& k = lower.tangent();
  ASSERT_EQ(k.nonZeros(), expected.nonZeros());
  EXPECT_TRUE(std::equal(k.outerIndexPtr(), k.outerIndexPtr() + k.cols() + 1, expected.outerIndexPtr()));
  EXPECT_TRUE(std::equal(k.innerIndexPtr(), k.innerIndexPtr() + k.nonZeros(), expected.innerIndexPtr()));
  EXPECT_EQ(std::memcmp(k.valuePtr(), expected.valuePtr(), sizeof(double) * static_cast<std::size_t>(k.nonZeros())), 0);
  EXPECT_LT(k.nonZeros(), full.tangent().nonZeros() * 6 / 10);
}

TEST(Assembler, PropagatesContributionFailure) {
  class Broken final : public Contribution {
   public:
    std::span<const int> dofs() const override { return dofs_; }
    void evaluate(const EvaluationState&, LocalSystem&, bool) const override { throw std::runtime_error("boom"); }
    std::string describe() const override { return "broken"; }
    bool symmetric_tangent(bool) const override { return false; }
    bool linear_in_u(bool) const override { return false; }
    std::vector<int> dofs_{0};
  } broken;
  Assembler assembler({&broken}, EquationMap(std::vector<bool>(1, false)));
  Eigen::VectorXd u = Eigen::VectorXd::Zero(1), r;
  SparseMatrix k;
  EXPECT_THROW(assembler.assemble(EvaluationState{u, u}, r, &k), std::runtime_error);
}

TEST(Assembler, TangentFollowsAPatternChangeOfEqualSize) {
  // Unknowns 0..3 in a chain of unit springs 0-1 and 2-3, plus one spring
  // 1-2 that moves to 1-3: the pattern keeps its number of entries.
  Spring s01(0, 1, 1.0), s23(2, 3, 1.0);
  Rewiring moving(1, 2, 3);
  Assembler assembler({&s01, &s23, &moving}, EquationMap(std::vector<bool>(4, false)));
  Eigen::VectorXd u = Eigen::VectorXd::Zero(4), r;
  const EvaluationState state{u, u};
  SparseMatrix k;
  assembler.assemble(state, r, &k);
  const auto nnz = k.nonZeros();
  ASSERT_TRUE(assembler.update_connectivity(state));
  EXPECT_EQ(assembler.pattern().nonZeros(), nnz);
  assembler.assemble(state, r, &k);  // the same matrix object, reused
  Eigen::MatrixXd expected(4, 4);
  expected << 1, -1, 0, 0, -1, 2, 0, -1, 0, 0, 1, -1, 0, -1, -1, 2;
  EXPECT_LT((Eigen::MatrixXd(k) - expected).norm(), 1e-15) << Eigen::MatrixXd(k);
}

TEST(Assembler, ReservedBlockTakesARepairingWithoutRebuildingThePattern) {
  // As above, with unknowns 1..3 reserved all to all: the moving spring is
  // placed in the existing pattern, assembled serially, and the matrix is
  // the same as after a rebuild.
  Spring s01(0, 1, 1.0), s23(2, 3, 1.0);
  Rewiring moving(1, 2, 3);
  Assembler assembler({&s01, &s23, &moving}, EquationMap(std::vector<bool>(4, false)), {1, 2, 3});
  Eigen::VectorXd u = Eigen::VectorXd::Zero(4), r;
  const EvaluationState state{u, u};
  SparseMatrix k;
  assembler.assemble(state, r, &k);
  EXPECT_FALSE(assembler.update_connectivity(state));  // no rebuild
  EXPECT_EQ(assembler.pattern_builds(), 1);
  EXPECT_EQ(assembler.relocations(), 1);
  assembler.assemble(state, r, &k);
  Eigen::MatrixXd expected(4, 4);
  expected << 1, -1, 0, 0, -1, 2, 0, -1, 0, 0, 1, -1, 0, -1, -1, 2;
  EXPECT_LT((Eigen::MatrixXd(k) - expected).norm(), 1e-15) << Eigen::MatrixXd(k);
  // Without the reservation the new entry (1, 3) is missing: a rebuild.
  Rewiring again(1, 2, 3);
  Assembler plain({&s01, &s23, &again}, EquationMap(std::vector<bool>(4, false)));
  EXPECT_TRUE(plain.update_connectivity(state));
  EXPECT_EQ(plain.pattern_builds(), 2);
  EXPECT_EQ(plain.relocations(), 0);
}

