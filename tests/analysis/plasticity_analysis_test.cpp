// Small-strain plasticity through the whole analysis: the perfectly plastic
// thick cylinder (Hill's elastic-plastic radius, the limit pressure, Newton's
// order with the consistent tangent, restart continuing identically, the
// yield flag), the plane-stress kinematic bar, the punch against CalculiX and
// combined hardening. The NLGEOM cases: finite_strain_plasticity_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "run_deck.hpp"
#include "tether/output/restart_file.hpp"

using namespace tether;
using namespace tether::testing;
namespace fs = std::filesystem;

namespace {

constexpr double kYield = 240, kA = 10, kB = 20;

std::string cylinder_deck() { return tether::testing::analysis_deck("plastic_cylinder.inp"); }

using tether::testing::replaced;

/// Hill: the pressure at which the plastic zone reaches r = c.
double hill_pressure(double c) {
  return kYield / std::sqrt(3.0) * (2 * std::log(c / kA) + 1 - c * c / (kB * kB));
}

/// Only step 1, loaded to `pressure`, with increments of `dt` (fixed when `fixed`).
std::string loaded_to(double pressure, const std::string& increments = "0.1, 1., 1e-6, 0.1") {
  std::string d = replaced(cylinder_deck(), "BORE, P, 172.99", "BORE, P, " + std::to_string(pressure));
  d = replaced(d, "0.1, 1., 1e-6, 0.1", increments);
  return d.substr(0, d.find("*STEP", d.find("*END STEP")));
}

}  // namespace

TEST(PlasticCylinder, PlasticZoneFollowsHillsSolution) {
  const double c = 15;
  const tether::testing::Run run = run_deck_text(loaded_to(hill_pressure(c)));
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  double outermost_plastic = 0, innermost_elastic = kB;
  for (const auto& element : run.last().points)
    for (const PointValues& p : element) {
      const double r = p.x.norm();
      (p.peeq > 0 ? outermost_plastic : innermost_elastic) =
          p.peeq > 0 ? std::max(outermost_plastic, r) : std::min(innermost_elastic, r);
    }
  // The front lies between the two; the radial point spacing is about 0.5.
  std::printf("Hill c = %.3f; plastic points up to r = %.3f, elastic from r = %.3f\n", c, outermost_plastic,
              innermost_elastic);
  EXPECT_LT(std::abs(outermost_plastic - c), 0.6);
  EXPECT_LT(std::abs(innermost_elastic - c), 0.6);
  EXPECT_LT(outermost_plastic, innermost_elastic);
}

TEST(PlasticCylinder, LimitPressureIsApproachedAndNotExceeded) {
  const double limit = 2 / std::sqrt(3.0) * kYield * std::log(kB / kA);
  const auto bore_displacement = [](const tether::testing::Run& run) {
    return run.last().displacement[static_cast<std::size_t>(run.node(1))].x();  // node 1 at (a, 0)
  };
  const tether::testing::Run below = run_deck_text(loaded_to(0.99 * limit, "0.05, 1., 1e-6, 0.05"));
  ASSERT_TRUE(below.summary.completed) << below.summary.message;
  const tether::testing::Run elastic = run_deck_text(loaded_to(0.5 * limit));
  // The bore moves much more than the elastic extrapolation near the limit.
  const double ratio = bore_displacement(below) / (bore_displacement(elastic) * 0.99 / 0.5);
  std::printf("0.99 p_L: bore displacement %.4g = %.2f x the elastic extrapolation\n", bore_displacement(below),
              ratio);
  EXPECT_GT(ratio, 2);
  const tether::testing::Run above = run_deck_text(loaded_to(1.02 * limit, "0.05, 1., 1e-4, 0.05"));
  EXPECT_FALSE(above.summary.completed);
  if (!above.recorder.results.empty()) {
    const double reached = above.recorder.results.back().step_time * 1.02;
    std::printf("1.02 p_L: stopped at p = %.6f p_L\n", reached);
    EXPECT_LT(reached, 1.002);
    EXPECT_GT(reached, 0.995);
  }
}

