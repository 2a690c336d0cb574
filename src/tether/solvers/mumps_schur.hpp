#pragma once
/// \file Sparse factorization with a dense Schur complement on chosen
/// equations (MUMPS, ICNTL(19)), and solves by condensation and expansion
/// (ICNTL(26)).
///
/// Splits the unknowns into the interface I (a short list) and the rest R and
/// factorizes A_RR only, returning
///     S = A_II - A_IR A_RR⁻¹ A_RI        (dense, |I| × |I|).
/// A system A x = b is then solved in three parts: reduce() gives
/// b_I - A_IR A_RR⁻¹ b_R, the caller solves its own interface system for x_I,
/// and expand() gives x_R = A_RR⁻¹ (b_R - A_RI x_I): one forward and one
/// backward sweep over the factors in all.
///
/// Symmetric matrices are factorized LDLT (only the lower triangle is read),
/// others LU. A zero pivot of A_RR is reported as a SolverError naming its
/// equation.

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <vector>

#include "tether/solvers/linear_solver.hpp"

namespace tether {

namespace detail {
struct MumpsInstance;
}

class MumpsSchur {
 public:
  MumpsSchur();
  ~MumpsSchur();
  MumpsSchur(const MumpsSchur&) = delete;
  MumpsSchur& operator=(const MumpsSchur&) = delete;

  /// Factorizes A_RR of `a` and forms S. `interface`: the equations of I,
  /// sorted and unique; `in_interface[e]` true exactly for them. Only the
  /// entries of `a` with a row or a column in R are passed to MUMPS (A_II is
  /// taken as zero, so schur() is -A_IR A_RR⁻¹ A_RI). `symmetric`: those
  /// entries are symmetric (LDLT). The ordering is recomputed only when
  /// their pattern or `symmetric` changed since the last call: above 100000
  /// equations METIS's nested dissection with I last (fill_ordering.hpp),
  /// else MUMPS's AMD. A symmetric
  /// `a` stored as its lower triangle (Assembler::lower_triangle()) has its
  /// values read by MUMPS in place: only MUMPS's row and column indices are
  /// built (8 bytes per entry, against 16 for a copy of the entries).
  /// MUMPS's coordinate input has no row-index array to lend (it counts from 1).
  void factorize(const SparseMatrix& a, const std::vector<int>& interface, const std::vector<char>& in_interface,
                 bool symmetric);

  /// True when the entries factorize() would pass to MUMPS for `a` (pattern
  /// and values, bitwise) equal those of the last factorization, so that it
  /// still holds for `a`. Only the lower triangle is compared for a symmetric
  /// factorization. Compared through a 128-bit fingerprint of the entries
  /// (row, column and value bits, in order), so that no copy of the matrix
  /// is kept: two different matrices pass for equal with a probability of
  /// about 2⁻¹²⁸. O(nnz), no allocation.
  [[nodiscard]] bool unchanged(const SparseMatrix& a, const std::vector<char>& in_interface) const;

  /// -A_IR A_RR⁻¹ A_RI of the last factorization, full (both triangles), |I| × |I|.
  [[nodiscard]] const Eigen::MatrixXd& schur() const { return schur_; }

  /// Condensation: returns -A_IR A_RR⁻¹ b_R (b over all equations; its I part
  /// is ignored). Must be followed by expand() before the next reduce().
  void reduce(const Eigen::VectorXd& b, Eigen::VectorXd& reduced);

  /// Expansion after reduce(b): x_R = A_RR⁻¹ (b_R - A_RI x_I) and x_I = `x_interface`.
  void expand(const Eigen::VectorXd& x_interface, Eigen::VectorXd& x);

  /// The solution for a right-hand side whose R part is zero, without
  /// reduce(): x_R = -A_RR⁻¹ A_RI x_I and x_I = `x_interface` (the same as
  /// reduce(b) with b_R = 0, whose reduced vector is zero, then expand()).
  /// The right-hand side -A_RI x_I is nonzero only on the equations of R
  /// coupled to I, so it is given to MUMPS as sparse (ICNTL(20)) and the
  /// forward sweep visits only the fronts on their paths to the root; the
  /// backward sweep is complete. Invalidates a pending reduce().
  void expand_interface(const Eigen::VectorXd& x_interface, Eigen::VectorXd& x);

