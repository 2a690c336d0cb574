#include "tether/solvers/cholmod_solver.hpp"

#include <cholmod.h>

#include <cstdio>
#include <string>

#include "tether/core/error.hpp"

namespace tether {

namespace {

/// A pivot below this fraction of its equation's diagonal term is taken as
/// zero: in floating point the zero pivot of a rigid-body mode comes out as
/// round-off of either sign (measured up to 9e-15 on 40-spring chains), and a
/// positive one passes the Cholesky factorization. The same threshold as
/// UMFPACK's reciprocal condition (its rows are scaled, so its pivots are
/// relative to their rows too).
constexpr double kMinRelativePivot = 1e-12;

/// The smallest pivot L_kk^2 of an LL' factor relative to the diagonal term
/// of its equation, and that equation (original numbering; -1 if none).
std::pair<double, int> weakest_pivot(const cholmod_factor& f, const Eigen::VectorXd& diagonal) {
  const auto* x = static_cast<const double*>(f.x);
  const auto* perm = static_cast<const int*>(f.Perm);
  std::pair<double, int> weakest{1.0, -1};
  const auto visit = [&](std::size_t k, double l_kk) {
    const int eq = perm ? perm[k] : static_cast<int>(k);
    const double a_kk = diagonal[eq];
    if (a_kk > 0 && l_kk * l_kk / a_kk < weakest.first) weakest = {l_kk * l_kk / a_kk, eq};
  };
  if (f.is_super) {
    const auto* super = static_cast<const int*>(f.super);
    const auto* pi = static_cast<const int*>(f.pi);
    const auto* px = static_cast<const int*>(f.px);
    for (std::size_t s = 0; s < f.nsuper; ++s) {
      const int rows = pi[s + 1] - pi[s];
      for (int j = 0; j < super[s + 1] - super[s]; ++j)
        visit(static_cast<std::size_t>(super[s] + j), x[px[s] + j + static_cast<std::ptrdiff_t>(j) * rows]);
    }
  } else {
    const auto* p = static_cast<const int*>(f.p);
    for (std::size_t k = 0; k < f.n; ++k) visit(k, x[p[k]]);
  }
  return weakest;
}

}  // namespace

struct CholmodSolver::Impl {
  cholmod_common common{};
  cholmod_factor* factor = nullptr;

  Impl() {
    cholmod_start(&common);
    common.supernodal = CHOLMOD_SUPERNODAL;
    common.final_ll = 1;
    common.print = 0;
    common.error_handler = nullptr;
  }
  ~Impl() {
    if (factor) cholmod_free_factor(&factor, &common);
    cholmod_finish(&common);
  }

  /// A view of `a` as a CHOLMOD matrix (no copy), lower triangle used.
  static cholmod_sparse view(const SparseMatrix& a) {
    cholmod_sparse s{};
    s.nrow = static_cast<size_t>(a.rows());
    s.ncol = static_cast<size_t>(a.cols());
    s.nzmax = static_cast<size_t>(a.nonZeros());
    s.p = const_cast<int*>(a.outerIndexPtr());
    s.i = const_cast<int*>(a.innerIndexPtr());
    s.x = const_cast<double*>(a.valuePtr());
    s.stype = -1;
    s.itype = CHOLMOD_INT;
    s.xtype = CHOLMOD_REAL;
    s.dtype = CHOLMOD_DOUBLE;
    s.sorted = 1;
    s.packed = 1;
    return s;
  }
};

CholmodSolver::CholmodSolver() : impl_(std::make_unique<Impl>()) {}
CholmodSolver::~CholmodSolver() = default;

void CholmodSolver::analyze(const SparseMatrix& a) {
  if (!a.isCompressed()) throw SolverError("CHOLMOD: matrix must be compressed");
  if (impl_->factor) cholmod_free_factor(&impl_->factor, &impl_->common);
  cholmod_sparse s = Impl::view(a);
  impl_->factor = cholmod_analyze(&s, &impl_->common);
  if (!impl_->factor) throw SolverError("CHOLMOD analysis failed (status " + std::to_string(impl_->common.status) + ")");
}

void CholmodSolver::factorize(const SparseMatrix& a, bool /*symmetric*/) {
  if (!impl_->factor) analyze(a);
  cholmod_sparse s = Impl::view(a);
  cholmod_factorize(&s, impl_->factor, &impl_->common);
  if (impl_->common.status == CHOLMOD_NOT_POSDEF || impl_->factor->minor < impl_->factor->n) {
    const auto k = static_cast<int>(impl_->factor->minor);
    const int* perm = static_cast<const int*>(impl_->factor->Perm);
    throw SolverError("the stiffness matrix is not positive definite", perm && k < static_cast<int>(a.cols()) ? perm[k] : -1);
  }
  if (impl_->common.status < CHOLMOD_OK)
    throw SolverError("CHOLMOD factorization failed (status " + std::to_string(impl_->common.status) + ")");
  if (!impl_->factor->is_ll) return;  // final_ll is set: not expected
  const auto [ratio, eq] = weakest_pivot(*impl_->factor, Eigen::VectorXd(a.diagonal()));
  if (ratio < kMinRelativePivot) {
    char text[96];
    std::snprintf(text, sizeof text, "the stiffness matrix is singular (CHOLMOD pivot %.3g of its diagonal term)", ratio);
    throw SolverError(text, eq);
  }
}

void CholmodSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  if (!impl_->factor) throw SolverError("CHOLMOD: solve before factorize");
  cholmod_dense rhs{};
  rhs.nrow = static_cast<size_t>(b.size());
  rhs.ncol = 1;
  rhs.nzmax = rhs.nrow;
  rhs.d = rhs.nrow;
  rhs.x = const_cast<double*>(b.data());
  rhs.xtype = CHOLMOD_REAL;
  rhs.dtype = CHOLMOD_DOUBLE;
  cholmod_dense* sol = cholmod_solve(CHOLMOD_A, impl_->factor, &rhs, &impl_->common);
  if (!sol) throw SolverError("CHOLMOD solve failed");
  x = Eigen::Map<const Eigen::VectorXd>(static_cast<const double*>(sol->x), b.size());
  cholmod_free_dense(&sol, &impl_->common);
}

}  // namespace tether
