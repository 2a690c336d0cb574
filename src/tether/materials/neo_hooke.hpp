#pragma once
/// \file `*HYPERELASTIC, NEO HOOKE`: ABAQUS's compressible neo-Hookean solid.

#include "tether/materials/constitutive_model.hpp"

namespace tether {

/// W = C10 (I1bar - 3) + (J - 1)^2 / D1 with I1bar = J^(-2/3) tr C,
/// initial shear modulus mu = 2 C10 and bulk modulus K = 2 / D1.
///
/// Without NLGEOM (small strain) tether uses linear elasticity with the
/// initial moduli mu and K (lambda = K - 2 mu / 3): the linearisation of W at
/// the undeformed state. This matches the hyperelastic law to first order in
/// the strain and keeps small-strain analyses linear.
class NeoHooke final : public ElasticModel {
 public:
  /// c10 > 0 [force/area], d1 > 0 [area/force].
  NeoHooke(double c10, double d1);

  void small_strain(const Vec6& eps, Vec6& sigma, Mat6& D) const override;
  [[nodiscard]] double small_strain_energy(const Vec6& eps) const override;
  void finite_strain(const Eigen::Matrix3d& C, Vec6& S, Mat6& D) const override;
  [[nodiscard]] double finite_strain_energy(const Eigen::Matrix3d& C) const override;
  [[nodiscard]] double shear_modulus() const override { return 2 * c10_; }
  [[nodiscard]] std::string describe() const override;

  [[nodiscard]] double bulk_modulus() const { return 2 / d1_; }  ///< K = 2/D1

 private:
  double c10_, d1_;
  Mat6 D0_;  ///< linearised (small-strain) stiffness
};

}  // namespace tether
