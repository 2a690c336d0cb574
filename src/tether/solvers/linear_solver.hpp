#pragma once
/// \file One small interface in front of the sparse direct solvers.
///
/// The assembler produces a square compressed-column matrix over the free
/// equations. A solver analyses its pattern once (fill-reducing ordering),
/// factorizes it every Newton iteration and solves. A singular or numerically
/// singular matrix is reported as a SolverError naming the equation whose
/// pivot vanished, so the caller can name the node and dof.

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <string>

namespace tether {

/// Global sparse matrix type: column-major, 32-bit indices (as UMFPACK's di_ routines).
using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

/// Which factorization to use.
enum class SolverKind {
  Auto,      ///< symmetric: CHOLMOD, or MUMPS LDLT when indefinite (multipliers); unsymmetric: UMFPACK
  Umfpack,   ///< SuiteSparse UMFPACK: unsymmetric and symmetric-indefinite (saddle-point) systems
  Cholmod,   ///< SuiteSparse CHOLMOD supernodal Cholesky: symmetric positive definite only
  SparseLU,  ///< Eigen's SparseLU with COLAMD: fallback without SuiteSparse
  Mumps,     ///< MUMPS LDLT with 2x2 pivots: symmetric (positive or indefinite) systems only
};

/// Parses "auto", "umfpack", "cholmod", "mumps", "sparselu" (case-insensitive); throws std::invalid_argument.
SolverKind parse_solver_kind(const std::string& name);

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;

  /// Symbolic analysis (ordering) of the pattern of `a`; call again when the pattern changes.
  virtual void analyze(const SparseMatrix& a) = 0;

  /// Numeric factorization of `a` (same pattern as analysed). `symmetric`
  /// says that `a` is symmetric (lets Auto pick Cholesky or LDLT); it may
  /// then be given as its lower triangle only (Assembler::lower_triangle()),
  /// which CHOLMOD, MUMPS and the condensation read as it is and Auto's
  /// UMFPACK fallback mirrors (UMFPACK and SparseLU on their own need the
  /// whole matrix). Throws SolverError
  /// for a singular matrix, naming the equation where a pivot vanished.
  virtual void factorize(const SparseMatrix& a, bool symmetric) = 0;

  /// The caller's word that the matrix of the next factorize() has, outside
  /// the equations a condensing solver condenses onto, bitwise the entries of
  /// the previous factorize()'s (Assembler::outer_revision): CondensedSolver
  /// then skips comparing them. Valid for that one call; ignored by the others.
  virtual void note_outer_unchanged() {}

  /// Solves a x = b with the last factorization.
  virtual void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) = 0;

  /// Name of the factorization last used, e.g. "UMFPACK" (for logs).
  [[nodiscard]] virtual std::string name() const = 0;

  /// How many factorizations so far kept their factors on disk (a memory
  /// budget; see make_linear_solver()); 0 for the solvers that never do.
  [[nodiscard]] virtual int out_of_core_factorizations() const { return 0; }
};

/// True when `a` holds no entry above its diagonal (rows sorted in each
/// column): a symmetric matrix given so is its lower triangle. O(columns).
[[nodiscard]] bool lower_triangle_only(const SparseMatrix& a);

/// The symmetric matrix whose lower triangle `lower` is (the entries below
/// the diagonal mirrored above it), compressed, rows sorted.
[[nodiscard]] SparseMatrix mirror_lower(const SparseMatrix& lower);

/// Creates a solver of the given kind. `memory_budget_mb`: memory the whole
/// process may use [MB], 0 for no limit; MUMPS factorizations that would not
/// fit keep their factors out of core (on disk, read back at each solve).
/// The other solvers ignore it.
std::unique_ptr<LinearSolver> make_linear_solver(SolverKind kind = SolverKind::Auto, double memory_budget_mb = 0);

/// Checks the directory MUMPS's out-of-core factors would go to ($TMPDIR,
/// else /tmp): throws ResourceError naming it when it is missing, not
/// writable or too long a path. Returns it.
std::string check_out_of_core_directory();

}  // namespace tether
