// Temperature loads through whole analyses: a free plate heated uniformly, a
// fully restrained plane-strain block, a thick cylinder with a logarithmic
// radial temperature (Timoshenko & Goodier), temperatures over several steps
// (ramp, AMPLITUDE=STEP, amplitudes, OP=NEW), NLGEOM free expansion, and a
// temperature-dependent E/nu/alpha deck against CalculiX.
#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <sstream>

#include "analysis/run_deck.hpp"

using namespace tether;
using tether::testing::run_deck_text;

namespace {

/// A 2 x 1 plate of two `type` elements, material E 2e5, nu 0.3 with
/// `expansion` lines, initial temperature 20, then `rest` (boundary, steps).
std::string plate(const std::string& type, const std::string& expansion, const std::string& rest) {
  return "*NODE, NSET=ALL\n1, 0, 0\n2, 1, 0\n3, 2, 0\n4, 0, 1\n5, 1, 1\n6, 2, 1\n*ELEMENT, TYPE=" + type +
         ", ELSET=E\n1, 1, 2, 5, 4\n2, 2, 3, 6, 5\n*NSET, NSET=EDGE\n1, 3, 4, 6\n*MATERIAL, NAME=M\n*ELASTIC\n"
         "2e5, 0.3\n" + expansion + "\n*SOLID SECTION, ELSET=E, MATERIAL=M\n*INITIAL CONDITIONS, "
         "TYPE=TEMPERATURE\nALL, 20\n" + rest;
}

/// Largest |value| of the point stresses of the last increment, component c.
double max_stress(const tether::testing::Run& run, int c) {
  double m = 0;
  for (const auto& element : run.last().points)
    for (const PointValues& p : element) m = std::max(m, std::abs(p.stress[c]));
  return m;
}

}  // namespace

TEST(ThermalStress, FreePlateHeatedUniformlyExpandsWithoutStress) {
  for (const bool nlgeom : {false, true}) {
    const std::string step = nlgeom ? "*STEP, NLGEOM\n" : "*STEP\n";
    const auto run = run_deck_text(plate("CPS4", "*EXPANSION, ZERO=20\n1.2e-5",
                                         "*BOUNDARY\n1, 1, 2\n4, 1\n" + step +
                                             "*STATIC\n*TEMPERATURE\nALL, 120\n*END STEP\n"));
    ASSERT_TRUE(run.summary.completed);
    const double eth = 1.2e-5 * 100;
    for (int id : {2, 3, 5, 6}) {
      const Eigen::Vector2d x = run.model.coords[run.node(id)];
      EXPECT_NEAR(run.last().displacement[run.node(id)].x(), eth * x.x(), 1e-10 * eth) << "nlgeom " << nlgeom;
      EXPECT_NEAR(run.last().displacement[run.node(id)].y(), eth * x.y(), 1e-10 * eth) << "nlgeom " << nlgeom;
    }
    for (int c = 0; c < 4; ++c) EXPECT_LT(max_stress(run, c), 1e-10 * 2e5 * eth) << "nlgeom " << nlgeom;
    for (double t : run.last().temperature) EXPECT_DOUBLE_EQ(t, 120);
    if (!nlgeom)  // small strain: the printed strain is the total one, alpha dT (eps_33 too in plane stress)
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(run.last().points[0][0].strain[c], eth, 1e-10 * eth);
  }
}

