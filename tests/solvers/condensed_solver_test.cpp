// CondensedSolver: the condensed solution equals the full one to round-off,
// the bulk factorization is reused while only interface entries change (in
// value, pattern and symmetry), and singular parts go to the fallback, which
// names the equation.

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <random>
#include <string>

#include <Eigen/LU>

#include "tether/core/error.hpp"
#include "tether/solvers/condensed_solver.hpp"

using namespace tether;

namespace {

constexpr int kGrid = 12;                  ///< grid of kGrid x kGrid unknowns
constexpr int kBulk = kGrid * kGrid;

/// Five-point Laplacian of the grid plus a spring to ground at node 0 (SPD),
/// and `extra` additional unknowns (multipliers: zero rows until coupled).
Eigen::MatrixXd bulk_matrix(int extra) {
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(kBulk + extra, kBulk + extra);
  const auto id = [](int i, int j) { return i * kGrid + j; };
  for (int i = 0; i < kGrid; ++i)
    for (int j = 0; j < kGrid; ++j) {
      if (i + 1 < kGrid) {
        const int p = id(i, j), q = id(i + 1, j);
        a(p, p) += 1, a(q, q) += 1, a(p, q) -= 1, a(q, p) -= 1;
      }
      if (j + 1 < kGrid) {
        const int p = id(i, j), q = id(i, j + 1);
        a(p, p) += 1, a(q, q) += 1, a(p, q) -= 1, a(q, p) -= 1;
      }
    }
  a(0, 0) += 1;
  return a;
}

/// The interface: the last grid row (the "contact surface") and the extra unknowns.
std::vector<int> interface_equations(int extra) {
  std::vector<int> out;
  for (int j = 0; j < kGrid; ++j) out.push_back((kGrid - 1) * kGrid + j);
  for (int k = 0; k < extra; ++k) out.push_back(kBulk + k);
  return out;
}

/// Sparse copy keeping every structurally coupled entry (the grid pattern plus
/// the interface block as given), also explicit zeros on the diagonal.
SparseMatrix sparse(const Eigen::MatrixXd& a) {
  std::vector<Eigen::Triplet<double>> t;
  for (int j = 0; j < a.cols(); ++j)
    for (int i = 0; i < a.rows(); ++i)
      if (a(i, j) != 0 || i == j) t.emplace_back(i, j, a(i, j));
  SparseMatrix s(a.rows(), a.cols());
  s.setFromTriplets(t.begin(), t.end());
  s.makeCompressed();
  return s;
}

/// Sparse copy of the nonzero entries only (no explicit zeros, unlike sparse()).
SparseMatrix nonzeros(const Eigen::MatrixXd& a) {
  SparseMatrix s = a.sparseView();
  s.makeCompressed();
  return s;
}

/// A contact-like change of the interface block: a random symmetric (or not)
/// coupling between surface unknowns and multipliers, with -eps on the
/// multiplier diagonal.
Eigen::MatrixXd with_contact(const Eigen::MatrixXd& bulk, int extra, unsigned seed, bool symmetric) {
  Eigen::MatrixXd a = bulk;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  const std::vector<int> surface = interface_equations(0);
  for (int k = 0; k < extra; ++k) {
    const int m = kBulk + k;
    const int s = surface[static_cast<std::size_t>((seed + 3 * k) % surface.size())];
    const double c = 1 + 0.5 * u(rng);
    a(m, s) = c, a(s, m) = symmetric ? c : c * (1 + 0.3 * u(rng));
    a(m, m) = -1e-3 * (1 + std::abs(u(rng)));
    a(s, s) += 0.2 * std::abs(u(rng));
  }
  return a;
}

Eigen::VectorXd solve_with(CondensedSolver& solver, const SparseMatrix& a, bool symmetric, const Eigen::VectorXd& b) {
  solver.analyze(a);
  solver.factorize(a, symmetric);
  Eigen::VectorXd x;
  solver.solve(b, x);
  return x;
}

double relative_error(const Eigen::MatrixXd& a, const Eigen::VectorXd& x, const Eigen::VectorXd& b) {
  return (a * x - b).norm() / b.norm();
}

}  // namespace

