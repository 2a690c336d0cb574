#include "tether/materials/neo_hooke.hpp"

#include <Eigen/LU>
#include <cmath>
#include <fmt/format.h>

namespace tether {

namespace {

constexpr int kVoigt[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {0, 2}};

}  // namespace

NeoHooke::NeoHooke(double c10, double d1)
    : c10_(c10), d1_(d1), D0_(isotropic_stiffness(2 / d1 - 2 * (2 * c10) / 3, 2 * c10)) {}

void NeoHooke::small_strain(const Vec6& eps, Vec6& sigma, Mat6& D) const {
  D = D0_;
  sigma.noalias() = D0_ * eps;
}

double NeoHooke::small_strain_energy(const Vec6& eps) const { return 0.5 * eps.dot(D0_ * eps); }

void NeoHooke::finite_strain(const Eigen::Matrix3d& C, Vec6& S, Mat6& D) const {
  const double det = C.determinant();
  const double J = std::sqrt(det);
  const Eigen::Matrix3d Ci = C.inverse();
  const double I1 = C.trace();
  const double mu = 2 * c10_;
  const double jm23 = std::pow(J, -2.0 / 3.0);
  const double vol = (2 / d1_) * (J - 1) * J;  // g(J) = J dU/dJ, U = (J-1)^2/D1
  const Eigen::Matrix3d Smat =
      mu * jm23 * (Eigen::Matrix3d::Identity() - (I1 / 3) * Ci) + vol * Ci;
  S << Smat(0, 0), Smat(1, 1), Smat(2, 2), Smat(0, 1), Smat(1, 2), Smat(0, 2);

  // D_ijkl = 2 dS_ij/dC_kl
  const double a = 2 * mu * jm23;
  const double b = (2 / d1_) * (2 * J - 1) * J;
  for (int I = 0; I < 6; ++I) {
    const int i = kVoigt[I][0], j = kVoigt[I][1];
    const double dij = i == j ? 1.0 : 0.0;
    for (int K = I; K < 6; ++K) {
      const int k = kVoigt[K][0], l = kVoigt[K][1];
      const double dkl = k == l ? 1.0 : 0.0;
      const double cc = Ci(i, j) * Ci(k, l);
      const double sym = 0.5 * (Ci(i, k) * Ci(j, l) + Ci(i, l) * Ci(j, k));
      D(I, K) = a * (I1 / 9 * cc - (dij * Ci(k, l) + Ci(i, j) * dkl) / 3 + I1 / 3 * sym) +
                b * cc - 2 * vol * sym;
      D(K, I) = D(I, K);
    }
  }
}

double NeoHooke::finite_strain_energy(const Eigen::Matrix3d& C) const {
  const double J = std::sqrt(C.determinant());
  return c10_ * (std::pow(J, -2.0 / 3.0) * C.trace() - 3) + (J - 1) * (J - 1) / d1_;
}

std::string NeoHooke::describe() const {
  return fmt::format("neo-Hookean (C10={:g}, D1={:g})", c10_, d1_);
}

}  // namespace tether
