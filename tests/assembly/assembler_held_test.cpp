// The assembler's held linear tangent (revisions, relocations, keyed
// tangents) and the residual updates from it (lower triangle, relocation,
// the reference kept across increments).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cstring>
#include <string>

#include "tether/assembly/assembler.hpp"
#include "test_contributions.hpp"

using namespace tether;
using tether::testing::DenseBlock;
using tether::testing::grid_quads;
using tether::testing::Rewiring;
using tether::testing::Spring;

namespace {

/// A nonlinear contribution over any dof list: tangent entries depend on u
/// (k_ab (1 + u_a^2 + u_b)), residual k (u + u^3 / 3) per dof pair (only the
/// tangent matters here).
class CubicBlock final : public Contribution {
 public:
  CubicBlock(std::vector<int> dofs, double seed) : dofs_(std::move(dofs)), seed_(seed) {}
  std::span<const int> dofs() const override { return dofs_; }
  void evaluate(const EvaluationState& s, LocalSystem& out, bool need_tangent) const override {
    const auto m = static_cast<Eigen::Index>(dofs_.size());
    for (Eigen::Index a = 0; a < m; ++a) {
      const double ua = s.u[dofs_[static_cast<std::size_t>(a)]];
      out.residual[a] = seed_ * (ua + ua * ua * ua / 3);
      if (!need_tangent) continue;
      for (Eigen::Index b = 0; b < m; ++b)
        out.tangent(a, b) = (seed_ + 0.1 * static_cast<double>(a + 3 * b)) *
                            (1 + ua * ua + s.u[dofs_[static_cast<std::size_t>(b)]]);
    }
  }
  std::string describe() const override { return "cubic block"; }
  bool symmetric_tangent(bool) const override { return false; }
  bool linear_in_u(bool) const override { return false; }

 private:
  std::vector<int> dofs_;
  double seed_;
};

/// A linear contribution whose tangent depends on the increment size, like
/// inertia: residual m (u - u_start) / dt^2, tangent m / dt^2 on the diagonal.
class InertiaLike final : public Contribution {
 public:
  InertiaLike(std::vector<int> dofs, double mass) : dofs_(std::move(dofs)), mass_(mass) {}
  std::span<const int> dofs() const override { return dofs_; }
  void evaluate(const EvaluationState& s, LocalSystem& out, bool need_tangent) const override {
    const double k = mass_ / (s.dt * s.dt);
    for (std::size_t a = 0; a < dofs_.size(); ++a) {
      const auto i = static_cast<Eigen::Index>(a);
      out.residual[i] = k * (s.u[dofs_[a]] - s.u_start[dofs_[a]]);
      if (need_tangent) out.tangent(i, i) = k;
    }
  }
  std::string describe() const override { return "inertia-like"; }
  bool symmetric_tangent(bool) const override { return true; }
  bool linear_in_u(bool) const override { return true; }

 private:
  std::vector<int> dofs_;
  double mass_;
};

/// Quads of a 6 x 4 node grid (two dofs per node) as DenseBlocks, node 0 held.
struct Grid {
  static constexpr int nx = 6, ny = 4, n = 2 * nx * ny;
  std::vector<DenseBlock> quads;
  Grid() {
    quads.reserve((nx - 1) * (ny - 1));
    for (int j = 0; j + 1 < ny; ++j)
      for (int i = 0; i + 1 < nx; ++i) {
        const int a = j * nx + i, b = a + 1, c = a + nx + 1, d = a + nx;
        quads.emplace_back(std::vector<int>{2 * a, 2 * a + 1, 2 * b, 2 * b + 1, 2 * c, 2 * c + 1, 2 * d, 2 * d + 1},
                           1.0 + 0.25 * static_cast<double>(quads.size()));
      }
  }
  [[nodiscard]] static EquationMap equations() {
    std::vector<bool> prescribed(n, false);
    prescribed[0] = prescribed[1] = true;
    return EquationMap(prescribed);
  }
};

std::vector<std::uint8_t> linear_flags(const std::vector<Contribution*>& list) {
  std::vector<std::uint8_t> flags;
  for (const Contribution* c : list) flags.push_back(c->linear_in_u(false));
  return flags;
}

/// Bitwise equality of two tangents over the same pattern.
bool same_bits(const SparseMatrix& a, const SparseMatrix& b) {
  return a.nonZeros() == b.nonZeros() &&
         std::memcmp(a.valuePtr(), b.valuePtr(), sizeof(double) * static_cast<std::size_t>(a.nonZeros())) == 0;
}

}  // namespace