TEST(CondensedSolver, EqualsFullSolveAndReusesTheBulkWhileOnlyTheInterfaceChanges) {
  constexpr int kExtra = 5;
  const Eigen::MatrixXd bulk = bulk_matrix(kExtra);
  CondensedSolver solver(interface_equations(kExtra), make_linear_solver(SolverKind::Auto));
  std::mt19937 rng(7);
  std::normal_distribution<double> g;
  double worst = 0;
  for (unsigned k = 0; k < 6; ++k) {
    const bool symmetric = k % 3 != 2;  // every third matrix unsymmetric in the interface block
    const Eigen::MatrixXd a = with_contact(bulk, kExtra, 11 + k, symmetric);
    Eigen::VectorXd b(a.rows());
    for (Eigen::Index i = 0; i < b.size(); ++i) b[i] = g(rng);
    const Eigen::VectorXd x = solve_with(solver, sparse(a), symmetric, b);
    worst = std::max(worst, relative_error(a, x, b));
    EXPECT_LT(relative_error(a, x, b), 1e-12) << "matrix " << k << " via " << solver.name();
  }
  std::printf("[ condensed ] 6 matrices (interface %d of %d equations): max |Ax - b|/|b| = %.2e; %d sparse "
              "factorization(s), %d reuse(s), %d fallback(s)\n",
              solver.statistics().interface_equations, kBulk + kExtra, worst,
              solver.statistics().sparse_factorizations, solver.statistics().reuses, solver.statistics().fallbacks);
  EXPECT_EQ(solver.statistics().sparse_factorizations, 1);
  EXPECT_EQ(solver.statistics().reuses, 5);
  EXPECT_EQ(solver.statistics().fallbacks, 0);
  EXPECT_FALSE(solver.statistics().gave_up);
}

TEST(CondensedSolver, ALowerTriangleGivesTheSolutionOfTheWholeMatrixBitForBit) {
  // A symmetric matrix stored as its lower triangle (the assembler's
  // storage): MumpsSchur lends its values to MUMPS (interface = the surface,
  // coupled to the bulk) or copies them with explicit zero interface
  // diagonals (multipliers coupled to the interface only); A_II is mirrored
  // into the dense interface matrix. Both give the solution of the whole matrix.
  for (int extra : {0, 3}) {
    const Eigen::MatrixXd bulk = bulk_matrix(extra);
    CondensedSolver whole(interface_equations(extra), make_linear_solver(SolverKind::Auto));
    CondensedSolver lower(interface_equations(extra), make_linear_solver(SolverKind::Auto));
    std::mt19937 rng(5);
    std::normal_distribution<double> g;
    for (unsigned k = 0; k < 3; ++k) {
      const Eigen::MatrixXd a = extra > 0 ? with_contact(bulk, extra, 21 + k, true) : bulk;
      Eigen::VectorXd b(a.rows());
      for (Eigen::Index i = 0; i < b.size(); ++i) b[i] = g(rng);
      const SparseMatrix full = sparse(a);
      const SparseMatrix triangle = full.triangularView<Eigen::Lower>();
      const Eigen::VectorXd x_whole = solve_with(whole, full, true, b);
      const Eigen::VectorXd x_lower = solve_with(lower, triangle, true, b);
      EXPECT_EQ(x_lower, x_whole) << "extra " << extra << ", matrix " << k << " via " << lower.name();
      EXPECT_LT(relative_error(a, x_lower, b), 1e-12);
    }
    EXPECT_EQ(lower.statistics().sparse_factorizations, whole.statistics().sparse_factorizations);
    EXPECT_EQ(lower.statistics().reuses, whole.statistics().reuses);
    EXPECT_EQ(lower.statistics().fallbacks, 0);
  }
}