TEST(PlasticCylinder, NewtonConvergesQuadraticallyWithTheConsistentTangent) {
  const tether::testing::Run run = run_deck_text(loaded_to(hill_pressure(17)));
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  // Order from three successive residuals above round-off: log(r2/r1) / log(r1/r0).
  double worst = INFINITY;
  int measured = 0;
  for (const auto& r : run.recorder.residuals) {
    for (std::size_t k = 1; k + 1 < r.size(); ++k) {
      if (r[k + 1] < 1e-9 * r[0] || r[k] >= r[k - 1] || r[k + 1] >= r[k]) continue;
      const double order = std::log(r[k + 1] / r[k]) / std::log(r[k] / r[k - 1]);
      worst = std::min(worst, order);
      ++measured;
    }
  }
  std::printf("Newton order: %d measurements, smallest %.2f; %d increments, %d iterations\n", measured, worst,
              run.summary.increments, run.summary.iterations);
  EXPECT_GE(measured, 3);
  EXPECT_GE(worst, 1.8);
}

namespace {

class StateRecorder final : public AnalysisObserver {
 public:
  void on_results(const IncrementResults& r, const Step&, bool) override { results.push_back(r); }
  void on_restart_state(const RestartState& s) override {
    states.push_back(decode_restart(encode_restart(s), "memory.rst"));
  }
  std::vector<IncrementResults> results;
  std::vector<RestartState> states;
};

struct Outcome {
  AnalysisSummary summary;
  Eigen::VectorXd u;
  StateRecorder recorder;
};

Outcome run_model(const Model& model, const RestartState* from = nullptr) {
  Outcome out;
  StaticAnalysis analysis(model, out.recorder);
  if (from) analysis.resume(*from, "memory.rst");
  out.summary = analysis.run();
  out.u = analysis.solution();
  return out;
}

}  // namespace

TEST(PlasticCylinder, RestartContinuesThePlasticAnalysisIdentically) {
  const Model model = read_deck_string(cylinder_deck(), "plastic_cylinder.inp");
  const Outcome full = run_model(model);
  ASSERT_TRUE(full.summary.completed) << full.summary.message;
  ASSERT_GE(full.recorder.states.size(), 10u);
  // Unloaded: residual plastic strain remains.
  double peeq = 0;
  for (const auto& element : full.recorder.results.back().points)
    for (const PointValues& p : element) peeq = std::max(peeq, p.peeq);
  EXPECT_GT(peeq, 1e-4);
  for (std::size_t k : {std::size_t{6}, std::size_t{10}, full.recorder.states.size() - 3}) {
    const Outcome resumed = run_model(model, &full.recorder.states[k]);
    ASSERT_TRUE(resumed.summary.completed) << resumed.summary.message;
    EXPECT_EQ((resumed.u - full.u).cwiseAbs().maxCoeff(), 0.0) << "from state " << k;
    const IncrementResults &a = resumed.recorder.results.back(), &b = full.recorder.results.back();
    for (std::size_t e = 0; e < a.points.size(); ++e)
      for (std::size_t q = 0; q < a.points[e].size(); ++q) {
        EXPECT_EQ(a.points[e][q].peeq, b.points[e][q].peeq);
        EXPECT_EQ(a.points[e][q].stress, b.points[e][q].stress);
      }
    EXPECT_EQ(encode_restart(resumed.recorder.states.back()), encode_restart(full.recorder.states.back()));
  }
}