TEST(Assembler, HeldLinearTangentIsBitForBitAFullAssembly) {
  // Linear quads with two nonlinear blocks across them (contact-like: they
  // share entries with the quads, and one couples nodes no quad couples).
  Grid grid;
  CubicBlock across({2 * 8, 2 * 8 + 1, 2 * 15, 2 * 15 + 1}, 0.7), corner({2 * 23, 2 * 5 + 1}, 1.3);
  std::vector<Contribution*> list;
  for (auto& q : grid.quads) list.push_back(&q);
  list.push_back(&across);
  list.push_back(&corner);
  Assembler held(list, Grid::equations()), fresh(list, Grid::equations());
  held.set_linear(linear_flags(list), false);

  Eigen::VectorXd r_held, r_fresh;
  for (int k = 0; k < 4; ++k) {
    const Eigen::VectorXd u = Eigen::VectorXd::LinSpaced(Grid::n, 0.1 * k, 1.0 + k * k);
    const EvaluationState state{u, u};
    held.assemble(state, r_held, true);
    fresh.assemble(state, r_fresh, true);
    EXPECT_TRUE(same_bits(held.tangent(), fresh.tangent())) << "state " << k;
    EXPECT_EQ(r_held, r_fresh);
  }
  EXPECT_EQ(held.linear_reuse().full, 1);
  EXPECT_EQ(held.linear_reuse().reused, 3);
  // A residual-only assembly keeps the held tangent as it is.
  const std::uint64_t revision = held.tangent_revision();
  const Eigen::VectorXd u = Eigen::VectorXd::Constant(Grid::n, 0.3);
  held.assemble(EvaluationState{u, u}, r_held, false);
  EXPECT_EQ(held.tangent_revision(), revision);
}

TEST(Assembler, HeldTangentRevisionChangesOnlyWithTheMatrix) {
  // All linear: the tangent is held and its revision stays, so a
  // factorization of it may be reused; a nonlinear contribution changes it.
  Grid grid;
  std::vector<Contribution*> list;
  for (auto& q : grid.quads) list.push_back(&q);
  Assembler assembler(list, Grid::equations());
  assembler.set_linear(linear_flags(list), false);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(Grid::n), r;
  assembler.assemble(EvaluationState{u, u}, r, true);
  const std::uint64_t first = assembler.tangent_revision();
  u.setConstant(2.0);
  assembler.assemble(EvaluationState{u, u}, r, true);
  EXPECT_EQ(assembler.tangent_revision(), first);

  CubicBlock block({4, 5}, 1.0);
  list.push_back(&block);
  Assembler mixed(list, Grid::equations());
  mixed.set_linear(linear_flags(list), false);
  mixed.assemble(EvaluationState{u, u}, r, true);
  const std::uint64_t before = mixed.tangent_revision();
  mixed.assemble(EvaluationState{u, u}, r, true);
  EXPECT_NE(mixed.tangent_revision(), before);
}