TEST(CondensedSolver, RefactorizesWhenTheBulkChangesAndGivesUpAfterTwoChangesInARow) {
  constexpr int kExtra = 3;
  Eigen::MatrixXd bulk = bulk_matrix(kExtra);
  CondensedSolver solver(interface_equations(kExtra), make_linear_solver(SolverKind::Auto));
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(kBulk + kExtra, -1, 2);
  for (int k = 0; k < 5; ++k) {
    if (k == 2) bulk(5, 5) += 0.5;          // change in R: refactorize
    if (k >= 3) bulk(7, 7) += 0.25 * k;     // changes in R twice in a row: give up
    const Eigen::MatrixXd a = with_contact(bulk, kExtra, 3, true);
    const Eigen::VectorXd x = solve_with(solver, sparse(a), true, b);
    EXPECT_LT(relative_error(a, x, b), 1e-12) << "matrix " << k << " via " << solver.name();
  }
  const CondensationStatistics& s = solver.statistics();
  EXPECT_EQ(s.sparse_factorizations, 2);  // k = 0, and k = 2 (a change)
  EXPECT_EQ(s.reuses, 1);                 // k = 1
  EXPECT_TRUE(s.gave_up);                 // k = 3: the second change in a row
  EXPECT_EQ(s.fallbacks, 2);              // k = 3, 4
}

TEST(CondensedSolver, SingularBulkGoesToTheFallbackWhichNamesTheEquation) {
  // An unknown of R coupled to nothing: A_RR has a zero pivot there.
  Eigen::MatrixXd a = bulk_matrix(0);
  a.row(5).setZero(), a.col(5).setZero();
  CondensedSolver solver(interface_equations(0), make_linear_solver(SolverKind::Auto));
  const SparseMatrix s = sparse(a);
  solver.analyze(s);
  try {
    solver.factorize(s, true);
    FAIL() << "singular matrix accepted";
  } catch (const SolverError& e) {
    EXPECT_EQ(e.equation(), 5) << e.what();
  }
  EXPECT_EQ(solver.statistics().fallbacks, 1);
}

TEST(CondensedSolver, FloatingBodyIsCaughtByTheInterfaceCheck) {
  // No spring to ground: the grid floats. A_RR (the last row held) is regular
  // but the interface system has the rigid mode; the fallback gets the call.
  Eigen::MatrixXd a = bulk_matrix(0);
  a(0, 0) -= 1;
  CondensedSolver solver(interface_equations(0), make_linear_solver(SolverKind::Auto));
  const SparseMatrix s = sparse(a);
  solver.analyze(s);
  try {
    solver.factorize(s, true);  // what the fallback says of a round-off-singular matrix is its business
  } catch (const SolverError&) {
  }
  EXPECT_EQ(solver.statistics().sparse_factorizations, 1);
  EXPECT_EQ(solver.statistics().fallbacks, 1);
}

TEST(CondensedSolver, SingularInterfaceSystemGoesToTheFallback) {
  // Regular A_RR, but a multiplier row with no coupling and no diagonal: the
  // dense interface system is singular, and so is the whole matrix.
  constexpr int kExtra = 2;
  Eigen::MatrixXd a = with_contact(bulk_matrix(kExtra), kExtra, 5, true);
  a.row(kBulk + 1).setZero(), a.col(kBulk + 1).setZero();
  CondensedSolver solver(interface_equations(kExtra), make_linear_solver(SolverKind::Auto));
  const SparseMatrix s = sparse(a);
  solver.analyze(s);
  EXPECT_THROW(solver.factorize(s, true), SolverError);
  EXPECT_EQ(solver.statistics().fallbacks, 1);
}

TEST(CondensedSolver, SiUnitsAndClosedHardMultipliersStillCondense) {
  // Steel in Pa (E ~ 2e11) and closed HARD multipliers (zero diagonal, unit
  // coupling): the equilibrated interface system must not look singular
  // because of the units (its condition was ~1/E before the multiplier rows
  // were scaled by their largest entry).
  constexpr int kExtra = 4;
  Eigen::MatrixXd a = with_contact(bulk_matrix(kExtra), kExtra, 9, true);
  a.topLeftCorner(kBulk, kBulk) *= 2.1e11;
  for (int k = 0; k < kExtra; ++k) a(kBulk + k, kBulk + k) = 0.0;
  CondensedSolver solver(interface_equations(kExtra), make_linear_solver(SolverKind::Auto));
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(kBulk + kExtra, 1, 2);
  const Eigen::VectorXd x = solve_with(solver, sparse(a), true, b);
  // The residual is dominated by round-off of the 1e11 entries; compare with
  // a dense LU solve instead.
  const Eigen::VectorXd reference = a.partialPivLu().solve(b);  // (full pivoting would call the multiplier pivots zero)
  EXPECT_LT((x - reference).norm() / reference.norm(), 1e-8);
  EXPECT_EQ(solver.statistics().fallbacks, 0);
  EXPECT_EQ(solver.statistics().sparse_factorizations, 1);
}

