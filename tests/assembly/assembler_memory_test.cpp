// What the assembler keeps per contribution: scatter positions (one per pair
// of nodes in a lower triangle) and dof lists (none for held linear ones),
// and that the tangent is the same, bit for bit, with less kept.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cstdint>
#include <cstring>
#include <vector>

#include "tether/assembly/assembler.hpp"
#include "test_contributions.hpp"

using namespace tether;
using tether::testing::DenseBlock;
using tether::testing::grid_list;
using tether::testing::grid_prescribed;
using tether::testing::grid_quads;
using tether::testing::Rewiring;
using tether::testing::Spring;

namespace {

bool same_bits(const SparseMatrix& a, const SparseMatrix& b) {
  return a.nonZeros() == b.nonZeros() && a.cols() == b.cols() &&
         std::equal(a.outerIndexPtr(), a.outerIndexPtr() + a.cols() + 1, b.outerIndexPtr()) &&
         std::equal(a.innerIndexPtr(), a.innerIndexPtr() + a.nonZeros(), b.innerIndexPtr()) &&
         std::memcmp(a.valuePtr(), b.valuePtr(), sizeof(double) * static_cast<std::size_t>(a.nonZeros())) == 0;
}

/// Assembles `held` (springs s01, s23 and a re-pairing spring that moves at
/// the first assembly), expects the move placed by a relocation, without a
/// rebuild, and the tangent then equal, bit for bit, to that of a fresh
/// assembler over s01, s23 and `twin` (a re-pairing spring like held's).
void expect_move_placed(Assembler& held, Spring& s01, Spring& s23, Rewiring& twin) {
  Eigen::VectorXd u = Eigen::VectorXd::LinSpaced(4, 0.0, 1.0), r;
  const EvaluationState state{u, u};
  held.assemble(state, r, true);
  EXPECT_FALSE(held.update_connectivity(state));  // relocated, no rebuild
  EXPECT_EQ(held.relocations(), 1);
  held.assemble(state, r, true);
  Assembler fresh({&s01, &s23, &twin}, EquationMap(std::vector<bool>(4, false)), {1, 2, 3});
  fresh.update_connectivity(state);
  fresh.assemble(state, r, true);
  EXPECT_TRUE(same_bits(held.tangent(), fresh.tangent()));
}

}  // namespace

TEST(AssemblerMemory, LowerTriangleKeepsOnePositionPerPairOfNodes) {
  // The grid of the lower-triangle test (4 x 2 quads of 4 nodes, three of
  // them blocked; the others keep full positions), a spring, and a collapsed
  // quad whose node 7 appears twice (both blocks of that pair lie on the
  // diagonal's side: both are scattered, from the pair's one position).
  const int nx = 5, ny = 3, n = 2 * nx * ny;
  std::vector<DenseBlock> quads = grid_quads(nx, ny);
  quads.emplace_back(std::vector<int>{2 * 6, 2 * 6 + 1, 2 * 7, 2 * 7 + 1, 2 * 8, 2 * 8 + 1, 2 * 7, 2 * 7 + 1}, 9.5);
  Spring spring(2 * 12, 2 * 14, 5.0);
  const std::vector<Contribution*> list = grid_list(quads, spring);
  const std::vector<bool> prescribed = grid_prescribed(n);
  Assembler full(list, EquationMap(prescribed)), lower(list, EquationMap(prescribed), {}, true);
  const auto blocked = static_cast<std::size_t>(lower.n_blocked());
  ASSERT_EQ(blocked, static_cast<std::size_t>(full.n_blocked()));
  ASSERT_GE(blocked, 4u);  // three of the grid's first row and the collapsed one
  const std::size_t others = (quads.size() - blocked) * 64 + 4;
  EXPECT_EQ(full.n_positions(), blocked * 16 + others);
  EXPECT_EQ(lower.n_positions(), blocked * 10 + others);  // was 16 per blocked quad here too

  Eigen::VectorXd u = Eigen::VectorXd::LinSpaced(n, 0.1, 2.0), r_full, r_lower;
  const EvaluationState state{u, u};
  full.assemble(state, r_full, true);
  lower.assemble(state, r_lower, true);
  EXPECT_EQ(r_lower, r_full);
  const SparseMatrix expected = full.tangent().triangularView<Eigen::Lower>();
  EXPECT_TRUE(same_bits(lower.tangent(), expected));
}

TEST(AssemblerMemory, HeldLinearContributionsKeepNoDofList) {
  // Linear springs and one re-pairing spring in a reserved block: once the
  // springs are held linear only the re-pairing one's list is kept, and its
  // move is still found and placed without a rebuild.
  Spring s01(0, 1, 1.0), s23(2, 3, 2.0);
  Rewiring moving(1, 2, 3), moving_too(1, 2, 3);
  const std::vector<Contribution*> list{&s01, &s23, &moving};
  Assembler held(list, EquationMap(std::vector<bool>(4, false)), {1, 2, 3});
  EXPECT_EQ(held.n_kept_dofs(), 6u);  // before set_linear: every list
  held.set_linear({1, 1, 0}, false);
  EXPECT_EQ(held.n_kept_dofs(), 2u);  // was 6
  expect_move_placed(held, s01, s23, moving_too);
}

TEST(AssemblerMemory, AContributionNoLongerHeldLinearIsWatchedAgain) {
  // set_linear() a second time with the re-pairing spring no longer held:
  // its list (dropped by the first call) is kept again, from its dofs, and
  // its move is found.
  Spring s01(0, 1, 1.0), s23(2, 3, 2.0);
  Rewiring moving(1, 2, 3), moving_too(1, 2, 3);
  Assembler held({&s01, &s23, &moving}, EquationMap(std::vector<bool>(4, false)), {1, 2, 3});
  held.set_linear({1, 1, 1}, false);
  EXPECT_EQ(held.n_kept_dofs(), 0u);
  held.set_linear({1, 1, 0}, false);
  EXPECT_EQ(held.n_kept_dofs(), 2u);
  expect_move_placed(held, s01, s23, moving_too);
}
