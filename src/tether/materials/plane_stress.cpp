#include "tether/materials/plane_stress.hpp"

#include <cmath>

namespace tether {

namespace {

constexpr int kMaxIterations = 50;

/// Convergence of the local Newton step on the 33 strain (dimensionless).
bool converged(double step, double value) { return std::abs(step) <= 1e-13 * (1 + std::abs(value)); }

}  // namespace

void condense_out_of_plane(Mat6& D) {
  const double d33 = D(2, 2);
  const Vec6 col = D.col(2);
  const Eigen::Matrix<double, 1, 6> row = D.row(2);
  D.noalias() -= col * row / d33;
  D.row(2).setZero();
  D.col(2).setZero();
}

Eigen::Vector3d thickness_sensitivity(const Mat6& D) { return Eigen::Vector3d(D(2, 0), D(2, 1), D(2, 3)) / -D(2, 2); }

void plane_stress_small_strain(const ElasticModel& model, Vec6& eps, Vec6& sigma, Mat6& D) {
  for (int it = 0; it < kMaxIterations; ++it) {
    model.small_strain(eps, sigma, D);
    if (!(D(2, 2) > 0)) break;
    const double step = -sigma(2) / D(2, 2);
    if (converged(step, eps(2))) {  // the remaining step is round-off: keep the evaluated state
      condense_out_of_plane(D);
      return;
    }
    eps(2) += step;
  }
  throw ModelError("plane stress: the out-of-plane strain iteration did not converge");
}

void plane_stress_finite_strain(const ElasticModel& model, Eigen::Matrix3d& C, Vec6& S, Mat6& D,
                                Eigen::Vector3d* sensitivity) {
  // Newton on E33 = (C33 - 1)/2; dS33/dE33 = D(2,2). Steps that would make C33 <= 0 are halved.
  for (int it = 0; it < kMaxIterations; ++it) {
    model.finite_strain(C, S, D);
    if (!(D(2, 2) > 0) || !std::isfinite(S(2))) break;
    double step = -S(2) / D(2, 2);  // in E33
    if (converged(step, 0.5 * (C(2, 2) - 1))) {  // remaining step is round-off
      if (sensitivity != nullptr) *sensitivity = thickness_sensitivity(D);
      condense_out_of_plane(D);
      return;
    }
    while (C(2, 2) + 2 * step <= 0.01 * C(2, 2)) step *= 0.5;
    C(2, 2) += 2 * step;
  }
  throw ModelError("plane stress: the out-of-plane stretch iteration did not converge");
}

}  // namespace tether
