#include "tether/materials/linear_elastic.hpp"

#include <fmt/format.h>

namespace tether {

LinearElastic::LinearElastic(double young, double poisson)
    : young_(young),
      poisson_(poisson),
      lambda_(young * poisson / ((1 + poisson) * (1 - 2 * poisson))),
      mu_(young / (2 * (1 + poisson))),
      D_(isotropic_stiffness(lambda_, mu_)) {}

void LinearElastic::small_strain(const Vec6& eps, Vec6& sigma, Mat6& D) const {
  D = D_;
  sigma.noalias() = D_ * eps;
}

double LinearElastic::small_strain_energy(const Vec6& eps) const { return 0.5 * eps.dot(D_ * eps); }

void LinearElastic::finite_strain(const Eigen::Matrix3d& C, Vec6& S, Mat6& D) const {
  const Eigen::Matrix3d E = 0.5 * (C - Eigen::Matrix3d::Identity());
  D = D_;
  S.noalias() = D_ * to_voigt_strain(E);
}

double LinearElastic::finite_strain_energy(const Eigen::Matrix3d& C) const {
  const Eigen::Matrix3d E = 0.5 * (C - Eigen::Matrix3d::Identity());
  const double tr = E.trace();
  return 0.5 * lambda_ * tr * tr + mu_ * (E.array() * E.array()).sum();
}

std::string LinearElastic::describe() const {
  return fmt::format("linear elastic (E={:g}, nu={:g})", young_, poisson_);
}

}  // namespace tether
