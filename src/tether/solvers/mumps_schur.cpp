#include "tether/solvers/mumps_schur.hpp"

#include <string>

#include "tether/solvers/mumps_instance.hpp"

namespace tether {

namespace {
constexpr Eigen::Index kMetisThreshold = 100000;  ///< as MumpsSolver: METIS above, AMD below
}

MumpsSchur::MumpsSchur() = default;
MumpsSchur::~MumpsSchur() = default;

namespace {

/// Calls `f(i, j, k)` for each entry of `a` passed to MUMPS, column by column:
/// row i, column j, value index k. Skips the entries with both row and
/// column in the interface, and the upper triangle when `symmetric`.
template <class F>
void for_each_passed(const SparseMatrix& a, const std::vector<char>& in_interface, bool symmetric, F&& f) {
  for (Eigen::Index j = 0; j < a.cols(); ++j)
    for (int k = a.outerIndexPtr()[j]; k < a.outerIndexPtr()[j + 1]; ++k) {
      const int i = a.innerIndexPtr()[k];
      if (symmetric && i < j) continue;
      if (in_interface[static_cast<std::size_t>(i)] && in_interface[static_cast<std::size_t>(j)]) continue;
      f(i, static_cast<int>(j), k);
    }
}

}  // namespace

void MumpsSchur::factorize(const SparseMatrix& a, const std::vector<int>& interface,
                           const std::vector<char>& in_interface, bool symmetric) {
  if (!a.isCompressed() || a.rows() != a.cols()) throw SolverError("MUMPS Schur: square compressed matrix expected");
  const Eigen::Index m = static_cast<Eigen::Index>(interface.size());
  // The entries MUMPS sees: every one with a row or column in R (lower
  // triangle when symmetric), then an explicit zero diagonal for each
  // interface equation so that it belongs to the pattern. Kept between
  // factorizations as rows and values plus the start of each column (12
  // bytes an entry); the column indices MUMPS also reads are built only
  // for the duration of its analysis and factorization.
  std::vector<int> rows, column_start(static_cast<std::size_t>(a.cols()) + 2, 0);
  rows.reserve(static_cast<std::size_t>(a.nonZeros()) / (symmetric ? 2 : 1) + interface.size());
  values_.clear();
  values_.reserve(rows.capacity());
  for_each_passed(a, in_interface, symmetric, [&](int i, int j, int k) {
    rows.push_back(i + 1), values_.push_back(a.valuePtr()[k]);
    ++column_start[static_cast<std::size_t>(j) + 1];
  });
  for (Eigen::Index j = 0; j < a.cols(); ++j)
    column_start[static_cast<std::size_t>(j) + 1] += column_start[static_cast<std::size_t>(j)];
  column_start.back() = column_start[static_cast<std::size_t>(a.cols())] + static_cast<int>(m);  // the interface diagonals
  for (int e : interface) rows.push_back(e + 1), values_.push_back(0.0);

  const bool new_pattern = !analysed_ || !mumps_ || symmetric != symmetric_ || n_ != a.cols() || rows != rows_ ||
                           column_start != column_start_;
  rows_ = std::move(rows), column_start_ = std::move(column_start);

  std::vector<int> cols(rows_.size());
  for (Eigen::Index j = 0; j < a.cols(); ++j)
    std::fill(cols.begin() + column_start_[static_cast<std::size_t>(j)],
              cols.begin() + column_start_[static_cast<std::size_t>(j) + 1], static_cast<int>(j) + 1);
  std::copy(rows_.end() - m, rows_.end(), cols.end() - m);
  if (new_pattern) {
    if (!mumps_ || symmetric != symmetric_) mumps_ = std::make_unique<detail::MumpsInstance>(symmetric ? 2 : 0);
    symmetric_ = symmetric;
    n_ = a.cols();
    schur_list_.resize(interface.size());
    for (std::size_t k = 0; k < interface.size(); ++k) schur_list_[k] = interface[k] + 1;
    DMUMPS_STRUC_C& id = mumps_->id;
    id.n = static_cast<int>(n_);
    id.nnz = static_cast<MUMPS_INT8>(rows_.size());
    id.irn = rows_.data();
    id.jcn = cols.data();
    id.a = values_.data();
    id.size_schur = static_cast<int>(m);
    id.listvar_schur = schur_list_.data();
    mumps_->icntl(19) = 1;  // Schur complement, centralized by rows on the host
    mumps_->icntl(7) = n_ > kMetisThreshold ? 5 : 0;
    analysed_ = false;  // until the analysis succeeds (a failed one must be redone, not factorized)
    mumps_->run(1);
    analysed_ = true;
  }
  DMUMPS_STRUC_C& id = mumps_->id;
  id.irn = rows_.data();  // the vectors were replaced above: MUMPS reads them again
  id.jcn = cols.data();
  id.a = values_.data();
  schur_rows_.assign(static_cast<std::size_t>(m * m), 0.0);
  id.schur = schur_rows_.data();
  id.schur_lld = static_cast<int>(m);
  reduced_ready_ = false;
  factorized_ = false;
  mumps_->plan_memory(memory_budget_mb_);
  try {
    mumps_->run(2);
  } catch (...) {
    id.jcn = nullptr;  // `cols` dies with this call: leave no dangling pointer
    throw;
  }
  id.jcn = nullptr;  // freed below; solves do not read the matrix
  cols = {};
  mumps_->throw_if_null_pivots();
  factorized_ = true;
  factor_entries_ = mumps_->infog(29) >= 0 ? mumps_->infog(29) : -1e6 * mumps_->infog(29);
  memory_mb_ = mumps_->infog(22);
  out_of_core_ = mumps_->icntl(22) == 1;
  // By rows: entry (i, j) at i m + j. A symmetric factorization fills the
  // lower triangle (j <= i) only; mirror it.
  schur_.resize(m, m);
  for (Eigen::Index i = 0; i < m; ++i)
    for (Eigen::Index j = 0; j < m; ++j)
      schur_(i, j) = symmetric_ && j > i ? schur_rows_[static_cast<std::size_t>(j * m + i)]
                                         : schur_rows_[static_cast<std::size_t>(i * m + j)];
}

bool MumpsSchur::unchanged(const SparseMatrix& a, const std::vector<char>& in_interface) const {
  if (!factorized_ || a.cols() != n_ || !a.isCompressed()) return false;
  const std::size_t outer = rows_.size() - schur_list_.size();
  std::size_t e = 0;
  bool same = true;
  Eigen::Index column = -1;
  for_each_passed(a, in_interface, symmetric_, [&](int i, int j, int k) {
    if (!same) return;
    if (j != column) {  // a column's first passed entry: the earlier columns must have ended here
      for (Eigen::Index c = column + 1; c <= j; ++c)
        if (column_start_[static_cast<std::size_t>(c)] != static_cast<int>(e)) same = false;
      column = j;
    }
    if (e >= outer || rows_[e] != i + 1 || values_[e] != a.valuePtr()[k]) same = false;
    ++e;
  });
  // Columns after the last one with a passed entry must be empty in the
  // factorized matrix too (their entries may have moved into earlier columns).
  for (Eigen::Index c = column + 1; same && c <= n_; ++c)
    if (column_start_[static_cast<std::size_t>(c)] != static_cast<int>(e)) same = false;
  return same && e == outer;
}

void MumpsSchur::run_schur_solve(int phase) {
  DMUMPS_STRUC_C& id = mumps_->id;
  id.rhs = rhs_.data();
  id.nrhs = 1;
  id.lrhs = static_cast<int>(n_);
  id.redrhs = reduced_.data();
  id.lredrhs = static_cast<int>(schur_list_.size());
  mumps_->icntl(26) = phase;
  try {
    mumps_->run(3);
  } catch (...) {
    mumps_->icntl(26) = 0;
    throw;
  }
  mumps_->icntl(26) = 0;
}

void MumpsSchur::reduce(const Eigen::VectorXd& b, Eigen::VectorXd& reduced) {
  if (!mumps_ || b.size() != n_) throw SolverError("MUMPS Schur: reduce before factorize or wrong size");
  rhs_ = b;
  for (int e : schur_list_) rhs_[e - 1] = 0.0;
  reduced_.setZero(static_cast<Eigen::Index>(schur_list_.size()));
  reduced_ready_ = false;
  run_schur_solve(1);
  reduced = reduced_;
  reduced_ready_ = true;
}

void MumpsSchur::expand(const Eigen::VectorXd& x_interface, Eigen::VectorXd& x) {
  if (!reduced_ready_) throw SolverError("MUMPS Schur: expand without reduce");
  reduced_ = x_interface;
  reduced_ready_ = false;
  run_schur_solve(2);
  x = rhs_;
  for (std::size_t k = 0; k < schur_list_.size(); ++k) x[schur_list_[k] - 1] = x_interface[static_cast<Eigen::Index>(k)];
}

}  // namespace tether
