#pragma once
/// \file Thermal expansion and temperature-dependent elasticity around any
/// constitutive model (`*EXPANSION`, `*ELASTIC` with a temperature column).
///
/// Small strain: the mechanical strain eps - eps_th I (normal components
/// only) goes to the wrapped model. Finite strain: the multiplicative split
/// F = F_th F_m with F_th = (1 + eps_th) I, so C_m = C / (1 + eps_th)^2, and
/// S = (1 + eps_th) S_m, dS/dE = D_m / (1 + eps_th), W = (1 + eps_th)^3 W_m
/// per reference volume. The thermal strain is the secant form ABAQUS and
/// CalculiX use: eps_th = alpha(T) (T - T0) - alpha(T_I) (T_I - T0), with T0
/// the ZERO= reference temperature and T_I the initial temperature of the
/// point. See docs/theory/thermal_stress.md.

#include <memory>
#include <span>
#include <vector>

#include "tether/materials/constitutive_model.hpp"

namespace tether {

/// Piecewise-linear table y(x), x strictly increasing, constant beyond the
/// first and last points (as ABAQUS and CalculiX interpolate material tables).
/// One point: that value everywhere. Precondition: x.size() == y.size() >= 1.
double interpolate_table(std::span<const double> x, std::span<const double> y, double at);

/// A piecewise-linear function of temperature (one row: a constant).
struct TemperatureTable {
  std::vector<double> temperature;  ///< strictly increasing; empty or one entry: constant
  std::vector<double> value;        ///< one per row (at least one)
  [[nodiscard]] double at(double t) const {
    if (value.size() == 1) return value.front();
    return interpolate_table(temperature, value, t);
  }
};

/// The thermal strain of an isotropic expansion table about `zero`:
/// alpha(T) (T - zero) - alpha(T_I) (T_I - zero) [-].
double thermal_strain(const TemperatureTable& alpha, double zero, double temperature, double initial_temperature);

/// Wraps a constitutive model with thermal expansion and/or a
/// temperature-dependent linear elasticity. The point temperatures come in
/// PointContext::temperature and ::initial_temperature.
class ThermalModel final : public ConstitutiveModel {
 public:
  /// `inner`: the mechanical model (with a temperature-dependent elasticity,
  /// the LinearElastic of the first row; it is rebuilt at the point's
  /// temperature). `alpha` empty (no value): no expansion. `young`/`poisson`
  /// tables empty: the inner model's constants at every temperature.
  ThermalModel(std::unique_ptr<ConstitutiveModel> inner, TemperatureTable alpha, double zero, TemperatureTable young,
               TemperatureTable poisson);

  [[nodiscard]] int n_state() const override { return inner_->n_state(); }
  void initial_state(std::span<double> state) const override { inner_->initial_state(state); }
  void update_small_strain(Vec6& eps, bool plane_stress, std::span<const double> old_state,
                           std::span<double> new_state, const PointContext& where,
                           MaterialResponse& out) const override;
  void update_finite_strain(Eigen::Matrix3d& C, bool plane_stress, std::span<const double> old_state,
                            std::span<double> new_state, const PointContext& where,
                            MaterialResponse& out) const override;
  /// The inner model's answer, and false with temperature-dependent
  /// elasticity (the tangent changes with the temperature over a step).
  [[nodiscard]] bool linear_small_strain() const override {
    return inner_->linear_small_strain() && young_.value.empty();
  }
  [[nodiscard]] bool symmetric_tangent(bool nlgeom) const override { return inner_->symmetric_tangent(nlgeom); }
  [[nodiscard]] double equivalent_plastic_strain(std::span<const double> state) const override {
    return inner_->equivalent_plastic_strain(state);
  }
  [[nodiscard]] Vec6 plastic_strain(std::span<const double> state) const override {
    return inner_->plastic_strain(state);
  }
  [[nodiscard]] bool actively_yielding(std::span<const double> state) const override {
    return inner_->actively_yielding(state);
  }
  [[nodiscard]] double shear_modulus() const override { return inner_->shear_modulus(); }
  [[nodiscard]] std::string describe() const override;

  /// Thermal strain at a point [-] (0 without expansion).
  [[nodiscard]] double thermal_strain(const PointContext& where) const;

 private:
  /// Runs `update` on the mechanical model at the point's temperature.
  template <class Update>
  void with_model(const PointContext& where, Update&& update) const;

  std::unique_ptr<ConstitutiveModel> inner_;
  TemperatureTable alpha_;
  double zero_;
  TemperatureTable young_, poisson_;
};

/// `model` wrapped in a ThermalModel when the material has `*EXPANSION` or a
/// temperature-dependent `*ELASTIC`; `model` itself otherwise. Throws
/// ModelError naming the material and its deck line for a
/// temperature-dependent *ELASTIC with *PLASTIC (not supported).
std::unique_ptr<ConstitutiveModel> with_thermal_behaviour(const MaterialData& data,
                                                          std::unique_ptr<ConstitutiveModel> model);

}  // namespace tether
