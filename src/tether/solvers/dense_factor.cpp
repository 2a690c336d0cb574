#include "tether/solvers/dense_factor.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "tether/core/error.hpp"

// LAPACK (Fortran interface): LU with partial pivoting and Cholesky, their
// solves, and their reciprocal condition numbers in the 1-norm.
extern "C" {
void dgetrf_(const int* m, const int* n, double* a, const int* lda, int* ipiv, int* info);
void dgetrs_(const char* trans, const int* n, const int* nrhs, const double* a, const int* lda, const int* ipiv,
             double* b, const int* ldb, int* info, std::size_t trans_len);
void dgecon_(const char* norm, const int* n, const double* a, const int* lda, const double* anorm, double* rcond,
             double* work, int* iwork, int* info, std::size_t norm_len);
void dpotrf_(const char* uplo, const int* n, double* a, const int* lda, int* info, std::size_t uplo_len);
void dpotrs_(const char* uplo, const int* n, const int* nrhs, const double* a, const int* lda, double* b,
             const int* ldb, int* info, std::size_t uplo_len);
void dpocon_(const char* uplo, const int* n, const double* a, const int* lda, const double* anorm, double* rcond,
             double* work, int* iwork, int* info, std::size_t uplo_len);
}

namespace tether {

namespace {
/// A diagonal below this fraction of the largest counts as absent for the scaling.
constexpr double kNegligibleDiagonal = 1e-14;
}  // namespace

Eigen::VectorXd equilibration(const Eigen::MatrixXd& a) {
  const Eigen::Index m = a.rows();
  Eigen::VectorXd scale(m);
  double largest_diagonal = 0;
  for (Eigen::Index k = 0; k < m; ++k)
    if (std::isfinite(a(k, k))) largest_diagonal = std::max(largest_diagonal, std::abs(a(k, k)));
  std::vector<Eigen::Index> without_diagonal;
  for (Eigen::Index k = 0; k < m; ++k) {
    const double d = std::abs(a(k, k));
    if (d > kNegligibleDiagonal * largest_diagonal && std::isfinite(d)) {
      scale[k] = 1.0 / std::sqrt(d);
    } else {
      scale[k] = 0.0;
      without_diagonal.push_back(k);
    }
  }
  for (Eigen::Index k : without_diagonal) {
    const double row = (a.row(k).cwiseAbs().transpose().cwiseProduct(scale)).maxCoeff();
    scale[k] = row > 0 && std::isfinite(row) ? 1.0 / row : 1.0;
  }
  return scale;
}

double DenseFactor::factorize(Eigen::MatrixXd a, bool try_cholesky, bool scale) {
  const int size = static_cast<int>(a.rows());
  factors_ = std::move(a);
  if (scale) {
    scale_ = equilibration(factors_);
    factors_.array().colwise() *= scale_.array();  // D A D: row i times d_i, then column j times d_j
    factors_.array().rowwise() *= scale_.transpose().array();
  } else {
    scale_ = Eigen::VectorXd::Ones(size);
  }
  cholesky_ = false;
  if (size == 0) return 1.0;  // nothing to factorize (LAPACK refuses a leading dimension 0)
  std::vector<double> work(4 * static_cast<std::size_t>(size));
  std::vector<int> iwork(static_cast<std::size_t>(size));
  int info = 0;
  double rcond = 0;
  if (try_cholesky) {
    // The 1-norm of the symmetric matrix from its lower triangle; dpotrf
    // overwrites that triangle and the diagonal, which are restored from
    // the (untouched) upper triangle and a copy of the diagonal should it fail.
    Eigen::VectorXd column_sums = Eigen::VectorXd::Zero(size);
    for (Eigen::Index j = 0; j < size; ++j)
      for (Eigen::Index i = j; i < size; ++i) {
        const double v = std::abs(factors_(i, j));
        column_sums[j] += v;
        if (i != j) column_sums[i] += v;
      }
    const double norm1 = column_sums.maxCoeff();
    const Eigen::VectorXd diagonal = factors_.diagonal();
    dpotrf_("L", &size, factors_.data(), &size, &info, 1);
    if (info == 0 && std::isfinite(norm1)) {
      dpocon_("L", &size, factors_.data(), &size, &norm1, &rcond, work.data(), iwork.data(), &info, 1);
      cholesky_ = true;
      return info == 0 ? rcond : 0.0;
    }
    factors_.diagonal() = diagonal;
    factors_.triangularView<Eigen::StrictlyLower>() = factors_.transpose();
  }
  const double norm1 = factors_.cwiseAbs().colwise().sum().maxCoeff();
  pivots_.resize(static_cast<std::size_t>(size));
  info = 0;
  dgetrf_(&size, &size, factors_.data(), &size, pivots_.data(), &info);
  // info > 0: an exactly zero pivot. Otherwise the condition estimate decides.
  if (info == 0 && std::isfinite(norm1))
    dgecon_("1", &size, factors_.data(), &size, &norm1, &rcond, work.data(), iwork.data(), &info, 1);
  return info == 0 ? rcond : 0.0;
}

void DenseFactor::solve(Eigen::VectorXd& b) const {
  const int size = static_cast<int>(factors_.rows()), one = 1;
  if (size == 0) return;
  b = scale_.asDiagonal() * b;
  int info = 0;
  if (cholesky_)
    dpotrs_("L", &size, &one, factors_.data(), &size, b.data(), &size, &info, 1);
  else
    dgetrs_("N", &size, &one, factors_.data(), &size, pivots_.data(), b.data(), &size, &info, 1);
  if (info != 0) throw SolverError("dense factor: LAPACK solve failed (info " + std::to_string(info) + ")");
  b = scale_.asDiagonal() * b;
}

void DenseFactor::solve(Eigen::MatrixXd& x) const {
  x = scale_.asDiagonal() * x;
  const int size = static_cast<int>(factors_.rows()), columns = static_cast<int>(x.cols());
  int info = 0;
  if (columns > 0 && size > 0) {
    if (cholesky_)
      dpotrs_("L", &size, &columns, factors_.data(), &size, x.data(), &size, &info, 1);
    else
      dgetrs_("N", &size, &columns, factors_.data(), &size, pivots_.data(), x.data(), &size, &info, 1);
  }
  if (info != 0) throw SolverError("dense factor: LAPACK solve failed (info " + std::to_string(info) + ")");
  x = scale_.asDiagonal() * x;
}

}  // namespace tether
