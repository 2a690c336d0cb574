#include "tether/solvers/umfpack_solver.hpp"

#include <umfpack.h>

#include <cmath>
#include <limits>
#include <vector>

#include "tether/core/error.hpp"

namespace tether {

namespace {
constexpr double kMinRcond = 1e-15;
}

UmfpackSolver::UmfpackSolver() {
  static_assert(UMFPACK_CONTROL <= 20, "control array too small");
  umfpack_di_defaults(control_);
  control_[UMFPACK_IRSTEP] = 0;  // Newton iterates anyway; skip iterative refinement
}

UmfpackSolver::~UmfpackSolver() {
  free_numeric();
  free_symbolic();
}

void UmfpackSolver::free_numeric() {
  if (numeric_) umfpack_di_free_numeric(&numeric_);
  numeric_ = nullptr;
}

void UmfpackSolver::free_symbolic() {
  if (symbolic_) umfpack_di_free_symbolic(&symbolic_);
  symbolic_ = nullptr;
}

void UmfpackSolver::analyze(const SparseMatrix& a) {
  free_numeric();
  free_symbolic();
  if (!a.isCompressed()) throw SolverError("UMFPACK: matrix must be compressed");
  double info[UMFPACK_INFO];
  const int status = umfpack_di_symbolic(static_cast<int>(a.rows()), static_cast<int>(a.cols()),
                                         a.outerIndexPtr(), a.innerIndexPtr(), a.valuePtr(),
                                         &symbolic_, control_, info);
  if (status != UMFPACK_OK) throw SolverError("UMFPACK symbolic analysis failed (status " + std::to_string(status) + ")");
}

void UmfpackSolver::factorize(const SparseMatrix& a, bool /*symmetric*/) {
  if (!symbolic_) analyze(a);
  free_numeric();
  double info[UMFPACK_INFO];
  const int status = umfpack_di_numeric(a.outerIndexPtr(), a.innerIndexPtr(), a.valuePtr(), symbolic_,
                                        &numeric_, control_, info);
  matrix_ = &a;
  if (status == UMFPACK_WARNING_singular_matrix || (status == UMFPACK_OK && info[UMFPACK_RCOND] < kMinRcond) ||
      !std::isfinite(info[UMFPACK_RCOND])) {
    const int eq = weakest_equation(a);
    throw SolverError("the stiffness matrix is singular (UMFPACK reciprocal condition " +
                          std::to_string(info[UMFPACK_RCOND]) + ")",
                      eq);
  }
  if (status != UMFPACK_OK) throw SolverError("UMFPACK numeric factorization failed (status " + std::to_string(status) + ")");
}

int UmfpackSolver::weakest_equation(const SparseMatrix& a) const {
  if (!numeric_) return -1;
  const int n = static_cast<int>(a.cols());
  int lnz = 0, unz = 0, nr = 0, nc = 0, nz_udiag = 0;
  if (umfpack_di_get_lunz(&lnz, &unz, &nr, &nc, &nz_udiag, numeric_) != UMFPACK_OK) return -1;
  std::vector<double> udiag(n);
  std::vector<int> p(n), q(n);
  int do_recip = 0;
  std::vector<double> rs(n);
  if (umfpack_di_get_numeric(nullptr, nullptr, nullptr, nullptr, nullptr, nullptr, p.data(), q.data(),
                             udiag.data(), &do_recip, rs.data(), numeric_) != UMFPACK_OK)
    return -1;
  // Compare each pivot with the largest entry of its (scaled) column.
  double worst = std::numeric_limits<double>::infinity();
  int worst_k = -1;
  for (int k = 0; k < n; ++k) {
    const int col = q[k];
    double colmax = 0;
    for (SparseMatrix::InnerIterator it(a, col); it; ++it) colmax = std::max(colmax, std::abs(it.value()));
    const double ratio = colmax > 0 ? std::abs(udiag[k]) / colmax : 0.0;
    // rows were scaled by rs; the ratio is only used to rank, scaling is acceptable
    if (!(ratio >= worst)) {
      worst = ratio;
      worst_k = k;
    }
  }
  return worst_k >= 0 ? q[worst_k] : -1;
}

void UmfpackSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  if (!numeric_ || !matrix_) throw SolverError("UMFPACK: solve before factorize");
  x.resize(b.size());
  double info[UMFPACK_INFO];
  const int status = umfpack_di_solve(UMFPACK_A, matrix_->outerIndexPtr(), matrix_->innerIndexPtr(),
                                      matrix_->valuePtr(), x.data(), b.data(), numeric_, control_, info);
  if (status != UMFPACK_OK) throw SolverError("UMFPACK solve failed (status " + std::to_string(status) + ")");
}

}  // namespace tether
