#include "tether/solvers/dense_dual_condensation.hpp"

#include <cmath>

// BLAS (Fortran interface): C ← α A B + β C.
extern "C" {
void dgemm_(const char* transa, const char* transb, const int* m, const int* n, const int* k, const double* alpha,
            const double* a, const int* lda, const double* b, const int* ldb, const double* beta, double* c,
            const int* ldc, std::size_t transa_len, std::size_t transb_len);
}

namespace tether {

namespace {
/// B counts as singular below this reciprocal condition number estimate
/// (as in DualCondensedSolver).
constexpr double kMinReciprocalCondition = 1e-14;
}  // namespace

double DenseDualCondensation::factorize(Eigen::MatrixXd s, const DualElimination& elimination, bool symmetric) {
  const Eigen::Index m = s.rows();
  // The previous system's matrices go first, so that they and the new ones
  // are never held together (a lower peak; nothing reads them once a new
  // factorization starts, whether it succeeds or not).
  b_ = DenseFactor();
  condensed_ = DenseFactor();
  w_ = Eigen::MatrixXd();
  s_kz_ = Eigen::MatrixXd();
  s_ = std::move(s);
  z_ = elimination.eliminated;
  apart_ = elimination.apart;
  for (auto& [i, d] : apart_) d = s_(i, i);  // that of s, which may be scaled
  std::vector<char> eliminated(static_cast<std::size_t>(m), 0);
  for (int i : z_) eliminated[static_cast<std::size_t>(i)] = 1;
  for (const auto& [i, d] : apart_) eliminated[static_cast<std::size_t>(i)] = 1;
  k_.clear();
  for (Eigen::Index i = 0; i < m; ++i)
    if (!eliminated[static_cast<std::size_t>(i)]) k_.push_back(static_cast<int>(i));
  const auto nz = static_cast<int>(z_.size()), nk = static_cast<int>(k_.size());
  Eigen::MatrixXd condensed = s_(k_, k_);
  if (nz > 0) {
    const double rcond = b_.factorize(s_(z_, z_), false);
    if (!(rcond >= kMinReciprocalCondition)) return 0.0;
    w_ = s_(z_, k_);
    b_.solve(w_);
    s_kz_ = s_(k_, z_);
    if (nk > 0) {
      const double minus_one = -1.0, one = 1.0;
      dgemm_("N", "N", &nk, &nk, &nz, &minus_one, s_kz_.data(), &nk, w_.data(), &nz, &one, condensed.data(), &nk, 1,
             1);
    }
  } else {
    w_.resize(0, nk);
    s_kz_.resize(nk, 0);
  }
  // Cholesky only where it can succeed: a symmetric system whose kept
  // diagonal is positive (no multiplier left without one).
  const bool try_cholesky = symmetric && (nk == 0 || condensed.diagonal().minCoeff() > 0);
  return condensed_.factorize(std::move(condensed), try_cholesky);
}

void DenseDualCondensation::solve_condensed(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  x.resize(b.size());
  Eigen::VectorXd b_z = b(z_);
  if (!z_.empty()) b_.solve(b_z);  // B⁻¹ b_Z
  Eigen::VectorXd x_k = b(k_);
  if (!z_.empty()) x_k.noalias() -= s_kz_ * b_z;
  condensed_.solve(x_k);
  x(k_) = x_k;
  if (!z_.empty()) x(z_) = b_z - w_ * x_k;
  for (const auto& [i, d] : apart_) x[i] = b[i] / d;
}

void DenseDualCondensation::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
  solve_condensed(b, x);
  const Eigen::VectorXd residual = b - s_ * x;
  Eigen::VectorXd correction;
  solve_condensed(residual, correction);
  x += correction;
}

}  // namespace tether
