#include "tether/solvers/condensed_solver.hpp"

#include <algorithm>
#include <cmath>
#include <vector>
#include <string>
#include <utility>

#include "tether/core/error.hpp"

// LAPACK (Fortran interface): LU with partial pivoting, its solve, and the
// reciprocal condition number in the 1-norm.
extern "C" {
void dgetrf_(const int* m, const int* n, double* a, const int* lda, int* ipiv, int* info);
void dgetrs_(const char* trans, const int* n, const int* nrhs, const double* a, const int* lda, const int* ipiv,
             double* b, const int* ldb, int* info, std::size_t trans_len);
void dgecon_(const char* norm, const int* n, const double* a, const int* lda, const double* anorm, double* rcond,
             double* work, int* iwork, int* info, std::size_t norm_len);
}

namespace tether {

namespace {
/// Reciprocal condition number of the equilibrated interface matrix below
/// which it counts as singular and the fallback decides.
constexpr double kSingularRcond = 1e-12;
/// A diagonal below this fraction of the largest counts as absent for the scaling.
constexpr double kNegligibleDiagonal = 1e-14;
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
    position_.assign(n, -1);
    for (std::size_t k = 0; k < interface_.size(); ++k)
      in_interface_[static_cast<std::size_t>(interface_[k])] = 1, position_[static_cast<std::size_t>(interface_[k])] = static_cast<int>(k);
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

  // Dense interface matrix A_II + C, equilibrated: D (A_II + C) D with
  // D = 1/sqrt|diag| on rows with a diagonal, and for rows without one (a
  // closed HARD multiplier) 1/(largest entry of the row already scaled), so
  // that the condition test does not depend on the units (1/(E t) otherwise).
  const auto m = static_cast<Eigen::Index>(interface_.size());
  lu_ = bulk_->schur();  // becomes A_II + C, equilibrated, then its LU, in place
  Eigen::MatrixXd& s = lu_;
  for (int j : interface_)
    for (int k = a.outerIndexPtr()[j]; k < a.outerIndexPtr()[j + 1]; ++k) {
      const int i = a.innerIndexPtr()[k];
      if (in_interface_[static_cast<std::size_t>(i)])
        s(position_[static_cast<std::size_t>(i)], position_[static_cast<std::size_t>(j)]) += a.valuePtr()[k];
    }
  scale_.resize(m);
  double largest_diagonal = 0;
  for (Eigen::Index k = 0; k < m; ++k)
    if (std::isfinite(s(k, k))) largest_diagonal = std::max(largest_diagonal, std::abs(s(k, k)));
  std::vector<Eigen::Index> without_diagonal;
  for (Eigen::Index k = 0; k < m; ++k) {
    const double d = std::abs(s(k, k));
    if (d > kNegligibleDiagonal * largest_diagonal && std::isfinite(d)) {
      scale_[k] = 1.0 / std::sqrt(d);
    } else {
      scale_[k] = 0.0;
      without_diagonal.push_back(k);
    }
  }
  for (Eigen::Index k : without_diagonal) {
    const double row = (s.row(k).cwiseAbs().transpose().cwiseProduct(scale_)).maxCoeff();
    scale_[k] = row > 0 && std::isfinite(row) ? 1.0 / row : 1.0;
  }
  lu_.array().colwise() *= scale_.array();  // D s D: row i times d_i, then column j times d_j
  lu_.array().rowwise() *= scale_.transpose().array();
  const int size = static_cast<int>(m);
  const double norm1 = lu_.cwiseAbs().colwise().sum().maxCoeff();
  pivots_.resize(interface_.size());
  int info = 0;
  dgetrf_(&size, &size, lu_.data(), &size, pivots_.data(), &info);
  // info > 0: an exactly zero pivot. Otherwise the condition estimate decides.
  double rcond = 0;
  if (info == 0 && std::isfinite(norm1)) {
    std::vector<double> work(4 * interface_.size());
    std::vector<int> iwork(interface_.size());
    dgecon_("1", &size, lu_.data(), &size, &norm1, &rcond, work.data(), iwork.data(), &info, 1);
  }
  if (info != 0 || !(rcond > kSingularRcond)) return use_fallback(a, symmetric);  // also NaN
  if (reused) ++statistics_.reuses, statistics_.promised += keep;  // served by the interface system alone
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
  Eigen::VectorXd y = scale_.asDiagonal() * reduced;
  const int size = static_cast<int>(interface_.size()), one = 1;
  int info = 0;
  dgetrs_("N", &size, &one, lu_.data(), &size, pivots_.data(), y.data(), &size, &info, 1);
  if (info != 0) throw SolverError("condensed solver: LAPACK dgetrs failed (info " + std::to_string(info) + ")");
  y = scale_.asDiagonal() * y;
  if (bulk_negligible)
    bulk_->expand_interface(y, x);
  else
    bulk_->expand(y, x);
}

std::string CondensedSolver::name() const {
  if (fallback_active_) return fallback_->name();
  return std::string("MUMPS ") + (bulk_symmetric_ ? "LDLT" : "LU") + " + dense interface (" +
         std::to_string(interface_.size()) + " equations)";
}

}  // namespace tether
