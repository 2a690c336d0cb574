// Thermal expansion and temperature-dependent elasticity (ThermalModel):
// table interpolation, the secant thermal strain, closed-form restrained
// stresses, and finite-difference checks of stress and tangent in small and
// finite strain, plane strain and plane stress.
#include <gtest/gtest.h>

#include <cmath>

#include "materials/material_fixtures.hpp"
#include "tether/materials/neo_hooke.hpp"
#include "tether/materials/thermal_model.hpp"

using namespace tether;

namespace {

/// E 2e5 -> 1e5 and nu 0.3 -> 0.2 over 0..400; alpha 1e-5 -> 2e-5 over 0..400, ZERO = 20.
ThermalModel hot_steel() {
  return ThermalModel(std::make_unique<LinearElastic>(2e5, 0.3), TemperatureTable{{0, 400}, {1e-5, 2e-5}}, 20,
                      TemperatureTable{{0, 200, 400}, {2e5, 1.5e5, 1e5}},
                      TemperatureTable{{0, 200, 400}, {0.3, 0.25, 0.2}});
}

PointContext at(double temperature, double initial) {
  PointContext c;
  c.temperature = temperature;
  c.initial_temperature = initial;
  return c;
}

}  // namespace

TEST(ThermalModel, TablesAreLinearInsideAndConstantOutside) {
  const std::vector<double> x = {0, 200, 400}, y = {2, 1.5, 1};
  EXPECT_DOUBLE_EQ(interpolate_table(x, y, -50), 2);
  EXPECT_DOUBLE_EQ(interpolate_table(x, y, 100), 1.75);
  EXPECT_DOUBLE_EQ(interpolate_table(x, y, 300), 1.25);
  EXPECT_DOUBLE_EQ(interpolate_table(x, y, 900), 1);
  EXPECT_DOUBLE_EQ(interpolate_table(std::vector<double>{7}, std::vector<double>{3}, -1e9), 3);
}

TEST(ThermalModel, ThermalStrainIsTheSecantFormAboutZero) {
  const TemperatureTable alpha{{0, 400}, {1e-5, 2e-5}};
  // alpha(T)(T - T0) - alpha(T_I)(T_I - T0), T0 = 20, T_I = 100, T = 300.
  const double expected = 1.75e-5 * 280 - 1.25e-5 * 80;
  EXPECT_NEAR(thermal_strain(alpha, 20, 300, 100), expected, 1e-18);
  EXPECT_EQ(thermal_strain(alpha, 20, 100, 100), 0.0);  // no strain at the initial temperature
  EXPECT_EQ(thermal_strain(TemperatureTable{}, 20, 300, 100), 0.0);
}

TEST(ThermalModel, FullyRestrainedPointCarriesTheClosedFormStress) {
  // E 2e5, nu 0.3, alpha 1.2e-5, dT = 100, all strains zero:
  // sigma = -E alpha dT / (1 - 2 nu) = -600 in every normal direction.
  const ThermalModel m(std::make_unique<LinearElastic>(2e5, 0.3), TemperatureTable{{}, {1.2e-5}}, 0, {}, {});
  Vec6 eps = Vec6::Zero();
  MaterialResponse r;
  m.update_small_strain(eps, false, {}, {}, at(120, 20), r);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(r.stress(i), -600, 1e-9);
  EXPECT_NEAR(r.stress(3), 0, 1e-12);
  // Plane stress restrained in-plane: sigma = -E alpha dT / (1 - nu), eps_33 free.
  eps.setZero();
  m.update_small_strain(eps, true, {}, {}, at(120, 20), r);
  EXPECT_NEAR(r.stress(0), -2e5 * 1.2e-3 / 0.7, 1e-8);
  EXPECT_NEAR(r.stress(2), 0, 1e-8);
  EXPECT_NEAR(eps(2), 1.2e-3 * (1 + 2 * 0.3 / 0.7), 1e-12);  // alpha dT + nu/(1-nu) * 2 alpha dT
}