TEST(Assembler, TangentKeyedOnTheIncrementIsAssembledAgainAtAnotherIncrement) {
  // Inertia-like linear contributions: M / dt^2 on the diagonal. Held with
  // keyed_on_dt, a new dt assembles them again (a cut-back in a dynamic step);
  // held without the key, the tangent would stay that of the first dt.
  Grid grid;
  std::vector<InertiaLike> masses;
  masses.reserve(Grid::nx * Grid::ny);
  for (int node = 0; node < Grid::nx * Grid::ny; ++node) masses.emplace_back(std::vector<int>{2 * node, 2 * node + 1}, 1.0 + node);
  CubicBlock contact({2 * 9, 2 * 9 + 1, 2 * 16 + 1}, 0.5);
  std::vector<Contribution*> list;
  for (auto& q : grid.quads) list.push_back(&q);
  for (auto& m : masses) list.push_back(&m);
  list.push_back(&contact);
  Assembler keyed(list, Grid::equations()), unkeyed(list, Grid::equations()), fresh(list, Grid::equations());
  keyed.set_linear(linear_flags(list), true);
  unkeyed.set_linear(linear_flags(list), false);
  const Eigen::VectorXd u = Eigen::VectorXd::LinSpaced(Grid::n, -1.0, 1.0), u0 = Eigen::VectorXd::Zero(Grid::n);
  Eigen::VectorXd r;
  for (const double dt : {0.1, 0.1, 0.05, 0.05}) {
    const EvaluationState state{u, u0, 0, 0, dt};
    keyed.assemble(state, r, true);
    unkeyed.assemble(state, r, true);
    fresh.assemble(state, r, true);
    EXPECT_TRUE(same_bits(keyed.tangent(), fresh.tangent())) << "dt " << dt;
  }
  EXPECT_EQ(keyed.linear_reuse().full, 2);  // dt 0.1, then 0.05
  EXPECT_EQ(keyed.linear_reuse().reused, 2);
  EXPECT_FALSE(same_bits(unkeyed.tangent(), fresh.tangent()));  // what the key prevents
}

TEST(Assembler, HeldTangentFollowsARelocatedNonlinearContribution) {
  // A re-paired (nonlinear) spring moves inside a reserved block: the
  // entries it left and those it moved to are assembled anew, and the held
  // tangent stays that of a fresh assembler.
  Spring s01(0, 1, 1.0), s23(2, 3, 2.0);
  Rewiring moving(1, 2, 3), moving_too(1, 2, 3);
  const std::vector<Contribution*> list{&s01, &s23, &moving};
  Assembler held(list, EquationMap(std::vector<bool>(4, false)), {1, 2, 3});
  held.set_linear(linear_flags(list), false);
  Eigen::VectorXd u = Eigen::VectorXd::LinSpaced(4, 0.0, 1.0), r;
  const EvaluationState state{u, u};
  held.assemble(state, r, true);
  held.assemble(state, r, true);
  EXPECT_FALSE(held.update_connectivity(state));  // relocated, no rebuild
  held.assemble(state, r, true);
  held.assemble(state, r, true);
  Assembler fresh({&s01, &s23, &moving_too}, EquationMap(std::vector<bool>(4, false)), {1, 2, 3});
  fresh.update_connectivity(state);
  fresh.assemble(state, r, true);
  EXPECT_TRUE(same_bits(held.tangent(), fresh.tangent()));
  EXPECT_EQ(held.linear_reuse().full, 1);  // the relocation only added the entries it moved to
  EXPECT_EQ(held.linear_reuse().reused, 3);
}

