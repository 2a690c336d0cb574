// *PLASTIC with a temperature column through the analysis
// (tests/analysis/decks/plastic_bar_temperature.inp): a uniaxial plane-stress
// bar at a uniform 150 degrees between the curves of 100 and 300 degrees is
// the bar with the hand-interpolated single curve; heated to 300 degrees at
// fixed strain its stress drops onto the hot curve as the closed form says
// (CalculiX 2.20 gives the same to its 7 printed digits).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "run_deck.hpp"

using namespace tether;
using namespace tether::testing;

namespace {

constexpr double kE = 200000, kStrain = 0.02;

/// The yield stress of the deck's table at PEEQ p and temperature T [stress].
double table_yield(double p, double T) {
  const auto cold = [](double q) { return q < 0.01 ? 200 + 1e4 * q : q < 0.05 ? 300 + 1250 * (q - 0.01) : 350.0; };
  const auto hot = [](double q) { return q < 0.02 ? 100 + 4000 * q : 180.0; };
  const double w = std::clamp((T - 100) / 200, 0.0, 1.0);
  return (1 - w) * cold(p) + w * hot(p);
}

/// The PEEQ of the uniaxial bar at total strain kStrain on the curve of T:
/// the root of g(p) = p + y(p, T) / E - kStrain, linear in p between the
/// table points 0, 0.01, 0.02, 0.05 of both curves (flat beyond 0.05).
double peeq_at(double T) {
  const double knots[] = {0, 0.01, 0.02, 0.05, 1};
  for (int i = 0; i + 1 < 5; ++i) {
    const double a = knots[i], b = knots[i + 1];
    const double slope = (table_yield(b, T) - table_yield(a, T)) / (b - a);
    const double p = a + (kStrain - a - table_yield(a, T) / kE) / (1 + slope / kE);
    if (p >= a && p <= b) return p;
  }
  return -1;
}

std::string deck() { return analysis_deck("plastic_bar_temperature.inp"); }

/// The deck with a single curve, the table interpolated at 150 degrees by
/// hand (through the union of the table points), and no heating.
std::string single_curve_deck() {
  std::string d = deck();
  const std::string table = "200., 0., 100.\n300., 0.01, 100.\n350., 0.05, 100.\n100., 0., 300.\n180., 0.02, 300.\n";
  const std::string hand = "175., 0.\n260., 0.01\n279.375, 0.02\n307.5, 0.05\n";
  d.replace(d.find(table), table.size(), hand);
  const std::string heat = "*TEMPERATURE\nNALL, 300.\n";
  d.replace(d.find(heat), heat.size(), "");
  return d;
}

}  // namespace

TEST(PlasticTemperature, BarBetweenTwoCurvesIsTheBarWithTheInterpolatedCurve) {
  const tether::testing::Run table = run_deck_text(deck()), single = run_deck_text(single_curve_deck());
  ASSERT_TRUE(table.summary.completed) << table.summary.message;
  ASSERT_TRUE(single.summary.completed) << single.summary.message;
  int compared = 0;
  for (const IncrementResults& a : table.recorder.results) {
    if (a.step != 1) continue;
    const auto b = std::find_if(single.recorder.results.begin(), single.recorder.results.end(),
                                [&](const IncrementResults& r) { return r.step == 1 && r.increment == a.increment; });
    ASSERT_NE(b, single.recorder.results.end());
    ASSERT_EQ(a.step_time, b->step_time);
    for (std::size_t n = 0; n < a.displacement.size(); ++n)
      EXPECT_LT((a.displacement[n] - b->displacement[n]).norm(), 1e-10 * 0.2) << n;
    for (std::size_t q = 0; q < a.points[0].size(); ++q) {
      const PointValues &pa = a.points[0][q], &pb = b->points[0][q];
      for (int c = 0; c < 4; ++c) EXPECT_NEAR(pa.stress[c], pb.stress[c], 1e-10 * 300) << c;
      EXPECT_NEAR(pa.peeq, pb.peeq, 1e-10 * std::max(pb.peeq, 1e-3));
    }
    ++compared;
  }
  EXPECT_EQ(compared, 10);  // *STATIC, DIRECT: ten increments of 0.1
  // The end of step 1 against the closed form on the curve of 150 degrees.
  const double p1 = peeq_at(150);
  EXPECT_NEAR(p1, 0.018616527390900650, 1e-15);  // (0.02 - 0.0013 + 0.000096875) / (1 + 1937.5 / E)
  for (const IncrementResults& r : table.recorder.results)
    if (r.step == 1 && std::abs(r.step_time - 1) < 1e-9)
      for (const PointValues& p : r.points[0]) {
        EXPECT_NEAR(p.stress[0], table_yield(p1, 150), 1e-9 * 300);
        EXPECT_NEAR(p.peeq, p1, 1e-12);
      }
}

