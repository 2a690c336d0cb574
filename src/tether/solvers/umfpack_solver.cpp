#include "tether/solvers/umfpack_solver.hpp"

#include <umfpack.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "tether/core/error.hpp"

namespace tether {

namespace {
/// UMFPACK's reciprocal condition min|U_ii| / max|U_ii| (of the row-scaled
/// matrix) below which the matrix is singular: a rigid-body mode's zero pivot
/// comes out as round-off, measured up to 9e-15 on 40-spring chains (it was
/// 1e-15, which let such a chain through).
constexpr double kMinRcond = 1e-12;
}

UmfpackSolver::UmfpackSolver() {
  static_assert(UMFPACK_CONTROL <= 20, "control array too small");
  umfpack_dl_defaults(control_);
  control_[UMFPACK_IRSTEP] = 0;  // Newton iterates anyway; skip iterative refinement
}

UmfpackSolver::~UmfpackSolver() {
  free_numeric();
  free_symbolic();
}

void UmfpackSolver::free_numeric() {
  if (numeric_) umfpack_dl_free_numeric(&numeric_);
  numeric_ = nullptr;
}

void UmfpackSolver::free_symbolic() {
  if (symbolic_) umfpack_dl_free_symbolic(&symbolic_);
  symbolic_ = nullptr;
}

void UmfpackSolver::analyze(const SparseMatrix& a) {
  free_numeric();
  free_symbolic();
  if (!a.isCompressed()) throw SolverError("UMFPACK: matrix must be compressed");
  outer_.assign(a.outerIndexPtr(), a.outerIndexPtr() + a.cols() + 1);
  inner_.assign(a.innerIndexPtr(), a.innerIndexPtr() + a.nonZeros());
  control_[UMFPACK_ORDERING] = a.cols() > kMetisThreshold ? UMFPACK_ORDERING_METIS : UMFPACK_ORDERING_AMD;
  double info[UMFPACK_INFO];
  const auto status = umfpack_dl_symbolic(a.rows(), a.cols(), outer_.data(), inner_.data(), a.valuePtr(),
                                          &symbolic_, control_, info);
  if (status != UMFPACK_OK) throw SolverError("UMFPACK symbolic analysis failed (status " + std::to_string(status) + ")");
}

void UmfpackSolver::factorize(const SparseMatrix& a, bool /*symmetric*/) {
  if (!symbolic_) analyze(a);
  free_numeric();
  double info[UMFPACK_INFO];
  if (static_cast<std::int64_t>(outer_.size()) != a.cols() + 1 || outer_.back() != a.nonZeros()) analyze(a);
  const auto status = umfpack_dl_numeric(outer_.data(), inner_.data(), a.valuePtr(), symbolic_, &numeric_, control_,
                                         info);
  matrix_ = &a;
  if (status == UMFPACK_WARNING_singular_matrix || (status == UMFPACK_OK && info[UMFPACK_RCOND] < kMinRcond) ||
      !std::isfinite(info[UMFPACK_RCOND])) {
    const int eq = weakest_equation(a);
    char rcond[32];
    std::snprintf(rcond, sizeof rcond, "%.3g", info[UMFPACK_RCOND]);
    throw SolverError("the stiffness matrix is singular (UMFPACK reciprocal condition " + std::string(rcond) + ")", eq);
  }
  if (status != UMFPACK_OK) throw SolverError("UMFPACK numeric factorization failed (status " + std::to_string(status) + ")");
}

int UmfpackSolver::weakest_equation(const SparseMatrix& a) const {
  if (!numeric_) return -1;
  const int n = static_cast<int>(a.cols());
  SuiteSparse_long lnz = 0, unz = 0, nr = 0, nc = 0, nz_udiag = 0;
  if (umfpack_dl_get_lunz(&lnz, &unz, &nr, &nc, &nz_udiag, numeric_) != UMFPACK_OK) return -1;
  std::vector<double> udiag(n);
  std::vector<SuiteSparse_long> p(n), q(n);
  SuiteSparse_long do_recip = 0;
  std::vector<double> rs(n);
  if (umfpack_dl_get_numeric(nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, p.data(), q.data(),
                             udiag.data(), &do_recip, rs.data(), numeric_) != UMFPACK_OK)
    return -1;
  // Compare each pivot with the largest entry of its (scaled) column.
  double worst = std::numeric_limits<double>::infinity();
  int worst_k = -1;
  for (int k = 0; k < n; ++k) {
    const auto col = static_cast<int>(q[k]);
    double colmax = 0;
    for (SparseMatrix::InnerIterator it(a, col); it; ++it) colmax = std::max(colmax, std::abs(it.value()));
    const double ratio = colmax > 0 ? std::abs(udiag[k]) / colmax : 0.0;
    // rows were scaled by rs; the ratio is only used to rank, scaling is acceptable
    if (!(ratio >= worst)) {
      worst = ratio;
      worst_k = k;
    }
  }
  return worst_k >= 0 ? static_cast<int>(q[worst_k]) : -1;
}

void UmfpackSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  if (!numeric_ || !matrix_) throw SolverError("UMFPACK: solve before factorize");
  x.resize(b.size());
  double info[UMFPACK_INFO];
  const auto status = umfpack_dl_solve(UMFPACK_A, outer_.data(), inner_.data(), matrix_->valuePtr(), x.data(),
                                       b.data(), numeric_, control_, info);
  if (status != UMFPACK_OK) throw SolverError("UMFPACK solve failed (status " + std::to_string(status) + ")");
}

}  // namespace tether