TEST(Assembler, OuterRevisionStaysWhileOnlyTheReservedBlockChanges) {
  // Nonlinear contributions inside the reserved block (condensed contact):
  // held assemblies leave the entries outside it as they are, and say so;
  // one nonlinear contribution outside the block, a new dt (keyed) or a
  // rebuild changes them.
  Grid grid;
  CubicBlock inside({2 * 22, 2 * 22 + 1, 2 * 23}, 0.8), outside({2 * 7, 2 * 7 + 1}, 0.4);
  std::vector<Contribution*> list;
  for (auto& q : grid.quads) list.push_back(&q);
  list.push_back(&inside);
  // Equations of dofs 44..47 (nodes 22, 23): the two prescribed dofs come first.
  const std::vector<int> block{42, 43, 44, 45};
  Assembler assembler(list, Grid::equations(), block);
  assembler.set_linear(linear_flags(list), true);
  Eigen::VectorXd u = Eigen::VectorXd::LinSpaced(Grid::n, 0.0, 1.0), r;
  assembler.assemble(EvaluationState{u, u, 0, 0, 0.1}, r, true);
  const std::uint64_t outer = assembler.outer_revision(), all = assembler.tangent_revision();
  u *= 2;
  assembler.assemble(EvaluationState{u, u, 0, 0, 0.1}, r, true);
  EXPECT_EQ(assembler.outer_revision(), outer);
  EXPECT_NE(assembler.tangent_revision(), all);
  assembler.assemble(EvaluationState{u, u, 0, 0, 0.2}, r, true);  // another increment: all assembled
  EXPECT_NE(assembler.outer_revision(), outer);

  list.push_back(&outside);
  Assembler spread(list, Grid::equations(), block);
  spread.set_linear(linear_flags(list), false);
  spread.assemble(EvaluationState{u, u}, r, true);
  const std::uint64_t before = spread.outer_revision();
  spread.assemble(EvaluationState{u, u}, r, true);
  EXPECT_NE(spread.outer_revision(), before);
}

TEST(Assembler, ResidualUpdatesFromTheHeldTangentMatchAFullAssembly) {
  // Linear quads (unsymmetric), two nonlinear blocks sharing entries with
  // some of them, node 0 prescribed. With residual updates the quads that
  // touch neither a nonlinear entry nor a prescribed dof are evaluated once
  // (the reference), then their residual comes from the held tangent; it
  // must match a fresh assembly to round-off, the reactions bit for bit.
  Grid grid;
  CubicBlock across({2 * 8, 2 * 8 + 1, 2 * 15, 2 * 15 + 1}, 0.7), corner({2 * 23, 2 * 5 + 1}, 1.3);
  std::vector<Contribution*> list;
  for (auto& q : grid.quads) list.push_back(&q);
  list.push_back(&across);
  list.push_back(&corner);
  Assembler held(list, Grid::equations()), fresh(list, Grid::equations());
  held.set_linear(linear_flags(list), false);
  held.enable_residual_updates(true);
  const DenseBlock& far = grid.quads[3];  // nodes 3, 4, 10, 9: away from node 0 and the blocks
  Eigen::VectorXd u = Eigen::VectorXd::LinSpaced(Grid::n, 0.1, 1.3), r_held, r_fresh;
  u[0] = 0.2, u[1] = -0.1;  // the prescribed values
  const auto expect_match = [&](bool with_tangent, const std::string& what) {
    const EvaluationState state{u, u};
    held.assemble(state, r_held, with_tangent);
    fresh.assemble(state, r_fresh, with_tangent);
    EXPECT_LE((r_held - r_fresh).cwiseAbs().maxCoeff(), 1e-13 * r_fresh.cwiseAbs().maxCoeff()) << what;
    EXPECT_EQ(r_held[0], r_fresh[0]) << what;  // reactions: evaluated, not updated
    EXPECT_EQ(r_held[1], r_fresh[1]) << what;
    if (with_tangent) EXPECT_TRUE(same_bits(held.tangent(), fresh.tangent())) << what;
  };
  expect_match(true, "full assembly");
  expect_match(false, "reference");
  const int evaluations = far.evaluations;
  for (int k = 1; k <= 3; ++k) {
    u.tail(Grid::n - 2) += Eigen::VectorXd::LinSpaced(Grid::n - 2, 0.05 * k, -0.2);
    expect_match(k % 2 == 1, "update " + std::to_string(k));
  }
  EXPECT_EQ(held.linear_reuse().residual_updates, 3);
  EXPECT_EQ(far.evaluations - evaluations, 3) << "the fresh assembler's only";
  // Other prescribed values: no prescribed dof is in L (the quads at node 0
  // are evaluated), so the reference serves on.
  u[1] = 0.4;
  expect_match(false, "moved support");
  EXPECT_EQ(held.linear_reuse().residual_updates, 4);
  u[5] -= 0.3;
  expect_match(true, "update after the moved support");
  EXPECT_EQ(held.linear_reuse().residual_updates, 5);
  // Another time: the quads (residual_depends_on_time by default) are
  // evaluated at u_ref at that time, and the update goes on.
  const int before_time = far.evaluations;
  held.assemble(EvaluationState{u, u, 0.5, 0.5}, r_held, false);
  fresh.assemble(EvaluationState{u, u, 0.5, 0.5}, r_fresh, false);
  EXPECT_LE((r_held - r_fresh).cwiseAbs().maxCoeff(), 1e-13 * r_fresh.cwiseAbs().maxCoeff()) << "another time";
  EXPECT_EQ(held.linear_reuse().residual_updates, 6);
  EXPECT_EQ(far.evaluations - before_time, 2) << "the fresh assembler's and the reference's";
  // Enabled anew (new loads): the time-dependent part is evaluated again.
  held.enable_residual_updates(true);
  expect_match(false, "update after enabling");
  EXPECT_EQ(held.linear_reuse().residual_updates, 7);
  EXPECT_EQ(far.evaluations - before_time, 4);
  held.enable_residual_updates(false);
  u[7] += 0.1;
  expect_match(false, "disabled");
  EXPECT_EQ(held.linear_reuse().residual_updates, 7);
}