TEST(ThermalStress, FullyRestrainedPlaneStrainBlockCarriesMinusEAlphaDTOverOneMinusTwoNu) {
  // E 2e5, alpha 1.2e-5, dT 100, nu 0.3: sigma_xx = sigma_yy = sigma_zz = -E alpha dT / (1 - 2 nu) = -600.
  const auto run = run_deck_text(plate("CPE4", "*EXPANSION\n1.2e-5", R"(*BOUNDARY
ALL, 1, 2
*STEP
*STATIC
*TEMPERATURE
ALL, 120
*END STEP
)"));
  ASSERT_TRUE(run.summary.completed);
  for (const auto& element : run.last().points)
    for (const PointValues& p : element) {
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(p.stress[c], -600, 1e-9);
      EXPECT_NEAR(p.stress[3], 0, 1e-9);
    }
}

TEST(ThermalStress, TemperaturesFollowTheStepsAsAbaqusAppliesThem) {
  // Step 1 ramps node set ALL to 120; step 2 (AMPLITUDE=STEP) holds EDGE at 220
  // from its start, the others keep 120; step 3 (OP=NEW) sends every node back
  // to its initial 20 except node 1, which follows an amplitude.
  const auto run = run_deck_text(plate("CPS4", "*EXPANSION\n1e-5", R"(*AMPLITUDE, NAME=TWICE
0, 0, 1, 2
*BOUNDARY
1, 1, 2
4, 1
*STEP
*STATIC
0.5, 1
*TEMPERATURE
ALL, 120
*END STEP
*STEP, AMPLITUDE=STEP
*STATIC
0.5, 1
*TEMPERATURE
EDGE, 220
*END STEP
*STEP
*STATIC
0.5, 1
*TEMPERATURE, OP=NEW, AMPLITUDE=TWICE
1, 50
*END STEP
)"));
  ASSERT_TRUE(run.summary.completed);
  const auto& r = run.recorder.results;
  ASSERT_EQ(r.size(), 6u);
  const auto T = [&](std::size_t k, int id) { return r[k].temperature[static_cast<std::size_t>(run.node(id))]; };
  EXPECT_DOUBLE_EQ(T(0, 2), 70);   // half-way up the ramp 20 -> 120
  EXPECT_DOUBLE_EQ(T(1, 2), 120);
  EXPECT_DOUBLE_EQ(T(2, 1), 220);  // AMPLITUDE=STEP: applied at the step's start
  EXPECT_DOUBLE_EQ(T(2, 2), 120);  // not listed: kept
  EXPECT_DOUBLE_EQ(T(4, 2), 70);   // OP=NEW: ramped back to its initial temperature
  EXPECT_DOUBLE_EQ(T(4, 3), 120);  // 220 -> 20, half-way
  EXPECT_DOUBLE_EQ(T(4, 1), 50);   // 50 * a(0.5) = 50 * 1
  EXPECT_DOUBLE_EQ(T(5, 1), 100);
  EXPECT_DOUBLE_EQ(T(5, 6), 20);
}

namespace {

/// Thick cylinder a = 1, b = 2 of `n` CAX8 elements through the wall, held
/// axially at z = 0 and z = h (plane strain), T(r) = Ta ln(b/r)/ln(b/a).
std::string thick_cylinder(int n, double Ta) {
  const double a = 1, b = 2, h = 0.05;
  std::ostringstream d, temps;
  d << std::setprecision(17) << "*NODE, NSET=ALL\n";
  temps << std::setprecision(17);
  const auto id = [&](int i, int j) { return 1 + i + j * (2 * n + 1); };  // i: radial, j: 0..2 axial
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i <= 2 * n; ++i) {
      if (j == 1 && i % 2 == 1) continue;
      const double r = a + (b - a) * i / (2.0 * n);
      d << id(i, j) << ", " << r << ", " << h * j / 2 << "\n";
      temps << id(i, j) << ", " << Ta * std::log(b / r) / std::log(b / a) << "\n";
    }
  d << "*ELEMENT, TYPE=CAX8, ELSET=E\n";
  for (int e = 0; e < n; ++e) {
    const int i = 2 * e;
    d << e + 1;
    for (int node : {id(i, 0), id(i + 2, 0), id(i + 2, 2), id(i, 2), id(i + 1, 0), id(i + 2, 1), id(i + 1, 2), id(i, 1)})
      d << ", " << node;
    d << "\n";
  }
  d << "*NSET, NSET=ENDS\n";
  for (int i = 0; i <= 2 * n; ++i) d << id(i, 0) << ",\n" << id(i, 2) << ",\n";
  d << "*MATERIAL, NAME=M\n*ELASTIC\n2e5, 0.3\n*EXPANSION\n1.2e-5\n"
       "*SOLID SECTION, ELSET=E, MATERIAL=M\n*BOUNDARY\nENDS, 2, 2\n*STEP\n*STATIC\n*TEMPERATURE\n"
    << temps.str() << "*END STEP\n";
  return d.str();
}

}  // namespace

TEST(ThermalStress, ThickCylinderWithLogarithmicTemperatureMatchesTimoshenkoGoodier) {
  // Timoshenko & Goodier, Theory of Elasticity, section 150 (plane strain,
  // T = Ta ln(b/r)/ln(b/a), stress free at T = 0):
  //   sigma_r = K [-ln(b/r) - a^2/(b^2-a^2) (1 - b^2/r^2) ln(b/a)]
  //   sigma_t = K [1 - ln(b/r) - a^2/(b^2-a^2) (1 + b^2/r^2) ln(b/a)]
  //   sigma_z = nu (sigma_r + sigma_t) - E alpha T,   K = alpha E Ta / (2 (1 - nu) ln(b/a)).
  // Mesh: 40 CAX8 elements through the wall (3 x 3 points), one axially.
  const double a = 1, b = 2, E = 2e5, nu = 0.3, alpha = 1.2e-5, Ta = 100;
  const auto run = run_deck_text(thick_cylinder(40, Ta));
  ASSERT_TRUE(run.summary.completed);
  const double L = std::log(b / a), K = alpha * E * Ta / (2 * (1 - nu) * L), c = a * a / (b * b - a * a);
  double err[3] = {0, 0, 0}, peak[3] = {0, 0, 0};
  for (const auto& element : run.last().points)
    for (const PointValues& p : element) {
      const double r = p.x.x(), T = Ta * std::log(b / r) / L;
      const double sr = K * (-std::log(b / r) - c * (1 - b * b / (r * r)) * L);
      const double st = K * (1 - std::log(b / r) - c * (1 + b * b / (r * r)) * L);
      const double sz = nu * (sr + st) - E * alpha * T;
      const double exact[3] = {sr, sz, st};  // tether's axisymmetric order: rr, zz, hoop
      for (int k = 0; k < 3; ++k) {
        err[k] = std::max(err[k], std::abs(p.stress[k] - exact[k]));
        peak[k] = std::max(peak[k], std::abs(exact[k]));
      }
    }
  for (int k = 0; k < 3; ++k) EXPECT_LT(err[k], 0.01 * peak[k]) << "component " << k << ": " << err[k] << " of " << peak[k];
}

TEST(ThermalStress, TemperatureDependentPlaneStressStripAgreesWithCalculix) {
  // ccx 2.20 on the same deck (its CPS8 expanded to C3D20, plane stress by
  // its expansion): sigma_xx at the points of element 1 (rows y = 0.11, 0.5,
  // 0.89) and the rise of nodes 6 and 11. tether within 0.2 %.
  const auto run = tether::testing::run_deck_file(std::string(TETHER_SOURCE_DIR) +
                                                  "/tests/analysis/decks/thermal_tdep_cps8.inp");
  ASSERT_TRUE(run.summary.completed);
  const auto& points = run.last().points[0];
  const double ccx_sxx[3] = {-2.417865e+02, -4.144583e+02, -5.677648e+02};
  for (int row = 0; row < 3; ++row)
    EXPECT_NEAR(points[static_cast<std::size_t>(3 * row)].stress[0], ccx_sxx[row], 2e-3 * std::abs(ccx_sxx[row]));
  EXPECT_NEAR(run.last().displacement[run.node(6)].y(), 1.181132e-03, 2e-3 * 1.181132e-03);
  EXPECT_NEAR(run.last().displacement[run.node(11)].y(), 3.440432e-03, 2e-3 * 3.440432e-03);
}

TEST(ThermalStress, ConstantElasticityKeepsTheLinearBulkAndATableDoesNot) {
  // A thermal load with constant E is affine in u (K u - f_th(t)): the held
  // bulk gives the displacements of a full assembly. With a temperature table
  // the tangent changes with T(t): nothing is held.
  const std::string rest = R"(*BOUNDARY
1, 1, 2
4, 1
3, 1
*STEP
*STATIC
0.5, 1
*TEMPERATURE
EDGE, 150
*CLOAD
6, 2, 50
*END STEP
)";
  for (const bool table : {false, true}) {
    const std::string expansion = table ? "*EXPANSION\n1e-5\n" : "*EXPANSION\n1e-5";
    std::string deck = plate("CPS4", expansion, rest);
    if (table) deck.replace(deck.find("2e5, 0.3\n"), 9, "2e5, 0.3, 0\n1e5, 0.2, 200\n");
    const auto held = run_deck_text(deck);
    AnalysisOptions fresh_options;
    fresh_options.reuse_linear_bulk = false;
    const auto fresh = run_deck_text(deck, fresh_options);
    ASSERT_TRUE(held.summary.completed && fresh.summary.completed);
    if (table) EXPECT_EQ(held.summary.timing.held_tangents, 0);
    else EXPECT_GT(held.summary.timing.held_tangents, 0);
    ASSERT_EQ(held.recorder.results.size(), fresh.recorder.results.size());
    for (std::size_t k = 0; k < held.recorder.results.size(); ++k)
      for (std::size_t n = 0; n < held.recorder.results[k].displacement.size(); ++n)
        EXPECT_LT((held.recorder.results[k].displacement[n] - fresh.recorder.results[k].displacement[n]).norm(), 1e-14)
            << "table " << table << " increment " << k;
  }
}
