#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "tether/core/error.hpp"
#include "tether/solvers/linear_solver.hpp"

using namespace tether;

namespace {

/// 1D Laplacian (SPD) of size n, optionally with a saddle-point row fixing u_0 - u_{n-1} = 0.
SparseMatrix laplacian(int n, double anchor) {
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, 2.0);
    if (i + 1 < n) t.emplace_back(i, i + 1, -1.0), t.emplace_back(i + 1, i, -1.0);
  }
  t.emplace_back(0, 0, anchor - 1.0);  // anchor = 1 keeps it SPD; anchor = 0 makes it singular
  t.emplace_back(n - 1, n - 1, -1.0);
  SparseMatrix a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  a.makeCompressed();
  return a;
}

/// A free-free chain of n springs of stiffness between 0.1 and 10 (seeded):
/// singular (a rigid translation), but its last pivot is round-off of either
/// sign rather than an exact zero.
SparseMatrix free_chain(int n, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> exponent(-1, 1);
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i + 1 < n; ++i) {
    const double k = std::pow(10.0, exponent(random));
    t.emplace_back(i, i, k), t.emplace_back(i + 1, i + 1, k);
    t.emplace_back(i, i + 1, -k), t.emplace_back(i + 1, i, -k);
  }
  SparseMatrix a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  a.makeCompressed();
  return a;
}

SparseMatrix saddle_point() {
  // [[2,-1, 1],[-1, 2, -1],[1,-1, 0]]: indefinite, regular
  SparseMatrix a(3, 3);
  std::vector<Eigen::Triplet<double>> t{{0, 0, 2}, {0, 1, -1}, {1, 0, -1}, {1, 1, 2}, {0, 2, 1}, {2, 0, 1}, {1, 2, -1}, {2, 1, -1}};
  a.setFromTriplets(t.begin(), t.end());
  a.makeCompressed();
  return a;
}

}  // namespace

class EverySolver : public ::testing::TestWithParam<SolverKind> {};

TEST_P(EverySolver, SolvesSpdSystem) {
  const SparseMatrix a = laplacian(200, 1.0);
  Eigen::VectorXd x_exact = Eigen::VectorXd::LinSpaced(200, -1, 3), x;
  const Eigen::VectorXd b = a * x_exact;
  auto solver = make_linear_solver(GetParam());
  solver->analyze(a);
  solver->factorize(a, true);
  solver->solve(b, x);
  EXPECT_LT((x - x_exact).norm() / x_exact.norm(), 1e-12) << solver->name();
}

TEST_P(EverySolver, ReportsSingularMatrixWithEquation) {
  const SparseMatrix a = laplacian(50, 0.0);  // pure Neumann: rigid mode
  auto solver = make_linear_solver(GetParam());
  solver->analyze(a);
  try {
    solver->factorize(a, true);
    FAIL() << "singular matrix accepted by " << solver->name();
  } catch (const SolverError& e) {
    EXPECT_GE(e.equation(), 0) << e.what();
    EXPECT_LT(e.equation(), 50);
  }
}