TEST(Assembler, ResidualUpdatesFromALowerTriangleMatchAFullAssembly) {
  // As above with symmetric quads and the tangent stored as its lower
  // triangle: the held product takes each entry below the diagonal for its
  // mirror too, and the quads evaluated beside the reference subtract their
  // mirrored entries as well. Against a fresh assembly of the whole matrix.
  Grid grid;
  std::vector<DenseBlock> quads;
  for (const DenseBlock& q : grid.quads)
    quads.emplace_back(std::vector<int>(q.dofs().begin(), q.dofs().end()), q.matrix()(0, 0), true);
  CubicBlock across({2 * 8, 2 * 8 + 1, 2 * 15, 2 * 15 + 1}, 0.7), corner({2 * 23, 2 * 5 + 1}, 1.3);
  std::vector<Contribution*> list;
  for (auto& q : quads) list.push_back(&q);
  list.push_back(&across);
  list.push_back(&corner);
  Assembler held(list, Grid::equations(), {}, true), fresh(list, Grid::equations());
  held.set_linear(linear_flags(list), false);
  held.enable_residual_updates(true);
  Eigen::VectorXd u = Eigen::VectorXd::LinSpaced(Grid::n, 0.1, 1.3), r_held, r_fresh;
  u[0] = 0.2, u[1] = -0.1;
  const auto expect_match = [&](bool with_tangent, const std::string& what) {
    const EvaluationState state{u, u};
    held.assemble(state, r_held, with_tangent);
    fresh.assemble(state, r_fresh, with_tangent);
    EXPECT_LE((r_held - r_fresh).cwiseAbs().maxCoeff(), 1e-13 * r_fresh.cwiseAbs().maxCoeff()) << what;
    EXPECT_EQ(r_held[0], r_fresh[0]) << what;
    EXPECT_EQ(r_held[1], r_fresh[1]) << what;
    if (with_tangent) {
      const SparseMatrix lower = fresh.tangent().triangularView<Eigen::Lower>();
      EXPECT_TRUE(same_bits(held.tangent(), lower)) << what;
    }
  };
  expect_match(true, "full assembly");
  expect_match(false, "reference");
  for (int k = 1; k <= 3; ++k) {
    u.tail(Grid::n - 2) += Eigen::VectorXd::LinSpaced(Grid::n - 2, 0.05 * k, -0.2);
    expect_match(k % 2 == 1, "update " + std::to_string(k));
  }
  EXPECT_EQ(held.linear_reuse().residual_updates, 3);
}