TEST(CondensedSolver, UnsymmetricBulkCouplingUsesLu) {
  // A_RI != A_IR^T (as a follower load would make it): the R entries are not
  // symmetric, so A_RR is factorized LU and the Schur complement read in full.
  constexpr int kExtra = 3;
  Eigen::MatrixXd a = with_contact(bulk_matrix(kExtra), kExtra, 4, false);
  const std::vector<int> surface = interface_equations(0);
  for (int s : surface) a(s - kGrid, s) += 0.07;  // row in R (the grid row below), column in I
  a(3, 4) += 0.05;                                // and one inside R
  CondensedSolver solver(interface_equations(kExtra), make_linear_solver(SolverKind::Auto));
  std::mt19937 rng(3);
  std::normal_distribution<double> g;
  Eigen::VectorXd b(a.rows());
  for (Eigen::Index i = 0; i < b.size(); ++i) b[i] = g(rng);
  for (int k = 0; k < 2; ++k) {
    const Eigen::MatrixXd ak = k == 0 ? a : with_contact(a, kExtra, 8, false);
    const Eigen::VectorXd x = solve_with(solver, sparse(ak), false, b);
    EXPECT_LT(relative_error(ak, x, b), 1e-12) << solver.name();
    EXPECT_NE(solver.name().find("LU"), std::string::npos) << solver.name();
  }
  EXPECT_EQ(solver.statistics().sparse_factorizations, 1);
  EXPECT_EQ(solver.statistics().reuses, 1);
  EXPECT_EQ(solver.statistics().fallbacks, 0);
}

TEST(CondensedSolver, AnEntryMovedToAnotherColumnIsAChangeEvenWithEqualValues) {
  // Two regular unsymmetric matrices whose R entries, read column by column,
  // have the same rows and values in the same order; only where one column
  // ends and the next begins differs: (1, 1) in the first is (1, 0) in the
  // second. The solver must see a change (the column starts are compared),
  // or it would reuse factors of the wrong matrix.
  const auto matrix = [](bool moved) {
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(4, 4);
    a(0, 0) = 4, a(0, 2) = 1, a(2, 1) = 3, a(2, 2) = 5, a(3, 3) = 1;  // equation 3: the interface
    (moved ? a(1, 0) : a(1, 1)) = 2;
    return a;
  };
  CondensedSolver solver({3}, make_linear_solver(SolverKind::Auto));
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(4, 1, 4);
  const auto passed = [](const Eigen::MatrixXd& a) {  // R entries as MUMPS reads them: rows and values
    std::vector<std::pair<int, double>> out;
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i)
        if ((i != 3 || j != 3) && a(i, j) != 0) out.emplace_back(i, a(i, j));
    return out;
  };
  ASSERT_EQ(passed(matrix(false)), passed(matrix(true)));  // the premise of the test
  solve_with(solver, nonzeros(matrix(false)), false, b);
  const Eigen::VectorXd x = solve_with(solver, nonzeros(matrix(true)), false, b);
  EXPECT_LT(relative_error(matrix(true), x, b), 1e-12);
  EXPECT_EQ(solver.statistics().sparse_factorizations, 2);
  EXPECT_EQ(solver.statistics().reuses, 0);
}