TEST_P(EverySolver, ReportsASingularMatrixWhosePivotIsRoundOff) {
  // A model held nowhere: in floating point its zero pivot comes out as
  // +-1e-16 of the stiffness, which a Cholesky factorization alone accepts
  // when the sign is positive (CHOLMOD did, for the Python test's free bar).
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const SparseMatrix a = free_chain(40, seed);
    auto solver = make_linear_solver(GetParam());
    solver->analyze(a);
    try {
      solver->factorize(a, true);
      ADD_FAILURE() << "singular chain (seed " << seed << ") accepted by " << solver->name();
    } catch (const SolverError& e) {
      EXPECT_GE(e.equation(), 0) << e.what();
      EXPECT_LT(e.equation(), 40);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Kinds, EverySolver,
                         ::testing::Values(SolverKind::Auto, SolverKind::Umfpack, SolverKind::Cholmod, SolverKind::SparseLU,
                                           SolverKind::Mumps));

TEST(LinearSolver, AutoAndUmfpackSolveSaddlePoint) {
  const SparseMatrix a = saddle_point();
  const Eigen::Vector3d x_exact(1, 2, 3);
  const Eigen::VectorXd b = a * x_exact;
  for (auto kind : {SolverKind::Auto, SolverKind::Umfpack, SolverKind::SparseLU, SolverKind::Mumps}) {
    auto solver = make_linear_solver(kind);
    solver->analyze(a);
    solver->factorize(a, true);
    Eigen::VectorXd x;
    solver->solve(b, x);
    EXPECT_LT((x - x_exact).norm(), 1e-12) << solver->name();
  }
}

TEST(LinearSolver, CholmodRefusesIndefinite) {
  const SparseMatrix a = saddle_point();
  auto solver = make_linear_solver(SolverKind::Cholmod);
  solver->analyze(a);
  EXPECT_THROW(solver->factorize(a, true), SolverError);
}

TEST(LinearSolver, ParsesNames) {
  EXPECT_EQ(parse_solver_kind("UMFPACK"), SolverKind::Umfpack);
  EXPECT_EQ(parse_solver_kind("Mumps"), SolverKind::Mumps);
  EXPECT_THROW(parse_solver_kind("pardiso"), std::invalid_argument);
}

TEST(LinearSolver, AutoUsesLdltForSymmetricSaddlePointsAndLuOtherwise) {
  // A symmetric saddle point (multipliers) goes to MUMPS LDLT; an SPD matrix to
  // CHOLMOD; an unsymmetric one to UMFPACK.
  auto solver = make_linear_solver(SolverKind::Auto);
  const SparseMatrix saddle = saddle_point();
  solver->analyze(saddle);
  solver->factorize(saddle, true);
  EXPECT_EQ(solver->name(), "MUMPS LDLT");
  const SparseMatrix spd = laplacian(20, 1.0);
  solver->analyze(spd);
  solver->factorize(spd, true);
  EXPECT_NE(solver->name().find("CHOLMOD"), std::string::npos) << solver->name();
  solver->analyze(saddle);
  solver->factorize(saddle, false);
  EXPECT_NE(solver->name().find("UMFPACK"), std::string::npos) << solver->name();
}

TEST(LinearSolver, MumpsNamesTheRedundantConstraintRow) {
  // Two identical constraint rows u_0 - u_1 = 0 on an SPD block: the second is
  // redundant; LDLT finds a zero pivot in a multiplier row (2 or 3).
  std::vector<Eigen::Triplet<double>> t{{0, 0, 2}, {1, 1, 2}, {0, 1, -1}, {1, 0, -1}};
  for (int r : {2, 3}) t.insert(t.end(), {{r, 0, 1}, {0, r, 1}, {r, 1, -1}, {1, r, -1}});
  SparseMatrix a(4, 4);
  a.setFromTriplets(t.begin(), t.end());
  a.makeCompressed();
  auto solver = make_linear_solver(SolverKind::Mumps);
  solver->analyze(a);
  try {
    solver->factorize(a, true);
    FAIL() << "redundant constraints accepted";
  } catch (const SolverError& e) {
    EXPECT_TRUE(e.equation() == 2 || e.equation() == 3) << e.what() << " at " << e.equation();
  }
}

TEST(LinearSolver, MumpsOutOfCoreUnderAMemoryBudgetGivesTheSameSolution) {
  // A 1 MB budget: the factors go to disk. Same answer as in core.
  const SparseMatrix a = laplacian(300, 1.0);
  const Eigen::VectorXd x_exact = Eigen::VectorXd::LinSpaced(300, -1, 3);
  const Eigen::VectorXd b = a * x_exact;
  for (double budget : {0.0, 1.0}) {
    auto solver = make_linear_solver(SolverKind::Mumps, budget);
    solver->analyze(a);
    solver->factorize(a, true);
    Eigen::VectorXd x;
    solver->solve(b, x);
    EXPECT_LT((x - x_exact).norm(), 1e-10 * x_exact.norm()) << "budget " << budget;
  }
}

TEST(LinearSolver, ALowerTriangleIsTheSymmetricMatrixForTheSolversThatReadOne) {
  // The assembler stores a symmetric tangent as its lower triangle: CHOLMOD,
  // MUMPS and Auto (its UMFPACK fallback mirrors it) must solve it as the
  // whole matrix, to the last bit where they read one triangle anyway.
  for (const SparseMatrix& whole : {laplacian(200, 1.0), saddle_point()}) {
    const SparseMatrix lower = whole.triangularView<Eigen::Lower>();
    EXPECT_TRUE(lower_triangle_only(lower));
    EXPECT_FALSE(lower_triangle_only(whole));
    EXPECT_EQ(Eigen::MatrixXd(mirror_lower(lower)), Eigen::MatrixXd(whole));
    const Eigen::VectorXd b = whole * Eigen::VectorXd::LinSpaced(whole.cols(), -1, 3);
    for (auto kind : {SolverKind::Auto, SolverKind::Cholmod, SolverKind::Mumps}) {
      if (kind == SolverKind::Cholmod && whole.cols() == 3) continue;  // indefinite
      Eigen::VectorXd x_whole, x_lower;
      auto solver = make_linear_solver(kind);
      solver->analyze(whole);
      solver->factorize(whole, true);
      solver->solve(b, x_whole);
      solver->analyze(lower);
      solver->factorize(lower, true);
      solver->solve(b, x_lower);
      EXPECT_EQ(x_lower, x_whole) << solver->name();
    }
  }
  // A singular lower triangle: Auto's UMFPACK (after MUMPS) still names an equation.
  const SparseMatrix singular = laplacian(50, 0.0).triangularView<Eigen::Lower>();
  auto solver = make_linear_solver(SolverKind::Auto);
  solver->analyze(singular);
  try {
    solver->factorize(singular, true);
    FAIL() << "singular lower triangle accepted by " << solver->name();
  } catch (const SolverError& e) {
    EXPECT_GE(e.equation(), 0) << e.what();
    EXPECT_LT(e.equation(), 50);
  }
}
