// J2Plasticity::update_finite_strain: multiplicative von Mises plasticity
// F = Fe Fp with a Hencky (logarithmic) elastic range and the exponential
// map, so the return on the logarithmic elastic trial strain is the
// small-strain radial return (Simo 1992; de Souza Neto, Peric and Owen,
// Computational Methods for Plasticity, chapter 14; Eterovic and Bathe 1990
// for the back stress). Plane stress: a local Newton iteration on C33.
// See docs/theory/plasticity.md.
#include <Eigen/Eigenvalues>
#include <cmath>

#include "tether/core/error.hpp"
#include "tether/materials/j2_plasticity.hpp"
#include "tether/materials/plane_stress.hpp"

namespace tether {

namespace {

/// Symmetric tensor of a Voigt strain (engineering shear).
Eigen::Matrix3d from_voigt_strain(const Vec6& e) {
  Eigen::Matrix3d m;
  m << e(0), 0.5 * e(3), 0.5 * e(5),  //
      0.5 * e(3), e(1), 0.5 * e(4),   //
      0.5 * e(5), 0.5 * e(4), e(2);
  return m;
}

Vec6 to_voigt_stress(const Eigen::Matrix3d& s) {
  Vec6 v;
  v << s(0, 0), s(1, 1), s(2, 2), s(0, 1), s(1, 2), s(0, 2);
  return v;
}

/// (ln a - ln b) / (a - b) for a, b > 0, and 1/a when they are equal.
double log_divided_difference(double a, double b) {
  const double x = (a - b) / b;
  if (std::abs(x) < 1e-8) return (1 - x / 2 + x * x / 3) / b;
  return std::log1p(x) / (b * x);
}

/// A symmetric positive definite tensor on its principal axes, X = Q diag(x) Q^T.
struct Spectral {
  Eigen::Matrix3d Q;
  Eigen::Vector3d x;
  explicit Spectral(const Eigen::Matrix3d& X) {
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(0.5 * (X + X.transpose()));
    Q = eig.eigenvectors();
    x = eig.eigenvalues();
  }
  /// Q diag(f(x)) Q^T.
  template <class Fn>
  [[nodiscard]] Eigen::Matrix3d apply(Fn f) const {
    Eigen::Vector3d y;
    for (int a = 0; a < 3; ++a) y(a) = f(x(a));
    return Q * y.asDiagonal() * Q.transpose();
  }
  /// The derivative of X -> Q diag(f(x)) Q^T in the direction dX, given the
  /// divided differences g(a, b) = (f(xa) - f(xb)) / (xa - xb) (f'(xa) when equal).
  template <class Divided>
  [[nodiscard]] Eigen::Matrix3d derivative(const Eigen::Matrix3d& dX, Divided g) const {
    Eigen::Matrix3d d = Q.transpose() * dX * Q;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) d(a, b) *= g(x(a), x(b));
    return Q * d * Q.transpose();
  }
};

}  // namespace

void J2Plasticity::update_finite_strain(Eigen::Matrix3d& C, bool plane_stress, std::span<const double> old_state,
                                        std::span<double> new_state, const PointContext& where,
                                        MaterialResponse& out) const {
  const bool loading = loading_tangent_applies(where);
  if (!plane_stress) {
    finite_strain_return(C, old_state, new_state, loading, where.temperature, out);
    return;
  }
  if (C(0, 2) != 0 || C(1, 2) != 0) throw ModelError("plane stress needs C13 = C23 = 0");
  // Newton on E33 = (C33 - 1)/2 with dS33/dE33 = D(2,2). Once the step is
  // below 1e-10 of E33 it is taken and the point evaluated once more, which
  // leaves S33 at round-off (quadratic convergence).
  bool last = false;
  for (int it = 0; it < 50; ++it) {
    finite_strain_return(C, old_state, new_state, loading, where.temperature, out);
    if (last) {
      out.thickness_sensitivity = thickness_sensitivity(out.tangent);
      condense_out_of_plane(out.tangent);
      return;
    }
    const double d33 = out.tangent(2, 2);
    if (!(d33 > 0) || !std::isfinite(out.stress(2))) break;
    double step = -out.stress(2) / d33;
    last = std::abs(step) <= 1e-10 * (1 + std::abs(0.5 * (C(2, 2) - 1)));
    while (C(2, 2) + 2 * step <= 0.01 * C(2, 2)) step *= 0.5;
    C(2, 2) += 2 * step;
  }
  throw ModelError("plane stress *PLASTIC under NLGEOM: the thickness stretch iteration did not converge");
}

