#pragma once
/// \file The interface every constitutive model implements.
///
/// A constitutive model sees strains (or the right Cauchy-Green tensor) and the
/// committed history of the point, and returns stress, consistent tangent,
/// energy and the trial history; it never sees the mesh.
///
/// Voigt order everywhere: 11, 22, 33, 12, 23, 13. Strain vectors carry
/// *engineering* shear (gamma_12 = 2 eps_12), stress vectors the tensor
/// components, so stress . strain is the work density and the tangent
/// D = d stress / d strain (6x6) is symmetric for hyperelastic models.
/// Units: stress and D in [force/area], energy density in [energy/volume].

#include <Eigen/Core>
#include <algorithm>
#include <memory>
#include <span>
#include <string>

#include "tether/model/model.hpp"

namespace tether {

/// Voigt vector (11, 22, 33, 12, 23, 13).
using Vec6 = Eigen::Matrix<double, 6, 1>;
/// Voigt matrix, e.g. a material tangent.
using Mat6 = Eigen::Matrix<double, 6, 6>;

/// What a material returns for one integration point and one trial strain.
struct MaterialResponse {
  Vec6 stress = Vec6::Zero();   ///< Cauchy (small strain) or PK2 (finite strain) stress [force/area]
  /// Consistent (algorithmic) tangent d stress / d strain of the update
  /// (engineering shear); plane stress: condensed, row and column 2 zero.
  Mat6 tangent = Mat6::Zero();
  double elastic_energy = 0;    ///< elastic strain energy density [energy/volume]
  double dissipation = 0;       ///< plastic dissipation of the increment, >= 0 [energy/volume]
  /// Plane stress under finite strain: the thickness strain's sensitivity
  /// dE33/dE_k to the in-plane strains k = 11, 22, 12 (engineering shear)
  /// along S33 = 0, -D_3k / D_33 of the uncondensed consistent tangent [-];
  /// zero otherwise.
  Eigen::Vector3d thickness_sensitivity = Eigen::Vector3d::Zero();
};

/// Where and when a point is updated: what a user material (UMAT) is told.
/// Zeros where the caller does not know.
struct PointContext {
  int element = 0;                   ///< element label
  int point = 0;                     ///< integration point, 1-based
  double x = 0, y = 0;               ///< reference coordinates of the point [length]
  double step_time = 0;              ///< step time at the end of the increment
  double total_time = 0;             ///< total time at the end of the increment
  double dt = 0;                     ///< increment size
  double temperature = 0;            ///< temperature of the point at the end of the increment [temperature]
  /// Its change over the increment (end less start) [temperature]; a UMAT's
  /// DTEMP, with TEMP = temperature - temperature_increment.
  double temperature_increment = 0;
  double initial_temperature = 0;    ///< its initial temperature (*INITIAL CONDITIONS, TYPE=TEMPERATURE)
};

/// A constitutive model with (possibly) history. The history of one
/// integration point is n_state() doubles laid out as the model chooses; the
/// caller owns them (committed state) and passes them in. An update never
/// changes the committed state: it returns the trial state of the end of the
/// increment in `new_state`, which the caller commits once the increment is
/// accepted. Models are immutable value types that never see the mesh.
class ConstitutiveModel {
 public:
  virtual ~ConstitutiveModel() = default;

  /// History values per integration point (0: no history, purely elastic).
  [[nodiscard]] virtual int n_state() const { return 0; }

  /// The state of a virgin integration point (n_state() values).
  virtual void initial_state(std::span<double> state) const { std::fill(state.begin(), state.end(), 0.0); }

  /// Small strain update. eps: total strain at the end of the increment
  /// (engineering shear); with plane_stress, eps(2) is a starting guess on
  /// entry and holds eps_33 (with sigma_33 = 0) on exit. old_state: the
  /// committed state (n_state() values); new_state: receives the trial state
  /// (same size, may not alias old_state). `where`: the point and the times.
  /// Throws ModelError when the update fails (local iteration not converged,
  /// a user routine's NaN or request for a smaller increment).
  virtual void update_small_strain(Vec6& eps, bool plane_stress, std::span<const double> old_state,
                                   std::span<double> new_state, const PointContext& where,
                                   MaterialResponse& out) const = 0;