TEST(PlasticCylinder, YieldFlagMarksThePointsWhosePeeqGrewInTheIncrement) {
  // Loaded to Hill's c = 15 in step 1 (the points flow from 0.6 of the load on,
  // an inner zone only), unloaded elastically in step 2.
  const tether::testing::Run run = run_deck_text(cylinder_deck());
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  std::vector<std::vector<double>> peeq_before;  // per element, per point: PEEQ of the increment before
  int yielding_at_end_of_loading = 0, points = 0;
  double outermost_yielding = 0;
  for (const IncrementResults& r : run.recorder.results) {
    SCOPED_TRACE("step " + std::to_string(r.step) + " increment " + std::to_string(r.increment));
    if (peeq_before.empty())
      for (const auto& element : r.points) peeq_before.emplace_back(element.size(), 0.0);
    int yielding = 0;
    points = 0;
    for (std::size_t e = 0; e < r.points.size(); ++e) {
      double fraction = 0;
      for (std::size_t q = 0; q < r.points[e].size(); ++q) {
        const PointValues& p = r.points[e][q];
        const bool grew = p.peeq > peeq_before[e][q];
        ASSERT_EQ(p.ac_yield, grew ? 1 : 0) << "element " << e << " point " << q << " at r = " << p.x.norm();
        peeq_before[e][q] = p.peeq;
        yielding += p.ac_yield, ++points;
        fraction += p.ac_yield / static_cast<double>(r.points[e].size());
        if (r.step == 1 && p.ac_yield) outermost_yielding = std::max(outermost_yielding, p.x.norm());
      }
      EXPECT_EQ(r.element_ac_yield.at(e), fraction);
    }
    for (const double v : r.nodal_ac_yield) {
      EXPECT_GE(v, 0.0);
      EXPECT_LE(v, 1.0);
    }
    if (r.step == 2) EXPECT_EQ(yielding, 0);  // unloading is elastic
    if (r.step == 1 && r.step_time > 1 - 1e-12) yielding_at_end_of_loading = yielding;
  }
  // At the end of loading the inner zone yields (r < c = 15, as PEEQ says), the outer ring does not.
  std::printf("end of loading: %d of %d points yielding, out to r = %.3f (Hill: c = 15)\n",
              yielding_at_end_of_loading, points, outermost_yielding);
  EXPECT_GT(yielding_at_end_of_loading, points / 4);
  EXPECT_LT(yielding_at_end_of_loading, points * 3 / 4);
  EXPECT_LT(std::abs(outermost_yielding - 15), 0.6);
  // Nodes: the bore's nodes sit in yielding elements only, the outer surface's in elastic ones.
  const IncrementResults& end1 = *std::find_if(run.recorder.results.rbegin(), run.recorder.results.rend(),
                                               [](const IncrementResults& r) { return r.step == 1; });
  EXPECT_EQ(end1.nodal_ac_yield[static_cast<std::size_t>(run.node(1))], 1.0);   // (a, 0)
  EXPECT_EQ(end1.nodal_ac_yield[static_cast<std::size_t>(run.node(164))], 0.0);  // on r = b
}

TEST(PlasticCylinder, RestartKeepsTheYieldFlag) {
  const Model model = read_deck_string(cylinder_deck(), "plastic_cylinder.inp");
  const Outcome full = run_model(model);
  ASSERT_TRUE(full.summary.completed) << full.summary.message;
  // Resume from each state of the loading step's plastic part: every later increment flags the same points.
  int compared = 0;
  for (std::size_t k = 5; k < 9; ++k) {
    const Outcome resumed = run_model(model, &full.recorder.states[k]);
    ASSERT_TRUE(resumed.summary.completed) << resumed.summary.message;
    ASSERT_EQ(resumed.recorder.results.size(), full.recorder.results.size() - k - 1);
    for (std::size_t i = 0; i < resumed.recorder.results.size(); ++i) {
      const IncrementResults &a = resumed.recorder.results[i], &b = full.recorder.results[k + 1 + i];
      for (std::size_t e = 0; e < a.points.size(); ++e)
        for (std::size_t q = 0; q < a.points[e].size(); ++q) {
          EXPECT_EQ(a.points[e][q].ac_yield, b.points[e][q].ac_yield) << "from state " << k << ", increment " << i;
          compared += b.points[e][q].ac_yield;
        }
      EXPECT_EQ(a.nodal_ac_yield, b.nodal_ac_yield);
    }
  }
  EXPECT_GT(compared, 100);  // yielding points were compared, not only zeros
}