TEST(CondensedSolver, OutOfCoreFactorsUnderAMemoryBudgetGiveTheSameSolution) {
  // A 1 MB budget is below any process' resident size: the bulk factors go to
  // disk (MUMPS ICNTL(22), files tether<pid>_* in the temporary directory);
  // the solution must match the in-core one, and the files must be gone
  // once the solver is.
  constexpr int kExtra = 4;
  const Eigen::MatrixXd a = with_contact(bulk_matrix(kExtra), kExtra, 9, true);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(kBulk + kExtra, -2, 1);
  const std::string prefix = "tether" + std::to_string(static_cast<long>(getpid())) + "_";
  const auto scratch_files = [&] {
    int n = 0;
    for (const auto& f : std::filesystem::directory_iterator(std::filesystem::temp_directory_path()))
      n += f.path().filename().string().rfind(prefix, 0) == 0;
    return n;
  };
  CondensedSolver in_core(interface_equations(kExtra), make_linear_solver(SolverKind::Auto));
  const Eigen::VectorXd x0 = solve_with(in_core, sparse(a), true, b);
  EXPECT_FALSE(in_core.statistics().out_of_core);
  {
    CondensedSolver on_disk(interface_equations(kExtra), make_linear_solver(SolverKind::Auto), 1.0);
    const Eigen::VectorXd x1 = solve_with(on_disk, sparse(a), true, b);
    Eigen::VectorXd x2;
    on_disk.solve(b, x2);  // a second solve reads the factors back again
    EXPECT_TRUE(on_disk.statistics().out_of_core);
    EXPECT_GT(scratch_files(), 0);
    EXPECT_LT(relative_error(a, x1, b), 1e-12);
    EXPECT_LT((x1 - x0).norm(), 1e-12 * x0.norm());
    EXPECT_LT((x2 - x1).norm(), 1e-14 * x1.norm());
  }
  EXPECT_EQ(scratch_files(), 0);
}

TEST(CondensedSolver, AnEntryAboveTheDiagonalWithoutItsMirrorMakesTheBulkUnsymmetric) {
  // The bulk has (3, 40) but not (40, 3): an LDLT, which reads the lower
  // triangle only, would drop it; the solver must see the asymmetry of the
  // pattern (not only of values) and factorize LU.
  constexpr int kExtra = 2;
  Eigen::MatrixXd a = with_contact(bulk_matrix(kExtra), kExtra, 4, true);
  a(3, 40) = -0.3;
  ASSERT_EQ(a(40, 3), 0.0);
  CondensedSolver solver(interface_equations(kExtra), make_linear_solver(SolverKind::Auto));
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(kBulk + kExtra, 0.5, 2);
  const Eigen::VectorXd x = solve_with(solver, sparse(a), false, b);
  EXPECT_LT(relative_error(a, x, b), 1e-12);
}

TEST(CondensedSolver, AReuseThatFallsBackIsCountedOnceAsAFallback) {
  // First matrix: regular, condensed. Second: same bulk, but a multiplier
  // decoupled and without diagonal, so the interface system is singular and
  // the call goes to the fallback: one fallback, no reuse.
  constexpr int kExtra = 2;
  const Eigen::MatrixXd a = with_contact(bulk_matrix(kExtra), kExtra, 5, true);
  Eigen::MatrixXd singular = a;
  singular.row(kBulk + 1).setZero(), singular.col(kBulk + 1).setZero();
  CondensedSolver solver(interface_equations(kExtra), make_linear_solver(SolverKind::Auto));
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(kBulk + kExtra, 1, 2);
  solve_with(solver, sparse(a), true, b);
  // Keep the pattern: sparse() drops the zeroed couplings, so assemble the
  // singular values into the first matrix's pattern.
  SparseMatrix s = sparse(a);
  for (Eigen::Index j = 0; j < s.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(s, j); it; ++it) it.valueRef() = singular(it.row(), it.col());
  EXPECT_THROW(solver.factorize(s, true), SolverError);
  EXPECT_EQ(solver.statistics().sparse_factorizations, 1);
  EXPECT_EQ(solver.statistics().reuses, 0);
  EXPECT_EQ(solver.statistics().fallbacks, 1);
}

TEST(CondensedSolver, EntriesMovedOutOfTheLastColumnsAreAChange) {
  // Interface {2, 3}, unsymmetric. Passed entries column by column: first
  // (0, 0) (1, 0) | (0, 1) | - | (1, 3); second (0, 0) (1, 0) | (0, 1) (1, 1):
  // the same rows and values in the same order, the last one moved out of
  // the trailing column 3 into column 1 (review finding). Both regular.
  const auto matrix = [](bool moved) {
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(4, 4);
    a(0, 0) = 4, a(1, 0) = 1, a(0, 1) = 3, a(2, 2) = 1, a(3, 3) = 1;
    (moved ? a(1, 1) : a(1, 3)) = 2;
    return a;
  };
  CondensedSolver solver({2, 3}, make_linear_solver(SolverKind::Auto));
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(4, 1, 4);
  solve_with(solver, nonzeros(matrix(false)), false, b);
  const Eigen::VectorXd x = solve_with(solver, nonzeros(matrix(true)), false, b);
  EXPECT_LT(relative_error(matrix(true), x, b), 1e-12);
  EXPECT_EQ(solver.statistics().reuses, 0);
}

