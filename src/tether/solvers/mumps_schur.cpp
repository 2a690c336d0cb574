#include "tether/solvers/mumps_schur.hpp"

#include <string>

#include "tether/solvers/mumps_instance.hpp"

namespace tether {

namespace {
constexpr Eigen::Index kMetisThreshold = 100000;  ///< as MumpsSolver: METIS above, AMD below
}

MumpsSchur::MumpsSchur() = default;
MumpsSchur::~MumpsSchur() = default;

void MumpsSchur::factorize(const SparseMatrix& a, const std::vector<int>& interface,
                           const std::vector<char>& in_interface, bool symmetric) {
  if (!a.isCompressed() || a.rows() != a.cols()) throw SolverError("MUMPS Schur: square compressed matrix expected");
  const Eigen::Index m = static_cast<Eigen::Index>(interface.size());
  // The entries MUMPS sees: every one with a row or column in R (lower
  // triangle when symmetric), then an explicit zero diagonal for each
  // interface equation so that it belongs to the pattern.
  std::vector<int> rows, cols, source;
  rows.reserve(static_cast<std::size_t>(a.nonZeros()) / (symmetric ? 2 : 1) + interface.size());
  cols.reserve(rows.capacity());
  source.reserve(rows.capacity());
  for (Eigen::Index j = 0; j < a.cols(); ++j)
    for (int k = a.outerIndexPtr()[j]; k < a.outerIndexPtr()[j + 1]; ++k) {
      const int i = a.innerIndexPtr()[k];
      if (symmetric && i < j) continue;
      if (in_interface[static_cast<std::size_t>(i)] && in_interface[static_cast<std::size_t>(j)]) continue;
      rows.push_back(i + 1), cols.push_back(static_cast<int>(j) + 1), source.push_back(k);
    }
  for (int e : interface) rows.push_back(e + 1), cols.push_back(e + 1), source.push_back(-1);

  const bool new_pattern =
      !analysed_ || !mumps_ || symmetric != symmetric_ || n_ != a.cols() || rows != rows_ || cols != cols_;
  rows_ = std::move(rows), cols_ = std::move(cols), source_ = std::move(source);
  values_.resize(source_.size());
  const double* v = a.valuePtr();
  for (std::size_t e = 0; e < source_.size(); ++e) values_[e] = source_[e] >= 0 ? v[source_[e]] : 0.0;

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
    id.jcn = cols_.data();
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
  id.jcn = cols_.data();
  id.a = values_.data();
  schur_rows_.assign(static_cast<std::size_t>(m * m), 0.0);
  id.schur = schur_rows_.data();
  id.schur_lld = static_cast<int>(m);
  reduced_ready_ = false;
  factorized_ = false;
  mumps_->run(2);
  mumps_->throw_if_null_pivots();
  factorized_ = true;
  factor_entries_ = mumps_->infog(29) >= 0 ? mumps_->infog(29) : -1e6 * mumps_->infog(29);
  memory_mb_ = mumps_->infog(22);
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
  std::size_t e = 0;
  const std::size_t outer = source_.size() - schur_list_.size();
  for (Eigen::Index j = 0; j < a.cols(); ++j)
    for (int k = a.outerIndexPtr()[j]; k < a.outerIndexPtr()[j + 1]; ++k) {
      const int i = a.innerIndexPtr()[k];
      if (symmetric_ && i < j) continue;
      if (in_interface[static_cast<std::size_t>(i)] && in_interface[static_cast<std::size_t>(j)]) continue;
      if (e >= outer || rows_[e] != i + 1 || cols_[e] != j + 1 || values_[e] != a.valuePtr()[k]) return false;
      ++e;
    }
  return e == outer;
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