TEST(PlasticBar, PlaneStressKinematicBarMatchesTheClosedFormWithItsOutput) {
  // One CPS4 (1 x 1, thickness 0.1) pulled to eps = 0.004, then pushed to -0.002:
  // uniaxial stress, linear kinematic hardening (yield 200, H = 10000, E = 200000).
  const std::string deck = R"(*NODE, NSET=ALL
1, 0, 0
2, 1, 0
3, 1, 1
4, 0, 1
*ELEMENT, TYPE=CPS4, ELSET=PS
1, 1, 2, 3, 4
*NSET, NSET=TOP
3, 4
*NSET, NSET=BOTTOM
1, 2
*MATERIAL, NAME=KIN
*ELASTIC
200000, 0.3
*PLASTIC, HARDENING=KINEMATIC
200., 0.
10200., 1.
*SOLID SECTION, ELSET=PS, MATERIAL=KIN
0.1
*BOUNDARY
BOTTOM, 2, 2
1, 1, 1
*STEP
*STATIC
0.1, 1.
*CONTROLS, PARAMETERS=FIELD
1e-12, 1e-12
*BOUNDARY
TOP, 2, 2, 0.004
*END STEP
*STEP
*STATIC
0.1, 1.
*CONTROLS, PARAMETERS=FIELD
1e-12, 1e-12
*BOUNDARY
TOP, 2, 2, -0.002
*END STEP
)";
  const tether::testing::Run run = run_deck_text(deck);
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  const double E = 200000, s0 = 200, H = 10000, volume = 0.1;
  const double ep1 = (0.004 - s0 / E) / (1 + H / E), s1 = s0 + H * ep1;
  const double s2 = (H * -0.002 - s0) / (1 + H / E), ep2 = -0.002 - s2 / E;
  const IncrementResults* end1 = nullptr;
  for (const auto& r : run.recorder.results)
    if (r.step == 1) end1 = &r;
  ASSERT_NE(end1, nullptr);
  const IncrementResults& end2 = run.last();
  for (const PointValues& p : end1->points[0]) {
    EXPECT_NEAR(p.stress[1], s1, 1e-9 * s1);
    EXPECT_NEAR(p.peeq, ep1, 1e-12);
    EXPECT_NEAR(p.plastic_strain[1], ep1, 1e-12);
    EXPECT_NEAR(p.plastic_strain[0], -0.5 * ep1, 1e-12);
  }
  for (const PointValues& p : end2.points[0]) {
    EXPECT_NEAR(p.stress[1], s2, 1e-9 * s0);
    EXPECT_NEAR(p.peeq, ep1 + (ep1 - ep2), 1e-12);
    EXPECT_NEAR(p.plastic_strain[1], ep2, 1e-12);
  }
  ASSERT_EQ(end2.nodal_peeq.size(), 4u);
  ASSERT_EQ(end2.element_peeq.size(), 1u);
  EXPECT_NEAR(end2.nodal_peeq[2], ep1 + (ep1 - ep2), 1e-12);
  EXPECT_NEAR(end2.element_peeq[0], ep1 + (ep1 - ep2), 1e-12);
  EXPECT_NEAR(end2.nodal_plastic_strain[2][1], ep2, 1e-12);
  // ALLPD: sigma d eps_p, linear in eps_p on both legs (reverse yield at s1 - 2 s0).
  const double work1 = 0.5 * (s0 + s1) * ep1, work2 = 0.5 * ((s1 - 2 * s0) + s2) * (ep2 - ep1);
  ASSERT_TRUE(end1->plastic_dissipation && end2.plastic_dissipation);
  EXPECT_NEAR(*end1->plastic_dissipation, volume * work1, 1e-10 * volume * work1);
  EXPECT_NEAR(*end2.plastic_dissipation, volume * (work1 + work2), 1e-10 * volume * (work1 + work2));
}

TEST(PlasticPunch, ForceAgainstIndentationMatchesCalculix) {
  // CalculiX 2.20 on the same deck: total punch force at t = 0.1, 0.2, ..., 1.0.
  const double ccx[] = {0.9303154, 1.113623, 1.17228, 1.215603, 1.254085,
                        1.289807, 1.323976, 1.356508, 1.386587, 1.414843};
  const tether::testing::Run run = tether::testing::run_deck_file(
      (fs::path(TETHER_SOURCE_DIR) / "tests/analysis/decks/plastic_punch.inp").string());
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  ASSERT_EQ(run.recorder.results.size(), 10u);
  double worst = 0;
  for (std::size_t k = 0; k < 10; ++k) {
    double force = 0;
    for (int n : run.model.node_sets.at("PUSH")) force += run.recorder.results[k].reaction[static_cast<std::size_t>(n)].y();
    worst = std::max(worst, std::abs(-force - ccx[k]) / ccx[k]);
  }
  std::printf("punch force against CalculiX: largest relative difference %.2e\n", worst);
  EXPECT_LT(worst, 1e-3);
  double peeq = 0;
  for (const auto& element : run.last().points)
    for (const PointValues& p : element) peeq = std::max(peeq, p.peeq);
  EXPECT_NEAR(peeq, 0.02614461, 0.002 * 0.02614461);  // CalculiX: largest PEEQ at t = 1
}