TEST(ThermalModel, ElasticityFollowsTheTemperatureAndLinearityIsDeclaredOff) {
  const ThermalModel m = hot_steel();
  EXPECT_FALSE(m.linear_small_strain());
  const ThermalModel constant(std::make_unique<LinearElastic>(2e5, 0.3), TemperatureTable{{}, {1e-5}}, 0, {}, {});
  EXPECT_TRUE(constant.linear_small_strain());
  // Uniaxial strain at T = T_I = 100 (no thermal strain): sigma_11 = (lambda + 2 mu) eps with E 1.75e5, nu 0.275.
  Vec6 eps = Vec6::Zero();
  eps(0) = 1e-3;
  MaterialResponse r;
  m.update_small_strain(eps, false, {}, {}, at(100, 100), r);
  const LinearElastic reference(1.75e5, 0.275);
  EXPECT_NEAR(r.stress(0), (reference.lambda() + 2 * reference.mu()) * 1e-3, 1e-9);
}

TEST(ThermalModel, SmallStrainTangentMatchesFiniteDifferences) {
  const ThermalModel m = hot_steel();
  const double h = 1e-7;
  for (const bool plane_stress : {false, true}) {
    Vec6 eps;
    eps << 1e-3, -4e-4, 0, 6e-4, 0, 0;
    MaterialResponse r;
    Vec6 e0 = eps;
    m.update_small_strain(e0, plane_stress, {}, {}, at(330, 40), r);
    for (int j : {0, 1, 3}) {
      Vec6 ep = eps, em = eps;
      ep(j) += h, em(j) -= h;
      MaterialResponse rp, rm;
      m.update_small_strain(ep, plane_stress, {}, {}, at(330, 40), rp);
      m.update_small_strain(em, plane_stress, {}, {}, at(330, 40), rm);
      for (int i : {0, 1, 3})
        EXPECT_NEAR(r.tangent(i, j), (rp.stress(i) - rm.stress(i)) / (2 * h), 1e-5 * 2e5)
            << "plane stress " << plane_stress << " entry " << i << "," << j;
    }
  }
}

TEST(ThermalModel, FiniteStrainStressIsEnergyGradientAndTangentIsStressGradient) {
  std::vector<std::unique_ptr<ThermalModel>> models;
  models.push_back(std::make_unique<ThermalModel>(hot_steel()));
  models.push_back(std::make_unique<ThermalModel>(std::make_unique<NeoHooke>(40.0, 0.02),
                                                  TemperatureTable{{0, 400}, {1e-4, 3e-4}}, 0,
                                                  TemperatureTable{}, TemperatureTable{}));
  const double h = 1e-6;
  for (const auto& m : models)
    for (const Eigen::Matrix3d& F : test::random_deformations(4, 0.15, true)) {
      const Eigen::Matrix3d C0 = F.transpose() * F;
      const Vec6 E0 = test::green_lagrange_of(C0);
      const PointContext where = at(350, 20);
      const auto evaluate = [&](const Vec6& E) {
        Eigen::Matrix3d C = test::cauchy_green_of(E);
        MaterialResponse r;
        m->update_finite_strain(C, false, {}, {}, where, r);
        return r;
      };
      const MaterialResponse r = evaluate(E0);
      const double scale = r.tangent.cwiseAbs().maxCoeff();
      for (int j : {0, 1, 2, 3}) {
        Vec6 Ep = E0, Em = E0;
        Ep(j) += h, Em(j) -= h;
        const MaterialResponse rp = evaluate(Ep), rm = evaluate(Em);
        EXPECT_NEAR(r.stress(j), (rp.elastic_energy - rm.elastic_energy) / (2 * h), 1e-6 * scale) << m->describe();
        for (int i : {0, 1, 2, 3})
          EXPECT_NEAR(r.tangent(i, j), (rp.stress(i) - rm.stress(i)) / (2 * h), 1e-6 * scale) << m->describe();
      }
    }
}

TEST(ThermalModel, FiniteStrainFreeExpansionIsStressFreeAndPlaneStressThickens) {
  const ThermalModel m = hot_steel();
  const PointContext where = at(300, 20);
  const double stretch = 1 + m.thermal_strain(where);
  Eigen::Matrix3d C = stretch * stretch * Eigen::Matrix3d::Identity();
  MaterialResponse r;
  m.update_finite_strain(C, false, {}, {}, where, r);
  EXPECT_LT(r.stress.norm(), 1e-9);
  // Plane stress held in-plane at the thermal stretch: the thickness takes the thermal stretch too.
  Eigen::Matrix3d Cp = Eigen::Matrix3d::Identity() * stretch * stretch;
  Cp(2, 2) = 1;
  m.update_finite_strain(Cp, true, {}, {}, where, r);
  EXPECT_NEAR(std::sqrt(Cp(2, 2)), stretch, 1e-12);
  EXPECT_LT(r.stress.norm(), 1e-8);
}
