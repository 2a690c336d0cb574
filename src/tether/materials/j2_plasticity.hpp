#pragma once
/// \file `*PLASTIC`: small-strain von Mises plasticity with isotropic or
/// kinematic piecewise-linear hardening. See docs/theory/plasticity.md.

#include <optional>

#include "tether/materials/constitutive_model.hpp"
#include "tether/materials/hardening_curve.hpp"
#include "tether/materials/linear_elastic.hpp"

namespace tether {

/// Von Mises (J2) elastoplasticity on isotropic linear elasticity, backward
/// Euler: radial return in 3D (plane strain, axisymmetry) and the
/// plane-stress return map (sigma_33 = 0 exactly) for plane stress, each with
/// its consistent tangent (symmetric).
///
/// Hardening from the curve y(p) of the *PLASTIC table (true yield stress
/// against equivalent plastic strain p):
/// - Isotropic: the yield stress is y(p), no back stress;
/// - Kinematic: the yield stress stays y(0) and the back stress moves by the
///   Prager-Ziegler rule with the modulus dy/dp (linear kinematic hardening
///   for a two-point table; piecewise in p for more rows).
/// - Combined (with *CYCLIC HARDENING, as CalculiX reads it): the yield
///   stress is c(p) of the cyclic table and the back stress moves as for
///   Kinematic with y(p) - y(0).
///
/// State (14 values): plastic strain (Voigt, engineering shear), back stress
/// alpha (deviatoric, Voigt tensor components) [stress], PEEQ p, and the
/// yield flag (1: the increment that produced the state flowed plastically,
/// dp > 0; 0: it did not -- ABAQUS's AC YIELD). Under NLGEOM: E_p =
/// (I - Cp^-1)/2 (Voigt, engineering shear), the back stress (Kirchhoff, on
/// the axes rotated back by R of F = R U), PEEQ, the flag.
///
/// Finite strain (NLGEOM; every hardening kind; plane strain, axisymmetry and
/// plane stress): F = Fe Fp, Hencky elasticity tau = D : ln(Ve) with the
/// small-strain constants, von Mises on the Kirchhoff stress less the back
/// stress (carried on the axes rotated by R of F = R U), isochoric flow
/// integrated by the exponential map; the return at the logarithmic elastic
/// trial strain is the small-strain radial return, and the tangent dS/dE is
/// its exact linearisation (symmetric without back stress).
class J2Plasticity final : public ConstitutiveModel {
 public:
  enum class Hardening { Isotropic, Kinematic, Combined };
  static constexpr int kStateSize = 14;
  static constexpr int kPeeq = 12;       ///< index of PEEQ in the state
  static constexpr int kYielding = 13;   ///< index of the yield flag (0 or 1) in the state

  /// young > 0, poisson in (-1, 0.5), curve values > 0 (checked by the
  /// caller); `curve` may depend on the temperature (the *PLASTIC
  /// temperature column). `cyclic`: the yield stress against PEEQ of Combined
  /// hardening (values > 0); required for Combined, ignored otherwise.
  J2Plasticity(double young, double poisson, HardeningTable curve, Hardening hardening,
               std::optional<HardeningTable> cyclic = std::nullopt);

  [[nodiscard]] int n_state() const override { return kStateSize; }
  void update_small_strain(Vec6& eps, bool plane_stress, std::span<const double> old_state,
                           std::span<double> new_state, const PointContext& where,
                           MaterialResponse& out) const override;
  /// Finite strain (see the class comment): PK2 stress, dS/dE, E_p, back
  /// stress and PEEQ; plane stress by a local Newton iteration on C33 (S33 = 0
  /// to round-off) with the condensed tangent. Throws ModelError when the
  /// return or the thickness iteration fails.
  void update_finite_strain(Eigen::Matrix3d& C, bool plane_stress, std::span<const double> old_state,
                            std::span<double> new_state, const PointContext& where,
                            MaterialResponse& out) const override;
  [[nodiscard]] bool linear_small_strain() const override { return false; }
  /// Under NLGEOM a back stress not coaxial with the elastic strain makes dS/dE unsymmetric.
  [[nodiscard]] bool symmetric_tangent(bool nlgeom) const override {
    return !nlgeom || hardening_ == Hardening::Isotropic;
  }
  [[nodiscard]] double equivalent_plastic_strain(std::span<const double> state) const override {
    return state[kPeeq];
  }
  [[nodiscard]] Vec6 plastic_strain(std::span<const double> state) const override;
  /// The state's yield flag: the increment that produced it had dp > 0.
  [[nodiscard]] bool actively_yielding(std::span<const double> state) const override {
    return state[kYielding] > 0.5;
  }
  [[nodiscard]] double shear_modulus() const override { return elastic_.mu(); }
  [[nodiscard]] std::string describe() const override;

  /// Radius of the yield surface at PEEQ p and temperature T (as a uniaxial stress) [stress].
  [[nodiscard]] double yield_radius(double p, double T = 0) const;
  /// Kinematic part: the uniaxial back stress magnitude function H(p) at T [stress].
  [[nodiscard]] double kinematic(double p, double T = 0) const;

  /// True when a point on the yield surface gets the loading tangent (the
  /// plastic branch's at a zero plastic increment) rather than the elastic
  /// one: in every increment of a step but its first. Within a step the loads
  /// and prescribed values move in one direction (a ramp), so a point that
  /// yielded in the last increment most likely goes on yielding; a new step
  /// may reverse them, and unloading predicted with a plastic tangent (very
  /// soft for little hardening) overshoots into reversed yielding, where
  /// Newton can cycle. An amplitude that reverses within a step costs
  /// iterations there, not the answer.
  [[nodiscard]] static bool loading_tangent_applies(const PointContext& where) {
    return where.dt > 0 && where.step_time - where.dt > 1e-9 * where.step_time;
  }

 private:
  struct Hardened;  // K, H and slopes at one p and T
  /// The hardening functions at PEEQ p and temperature T [stress]; slopes at fixed T.
  [[nodiscard]] Hardened hardened(double p, double T) const;
  /// Plastic work density of a return from PEEQ p_old by dp in the direction
  /// n (unit deviatoric tensor) at temperature T, given alpha_n : n [energy/volume].
  [[nodiscard]] double plastic_work(double p_old, double dp, double alpha_dot_n, double T) const;
  /// The returns, at the temperature T of the end of the increment (the
  /// point's current temperature; the hardening functions of the whole
  /// return are those of the curve at T). `on_surface_loading`: a trial state
  /// on the yield surface (within kOnSurfaceTolerance below it) gets the
  /// loading tangent instead of the elastic one (see loading_tangent_applies).
  void general_return(Vec6& eps, std::span<const double> old_state, std::span<double> new_state,
                      bool on_surface_loading, double T, MaterialResponse& out) const;
  void plane_stress_return(Vec6& eps, std::span<const double> old_state, std::span<double> new_state,
                           bool on_surface_loading, double T, MaterialResponse& out) const;
  /// Finite-strain update at C (3D; plane strain and axisymmetry): PK2, dS/dE, state.
  void finite_strain_return(const Eigen::Matrix3d& C, std::span<const double> old_state, std::span<double> new_state,
                            bool on_surface_loading, double T, MaterialResponse& out) const;

  double young_, poisson_;
  LinearElastic elastic_;
  HardeningTable curve_;
  Hardening hardening_;
  std::optional<HardeningTable> cyclic_;  ///< Combined: the yield stress c(p, T)
};

}  // namespace tether