// The bulk entries are recognised by a fingerprint, not by a copy: a change
// of one unit in the last place of one entry, and two entries that swap
// their values (the same multiset of values, the same pattern), are changes.
TEST(CondensedSolver, OneUlpOrTwoSwappedValuesInTheBulkAreAChange) {
  constexpr int kExtra = 2;
  const Eigen::MatrixXd bulk = bulk_matrix(kExtra);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(kBulk + kExtra, -1, 2);
  Eigen::MatrixXd ulp = bulk, swapped = bulk;
  ulp(5, 5) = std::nextafter(ulp(5, 5), 10.0);
  swapped(1, 1) = bulk(13, 13), swapped(13, 13) = bulk(1, 1);  // 3 and 4
  ASSERT_NE(bulk(1, 1), bulk(13, 13));
  for (const Eigen::MatrixXd& changed : {ulp, swapped}) {
    CondensedSolver solver(interface_equations(kExtra), make_linear_solver(SolverKind::Auto));
    for (const Eigen::MatrixXd& bulk_k : {bulk, changed}) {
      const Eigen::MatrixXd a = with_contact(bulk_k, kExtra, 3, true);
      const Eigen::VectorXd x = solve_with(solver, sparse(a), true, b);
      EXPECT_LT(relative_error(a, x, b), 1e-12);
    }
    EXPECT_EQ(solver.statistics().sparse_factorizations, 2);
    EXPECT_EQ(solver.statistics().reuses, 0);
  }
}

TEST(CondensedSolver, APromiseOfAnUnchangedBulkIsTakenWithoutComparing) {
  // note_outer_unchanged(): the next factorize() keeps the bulk without
  // comparing its entries, and solves as if they had been compared (the same
  // matrix); the promise holds for one call only.
  constexpr int kExtra = 4;
  const Eigen::MatrixXd bulk = bulk_matrix(kExtra);
  CondensedSolver promised(interface_equations(kExtra), make_linear_solver(SolverKind::Auto));
  CondensedSolver compared(interface_equations(kExtra), make_linear_solver(SolverKind::Auto));
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(kBulk + kExtra, -1.0, 2.0);
  for (unsigned k = 0; k < 3; ++k) {
    const SparseMatrix a = sparse(with_contact(bulk, kExtra, 21 + k, true));
    if (k > 0) promised.note_outer_unchanged();
    EXPECT_EQ(solve_with(promised, a, true, b), solve_with(compared, a, true, b)) << "matrix " << k;
  }
  EXPECT_EQ(promised.statistics().promised, 2);
  EXPECT_EQ(promised.statistics().reuses, 2);
  EXPECT_EQ(compared.statistics().promised, 0);
  // Without a promise a changed bulk is found and factorized again.
  Eigen::MatrixXd changed = with_contact(bulk, kExtra, 30, true);
  changed(0, 0) += 1;
  const SparseMatrix a = sparse(changed);
  solve_with(promised, a, true, b);
  EXPECT_EQ(promised.statistics().sparse_factorizations, 2);
}