  /// Entries of the factors (INFOG(29)) and MUMPS' memory for it [MB] (INFOG(22)) of the last factorization.
  [[nodiscard]] double factor_entries() const { return factor_entries_; }
  [[nodiscard]] int memory_mb() const { return memory_mb_; }

  /// Memory the whole process may use [MB], 0 for no limit. When MUMPS'
  /// estimate for an in-core factorization does not fit in what the process
  /// leaves of it, the factors are written out of core (MUMPS ICNTL(22), in
  /// the temporary directory) at the price of reading them back at each solve.
  void set_memory_budget(double mb) { memory_budget_mb_ = mb; }
  /// The last factorization kept its factors out of core.
  [[nodiscard]] bool out_of_core() const { return out_of_core_; }

 private:
  /// Solve phase with ICNTL(26) = `phase` (1 condensation, 2 expansion) on rhs_ and reduced_.
  void run_schur_solve(int phase);

  /// An entry of A_RI: R equation `row`, interface equation `column` (0-based).
  struct Coupling {
    int row, column;
    double value;
  };
  /// Keeps A_RI (`coupling`, sorted here) in the coupling_* arrays for expand_interface().
  void keep_coupling(std::vector<Coupling>& coupling, const std::vector<int>& interface);

  /// 128-bit fingerprint of a sequence of entries (two independent 64-bit lanes).
  struct Fingerprint {
    std::uint64_t a = 0, b = 0;
    std::size_t count = 0;
    bool operator==(const Fingerprint&) const = default;
  };

  /// Adds the entry (i, j) = `value` to `f` (0-based; the pattern fingerprint uses value 0).
  static void add_entry(Fingerprint& f, int i, int j, double value = 0.0);

  /// MUMPS's coordinate input for factorize(): 1-based row and column
  /// indices and, unless `lent`, the values. They exist only for the
  /// duration of MUMPS's analysis and factorization; what is kept to
  /// recognise the entries later is their fingerprint.
  struct Input {
    std::vector<int> rows, cols;
    std::vector<double> values;
    /// The values are those of the matrix itself, a symmetric one stored as
    /// its lower triangle: every entry of it is given (rows and columns
    /// parallel to its value array), those of A_II with the out-of-range row
    /// 0, and no explicit interface diagonal. No copy of the values.
    bool lent = false;
  };
  /// Fills `input` for `a` (see factorize()) and, over the entries passed,
  /// the fingerprints and A_RI.
  static void gather(const SparseMatrix& a, const std::vector<int>& interface, const std::vector<char>& in_interface,
                     bool symmetric, Input& input, Fingerprint& pattern, Fingerprint& entries,
                     std::vector<Coupling>& coupling);

  std::unique_ptr<detail::MumpsInstance> mumps_;
  bool symmetric_ = false;
  Fingerprint pattern_;              ///< rows and columns of the entries analysed last
  Fingerprint entries_;              ///< rows, columns and values of the entries factorized last
  double memory_budget_mb_ = 0;      ///< see set_memory_budget()
  bool out_of_core_ = false;
  bool factorized_ = false;
  bool analysed_ = false;            ///< the last analysis (job 1) succeeded
  std::vector<int> schur_list_;      ///< interface equations, 1-based
  /// A_RI of the last factorization, for expand_interface(): entry k couples
  /// R row coupled_rows_[coupling_row_[k]] to interface column coupling_column_[k]
  /// (index into schur_list_) with value coupling_value_[k].
  std::vector<int> coupled_rows_;    ///< distinct R equations with an entry in A_RI, 1-based, ascending
  std::vector<int> coupling_row_, coupling_column_;
  std::vector<double> coupling_value_;
  std::vector<double> sparse_rhs_;   ///< -A_RI x_I on coupled_rows_
  std::vector<double> schur_rows_;   ///< MUMPS' Schur array (by rows)
  Eigen::MatrixXd schur_;
  Eigen::VectorXd rhs_, reduced_;    ///< kept from reduce() for expand()
  Eigen::Index n_ = 0;
  bool reduced_ready_ = false;
  double factor_entries_ = 0;
  int memory_mb_ = 0;
};

}  // namespace tether