TEST(Assembler, ResidualUpdatesCarryTheReferenceAcrossARelocation) {
  // A chain of linear springs 0-1-2-3-4-5 (dof 0 prescribed) and a
  // nonlinear spring 1-2 that re-pairs to 1-3 inside the reserved block
  // {1, 2, 3}: the spring 3-4 then touches a nonlinear entry and leaves L,
  // its part of the reference with it; the updates go on without a new
  // reference and match a fresh assembly.
  Spring s01(0, 1, 1.0), s12(1, 2, 2.0), s23(2, 3, 3.0), s34(3, 4, 4.0), s45(4, 5, 5.0);
  Rewiring moving(1, 2, 3), moved(1, 2, 3), unmoved(1, 2, 3);
  std::vector<bool> prescribed(6, false);
  prescribed[0] = true;
  const std::vector<int> block{0, 1, 2};  // equations of dofs 1, 2, 3
  const std::vector<Contribution*> list{&s01, &s12, &s23, &s34, &s45, &moving};
  Assembler held(list, EquationMap(prescribed), block);
  Assembler before({&s01, &s12, &s23, &s34, &s45, &unmoved}, EquationMap(prescribed), block);
  Assembler after({&s01, &s12, &s23, &s34, &s45, &moved}, EquationMap(prescribed), block);
  held.set_linear(linear_flags(list), false);
  held.enable_residual_updates(true);
  Eigen::VectorXd u = Eigen::VectorXd::LinSpaced(6, 0.5, 2.0), r_held, r_fresh;
  const auto expect_match = [&](Assembler& fresh, bool with_tangent, const std::string& what) {
    const EvaluationState state{u, u};
    held.assemble(state, r_held, with_tangent);
    fresh.assemble(state, r_fresh, with_tangent);
    EXPECT_LE((r_held - r_fresh).cwiseAbs().maxCoeff(), 1e-13 * r_fresh.cwiseAbs().maxCoeff()) << what;
  };
  expect_match(before, true, "full assembly");
  u[3] += 0.25;
  expect_match(before, true, "reference");
  u[4] -= 0.5;
  expect_match(before, false, "update before the relocation");
  EXPECT_EQ(held.linear_reuse().residual_updates, 1);
  const EvaluationState state{u, u};
  EXPECT_FALSE(held.update_connectivity(state));  // relocated in the reserved block
  EXPECT_FALSE(after.update_connectivity(state));
  EXPECT_EQ(held.relocations(), 1);
  u[5] += 0.75, u[2] -= 0.125;
  expect_match(after, true, "update after the relocation");
  u[3] *= 1.5;
  expect_match(after, false, "update after the relocation, residual only");
  EXPECT_EQ(held.linear_reuse().residual_updates, 3);
}

namespace {

/// A load like a pressure under an *AMPLITUDE: residual -a(t) p (1 + a/2)
/// at local dof a, with a(t) = 1 + t^2 of the step time and a magnitude p
/// set per increment (as FacePressure::set_pressure); no stiffness. Linear
/// in u; its residual depends on time (the default).
class AmplitudeLoad final : public Contribution {
 public:
  explicit AmplitudeLoad(std::vector<int> dofs) : dofs_(std::move(dofs)) {}
  std::span<const int> dofs() const override { return dofs_; }
  void evaluate(const EvaluationState& s, LocalSystem& out, bool) const override {
    ++evaluations;
    const double amplitude = 1 + s.step_time * s.step_time;
    for (Eigen::Index a = 0; a < out.residual.size(); ++a)
      out.residual[a] = -amplitude * magnitude * (1 + 0.5 * static_cast<double>(a));
  }
  std::string describe() const override { return "amplitude load"; }
  bool symmetric_tangent(bool) const override { return true; }
  bool linear_in_u(bool) const override { return true; }
  double magnitude = 1;         ///< p [force]
  mutable int evaluations = 0;  ///< evaluate() calls

 private:
  std::vector<int> dofs_;
};

}  // namespace