TEST(CondensedSolver, ARightHandSideWithANegligibleBulkPartSkipsTheFullForwardSweep) {
  // After a first solve with a bulk load, right-hand sides whose entries
  // outside the interface are zero or round-off (as in Newton once a linear
  // bulk is in equilibrium) are solved from the interface alone: the same
  // solution as the full solve with those entries zero, to round-off. A bulk
  // part above the threshold takes the full path, and so does every solve of
  // a matrix declared unsymmetric (friction: its path rests on round-off).
  constexpr int kExtra = 4;
  for (const bool symmetric : {true, false}) {
    const Eigen::MatrixXd a = with_contact(bulk_matrix(kExtra), kExtra, 5, symmetric);
    CondensedSolver solver(interface_equations(kExtra), make_linear_solver(SolverKind::Auto));
    std::mt19937 rng(17);
    std::normal_distribution<double> g;
    Eigen::VectorXd load(a.rows());
    for (Eigen::Index i = 0; i < load.size(); ++i) load[i] = g(rng);
    const Eigen::PartialPivLU<Eigen::MatrixXd> exact(a);
    Eigen::VectorXd x = solve_with(solver, sparse(a), symmetric, load);
    EXPECT_LT(relative_error(a, x, load), 1e-12);
    EXPECT_EQ(solver.statistics().interface_only_solves, 0);

    std::vector<char> in_interface(static_cast<std::size_t>(a.rows()), 0);
    for (int e : interface_equations(kExtra)) in_interface[static_cast<std::size_t>(e)] = 1;
    Eigen::VectorXd interface_only = Eigen::VectorXd::Zero(a.rows());
    for (Eigen::Index i = 0; i < a.rows(); ++i)
      if (in_interface[static_cast<std::size_t>(i)]) interface_only[i] = g(rng);
    Eigen::VectorXd round_off = interface_only;
    for (Eigen::Index i = 0; i < a.rows(); ++i)
      if (!in_interface[static_cast<std::size_t>(i)]) round_off[i] = 1e-15 * g(rng);
    Eigen::VectorXd small_load = interface_only;
    for (Eigen::Index i = 0; i < a.rows(); ++i)
      if (!in_interface[static_cast<std::size_t>(i)]) small_load[i] = 1e-6 * g(rng);

    const int skips = symmetric ? 1 : 0;
    solver.solve(interface_only, x);  // b_R exactly zero: exact either way
    EXPECT_LT((x - exact.solve(interface_only)).norm() / x.norm(), 1e-12) << symmetric;
    EXPECT_EQ(solver.statistics().interface_only_solves, skips);
    solver.solve(round_off, x);  // b_R round-off: the solution of b_R = 0 when skipped
    if (symmetric) EXPECT_LT((x - exact.solve(interface_only)).norm() / x.norm(), 1e-12);
    EXPECT_LT(relative_error(a, x, round_off), 1e-12) << symmetric;
    EXPECT_EQ(solver.statistics().interface_only_solves, 2 * skips);
    solver.solve(small_load, x);  // 1e-6 of the first load: a load, solved in full
    EXPECT_LT(relative_error(a, x, small_load), 1e-12) << symmetric;
    EXPECT_GT((x - exact.solve(interface_only)).norm() / x.norm(), 1e-8) << symmetric;
    EXPECT_EQ(solver.statistics().interface_only_solves, 2 * skips);
  }
}

TEST(MumpsSchur, ExpandFromTheInterfaceEqualsReduceOfAZeroBulkThenExpand) {
  // LDLT and LU (A_RI != A_IR^T) bulks: expand_interface(x_I) is reduce(b)
  // with b_R = 0 followed by expand(x_I).
  constexpr int kExtra = 3;
  for (const bool symmetric : {true, false}) {
    Eigen::MatrixXd a = with_contact(bulk_matrix(kExtra), kExtra, 9, symmetric);
    if (!symmetric)
      for (int s : interface_equations(0)) a(s - kGrid, s) += 0.07;  // row in R, column in I
    const std::vector<int> interface = interface_equations(kExtra);
    std::vector<char> in_interface(static_cast<std::size_t>(a.rows()), 0);
    for (int e : interface) in_interface[static_cast<std::size_t>(e)] = 1;
    MumpsSchur schur;
    schur.factorize(sparse(a), interface, in_interface, symmetric);
    Eigen::VectorXd x_interface(static_cast<Eigen::Index>(interface.size()));
    for (Eigen::Index k = 0; k < x_interface.size(); ++k) x_interface[k] = std::sin(1.0 + static_cast<double>(k));
    Eigen::VectorXd reduced, reference, x;
    schur.reduce(Eigen::VectorXd::Zero(a.rows()), reduced);
    EXPECT_EQ(reduced.norm(), 0.0);
    schur.expand(x_interface, reference);
    schur.expand_interface(x_interface, x);
    EXPECT_LT((x - reference).norm() / reference.norm(), 1e-13) << symmetric;
    EXPECT_GT(reference.head(kBulk - kGrid).norm(), 1e-3) << "x_R must not be trivially zero";
  }
}
