#pragma once
/// \file The interface every constitutive model implements.
///
/// A constitutive model sees strains (or the right Cauchy-Green tensor) and
/// returns stress, consistent tangent and strain energy; it never sees the mesh.
///
/// Voigt order everywhere: 11, 22, 33, 12, 23, 13. Strain vectors carry
/// *engineering* shear (gamma_12 = 2 eps_12), stress vectors the tensor
/// components, so stress . strain is the work density and the tangent
/// D = d stress / d strain (6x6) is symmetric for hyperelastic models.
/// Units: stress and D in [force/area], energy density in [energy/volume].

#include <Eigen/Core>
#include <memory>
#include <string>

#include "tether/model/model.hpp"

namespace tether {

/// Voigt vector (11, 22, 33, 12, 23, 13).
using Vec6 = Eigen::Matrix<double, 6, 1>;
/// Voigt matrix, e.g. a material tangent.
using Mat6 = Eigen::Matrix<double, 6, 6>;

/// Stateless elastic constitutive law (small and finite strain).
class ConstitutiveModel {
 public:
  virtual ~ConstitutiveModel() = default;

  /// Small strain: Cauchy stress sigma and tangent D = d sigma / d eps from the
  /// small strain eps (engineering shear).
  virtual void small_strain(const Vec6& eps, Vec6& sigma, Mat6& D) const = 0;

  /// Small-strain energy density W(eps) with sigma = dW/deps.
  [[nodiscard]] virtual double small_strain_energy(const Vec6& eps) const = 0;

  /// Finite strain (total Lagrangian): second Piola-Kirchhoff stress S and
  /// tangent D = dS/dE (E = (C - I)/2, engineering shear in Voigt) from the
  /// right Cauchy-Green tensor C (symmetric, det C > 0).
  virtual void finite_strain(const Eigen::Matrix3d& C, Vec6& S, Mat6& D) const = 0;

  /// Finite-strain energy density per reference volume W(C), S = 2 dW/dC.
  [[nodiscard]] virtual double finite_strain_energy(const Eigen::Matrix3d& C) const = 0;

  /// Initial (small-strain) shear modulus mu [force/area].
  [[nodiscard]] virtual double shear_modulus() const = 0;

  /// Short description, e.g. "neo-Hookean (C10=1, D1=0.1)".
  [[nodiscard]] virtual std::string describe() const = 0;
};

/// Builds the model of a `*MATERIAL`: `*ELASTIC` -> LinearElastic (St.Venant-
/// Kirchhoff under NLGEOM), `*HYPERELASTIC, NEO HOOKE` -> NeoHooke.
/// Throws ModelError naming the material and its deck line when neither or
/// both are given or the constants are out of range (E <= 0, nu outside
/// (-1, 0.5), C10 <= 0, D1 <= 0).
std::unique_ptr<ConstitutiveModel> make_constitutive_model(const MaterialData& data);

/// Isotropic linear elastic Voigt stiffness from the Lame constants
/// lambda and mu [force/area].
Mat6 isotropic_stiffness(double lambda, double mu);

/// Voigt strain vector (engineering shear) of a symmetric 3x3 strain tensor.
Vec6 to_voigt_strain(const Eigen::Matrix3d& e);

/// Symmetric 3x3 stress tensor of a Voigt stress vector.
Eigen::Matrix3d from_voigt_stress(const Vec6& s);

}  // namespace tether
