// The plane-stress strip pulled by a follower pressure under NLGEOM
// (tests/analysis/decks/plastic_strip_pressure.inp) through the program: every
// writer, and the .dat and the last VTU read back against the closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include "cli_support.hpp"

using namespace cli_test;

TEST(Cli, PlaneStressStripPulledByPressureRunsWithAllWritersAndReadsBackTheClosedForm) {
  const fs::path dir = scratch("plastic_strip_pressure");
  const fs::path deck = fs::path(TETHER_SOURCE_DIR) / "tests/analysis/decks/plastic_strip_pressure.inp";
  const auto run = tether("run --ascii " + deck.string() + " -o " + (dir / "out").string());
  ASSERT_EQ(run.code, 0) << run.out;
  const std::string job = "plastic_strip_pressure";
  for (const std::string f : {".pvd", ".dat", ".sta", ".msg", "_1_1.vtu", "_1_20.vtu"})
    EXPECT_TRUE(fs::exists(dir / "out" / (job + f))) << f;
  // Closed form (FiniteStrainPlasticity.PlaneStressStripPulledByPressureFollowsTheClosedForm).
  const double E = 200000, nu = 0.3, s0 = 200, H = 1000, p = 300, L = 10;
  double tau = p;
  for (int k = 0; k < 50; ++k) {
    const double a = std::exp(-(1 - 2 * nu) * tau / E);
    tau -= (tau * a - p) / (a * (1 - (1 - 2 * nu) * tau / E));
  }
  const double ep = (tau - s0) / H, ux = L * (std::exp(tau / E + ep) - 1), uy = std::exp(-nu * tau / E - ep / 2) - 1;

  // .dat: the last displacement block, node 3; the last stress and PEEQ rows (7 digits).
  const std::string dat = slurp(dir / "out" / (job + ".dat"));
  const auto last_block = [&](const std::string& title) {
    const auto at = dat.rfind(title);
    return at == std::string::npos ? std::string{} : dat.substr(dat.find('\n', at) + 1);
  };
  int node = 0;
  double u[3] = {};
  const std::string disp = last_block(" displacements (vx,vy,vz) for set ALL");
  const auto row3 = disp.find("\n         3 ");
  ASSERT_NE(row3, std::string::npos) << disp;
  ASSERT_EQ(std::sscanf(disp.c_str() + row3, "%d %lf %lf %lf", &node, &u[0], &u[1], &u[2]), 4);
  EXPECT_NEAR(u[0], ux, 1e-6 * ux);
  EXPECT_NEAR(u[1], uy, 1e-6 * std::abs(uy));
  int element = 0, point = 0;
  double s[6] = {}, peeq = 0;
  ASSERT_EQ(std::sscanf(last_block(" stresses (elem").c_str(), "%d %d %lf %lf %lf %lf %lf %lf", &element, &point, &s[0],
                        &s[1], &s[2], &s[3], &s[4], &s[5]),
            8);
  EXPECT_NEAR(s[0], p, 1e-6 * p);
  ASSERT_EQ(std::sscanf(last_block(" equivalent plastic strain").c_str(), "%d %d %lf", &element, &point, &peeq), 3);
  EXPECT_NEAR(peeq, ep, 1e-6 * ep);

  // The last VTU, at full precision: U of node 3, S and PEEQ at the points and nodes.
  const std::string vtu = slurp(dir / "out" / (job + "_1_20.vtu"));
  const std::vector<double> U = vtu_values(vtu, "U", 12);
  ASSERT_EQ(U.size(), 12u);
  EXPECT_NEAR(U[6], ux, 1e-8 * ux);
  EXPECT_NEAR(U[7], uy, 1e-8 * std::abs(uy));
  const std::vector<double> S = vtu_values(vtu, "S", 1), P = vtu_values(vtu, "PEEQ", 4);
  ASSERT_EQ(S.size(), 1u);
  ASSERT_EQ(P.size(), 4u);
  EXPECT_NEAR(S[0], p, 1e-8 * p);
  for (double v : P) EXPECT_NEAR(v, ep, 1e-8 * ep);
}

TEST(Cli, PlasticTemperatureTableBarRunsWithAllWritersAndReadsBackTheHotCurve) {
  // tests/analysis/decks/plastic_bar_temperature.inp: pulled at 150 degrees,
  // heated to 300 at fixed strain; at the end the stress is on the curve of
  // 300 degrees: p + (100 + 4000 p) / E = 0.02 (PlasticTemperature tests).
  const fs::path dir = scratch("plastic_bar_temperature");
  const fs::path deck = fs::path(TETHER_SOURCE_DIR) / "tests/analysis/decks/plastic_bar_temperature.inp";
  const auto run = tether("run --ascii " + deck.string() + " -o " + (dir / "out").string());
  ASSERT_EQ(run.code, 0) << run.out;
  const std::string job = "plastic_bar_temperature";
  for (const std::string f : {".pvd", ".dat", ".sta", ".msg", "_1_10.vtu", "_2_4.vtu"})
    EXPECT_TRUE(fs::exists(dir / "out" / (job + f))) << f;
  const double p = 0.0195 / 1.02, s = 100 + 4000 * p;

  // .dat (7 digits): the last stress and PEEQ rows.
  const std::string dat = slurp(dir / "out" / (job + ".dat"));
  const auto last_block = [&](const std::string& title) {
    const auto at = dat.rfind(title);
    return at == std::string::npos ? std::string{} : dat.substr(dat.find('\n', at) + 1);
  };
  int element = 0, point = 0;
  double sd[6] = {}, peeq = 0;
  ASSERT_EQ(std::sscanf(last_block(" stresses (elem").c_str(), "%d %d %lf %lf %lf %lf %lf %lf", &element, &point,
                        &sd[0], &sd[1], &sd[2], &sd[3], &sd[4], &sd[5]),
            8);
  EXPECT_NEAR(sd[0], s, 1e-6 * s);
  ASSERT_EQ(std::sscanf(last_block(" equivalent plastic strain").c_str(), "%d %d %lf", &element, &point, &peeq), 3);
  EXPECT_NEAR(peeq, p, 1e-6 * p);

  // The last VTU at full precision: S and PEEQ, and U of node 2 (the strain 0.02 held).
  const std::string vtu = slurp(dir / "out" / (job + "_2_4.vtu"));
  const std::vector<double> S = vtu_values(vtu, "S", 1), P = vtu_values(vtu, "PEEQ", 4), U = vtu_values(vtu, "U", 6);
  ASSERT_EQ(S.size(), 1u);
  ASSERT_EQ(P.size(), 4u);
  ASSERT_EQ(U.size(), 6u);
  EXPECT_NEAR(S[0], s, 1e-9 * s);
  for (double v : P) EXPECT_NEAR(v, p, 1e-10);
  EXPECT_NEAR(U[3], 0.2, 1e-12);
}
