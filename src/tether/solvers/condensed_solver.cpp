#include "tether/solvers/condensed_solver.hpp"

#include <algorithm>
#include <cmath>
#include <vector>
#include <string>
#include <utility>

#include "tether/core/error.hpp"

namespace tether {

namespace {
/// Reciprocal condition number of the equilibrated interface matrix below
/// which it counts as singular and the fallback decides.
constexpr double kSingularRcond = 1e-12;
/// A right-hand side whose entries outside the interface are all at most
/// this fraction of the largest such entry since the bulk factorization is
/// solved as if they were zero (see CondensedSolver::solve).
constexpr double kNegligibleBulk = 1e-10;
}  // namespace

CondensedSolver::CondensedSolver(std::vector<int> interface, std::unique_ptr<LinearSolver> fallback,
                                 double memory_budget_mb)
    : interface_(std::move(interface)), fallback_(std::move(fallback)), bulk_(std::make_unique<MumpsSchur>()) {
  bulk_->set_memory_budget(memory_budget_mb);
  std::sort(interface_.begin(), interface_.end());
  interface_.erase(std::unique(interface_.begin(), interface_.end()), interface_.end());
  statistics_.interface_equations = static_cast<int>(interface_.size());
}

CondensedSolver::~CondensedSolver() = default;

void CondensedSolver::analyze(const SparseMatrix& a) {
  // Nothing to do for the condensed path: MumpsSchur re-orders only when the
  // R pattern changed. The fallback must analyse the new pattern before use.
  (void)a;
  fallback_analysed_ = false;
}

void CondensedSolver::use_fallback(const SparseMatrix& a, bool symmetric) {
  if (!fallback_analysed_) fallback_->analyze(a), fallback_analysed_ = true;
  fallback_active_ = true;
  ++statistics_.fallbacks;
  fallback_->factorize(a, symmetric);
}

bool CondensedSolver::outer_symmetric(const SparseMatrix& a) const {
  // Each entry (i, j) below the diagonal and outside I×I against its mirror
  // (j, i), found by bisection in column i (rows sorted): no copy of `a`.
  // The upper triangle is covered by counting: every column must hold as
  // many upper as mirrored lower entries, which the lower walk checks.
  const int* outer = a.outerIndexPtr();
  const int* inner = a.innerIndexPtr();
  const double* value = a.valuePtr();
  std::vector<int> upper(static_cast<std::size_t>(a.cols()), 0), matched(static_cast<std::size_t>(a.cols()), 0);
  for (Eigen::Index j = 0; j < a.cols(); ++j)
    for (int k = outer[j]; k < outer[j + 1]; ++k) {
      const int i = inner[k];
      if (i < j) {
        ++upper[static_cast<std::size_t>(j)];
        continue;
      }
      if (i == j) continue;
      const int* begin = inner + outer[i];
      const int* end = inner + outer[i + 1];
      const int* m = std::lower_bound(begin, end, static_cast<int>(j));
      if (m == end || *m != j) return false;
      ++matched[static_cast<std::size_t>(i)];
      if (in_interface_[static_cast<std::size_t>(i)] && in_interface_[static_cast<std::size_t>(j)]) continue;
      if (value[k] != value[outer[i] + (m - begin)]) return false;
    }
  return upper == matched;
}

void CondensedSolver::factorize(const SparseMatrix& a, bool symmetric) {
  fallback_active_ = false;
  system_symmetric_ = symmetric;
  const bool promised = std::exchange(outer_unchanged_, false);
  const auto n = static_cast<std::size_t>(a.cols());
  if (in_interface_.size() != n) {
    if (!interface_.empty() && (interface_.front() < 0 || static_cast<std::size_t>(interface_.back()) >= n))
      throw SolverError("condensed solver: an interface equation is outside the matrix");
    in_interface_.assign(n, 0);
    for (int e : interface_) in_interface_[static_cast<std::size_t>(e)] = 1;
    bulk_valid_ = false;
  }
  if (statistics_.gave_up || interface_.empty()) return use_fallback(a, symmetric);

  // The R entries must be symmetric for the LDLT of A_RR; a matrix declared
  // unsymmetric (friction) often still is outside the interface.
  // Promised unchanged: the bulk factorized for the previous call's R entries holds.
  const bool keep = promised && bulk_valid_;
  const bool outer_sym = symmetric || (keep ? bulk_symmetric_ : outer_symmetric(a));
  const bool reused = keep || (bulk_valid_ && outer_sym == bulk_symmetric_ && bulk_->unchanged(a, in_interface_));
  if (reused) {
    changes_in_row_ = 0;
  } else {
    if (bulk_valid_ && ++changes_in_row_ >= 2) {
      // The bulk itself changes every iteration: condensing only adds work.
      statistics_.gave_up = true;
      bulk_valid_ = false;
      bulk_ = std::make_unique<MumpsSchur>();  // frees the factors
      return use_fallback(a, symmetric);
    }
    try {
      bulk_valid_ = false;
      bulk_->factorize(a, interface_, in_interface_, outer_sym);
      bulk_valid_ = true;
      bulk_symmetric_ = outer_sym;
      bulk_scale_ = 0;
      ++statistics_.sparse_factorizations;
      statistics_.factor_entries = bulk_->factor_entries();
      statistics_.factor_memory_mb = bulk_->memory_mb();
      statistics_.out_of_core = bulk_->out_of_core();
      if (statistics_.out_of_core) ++statistics_.out_of_core_factorizations;
    } catch (const SolverError&) {
      // A_RR singular (or MUMPS failed): the fallback decides and names the
      // equation; trying again at every iteration would only double the cost.
      statistics_.gave_up = true;
      bulk_ = std::make_unique<MumpsSchur>();
      return use_fallback(a, symmetric);
    }
  }

  // Dense interface matrix A_II + C (a symmetric matrix given as its lower
  // triangle adds each entry below the diagonal to its mirror too). Only the
  // interface columns are looked at: a whole matrix with no entry above the
  // diagonal in any of them has no entry off the diagonal in A_II, where
  // mirroring then changes nothing.
  Eigen::MatrixXd s = bulk_->schur();
  bool mirror = symmetric;
  for (int j : interface_)
    if (a.outerIndexPtr()[j + 1] > a.outerIndexPtr()[j] && a.innerIndexPtr()[a.outerIndexPtr()[j]] < j) mirror = false;
  // Column j's interface rows ascend, as interface_ does: their positions
  // in it are found by one walk along it per column (no table over all
  // equations), from j's own when the column holds no row above j (a lower
  // triangle); the reserved block puts every later interface row in the
  // column, so the walk mostly moves one place per entry.
  const int* interface = interface_.data();
  const auto m = static_cast<int>(interface_.size());
  for (int pj = 0; pj < m; ++pj) {
    const int j = interface[pj];
    const int begin = a.outerIndexPtr()[j], end = a.outerIndexPtr()[j + 1];
    int pi = begin < end && a.innerIndexPtr()[begin] >= j ? pj : 0;
    for (int k = begin; k < end; ++k) {
      const int i = a.innerIndexPtr()[k];
      if (!in_interface_[static_cast<std::size_t>(i)]) continue;
      while (interface[pi] != i) ++pi;
      s(pi, pj) += a.valuePtr()[k];
      if (mirror && i != j) s(pj, pi) += a.valuePtr()[k];
      ++pi;
    }
  }
  if (!factorize_interface(std::move(s), a, symmetric)) return use_fallback(a, symmetric);
  if (reused) ++statistics_.reuses, statistics_.promised += keep;  // served by the interface system alone
}

DualElimination CondensedSolver::interface_elimination(const SparseMatrix& a) const {
  DualElimination e = choose_dual_elimination(a, dual_nodes_, &interface_);
  const auto at = [&](int& equation) {  // to its position in interface_; false when it is not there
    const auto it = std::lower_bound(interface_.begin(), interface_.end(), equation);
    if (it == interface_.end() || *it != equation) return false;
    equation = static_cast<int>(it - interface_.begin());
    return true;
  };
  for (int& equation : e.eliminated)
    if (!at(equation)) return {};
  for (auto& [equation, diagonal] : e.apart)
    if (!at(equation)) return {};
  return e;
}

bool CondensedSolver::factorize_interface(Eigen::MatrixXd s, const SparseMatrix& a, bool symmetric) {
  // The matrix is equilibrated (DenseFactor: D s D, D = 1/sqrt|diag|, rows
  // without a diagonal by their largest entry) so that the condition test
  // does not depend on the units; a reciprocal condition number below
  // kSingularRcond (also NaN) counts as singular.
  const auto record = [&](double rcond, Eigen::Index size, bool cholesky) {
    statistics_.dense_rcond = rcond;
    statistics_.dense_equations = static_cast<int>(size);
    statistics_.dense_cholesky = cholesky;
    if (rcond > kSingularRcond)
      statistics_.smallest_dense_rcond =
          statistics_.smallest_dense_rcond > 0 ? std::min(statistics_.smallest_dense_rcond, rcond) : rcond;
    return rcond > kSingularRcond;
  };
  dual_active_ = false;
  dual_scaled_ = false;
  if (!dual_nodes_.empty()) {
    const DualElimination e = interface_elimination(a);
    if (e.closed + e.diagonal > 0) {
      // Equilibrated in place (no copy of the |I|² matrix): should the
      // elimination fail, the plain factorization takes D s D too.
      dual_scale_ = equilibration(s);
      s.array().colwise() *= dual_scale_.array();
      s.array().rowwise() *= dual_scale_.transpose().array();
      dual_scaled_ = true;
      const double rcond = dual_.factorize(std::move(s), e, symmetric);
      if (record(rcond, dual_.condensed_size(), dual_.cholesky())) {
        dual_active_ = true;
        ++statistics_.dual_eliminations;
        statistics_.dual_closed = e.closed;
        return true;
      }
      s = dual_.release_matrix();
    }
  }
  const Eigen::Index m = s.rows();
  const double rcond = interface_factor_.factorize(std::move(s), false);
  return record(rcond, m, false);
}

void CondensedSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  if (fallback_active_) return fallback_->solve(b, x);
  if (!bulk_valid_) throw SolverError("condensed solver: solve before factorize");
  // Largest |b_i| outside the interface (b_R); a non-finite one is never negligible.
  double bulk = 0;
  for (Eigen::Index i = 0; i < b.size(); ++i)
    if (!in_interface_[static_cast<std::size_t>(i)]) bulk = std::max(bulk, std::abs(b[i]));
  const bool bulk_negligible = system_symmetric_ && b.allFinite() && bulk <= kNegligibleBulk * bulk_scale_;
  if (std::isfinite(bulk)) bulk_scale_ = std::max(bulk_scale_, bulk);
  Eigen::VectorXd reduced;
  if (bulk_negligible) {
    reduced.setZero(static_cast<Eigen::Index>(interface_.size()));
    ++statistics_.interface_only_solves;
  } else {
    bulk_->reduce(b, reduced);
  }
  for (std::size_t k = 0; k < interface_.size(); ++k)
    reduced[static_cast<Eigen::Index>(k)] += b[interface_[k]];
  Eigen::VectorXd y;
  if (dual_active_) {
    dual_.solve(dual_scale_.asDiagonal() * reduced, y);
  } else {
    y = dual_scaled_ ? Eigen::VectorXd(dual_scale_.asDiagonal() * reduced) : std::move(reduced);
    interface_factor_.solve(y);
  }
  if (dual_scaled_) y = dual_scale_.asDiagonal() * y;
  if (bulk_negligible)
    bulk_->expand_interface(y, x);
  else
    bulk_->expand(y, x);
}

std::string CondensedSolver::name() const {
  if (fallback_active_) return fallback_->name();
  std::string dense = "dense interface (" + std::to_string(interface_.size()) + " equations)";
  if (dual_active_)
    dense = "dense interface (" + std::to_string(interface_.size()) + " equations, " +
            std::to_string(statistics_.dense_equations) + " after the dual elimination, " +
            (statistics_.dense_cholesky ? "Cholesky" : "LU") + ")";
  return std::string("MUMPS ") + (bulk_symmetric_ ? "LDLT" : "LU") + " + " + dense;
}

}  // namespace tether
