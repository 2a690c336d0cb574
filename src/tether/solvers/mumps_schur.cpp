#include "tether/solvers/mumps_schur.hpp"

#include <algorithm>
#include <bit>
#include <string>

#include "tether/solvers/fill_ordering.hpp"
#include "tether/solvers/mumps_instance.hpp"

namespace tether {

namespace {
/// Above this many equations the ordering is METIS's nested dissection with
/// the interface last, given to MUMPS as PERM_IN (MUMPS itself orders by AMD
/// when a Schur complement is asked for, whatever ICNTL(7) says); below, AMD.
constexpr Eigen::Index kMetisThreshold = 100000;
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

/// SplitMix64's finalizer: a bijection of 64-bit words that spreads every input bit.
std::uint64_t mix(std::uint64_t x) {
  x ^= x >> 30, x *= 0xbf58476d1ce4e5b9ULL;
  x ^= x >> 27, x *= 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

}  // namespace

// Each entry adds a hash of (row, column, value bits) to both lanes, the
// lanes with different keys. A matrix is a set of distinct (row, column)
// entries, so the sum (order-free, and pipelined where a chain would not be)
// identifies it; an entry that moves, appears or changes value changes each
// lane by a pseudo-random 64-bit amount.
void MumpsSchur::add_entry(Fingerprint& f, int i, int j, double value) {
  const std::uint64_t position = (static_cast<std::uint64_t>(static_cast<std::uint32_t>(i)) << 32) |
                                 static_cast<std::uint32_t>(j);
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(value);
  f.a += mix(position * 0x9e3779b97f4a7c15ULL + bits);
  f.b += mix((bits ^ 0xd6e8feb86659fd93ULL) * 0xa0761d6478bd642fULL + position);
  ++f.count;
}

void MumpsSchur::factorize(const SparseMatrix& a, const std::vector<int>& interface,
                           const std::vector<char>& in_interface, bool symmetric) {
  if (!a.isCompressed() || a.rows() != a.cols()) throw SolverError("MUMPS Schur: square compressed matrix expected");
  const Eigen::Index m = static_cast<Eigen::Index>(interface.size());
  Input input;
  Fingerprint pattern, entries;
  std::vector<Coupling> coupling;  // A_RI: for a symmetric matrix each passed entry between R and I is one of it
  gather(a, interface, in_interface, symmetric, input, pattern, entries, coupling);
  std::vector<int>& rows = input.rows;
  std::vector<int>& cols = input.cols;
  // MUMPS only reads its input matrix (analysis and factorization): a lent
  // lower triangle's values are not written.
  double* values = input.lent ? const_cast<double*>(a.valuePtr()) : input.values.data();

  const bool new_pattern =
      !analysed_ || !mumps_ || symmetric != symmetric_ || n_ != a.cols() || pattern != pattern_ ||
      schur_list_.size() != interface.size() ||
      !std::equal(interface.begin(), interface.end(), schur_list_.begin(), [](int e, int s) { return e + 1 == s; });
  DMUMPS_STRUC_C* id = mumps_ ? &mumps_->id : nullptr;
  if (new_pattern) {
    if (!mumps_ || symmetric != symmetric_) mumps_ = std::make_unique<detail::MumpsInstance>(symmetric ? 2 : 0);
    id = &mumps_->id;
    symmetric_ = symmetric;
    n_ = a.cols();
    pattern_ = pattern;
    schur_list_.resize(interface.size());
    for (std::size_t k = 0; k < interface.size(); ++k) schur_list_[k] = interface[k] + 1;
    id->n = static_cast<int>(n_);
    id->nnz = static_cast<MUMPS_INT8>(rows.size());
    id->irn = rows.data();
    id->jcn = cols.data();
    id->a = values;
    id->size_schur = static_cast<int>(m);
    id->listvar_schur = schur_list_.data();
    mumps_->icntl(19) = 1;  // Schur complement, centralized by rows on the host
    std::vector<int> perm_in;  // read by the analysis only
    if (n_ > kMetisThreshold) {
      try {
        perm_in = nested_dissection_last(a, in_interface);
      } catch (const SolverError&) {
        perm_in.clear();  // METIS failed (or CHOLMOD was built without it): MUMPS's AMD, as below the threshold
      }
    }
    id->perm_in = perm_in.empty() ? nullptr : perm_in.data();
    mumps_->icntl(7) = perm_in.empty() ? 0 : 1;
    analysed_ = false;  // until the analysis succeeds (a failed one must be redone, not factorized)
    try {
      mumps_->run(1);
    } catch (...) {
      id->irn = id->jcn = nullptr, id->a = nullptr, id->perm_in = nullptr;  // the arrays die with this call
      throw;
    }
    id->perm_in = nullptr;
    analysed_ = true;
  }
  struct Detach {  // solves read neither the matrix nor the Schur array: no dangling pointer, whatever happens
    DMUMPS_STRUC_C* id;
    ~Detach() { id->irn = id->jcn = nullptr, id->a = nullptr, id->schur = nullptr; }
  } detach{id};
  id->irn = rows.data();  // this call's arrays: MUMPS reads them again
  id->jcn = cols.data();
  id->a = values;
  schur_rows_.assign(static_cast<std::size_t>(m * m), 0.0);
  id->schur = schur_rows_.data();
  id->schur_lld = static_cast<int>(m);
  reduced_ready_ = false;
  factorized_ = false;
  mumps_->plan_memory(memory_budget_mb_);
  mumps_->run(2);
  mumps_->throw_if_null_pivots();
  factorized_ = true;
  entries_ = entries;
  keep_coupling(coupling, interface);
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
  schur_rows_ = {};  // m² doubles: the next factorization allocates its own
}

void MumpsSchur::gather(const SparseMatrix& a, const std::vector<int>& interface, const std::vector<char>& in_interface,
                        bool symmetric, Input& input, Fingerprint& pattern, Fingerprint& entries,
                        std::vector<Coupling>& coupling) {
  const auto visit = [&](int i, int j, int k) {
    add_entry(pattern, i, j), add_entry(entries, i, j, a.valuePtr()[k]);
    const bool i_in = in_interface[static_cast<std::size_t>(i)], j_in = in_interface[static_cast<std::size_t>(j)];
    if (j_in && !i_in) coupling.push_back({i, j, a.valuePtr()[k]});
    else if (symmetric && i_in && !j_in) coupling.push_back({j, i, a.valuePtr()[k]});
  };
  input.lent = symmetric && lower_triangle_only(a);
  if (input.lent) {
    // A lower triangle is lent whole: one row and one column index per
    // entry of `a` (MUMPS counts from 1, `a` from 0), and the row 0, which
    // MUMPS ignores as out of range, for the entries of A_II. An interface
    // equation with no entry outside A_II (a contact multiplier) is then in
    // no entry MUMPS reads; MUMPS takes it as a Schur variable all the same,
    // and the Schur complement is that of the copy below with its explicit
    // zero diagonal, bit for bit (CondensedSolver's tests, the Hertz decks).
    const auto nnz = static_cast<std::size_t>(a.nonZeros());
    input.rows.resize(nnz), input.cols.resize(nnz);
    for (Eigen::Index j = 0; j < a.cols(); ++j)
      for (int k = a.outerIndexPtr()[j]; k < a.outerIndexPtr()[j + 1]; ++k) {
        const int i = a.innerIndexPtr()[k];
        const bool skip = in_interface[static_cast<std::size_t>(i)] && in_interface[static_cast<std::size_t>(j)];
        input.rows[static_cast<std::size_t>(k)] = skip ? 0 : i + 1;
        input.cols[static_cast<std::size_t>(k)] = static_cast<int>(j) + 1;
        if (!skip) visit(i, static_cast<int>(j), k);
      }
    return;
  }
  // A copy of the entries MUMPS sees: every one with a row or column in R
  // (lower triangle when symmetric), then an explicit zero diagonal for
  // each interface equation so that it belongs to the pattern.
  const std::size_t capacity = static_cast<std::size_t>(a.nonZeros()) / (symmetric ? 2 : 1) + interface.size();
  input.rows.reserve(capacity), input.cols.reserve(capacity), input.values.reserve(capacity);
  for_each_passed(a, in_interface, symmetric, [&](int i, int j, int k) {
    input.rows.push_back(i + 1), input.cols.push_back(j + 1), input.values.push_back(a.valuePtr()[k]);
    visit(i, j, k);
  });
  for (int e : interface) input.rows.push_back(e + 1), input.cols.push_back(e + 1), input.values.push_back(0.0);
}

bool MumpsSchur::unchanged(const SparseMatrix& a, const std::vector<char>& in_interface) const {
  if (!factorized_ || a.cols() != n_ || !a.isCompressed()) return false;
  Fingerprint entries;
  for_each_passed(a, in_interface, symmetric_, [&](int i, int j, int k) { add_entry(entries, i, j, a.valuePtr()[k]); });
  return entries == entries_;
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

void MumpsSchur::keep_coupling(std::vector<Coupling>& coupling, const std::vector<int>& interface) {
  std::sort(coupling.begin(), coupling.end(), [](const Coupling& p, const Coupling& q) { return p.row < q.row; });
  coupled_rows_.clear(), coupling_row_.clear(), coupling_column_.clear(), coupling_value_.clear();
  for (const Coupling& c : coupling) {
    if (coupled_rows_.empty() || coupled_rows_.back() != c.row + 1) coupled_rows_.push_back(c.row + 1);
    coupling_row_.push_back(static_cast<int>(coupled_rows_.size()) - 1);
    coupling_column_.push_back(
        static_cast<int>(std::lower_bound(interface.begin(), interface.end(), c.column) - interface.begin()));
    coupling_value_.push_back(c.value);
  }
  coupled_rows_.shrink_to_fit(), coupling_row_.shrink_to_fit(), coupling_column_.shrink_to_fit();
  coupling_value_.shrink_to_fit();
  sparse_rhs_.assign(coupled_rows_.size(), 0.0);
}

void MumpsSchur::expand_interface(const Eigen::VectorXd& x_interface, Eigen::VectorXd& x) {
  if (!factorized_ || x_interface.size() != static_cast<Eigen::Index>(schur_list_.size()))
    throw SolverError("MUMPS Schur: expand_interface before factorize or wrong size");
  reduced_ready_ = false;
  std::fill(sparse_rhs_.begin(), sparse_rhs_.end(), 0.0);
  for (std::size_t k = 0; k < coupling_value_.size(); ++k)
    sparse_rhs_[static_cast<std::size_t>(coupling_row_[k])] -=
        coupling_value_[k] * x_interface[coupling_column_[k]];
  x.setZero(n_);
  if (!coupled_rows_.empty()) {  // else A_RI = 0 and x_R = 0
    DMUMPS_STRUC_C& id = mumps_->id;
    int pointers[2] = {1, static_cast<int>(coupled_rows_.size()) + 1};
    id.nz_rhs = static_cast<int>(coupled_rows_.size());
    id.nrhs = 1;
    id.rhs_sparse = sparse_rhs_.data();
    id.irhs_sparse = coupled_rows_.data();
    id.irhs_ptr = pointers;
    id.rhs = x.data();
    id.lrhs = static_cast<int>(n_);
    mumps_->icntl(20) = 1;  // sparse right-hand side; with ICNTL(26) = 0 the internal problem A_RR alone
    struct Restore {
      detail::MumpsInstance& m;
      ~Restore() {
        m.icntl(20) = 0;
        m.id.rhs_sparse = nullptr, m.id.irhs_sparse = nullptr, m.id.irhs_ptr = nullptr, m.id.nz_rhs = 0;
      }
    } restore{*mumps_};
    mumps_->run(3);
  }
  for (std::size_t k = 0; k < schur_list_.size(); ++k) x[schur_list_[k] - 1] = x_interface[static_cast<Eigen::Index>(k)];
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
