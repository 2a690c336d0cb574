#include "tether/materials/thermal_model.hpp"

#include <algorithm>
#include <cassert>
#include <fmt/format.h>

#include "tether/materials/linear_elastic.hpp"

namespace tether {

double interpolate_table(std::span<const double> x, std::span<const double> y, double at) {
  assert(!x.empty() && x.size() == y.size());
  if (x.size() == 1 || at <= x.front()) return y.front();
  if (at >= x.back()) return y.back();
  const auto upper = std::upper_bound(x.begin(), x.end(), at);
  const auto k = static_cast<std::size_t>(upper - x.begin());  // x[k-1] <= at < x[k]
  const double w = (at - x[k - 1]) / (x[k] - x[k - 1]);
  return y[k - 1] + w * (y[k] - y[k - 1]);
}

double thermal_strain(const TemperatureTable& alpha, double zero, double temperature, double initial_temperature) {
  if (alpha.value.empty()) return 0;
  return alpha.at(temperature) * (temperature - zero) - alpha.at(initial_temperature) * (initial_temperature - zero);
}

ThermalModel::ThermalModel(std::unique_ptr<ConstitutiveModel> inner, TemperatureTable alpha, double zero,
                           TemperatureTable young, TemperatureTable poisson)
    : inner_(std::move(inner)), alpha_(std::move(alpha)), zero_(zero), young_(std::move(young)),
      poisson_(std::move(poisson)) {}

double ThermalModel::thermal_strain(const PointContext& where) const {
  return tether::thermal_strain(alpha_, zero_, where.temperature, where.initial_temperature);
}

template <class Update>
void ThermalModel::with_model(const PointContext& where, Update&& update) const {
  if (young_.value.empty()) {
    update(*inner_);
    return;
  }
  const LinearElastic at_temperature(young_.at(where.temperature), poisson_.at(where.temperature));
  update(at_temperature);
}

void ThermalModel::update_small_strain(Vec6& eps, bool plane_stress, std::span<const double> old_state,
                                       std::span<double> new_state, const PointContext& where,
                                       MaterialResponse& out) const {
  const double eth = thermal_strain(where);
  Vec6 mechanical = eps;
  mechanical.head<3>().array() -= eth;
  with_model(where, [&](const ConstitutiveModel& m) {
    m.update_small_strain(mechanical, plane_stress, old_state, new_state, where, out);
  });
  if (plane_stress) eps(2) = mechanical(2) + eth;  // the free thickness strain, thermal part included
}

void ThermalModel::update_finite_strain(Eigen::Matrix3d& C, bool plane_stress, std::span<const double> old_state,
                                        std::span<double> new_state, const PointContext& where,
                                        MaterialResponse& out) const {
  const double stretch = 1 + thermal_strain(where);  // F_th = stretch * I
  if (!(stretch > 0))
    throw ModelError(fmt::format("the thermal stretch 1 + eps_th = {:.3g} is not positive", stretch));
  const double s2 = stretch * stretch, s3 = s2 * stretch;
  Eigen::Matrix3d mechanical = C / s2;
  with_model(where, [&](const ConstitutiveModel& m) {
    m.update_finite_strain(mechanical, plane_stress, old_state, new_state, where, out);
  });
  if (plane_stress) C(2, 2) = mechanical(2, 2) * s2;
  // thickness_sensitivity is the mechanical one: E33 = s^2 E33_m + (s^2 - 1)/2 and E_m = (E - (s^2 - 1)/2 I) / s^2.
  out.stress *= stretch;   // S = 2 dW/dC with W = s^3 W_m(C / s^2)
  out.tangent /= stretch;  // dS/dE = s D_m dE_m/dE, dE_m/dE = 1 / s^2
  out.elastic_energy *= s3;
  out.dissipation *= s3;
}

std::string ThermalModel::describe() const {
  std::string text = inner_->describe();
  if (!young_.value.empty()) text += fmt::format(", elasticity at {} temperatures", young_.value.size());
  if (!alpha_.value.empty())
    text += alpha_.value.size() == 1 ? fmt::format(", expansion alpha={:g} about {:g}", alpha_.value[0], zero_)
                                     : fmt::format(", expansion at {} temperatures about {:g}", alpha_.value.size(),
                                                   zero_);
  return text;
}

std::unique_ptr<ConstitutiveModel> with_thermal_behaviour(const MaterialData& data,
                                                          std::unique_ptr<ConstitutiveModel> model) {
  const bool table = data.elastic && !data.elastic->table_young.empty();
  if (!table && !data.expansion) return model;
  if (table && data.plastic)
    throw ModelError(data.where.str() + ": material " + data.name + ": a temperature-dependent *ELASTIC with "
                     "*PLASTIC is not supported (give *ELASTIC one row)");
  TemperatureTable alpha, young, poisson;
  double zero = 0;
  if (data.expansion) alpha = {data.expansion->temperature, data.expansion->alpha}, zero = data.expansion->zero;
  if (table) {
    young = {data.elastic->table_temperature, data.elastic->table_young};
    poisson = {data.elastic->table_temperature, data.elastic->table_poisson};
  }
  return std::make_unique<ThermalModel>(std::move(model), std::move(alpha), zero, std::move(young),
                                        std::move(poisson));
}

}  // namespace tether
