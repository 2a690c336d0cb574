#include "tether/materials/j2_plasticity.hpp"

#include <Eigen/LU>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <stdexcept>

#include "tether/core/error.hpp"

namespace tether {

namespace {

const double kSqrt23 = std::sqrt(2.0 / 3.0);
const double kSqrt32 = std::sqrt(1.5);

/// A trial state is plastic when the yield function exceeds this fraction of the yield radius.
constexpr double kYieldTolerance = 1e-12;

/// A trial state this close below the yield surface (as a fraction of the
/// yield radius) is on it: its stress is the elastic one, but its tangent is
/// the plastic branch's at a zero plastic increment (the continuum
/// elastoplastic tangent), the one-sided derivative for further loading. A
/// point that yielded in the last increment sits here at the first iteration
/// of the next (its strain unchanged, the return having left it on the
/// surface to round-off, about 1e-14, well inside this band), so Newton's
/// first correction is no longer computed with
/// the elastic stiffness of points that go on yielding (when
/// J2Plasticity::loading_tangent_applies).
constexpr double kOnSurfaceTolerance = 1e-8;

/// Tensor norm of a Voigt vector holding tensor components (shear counted twice).
double tensor_norm(const Vec6& t) {
  return std::sqrt(t.head<3>().squaredNorm() + 2 * t.tail<3>().squaredNorm());
}

/// Root of the decreasing function g on [0, inf) with g(0) > 0: Newton's
/// method safeguarded by bisection (g may have kinks at table points).
/// `eval(x, slope)` returns g(x) and sets slope = g'(x); `scale` is a typical
/// step; |g| <= tolerance ends the iteration.
template <class G>
double solve_plastic_increment(G&& eval, double scale, double tolerance) {
  double lo = 0, hi = std::numeric_limits<double>::infinity(), x = 0;
  for (int it = 0; it < 200; ++it) {
    double slope = 0;
    const double g = eval(x, slope);
    if (!std::isfinite(g)) break;
    if (std::abs(g) <= tolerance) return x;
    (g > 0 ? lo : hi) = x;
    double next = slope < 0 ? x - g / slope : std::numeric_limits<double>::quiet_NaN();
    if (!(next > lo && next < hi)) next = std::isfinite(hi) ? 0.5 * (lo + hi) : std::max(2 * x, scale);
    if (std::isfinite(hi) && hi - lo <= 4 * std::numeric_limits<double>::epsilon() * hi) return next;
    x = next;
  }
  throw ModelError("von Mises return map: the plastic strain increment did not converge");
}

/// Plane-stress elasticity over (11, 22, 12) with engineering shear.
Eigen::Matrix3d plane_stress_elasticity(double E, double nu) {
  Eigen::Matrix3d C;
  C << 1, nu, 0, nu, 1, 0, 0, 0, (1 - nu) / 2;
  return C * (E / (1 - nu * nu));
}

/// The plane-stress projection P: eta^T P eta = |dev eta|^2 for an in-plane
/// stress eta = (11, 22, 12) with eta_33 = 0, and P eta = (dev 11, dev 22, 2 dev 12).
Eigen::Matrix3d plane_stress_projection() {
  Eigen::Matrix3d P;
  P << 2, -1, 0, -1, 2, 0, 0, 0, 6;
  return P / 3;
}

constexpr int kPlane[3] = {0, 1, 3};  // Voigt indices of the in-plane components

}  // namespace

struct J2Plasticity::Hardened {
  double K, dK;  ///< yield radius (uniaxial) and dK/dp
  double H, dH;  ///< uniaxial back stress function and dH/dp
};

J2Plasticity::J2Plasticity(double young, double poisson, HardeningTable curve, Hardening hardening,
                           std::optional<HardeningTable> cyclic)
    : young_(young),
      poisson_(poisson),
      elastic_(young, poisson),
      curve_(std::move(curve)),
      hardening_(hardening),
      cyclic_(std::move(cyclic)) {
  if (hardening_ == Hardening::Combined && !cyclic_)
    throw std::invalid_argument("combined hardening needs the cyclic hardening table");
}

J2Plasticity::Hardened J2Plasticity::hardened(double p, double T) const {
  if (hardening_ == Hardening::Isotropic) return {curve_.value(p, T), curve_.slope(p, T), 0, 0};
  const double H = curve_.value(p, T) - curve_.initial(T), dH = curve_.slope(p, T);
  if (hardening_ == Hardening::Combined) return {cyclic_->value(p, T), cyclic_->slope(p, T), H, dH};
  return {curve_.initial(T), 0, H, dH};
}

double J2Plasticity::plastic_work(double p_old, double dp, double alpha_dot_n, double T) const {
  // sigma : d eps_p along the return, d eps_p = sqrt(3/2) dp n: the relative
  // stress gives K dp, the back stress (alpha_n + sqrt(2/3) (H - H_n) n) : n
  // sqrt(3/2) dp; summed, (K + H)(p) dp - H_n dp + sqrt(3/2) alpha_n : n dp,
  // with K + H = y for isotropic and kinematic hardening, c + y - y(0) for combined.
  const double p_new = p_old + dp;
  double k_plus_h = curve_.integral(p_old, p_new, T);
  if (hardening_ == Hardening::Combined) k_plus_h += cyclic_->integral(p_old, p_new, T) - curve_.initial(T) * dp;
  return k_plus_h - hardened(p_old, T).H * dp + kSqrt32 * alpha_dot_n * dp;
}

double J2Plasticity::yield_radius(double p, double T) const { return hardened(p, T).K; }
double J2Plasticity::kinematic(double p, double T) const { return hardened(p, T).H; }

Vec6 J2Plasticity::plastic_strain(std::span<const double> state) const {
  return Eigen::Map<const Vec6>(state.data());
}

std::string J2Plasticity::describe() const {
  const char* kind = hardening_ == Hardening::Isotropic   ? "isotropic"
                     : hardening_ == Hardening::Kinematic ? "kinematic"
                                                          : "combined";
  if (curve_.depends_on_temperature())
    return fmt::format("von Mises plasticity (E={:g}, nu={:g}, {} hardening, {} table rows at {} temperatures)",
                       young_, poisson_, kind, curve_.n_points(), curve_.n_temperatures());
  return fmt::format("von Mises plasticity (E={:g}, nu={:g}, yield stress {:g}, {} hardening, {} table rows)",
                     young_, poisson_, yield_radius(0), kind, curve_.n_points());
}

void J2Plasticity::update_small_strain(Vec6& eps, bool plane_stress, std::span<const double> old_state,
                                       std::span<double> new_state, const PointContext& where,
                                       MaterialResponse& out) const {
  std::copy(old_state.begin(), old_state.end(), new_state.begin());
  if (plane_stress)
    plane_stress_return(eps, old_state, new_state, loading_tangent_applies(where), where.temperature, out);
  else
    general_return(eps, old_state, new_state, loading_tangent_applies(where), where.temperature, out);
}

void J2Plasticity::general_return(Vec6& eps, std::span<const double> old_state, std::span<double> new_state,
                                  bool on_surface_loading, double T, MaterialResponse& out) const {
  const double mu = elastic_.mu(), kappa = elastic_.lambda() + 2 * mu / 3;
  const Eigen::Map<const Vec6> ep_old(old_state.data()), alpha_old(old_state.data() + 6);
  const double p_old = old_state[kPeeq];
  const Vec6 ee_trial = eps - ep_old;
  const double volumetric = ee_trial.head<3>().sum();
  Vec6 s_trial;  // deviatoric trial stress, tensor components
  for (int i = 0; i < 3; ++i) s_trial(i) = 2 * mu * (ee_trial(i) - volumetric / 3);
  for (int i = 3; i < 6; ++i) s_trial(i) = mu * ee_trial(i);
  const Vec6 xi_trial = s_trial - alpha_old;
  const double xi_norm = tensor_norm(xi_trial);
  const double q_trial = kSqrt32 * xi_norm;  // von Mises of the relative trial stress
  const Hardened h_old = hardened(p_old, T);
  Vec6 pressure_part = Vec6::Zero();
  pressure_part.head<3>().setConstant(kappa * volumetric);

  const bool inside = q_trial - h_old.K <= kYieldTolerance * h_old.K;
  if (inside && (!on_surface_loading || q_trial - h_old.K < -kOnSurfaceTolerance * h_old.K)) {  // elastic
    out.stress = s_trial + pressure_part;
    out.tangent = isotropic_stiffness(elastic_.lambda(), mu);
    out.elastic_energy = 0.5 * out.stress.dot(ee_trial);
    out.dissipation = 0;
    new_state[kYielding] = 0;
    return;
  }
  // On the yield surface (inside): no plastic increment, the loading tangent.
  const double dp = inside ? 0.0
                           : solve_plastic_increment(
                                 [&](double x, double& slope) {
                                   const Hardened h = hardened(p_old + x, T);
                                   slope = -3 * mu - h.dK - h.dH;
                                   return q_trial - 3 * mu * x - (h.H - h_old.H) - h.K;
                                 },
                                 (q_trial - h_old.K) / (3 * mu), 1e-14 * q_trial);
  const Hardened h = hardened(p_old + dp, T);
  const Vec6 n = xi_trial / xi_norm;
  Vec6 n_strain = n;  // engineering shear
  n_strain.tail<3>() *= 2;
  Eigen::Map<Vec6> ep(new_state.data()), alpha(new_state.data() + 6);
  const Vec6 dep = kSqrt32 * dp * n_strain;
  ep = ep_old + dep;
  alpha = alpha_old + kSqrt23 * (h.H - h_old.H) * n;
  new_state[kPeeq] = p_old + dp;
  new_state[kYielding] = dp > 0 ? 1 : 0;
  out.stress = s_trial - 2 * mu * kSqrt32 * dp * n + pressure_part;

  const double theta = 1 - 3 * mu * dp / q_trial;
  const double theta_bar = 1 / (1 + (h.dK + h.dH) / (3 * mu)) - (1 - theta);
  Mat6 dev = Mat6::Zero();
  dev.topLeftCorner<3, 3>().setConstant(-1.0 / 3);
  for (int i = 0; i < 3; ++i) dev(i, i) += 1, dev(3 + i, 3 + i) = 0.5;
  out.tangent = 2 * mu * theta * dev - 2 * mu * theta_bar * n * n.transpose();
  out.tangent.topLeftCorner<3, 3>().array() += kappa;
  out.elastic_energy = 0.5 * out.stress.dot(eps - ep);
  out.dissipation = plastic_work(p_old, dp, alpha_old.dot(n_strain), T);
}

void J2Plasticity::plane_stress_return(Vec6& eps, std::span<const double> old_state, std::span<double> new_state,
                                       bool on_surface_loading, double T, MaterialResponse& out) const {
  const Eigen::Matrix3d C = plane_stress_elasticity(young_, poisson_);
  const Eigen::Matrix3d P = plane_stress_projection();
  const Eigen::Map<const Vec6> ep_old(old_state.data()), alpha_old(old_state.data() + 6);
  const double p_old = old_state[kPeeq];
  Eigen::Vector3d e, ep_r, beta_old;  // in-plane strain, plastic strain; back stress as a plane stress
  for (int k = 0; k < 3; ++k) e(k) = eps(kPlane[k]), ep_r(k) = ep_old(kPlane[k]);
  beta_old << alpha_old(0) - alpha_old(2), alpha_old(1) - alpha_old(2), alpha_old(3);
  const Eigen::Vector3d sigma_trial = C * (e - ep_r);
  const Eigen::Vector3d eta_trial = sigma_trial - beta_old;
  const double q_trial = kSqrt32 * std::sqrt(eta_trial.dot(P * eta_trial));
  const Hardened h_old = hardened(p_old, T);
  const auto finish = [&](const Eigen::Vector3d& sigma, const Eigen::Matrix3d& D, const Vec6& ep) {
    out.stress.setZero();
    out.tangent.setZero();
    for (int a = 0; a < 3; ++a) {
      out.stress(kPlane[a]) = sigma(a);
      for (int b = 0; b < 3; ++b) out.tangent(kPlane[a], kPlane[b]) = D(a, b);
    }
    eps(2) = -poisson_ / young_ * (sigma(0) + sigma(1)) + ep(2);
    out.elastic_energy = 0.5 * sigma.dot(C.inverse() * sigma);
  };
  const bool inside = q_trial - h_old.K <= kYieldTolerance * h_old.K;
  if (inside && (!on_surface_loading || q_trial - h_old.K < -kOnSurfaceTolerance * h_old.K)) {
    out.dissipation = 0;
    new_state[kYielding] = 0;
    finish(sigma_trial, C, ep_old);
    return;
  }
  // Unknown: the PEEQ increment dp. With q = sqrt(2/3) K(p), c = sqrt(2/3) dH / q and
  // dgamma = dp / (sqrt(2/3) q): [(1 + c) I + dgamma C P] eta = eta_trial, g = eta^T P eta - q^2.
  struct Trial {
    double q, dq, c, dc, dgamma, ddgamma;
    Eigen::Matrix3d A_inv;
    Eigen::Vector3d eta, deta;  // eta and d eta / d dp
  };
  const auto trial_at = [&](double dp) {
    const Hardened h = hardened(p_old + dp, T);
    Trial t;
    t.q = kSqrt23 * h.K;
    t.dq = kSqrt23 * h.dK;
    t.c = kSqrt23 * (h.H - h_old.H) / t.q;
    t.dc = kSqrt23 * (h.dH / t.q - (h.H - h_old.H) * t.dq / (t.q * t.q));
    t.dgamma = dp / (kSqrt23 * t.q);
    t.ddgamma = 1 / (kSqrt23 * t.q) - dp * t.dq / (kSqrt23 * t.q * t.q);
    t.A_inv = ((1 + t.c) * Eigen::Matrix3d::Identity() + t.dgamma * C * P).inverse();
    t.eta = t.A_inv * eta_trial;
    t.deta = -t.A_inv * ((t.dc * Eigen::Matrix3d::Identity() + t.ddgamma * C * P) * t.eta);
    return t;
  };
  // On the yield surface (inside): no plastic increment, the loading tangent.
  const double dp = inside ? 0.0 : solve_plastic_increment(
      [&](double x, double& slope) {
        const Trial t = trial_at(x);
        slope = 2 * t.eta.dot(P * t.deta) - 2 * t.q * t.dq;
        return t.eta.dot(P * t.eta) - t.q * t.q;
      },
      (q_trial - h_old.K) / (3 * elastic_.mu()), 1e-14 * q_trial * q_trial);
  const Trial t = trial_at(dp);
  const double slope = 2 * t.eta.dot(P * t.deta) - 2 * t.q * t.dq;
  const Eigen::Vector3d sigma = beta_old + (1 + t.c) * t.eta;
  const Eigen::Vector3d beta = beta_old + t.c * t.eta;
  const Eigen::Vector3d dep_r = t.dgamma * P * t.eta;  // engineering shear
  // Consistent tangent: sigma(e, dp) with g(e, dp) = 0.
  const Eigen::Matrix3d dsigma_de = (1 + t.c) * t.A_inv * C;
  const Eigen::RowVector3d dg_de = 2 * (P * t.eta).transpose() * t.A_inv * C;
  const Eigen::Vector3d dsigma_ddp = t.dc * t.eta + (1 + t.c) * t.deta;
  const Eigen::Matrix3d D = dsigma_de - dsigma_ddp * dg_de / slope;

  Vec6 dep = Vec6::Zero();
  dep << dep_r(0), dep_r(1), -(dep_r(0) + dep_r(1)), dep_r(2), 0, 0;
  Eigen::Map<Vec6> ep(new_state.data()), alpha(new_state.data() + 6);
  ep = ep_old + dep;
  alpha.setZero();
  alpha << (2 * beta(0) - beta(1)) / 3, (2 * beta(1) - beta(0)) / 3, -(beta(0) + beta(1)) / 3, beta(2), 0, 0;
  new_state[kPeeq] = p_old + dp;
  new_state[kYielding] = dp > 0 ? 1 : 0;
  Vec6 xi = Vec6::Zero();  // deviatoric relative stress, shear doubled; |xi| = q at convergence
  xi << (2 * t.eta(0) - t.eta(1)) / 3, (2 * t.eta(1) - t.eta(0)) / 3, -(t.eta(0) + t.eta(1)) / 3, 2 * t.eta(2), 0, 0;
  out.dissipation = plastic_work(p_old, dp, alpha_old.dot(xi) / t.q, T);
  finish(sigma, D, ep);
}

}  // namespace tether