TEST(PlasticTemperature, HeatingAtFixedStrainDropsTheStressOntoTheHotterCurve) {
  const tether::testing::Run run = run_deck_text(deck());
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  int checked = 0;
  for (const IncrementResults& r : run.recorder.results) {
    if (r.step != 2) continue;
    // The temperature ramps from 150 to 300 over the step; PEEQ only grows, and
    // the yield stress falls with T, so the point sits on the curve of T.
    const double T = 150 + 150 * r.step_time / r.period;
    const double p = peeq_at(T), stress = table_yield(p, T);
    for (const PointValues& q : r.points[0]) {
      EXPECT_NEAR(q.stress[0], stress, 1e-9 * 300) << "T = " << T;
      EXPECT_NEAR(q.peeq, p, 1e-12) << "T = " << T;
      EXPECT_NEAR(q.stress[1], 0, 1e-9 * 300);
    }
    ++checked;
  }
  EXPECT_EQ(checked, 4);  // *STATIC, DIRECT: four increments of 0.25
  // The end: on the hot curve, p + (100 + 4000 p) / E = 0.02.
  const double p2 = 0.0195 / 1.02;
  for (const PointValues& q : run.last().points[0]) {
    EXPECT_NEAR(q.peeq, p2, 1e-12);
    EXPECT_NEAR(q.stress[0], 100 + 4000 * p2, 1e-9 * 300);  // 176.4706, CalculiX 2.20: 1.764706E+02
  }
  // CalculiX 2.20 on the same deck, S11 at the end of each increment of step 2 (7 digits).
  const double ccx[] = {251.4471, 226.3279, 201.3361, 176.4706};
  int k = 0;
  for (const IncrementResults& r : run.recorder.results)
    if (r.step == 2 && k < 4) {
      EXPECT_NEAR(r.points[0][0].stress[0], ccx[k], 5e-7 * ccx[k]) << k;
      std::printf("ccx %.7g tether %.10g difference %.2e\n", ccx[k], r.points[0][0].stress[0],
                  r.points[0][0].stress[0] - ccx[k]);
      ++k;
    }
}

TEST(PlasticTemperature, CyclicHardeningWithATemperatureColumnIsRead) {
  // HARDENING=COMBINED, both tables with temperatures: the reader keeps the
  // column and the analysis runs (the constitutive tests check the values).
  std::string d = deck();
  d.replace(d.find("*PLASTIC\n"), 9, "*PLASTIC, HARDENING=COMBINED\n");
  const std::string after = "180., 0.02, 300.\n";
  d.replace(d.find(after), after.size(), after + "*CYCLIC HARDENING\n200., 0., 100.\n150., 0., 300.\n");
  const tether::testing::Run run = run_deck_text(d);
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  const auto& plastic = *run.model.materials.at(0).plastic;
  EXPECT_EQ(plastic.temperature, (std::vector<double>{100, 100, 100, 300, 300}));
  EXPECT_EQ(plastic.cyclic_temperature, (std::vector<double>{100, 300}));
  // Perfectly plastic cyclic yield stress at 150 degrees: 0.75 * 200 + 0.25 * 150 plus the back stress.
  EXPECT_GT(run.last().points[0][0].peeq, 0.01);
}

TEST(PlasticTemperature, TemperatureDependentElasticityWithPlasticityIsStillRefused) {
  std::string d = deck();
  d.replace(d.find("200000., 0.3\n"), 13, "200000., 0.3, 100.\n150000., 0.3, 300.\n");
  try {
    run_deck_text(d);
    FAIL() << "accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("temperature-dependent *ELASTIC with *PLASTIC is not supported"),
              std::string::npos)
        << e.what();
  }
}