void J2Plasticity::finite_strain_return(const Eigen::Matrix3d& C, std::span<const double> old_state,
                                        std::span<double> new_state, bool on_surface_loading, double T,
                                        MaterialResponse& out) const {
  // State: E_p = (I - Cp^-1) / 2 (Voigt, engineering shear; as CalculiX reports
  // PE under NLGEOM), the back stress B on the rotated axes R^T (.) R of F = R U, PEEQ.
  const Eigen::Matrix3d Cp_inv =
      Eigen::Matrix3d::Identity() - 2 * from_voigt_strain(Eigen::Map<const Vec6>(old_state.data()));
  const Spectral c(C);
  if (!(c.x.minCoeff() > 0)) throw ModelError("the right Cauchy-Green tensor is not positive definite");
  const Eigen::Matrix3d U = c.apply([](double v) { return std::sqrt(v); });
  const Eigen::Matrix3d U_inv = c.apply([](double v) { return 1 / std::sqrt(v); });
  const Eigen::Matrix3d be_trial = U * Cp_inv * U;  // R^T be* R
  const Spectral be(be_trial);
  if (!(be.x.minCoeff() > 0)) throw ModelError("the elastic trial left Cauchy-Green tensor is not positive definite");

  // The small-strain return at the logarithmic elastic trial strain, from no
  // plastic strain and the committed back stress: rotated Kirchhoff stress, d tau / d eps.
  const Eigen::Matrix3d ee_trial = be.apply([](double v) { return 0.5 * std::log(v); });
  Vec6 eps = to_voigt_strain(ee_trial);
  double start[kStateSize] = {}, end[kStateSize] = {};
  for (int i = 6; i < kStateSize; ++i) start[i] = end[i] = old_state[i];  // the elastic branch writes nothing
  MaterialResponse r;
  general_return(eps, start, end, on_surface_loading, T, r);

  // be = exp(2 (ee_trial - d eps_p)), the exponential map (exact when the flow
  // is coaxial with be*, always so without back stress); Cp^-1 = U^-1 be U^-1.
  const Eigen::Matrix3d ee = ee_trial - from_voigt_strain(Eigen::Map<const Vec6>(end));
  const Eigen::Matrix3d be_new = Spectral(ee).apply([](double v) { return std::exp(2 * v); });
  Eigen::Map<Vec6>(new_state.data()) = to_voigt_strain(0.5 * (Eigen::Matrix3d::Identity() - U_inv * be_new * U_inv));
  for (int i = 6; i < kStateSize; ++i) new_state[i] = end[i];

  const Eigen::Matrix3d tau = from_voigt_stress(r.stress);
  out.stress = to_voigt_stress(U_inv * tau * U_inv);  // S = F^-1 tau F^-T = U^-1 (R^T tau R) U^-1
  out.elastic_energy = r.elastic_energy;
  out.dissipation = r.dissipation;

  // Tangent dS/dE, column by column (dC = 2 dE): dU from the square root on
  // the axes of C, d ee_trial from the logarithm on the axes of be*
  // (Daleckii-Krein), d tau = D_alg d ee_trial, dS = d(U^-1 tau U^-1).
  const auto sqrt_divided = [](double a, double b) { return 1 / (std::sqrt(a) + std::sqrt(b)); };
  const auto half_log_divided = [](double a, double b) { return 0.5 * log_divided_difference(a, b); };
  for (int j = 0; j < 6; ++j) {
    Vec6 unit = Vec6::Zero();
    unit(j) = 1;
    const Eigen::Matrix3d dU = c.derivative(2 * from_voigt_strain(unit), sqrt_divided);
    const Eigen::Matrix3d dU_inv = -U_inv * dU * U_inv;
    const Eigen::Matrix3d dbe = dU * Cp_inv * U + U * Cp_inv * dU;
    const Eigen::Matrix3d dee = be.derivative(dbe, half_log_divided);
    const Eigen::Matrix3d dtau = from_voigt_stress(r.tangent * to_voigt_strain(dee));
    const Eigen::Matrix3d dS = dU_inv * tau * U_inv + U_inv * tau * dU_inv + U_inv * dtau * U_inv;
    out.tangent.col(j) = to_voigt_stress(dS);
  }
}

}  // namespace tether
