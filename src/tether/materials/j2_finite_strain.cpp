// J2Plasticity::update_finite_strain: multiplicative von Mises plasticity
// F = Fe Fp with a Hencky (logarithmic) elastic range and the exponential
// map, so the return in principal logarithmic strains is the small-strain
// radial return (Simo 1992; de Souza Neto, Peric and Owen, Computational
// Methods for Plasticity, chapter 14). See docs/theory/plasticity.md.
#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <cmath>

#include "tether/core/error.hpp"
#include "tether/materials/j2_plasticity.hpp"

namespace tether {

namespace {

constexpr int kPair[3][2] = {{0, 1}, {1, 2}, {0, 2}};  // Voigt shear 12, 23, 13

/// Symmetric tensor of a Voigt strain (engineering shear).
Eigen::Matrix3d from_voigt_strain(const Vec6& e) {
  Eigen::Matrix3d m;
  m << e(0), 0.5 * e(3), 0.5 * e(5),  //
      0.5 * e(3), e(1), 0.5 * e(4),   //
      0.5 * e(5), 0.5 * e(4), e(2);
  return m;
}

/// Voigt matrix (engineering shear in and out) of X -> A X A^T on symmetric X.
Mat6 congruence(const Eigen::Matrix3d& A) {
  Mat6 R;
  for (int J = 0; J < 6; ++J) {
    Vec6 unit = Vec6::Zero();
    unit(J) = 1;
    R.col(J) = to_voigt_strain(A * from_voigt_strain(unit) * A.transpose());
  }
  return R;
}

/// (ln a - ln b) / (a - b) for a, b > 0, and 1/a when they are equal.
double log_divided_difference(double a, double b) {
  const double x = (a - b) / b;
  if (std::abs(x) < 1e-8) return (1 - x / 2 + x * x / 3) / b;
  return std::log1p(x) / (b * x);
}

}  // namespace

void J2Plasticity::update_finite_strain(Eigen::Matrix3d& C, bool plane_stress, std::span<const double> old_state,
                                        std::span<double> new_state, const PointContext&,
                                        MaterialResponse& out) const {
  if (plane_stress)
    throw ModelError("*PLASTIC under NLGEOM is not available for plane stress (CPS elements) in tether: use plane "
                     "strain (CPE) or axisymmetric (CAX) elements, or run the step without NLGEOM");
  if (hardening_ != Hardening::Isotropic)
    throw ModelError("*PLASTIC, HARDENING=KINEMATIC or COMBINED under NLGEOM is not available in tether (the logarithmic "
                     "return needs the back stress coaxial with the elastic strain): use isotropic hardening, "
                     "or run the step without NLGEOM");
  // State: E_p = (I - Cp^-1) / 2 (Voigt, engineering shear; the plastic strain
  // at small strain, as CalculiX reports PE under NLGEOM), unused (6), PEEQ.
  const Eigen::Matrix3d Cp_inv =
      Eigen::Matrix3d::Identity() - 2 * from_voigt_strain(Eigen::Map<const Vec6>(old_state.data()));
  // Any F with F^T F = C gives the same S and dS/dE (isotropy): the Cholesky factor.
  const Eigen::LLT<Eigen::Matrix3d> llt(C);
  if (llt.info() != Eigen::Success) throw ModelError("the right Cauchy-Green tensor is not positive definite");
  const Eigen::Matrix3d F = llt.matrixL().transpose();
  const Eigen::Matrix3d F_inv = F.inverse();
  const Eigen::Matrix3d be_trial = F * Cp_inv * F.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(0.5 * (be_trial + be_trial.transpose()));
  const Eigen::Vector3d lambda = eig.eigenvalues();  // squared elastic trial stretches
  const Eigen::Matrix3d& Q = eig.eigenvectors();
  if (!(lambda.minCoeff() > 0)) throw ModelError("the elastic trial left Cauchy-Green tensor is not positive definite");

  // The small-strain return on the principal logarithmic trial strains: Kirchhoff stress, tangent d tau / d eps.
  Vec6 eps_trial = Vec6::Zero();
  for (int a = 0; a < 3; ++a) eps_trial(a) = 0.5 * std::log(lambda(a));
  double principal_old[kStateSize] = {};
  principal_old[12] = old_state[12];
  double principal_new[kStateSize] = {};
  principal_new[12] = old_state[12];  // the elastic branch writes nothing
  MaterialResponse r;
  general_return(eps_trial, principal_old, principal_new, r);

  // Exponential map: be = Q exp(2 (eps_trial - d eps_p)) Q^T; Cp^-1 = F^-1 be F^-T.
  Eigen::Vector3d be_principal;
  for (int a = 0; a < 3; ++a) be_principal(a) = std::exp(2 * (eps_trial(a) - principal_new[a]));
  const Eigen::Matrix3d be = Q * be_principal.asDiagonal() * Q.transpose();
  const Eigen::Matrix3d Cp_inv_new = F_inv * be * F_inv.transpose();
  Eigen::Map<Vec6>(new_state.data()) = to_voigt_strain(0.5 * (Eigen::Matrix3d::Identity() - Cp_inv_new));
  Eigen::Map<Vec6>(new_state.data() + 6).setZero();
  new_state[12] = principal_new[12];

  // S = F^-1 tau F^-T = A^T tau_hat A with A = Q^T F^-T, tau_hat = diag(tau_a).
  const Eigen::Matrix3d A = Q.transpose() * F_inv.transpose();
  const Eigen::Vector3d tau = r.stress.head<3>();
  const Eigen::Matrix3d S = A.transpose() * tau.asDiagonal() * A;
  out.stress << S(0, 0), S(1, 1), S(2, 2), S(0, 1), S(1, 2), S(0, 2);

  // Tangent: with d = F^-T dE F^-1 and d_hat = A dE A^T (principal axes),
  // dS = A^T (D_hat d eps_hat - d_hat tau_hat - tau_hat d_hat) A, where
  // d eps_hat = M d_hat: 1 on the normal components, theta_ab (lambda_a + lambda_b) / 2
  // on the shear ones (the derivative of the logarithm, Daleckii-Krein).
  Vec6 m = Vec6::Ones(), t;
  for (int a = 0; a < 3; ++a) t(a) = 2 * tau(a);
  for (int k = 0; k < 3; ++k) {
    const int a = kPair[k][0], b = kPair[k][1];
    m(3 + k) = 0.5 * log_divided_difference(lambda(a), lambda(b)) * (lambda(a) + lambda(b));
    t(3 + k) = 0.5 * (tau(a) + tau(b));
  }
  Mat6 c_hat = r.tangent * m.asDiagonal();
  c_hat.diagonal() -= t;
  const Mat6 R = congruence(A);
  out.tangent = R.transpose() * c_hat * R;
  out.elastic_energy = r.elastic_energy;
  out.dissipation = r.dissipation;
}

}  // namespace tether
