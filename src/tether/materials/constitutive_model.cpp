#include "tether/materials/constitutive_model.hpp"

#include <cstddef>

#include "tether/materials/j2_plasticity.hpp"
#include "tether/materials/linear_elastic.hpp"
#include "tether/materials/neo_hooke.hpp"
#include "tether/materials/plane_stress.hpp"
#include "tether/materials/thermal_model.hpp"
#include "tether/materials/user_material.hpp"

namespace tether {

namespace {

[[noreturn]] void fail(const MaterialData& data, const std::string& what) {
  const std::string where = data.where.file.empty() ? std::string{} : data.where.str() + ": ";
  throw ModelError(where + "material " + data.name + ": " + what);
}

/// The hardening table of rows (plastic strain, yield stress[, temperature]):
/// one curve per run of equal temperatures, or one curve without the column.
/// Throws std::invalid_argument from HardeningCurve / HardeningTable.
HardeningTable hardening_table(const std::vector<double>& strain, const std::vector<double>& stress,
                               const std::vector<double>& temperature) {
  if (temperature.empty()) return HardeningCurve(strain, stress);
  std::vector<double> temperatures;
  std::vector<HardeningCurve> curves;
  for (std::size_t begin = 0, end = 0; begin < strain.size(); begin = end) {
    while (end < strain.size() && temperature[end] == temperature[begin]) ++end;
    const auto at = [&](const std::vector<double>& v) {
      return std::vector<double>(v.begin() + static_cast<std::ptrdiff_t>(begin),
                                 v.begin() + static_cast<std::ptrdiff_t>(end));
    };
    temperatures.push_back(temperature[begin]);
    curves.emplace_back(at(strain), at(stress));
  }
  return {std::move(temperatures), std::move(curves)};
}

std::unique_ptr<ConstitutiveModel> make_plasticity(const MaterialData& data) {
  const MaterialData::Plastic& p = *data.plastic;
  for (double y : p.yield_stress)
    if (!(y > 0)) fail(data, "*PLASTIC yield stress must be positive (got " + std::to_string(y) + ")");
  using Kind = MaterialData::Plastic::Hardening;
  const bool combined = p.hardening == Kind::Combined;
  if (combined && p.cyclic_yield_stress.empty())
    fail(data, "*PLASTIC, HARDENING=COMBINED (" + p.where.str() + ") needs *CYCLIC HARDENING (the yield stress "
               "against the equivalent plastic strain) after it");
  if (!combined && !p.cyclic_yield_stress.empty())
    fail(data, "*CYCLIC HARDENING (" + p.cyclic_where.str() + ") needs *PLASTIC, HARDENING=COMBINED");
  try {
    HardeningTable curve = hardening_table(p.plastic_strain, p.yield_stress, p.temperature);
    const auto hardening = p.hardening == Kind::Kinematic ? J2Plasticity::Hardening::Kinematic
                           : combined                     ? J2Plasticity::Hardening::Combined
                                                          : J2Plasticity::Hardening::Isotropic;
    std::optional<HardeningTable> cyclic;
    if (combined) cyclic = hardening_table(p.cyclic_plastic_strain, p.cyclic_yield_stress, p.cyclic_temperature);
    return std::make_unique<J2Plasticity>(data.elastic->young, data.elastic->poisson, std::move(curve), hardening,
                                          std::move(cyclic));
  } catch (const std::invalid_argument& e) {
    fail(data, std::string("*PLASTIC: ") + e.what());
  }
}

}  // namespace

void ElasticModel::update_small_strain(Vec6& eps, bool plane_stress, std::span<const double>, std::span<double>,
                                       const PointContext&, MaterialResponse& out) const {
  if (plane_stress)
    plane_stress_small_strain(*this, eps, out.stress, out.tangent);
  else
    small_strain(eps, out.stress, out.tangent);
  out.elastic_energy = small_strain_energy(eps);
  out.dissipation = 0;
}

void ElasticModel::update_finite_strain(Eigen::Matrix3d& C, bool plane_stress, std::span<const double>,
                                        std::span<double>, const PointContext&, MaterialResponse& out) const {
  if (plane_stress)
    plane_stress_finite_strain(*this, C, out.stress, out.tangent, &out.thickness_sensitivity);
  else
    finite_strain(C, out.stress, out.tangent);
  out.elastic_energy = finite_strain_energy(C);
  out.dissipation = 0;
}

namespace {

std::unique_ptr<ConstitutiveModel> make_user_material(const MaterialData& data) {
  const MaterialData::User& u = *data.user;
  if (data.elastic || data.neo_hooke || data.plastic)
    fail(data, "*USER MATERIAL (" + u.where.str() + ") defines the whole mechanical behaviour: remove *ELASTIC, "
               "*HYPERELASTIC and *PLASTIC");
  try {
    return std::make_unique<UserMaterial>(data.name, u.library, u.symbol, u.constants, data.depvar.value_or(0));
  } catch (const ModelError& e) {
    throw ModelError(u.where.str() + ": material " + data.name + ": " + e.what());
  }
}

std::unique_ptr<ConstitutiveModel> make_mechanical_model(const MaterialData& data) {
  if (data.user) return make_user_material(data);
  if (data.depvar)
    fail(data, "*DEPVAR (" + data.depvar_where.str() + ") without *USER MATERIAL: only user materials have "
               "state variables in tether");
  if (data.elastic && data.neo_hooke)
    fail(data, "both *ELASTIC and *HYPERELASTIC are given; keep one");
  if (data.elastic) {
    const auto& e = *data.elastic;
    if (!(e.young > 0)) fail(data, "Young's modulus must be positive (got " + std::to_string(e.young) + ")");
    if (!(e.poisson > -1 && e.poisson < 0.5))
      fail(data, "Poisson's ratio must lie in (-1, 0.5) (got " + std::to_string(e.poisson) + ")");
    if (data.plastic) return make_plasticity(data);
    return std::make_unique<LinearElastic>(e.young, e.poisson);
  }
  if (data.plastic) fail(data, "*PLASTIC needs *ELASTIC (the elastic range of the plastic model)");
  if (data.neo_hooke) {
    const auto& n = *data.neo_hooke;
    if (!(n.c10 > 0)) fail(data, "NEO HOOKE C10 must be positive (got " + std::to_string(n.c10) + ")");
    if (!(n.d1 > 0))
      fail(data, "NEO HOOKE D1 must be positive; D1 = 0 (incompressible) needs a hybrid "
                 "formulation, which tether does not provide");
    return std::make_unique<NeoHooke>(n.c10, n.d1);
  }
  fail(data, "no *ELASTIC or *HYPERELASTIC, NEO HOOKE definition");
}

}  // namespace

std::unique_ptr<ConstitutiveModel> make_constitutive_model(const MaterialData& data) {
  return with_thermal_behaviour(data, make_mechanical_model(data));
}

Mat6 isotropic_stiffness(double lambda, double mu) {
  Mat6 D = Mat6::Zero();
  D.topLeftCorner<3, 3>().setConstant(lambda);
  for (int i = 0; i < 3; ++i) {
    D(i, i) += 2 * mu;
    D(3 + i, 3 + i) = mu;
  }
  return D;
}

Vec6 to_voigt_strain(const Eigen::Matrix3d& e) {
  Vec6 v;
  v << e(0, 0), e(1, 1), e(2, 2), 2 * e(0, 1), 2 * e(1, 2), 2 * e(0, 2);
  return v;
}

Eigen::Matrix3d from_voigt_stress(const Vec6& s) {
  Eigen::Matrix3d m;
  m << s(0), s(3), s(5),  //
      s(3), s(1), s(4),   //
      s(5), s(4), s(2);
  return m;
}

}  // namespace tether
