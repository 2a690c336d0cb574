#pragma once
/// \file `*ELASTIC`: isotropic linear elasticity, St.Venant-Kirchhoff under NLGEOM.

#include "tether/materials/constitutive_model.hpp"

namespace tether {

/// Isotropic linear elastic material (E, nu). Small strain: sigma = D eps.
/// Finite strain: St.Venant-Kirchhoff S = lambda tr(E) I + 2 mu E with the same
/// constant D; note SVK softens and loses stability in strong compression
/// (stretch below about 0.58 in uniaxial compression).
class LinearElastic final : public ElasticModel {
 public:
  /// young = E > 0 [force/area], poisson = nu in (-1, 0.5).
  LinearElastic(double young, double poisson);

  void small_strain(const Vec6& eps, Vec6& sigma, Mat6& D) const override;
  [[nodiscard]] double small_strain_energy(const Vec6& eps) const override;
  void finite_strain(const Eigen::Matrix3d& C, Vec6& S, Mat6& D) const override;
  [[nodiscard]] double finite_strain_energy(const Eigen::Matrix3d& C) const override;
  [[nodiscard]] double shear_modulus() const override { return mu_; }
  [[nodiscard]] std::string describe() const override;

  [[nodiscard]] double lambda() const { return lambda_; }  ///< Lame's first constant
  [[nodiscard]] double mu() const { return mu_; }          ///< shear modulus

 private:
  double young_, poisson_, lambda_, mu_;
  Mat6 D_;
};

}  // namespace tether