TEST(Assembler, ResidualUpdatesKeepTheReferenceAcrossIncrements) {
  // Four increments of a step as the procedures run them: each a Newton
  // solve with residual updates enabled anew (then off), at a new time, with
  // new prescribed values (node 0), a load under an amplitude whose
  // magnitude is also set per increment, and an inertia-like contribution
  // reading u_start and dt. The quads whose residual is K u alone are
  // evaluated for the step's first two assemblies only (the full tangent,
  // then the reference); the time-dependent members of L once per increment
  // and per other time, at u_ref; every residual matches a fresh assembly
  // to round-off, the reactions bit for bit.
  Grid grid;
  for (DenseBlock& q : grid.quads) q.timed = false;
  DenseBlock& far = grid.quads[3];     // nodes 3, 4, 10, 9
  DenseBlock& heated = grid.quads[11];  // nodes 13, 14, 20, 19: flagged as time-dependent
  heated.timed = true;
  CubicBlock across({2 * 8, 2 * 8 + 1, 2 * 15, 2 * 15 + 1}, 0.7);
  AmplitudeLoad load({2 * 10, 2 * 10 + 1, 2 * 16 + 1});
  InertiaLike mass({2 * 9, 2 * 9 + 1, 2 * 20}, 0.3);
  std::vector<Contribution*> list;
  for (auto& q : grid.quads) list.push_back(&q);
  list.push_back(&across);
  list.push_back(&load);
  list.push_back(&mass);
  Assembler held(list, Grid::equations()), fresh(list, Grid::equations());
  held.set_linear(linear_flags(list), true);
  Eigen::VectorXd u = Eigen::VectorXd::LinSpaced(Grid::n, 0.1, 1.3), r_held, r_fresh;
  Eigen::VectorXd u_start = u;
  int assemblies = 0;
  const auto expect_match = [&](double t, double dt, bool with_tangent, const std::string& what) {
    const EvaluationState state{u, u_start, t, t, dt};
    held.assemble(state, r_held, with_tangent);
    fresh.assemble(state, r_fresh, with_tangent);
    ++assemblies;
    EXPECT_LE((r_held - r_fresh).cwiseAbs().maxCoeff(), 1e-13 * r_fresh.cwiseAbs().maxCoeff()) << what;
    EXPECT_EQ(r_held[0], r_fresh[0]) << what;
    EXPECT_EQ(r_held[1], r_fresh[1]) << what;
    if (with_tangent) EXPECT_TRUE(same_bits(held.tangent(), fresh.tangent())) << what;
  };
  const double dt = 0.25;
  for (int increment = 1; increment <= 4; ++increment) {
    const double t = dt * increment;
    const std::string name = "increment " + std::to_string(increment);
    load.magnitude = 1.0 + increment;
    u[0] = 0.1 * increment, u[1] = -0.05 * increment;  // the prescribed displacement
    held.enable_residual_updates(true);
    for (int iteration = 0; iteration < 3; ++iteration) {
      u.tail(Grid::n - 2) += Eigen::VectorXd::LinSpaced(Grid::n - 2, 0.02 * iteration, -0.03 * increment);
      expect_match(t, dt, iteration != 1, name + ", iteration " + std::to_string(iteration));
    }
    if (increment == 2) {  // in the middle of the increment (at the same dt), and back
      expect_match(t - dt / 2, dt, false, name + ", half way");
      expect_match(t, dt, false, name + ", back at its end");
    }
    held.enable_residual_updates(false);
    u_start = u;
  }
  EXPECT_EQ(held.linear_reuse().full, 1);
  EXPECT_EQ(held.linear_reuse().residual_updates, assemblies - 2);
  // Once per assembly by the fresh assembler; twice by the held one.
  EXPECT_EQ(far.evaluations, assemblies + 2);
  // And at u_ref in increments 2 to 4 and at the two time changes in increment 2.
  EXPECT_EQ(heated.evaluations, assemblies + 2 + 3 + 2);
  EXPECT_EQ(load.evaluations, assemblies + 2 + 3 + 2);
}