  /// Finite strain (total Lagrangian) update from the right Cauchy-Green tensor
  /// C (symmetric, det C > 0); with plane_stress, C(2,2) is a starting guess
  /// on entry and solved so that S_33 = 0 on exit (C(0,2) = C(1,2) = 0).
  /// Stress: PK2 S; tangent dS/dE (E = (C - I)/2, engineering shear). States
  /// as in update_small_strain. Throws ModelError when the model has no
  /// finite-strain form or the update fails.
  virtual void update_finite_strain(Eigen::Matrix3d& C, bool plane_stress, std::span<const double> old_state,
                                    std::span<double> new_state, const PointContext& where,
                                    MaterialResponse& out) const = 0;

  /// True when the small-strain stress is linear in the strain with a constant
  /// tangent (elasticity): a small-strain element of it is linear in u.
  [[nodiscard]] virtual bool linear_small_strain() const { return true; }

  /// True when every tangent the updates return is symmetric (`nlgeom`: of
  /// the finite-strain update, else of the small-strain one).
  [[nodiscard]] virtual bool symmetric_tangent(bool /*nlgeom*/) const { return true; }

  /// Equivalent plastic strain PEEQ [-] of a state (0 without plasticity).
  [[nodiscard]] virtual double equivalent_plastic_strain(std::span<const double> /*state*/) const { return 0; }

  /// Plastic strain PE of a state, Voigt with engineering shear [-] (zero
  /// without plasticity).
  [[nodiscard]] virtual Vec6 plastic_strain(std::span<const double> /*state*/) const { return Vec6::Zero(); }

  /// ABAQUS's AC YIELD of a state: true when the increment that produced it
  /// (the committed state of the last converged increment, or a trial state
  /// of update_*) flowed plastically, a plastic increment > 0; false when it
  /// ended elastic, on the yield surface without flow, or unloaded. False for
  /// models without plasticity, and for a user material (UMAT), whose
  /// yielding tether cannot know (tether writes 0 for it; see
  /// docs/theory/plasticity.md).
  [[nodiscard]] virtual bool actively_yielding(std::span<const double> /*state*/) const { return false; }

  /// Number of a user material's (UMAT's) solution-dependent state
  /// variables, NSTATV of `*DEPVAR`: the SDV written to the output (ABAQUS's
  /// meaning). 0 for tether's own models, whose history is written under its
  /// own names (PEEQ, PE, AC YIELD; CalculiX prints its built-in materials'
  /// internal variables as SDV, tether does not).
  [[nodiscard]] virtual int n_user_state() const { return 0; }

  /// The n_user_state() state variables STATEV within a state (a committed
  /// one or a trial one of update_*); empty for tether's own models.
  [[nodiscard]] virtual std::span<const double> user_state(std::span<const double> /*state*/) const { return {}; }

  /// Initial (small-strain) shear modulus mu [force/area].
  [[nodiscard]] virtual double shear_modulus() const = 0;

  /// Short description, e.g. "neo-Hookean (C10=1, D1=0.1)".
  [[nodiscard]] virtual std::string describe() const = 0;
};

/// Stateless elastic (hyperelastic) constitutive law, small and finite
/// strain; its updates ignore the (empty) state.
class ElasticModel : public ConstitutiveModel {
 public:
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

  void update_small_strain(Vec6& eps, bool plane_stress, std::span<const double> old_state,
                           std::span<double> new_state, const PointContext& where,
                           MaterialResponse& out) const final;
  void update_finite_strain(Eigen::Matrix3d& C, bool plane_stress, std::span<const double> old_state,
                            std::span<double> new_state, const PointContext& where,
                            MaterialResponse& out) const final;
};

/// Builds the model of a `*MATERIAL`: `*ELASTIC` -> LinearElastic (St.Venant-
/// Kirchhoff under NLGEOM), `*HYPERELASTIC, NEO HOOKE` -> NeoHooke,
/// `*ELASTIC` with `*PLASTIC` -> J2Plasticity (finite strain under NLGEOM).
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
