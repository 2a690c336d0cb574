#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "tether/assembly/assembler.hpp"

using namespace tether;

namespace {

/// Linear spring of stiffness k between two scalar unknowns.
class Spring final : public Contribution {
 public:
  Spring(int a, int b, double k) : dofs_{a, b}, k_(k) {}
  std::span<const int> dofs() const override { return dofs_; }
  void evaluate(const EvaluationState& s, LocalSystem& out, bool need_tangent) const override {
    const double f = k_ * (s.u[dofs_[0]] - s.u[dofs_[1]]);
    out.residual << f, -f;
    if (need_tangent) out.tangent << k_, -k_, -k_, k_;
  }
  std::string describe() const override { return "spring"; }

 private:
  std::vector<int> dofs_;
  double k_;
};

}  // namespace

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

TEST(Assembler, PropagatesContributionFailure) {
  class Broken final : public Contribution {
   public:
    std::span<const int> dofs() const override { return dofs_; }
    void evaluate(const EvaluationState&, LocalSystem&, bool) const override { throw std::runtime_error("boom"); }
    std::string describe() const override { return "broken"; }
    std::vector<int> dofs_{0};
  } broken;
  Assembler assembler({&broken}, EquationMap(std::vector<bool>(1, false)));
  Eigen::VectorXd u = Eigen::VectorXd::Zero(1), r;
  SparseMatrix k;
  EXPECT_THROW(assembler.assemble(EvaluationState{u, u}, r, &k), std::runtime_error);
}

namespace {

/// A spring whose second end jumps to another unknown on update_connectivity()
/// (a re-paired contact node): same number of entries, different positions.
class Rewiring final : public Contribution {
 public:
  Rewiring(int a, int b, int later) : dofs_{a, b}, later_(later) {}
  std::span<const int> dofs() const override { return dofs_; }
  void evaluate(const EvaluationState& s, LocalSystem& out, bool need_tangent) const override {
    const double f = s.u[dofs_[0]] - s.u[dofs_[1]];
    out.residual << f, -f;
    if (need_tangent) out.tangent << 1, -1, -1, 1;
  }
  bool update_connectivity(const EvaluationState&) override {
    if (dofs_[1] == later_) return false;
    dofs_[1] = later_;
    return true;
  }
  std::string describe() const override { return "rewiring spring"; }

 private:
  std::vector<int> dofs_;
  int later_;
};

}  // namespace

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