namespace {

std::string error_of(const std::string& deck) {
  try {
    const tether::testing::Run run = run_deck_text(deck);
    return run.summary.completed ? "(completed)" : run.summary.message;
  } catch (const std::exception& e) {
    return e.what();
  }
}

}  // namespace

TEST(CombinedHardening, ConstantCyclicTableGivesTheKinematicAnswer) {
  // HARDENING=COMBINED with *CYCLIC HARDENING at the constant first yield
  // stress is kinematic hardening: the thick cylinder loaded and unloaded.
  const std::string from = "*PLASTIC\n240., 0.\n";
  const auto kinematic = run_deck_text(replaced(cylinder_deck(), from, "*PLASTIC, HARDENING=KINEMATIC\n240., 0.\n"
                                                                       "1240., 1.\n"));
  const auto combined = run_deck_text(replaced(cylinder_deck(), from, "*PLASTIC, HARDENING=COMBINED\n240., 0.\n"
                                                                      "1240., 1.\n*CYCLIC HARDENING\n240., 0.\n"));
  ASSERT_TRUE(kinematic.summary.completed) << kinematic.summary.message;
  ASSERT_TRUE(combined.summary.completed) << combined.summary.message;
  ASSERT_EQ(kinematic.recorder.results.size(), combined.recorder.results.size());
  double worst = 0, scale = 0;
  for (std::size_t k = 0; k < kinematic.recorder.results.size(); ++k)
    for (std::size_t n = 0; n < kinematic.last().displacement.size(); ++n) {
      const Eigen::Vector2d a = kinematic.recorder.results[k].displacement[n];
      scale = std::max(scale, a.cwiseAbs().maxCoeff());
      worst = std::max(worst, (a - combined.recorder.results[k].displacement[n]).cwiseAbs().maxCoeff());
    }
  EXPECT_LT(worst, 1e-12 * scale);
  EXPECT_GT(*combined.last().plastic_dissipation, 0);
}

TEST(CombinedHardening, BadInputIsRefusedNamingTheLine) {
  const std::string from = "*PLASTIC\n240., 0.\n";
  std::string m = error_of(replaced(cylinder_deck(), from, "*PLASTIC, HARDENING=COMBINED\n240., 0.\n300., 1.\n"));
  EXPECT_NE(m.find("test.inp:"), std::string::npos) << m;
  EXPECT_NE(m.find("needs *CYCLIC HARDENING"), std::string::npos) << m;
  m = error_of(replaced(cylinder_deck(), from, "*PLASTIC\n240., 0.\n*CYCLIC HARDENING\n240., 0.\n"));
  EXPECT_NE(m.find("test.inp:"), std::string::npos) << m;
  EXPECT_NE(m.find("needs a *PLASTIC, HARDENING=COMBINED"), std::string::npos) << m;
  m = error_of(replaced(cylinder_deck(), from, "*PLASTIC, HARDENING=COMBINED\n240., 0.\n300., 1.\n"
                                               "*CYCLIC HARDENING\n240., 0.\n230., 0.1\n250., 0.05\n"));
  EXPECT_NE(m.find("test.inp:"), std::string::npos) << m;
  EXPECT_NE(m.find("*CYCLIC HARDENING plastic strain 0.05"), std::string::npos) << m;
  m = error_of(replaced(cylinder_deck(), from, "*PLASTIC, HARDENING=COMBINED\n240., 0.\n300., 1.\n"
                                               "*CYCLIC HARDENING, PARAMETERS\n240., 100., 10.\n"));
  EXPECT_NE(m.find("PARAMETERS"), std::string::npos) << m;
  // Under NLGEOM combined hardening runs (it was refused before finite-strain kinematic hardening).
  const tether::testing::Run nlgeom =
      run_deck_text(replaced(replaced(cylinder_deck(), from, "*PLASTIC, HARDENING=COMBINED\n240., 0.\n300., 1.\n"
                                                               "*CYCLIC HARDENING\n240., 0.\n"),
                             "*STEP, INC=200", "*STEP, NLGEOM, INC=200"));
  EXPECT_TRUE(nlgeom.summary.completed) << nlgeom.summary.message;
}

