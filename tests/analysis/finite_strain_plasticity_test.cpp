// Finite-strain (NLGEOM) plasticity through the whole analysis: Cook's
// membrane against the published tip displacement and Newton's order on it,
// the plane-stress kinematic bar and the pressure-pulled strip against their
// closed forms (also heated), and the necking bar against CalculiX.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "run_deck.hpp"

using namespace tether;
using namespace tether::testing;
namespace fs = std::filesystem;

using tether::testing::replaced;

namespace {

std::string deck_file(const std::string& name) {
  std::ifstream in(fs::path(TETHER_SOURCE_DIR) / "tests/analysis/decks" / name);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Vertical displacement of Cook's membrane's tip (node set TIP) at the end.
double cook_tip(const tether::testing::Run& run) { return run.last().displacement[run.model.node_sets.at("TIP").front()].y(); }

/// Converged tip displacement of Simo and Armero's (1992) elastoplastic Cook's
/// membrane (their Q1/E4 element on fine meshes).
constexpr double kCookReference = 6.94;

}  // namespace

TEST(FiniteStrainPlasticity, CooksMembraneApproachesThePublishedTipDisplacement) {
  // CPE8R, 4x4 and 8x8, ten load increments of the dead shear load 5 (NLGEOM).
  const tether::testing::Run coarse = run_deck_text(deck_file("cook_membrane_4.inp"));
  const tether::testing::Run fine = run_deck_text(deck_file("cook_membrane_8.inp"));
  ASSERT_TRUE(coarse.summary.completed) << coarse.summary.message;
  ASSERT_TRUE(fine.summary.completed) << fine.summary.message;
  const double u4 = cook_tip(coarse), u8 = cook_tip(fine);
  double peeq = 0;
  for (const auto& element : fine.last().points)
    for (const auto& p : element) peeq = std::max(peeq, p.peeq);
  std::printf("Cook's membrane tip: 4x4 %.4f, 8x8 %.4f (reference %.2f: %.1f %%, %.1f %%); largest PEEQ %.3f\n", u4,
              u8, kCookReference, 100 * (u4 / kCookReference - 1), 100 * (u8 / kCookReference - 1), peeq);
  EXPECT_LT(u4, u8);  // from below, as CPE8R converges here (16x16: 6.913, 32x32: 6.964)
  EXPECT_NEAR(u8, kCookReference, 0.03 * kCookReference);
  EXPECT_NEAR(u4, kCookReference, 0.05 * kCookReference);
  EXPECT_GT(peeq, 0.1);  // well into finite plastic strain
}

TEST(FiniteStrainPlasticity, NewtonConvergesQuadraticallyOnCooksMembrane) {
  // Linear hardening (two table rows): the kinks of the saturation table
  // would make the order drop to one whenever a point crosses a table row.
  std::string deck = replaced(deck_file("cook_membrane_4.inp"), "0.1, 1., 1e-5, 0.1\n",
                              "0.1, 1., 1e-5, 0.1\n*CONTROLS, PARAMETERS=FIELD\n1e-12, 1e-12\n");
  const auto table = deck.find("*PLASTIC\n"), section = deck.find("*SOLID SECTION");
  ASSERT_TRUE(table != std::string::npos && section != std::string::npos);
  deck.replace(table, section - table, "*PLASTIC\n0.45, 0.\n1.45, 1.\n");
  const tether::testing::Run run = run_deck_text(deck);
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  std::vector<double> orders;
  for (const auto& r : run.recorder.residuals)
    for (std::size_t k = 1; k + 1 < r.size(); ++k) {
      // Asymptotic range: decreasing residuals, r_k below 1e-3 r_0 and r_k+1
      // above round-off (about 1e-12 here).
      if (r[k + 1] < 1e-9 * r[0] || r[k] >= r[k - 1] || r[k + 1] >= r[k] || r[k] > 1e-3 * r[0]) continue;
      orders.push_back(std::log(r[k + 1] / r[k]) / std::log(r[k] / r[k - 1]));
    }
  ASSERT_GE(orders.size(), 3u);
  std::sort(orders.begin(), orders.end());
  const double median = orders[orders.size() / 2];
  std::printf("Newton order on Cook's membrane (NLGEOM plasticity): %zu measurements, median %.2f, smallest %.2f; %d "
              "increments, %d iterations\n", orders.size(), median, orders.front(), run.summary.increments,
              run.summary.iterations);
  // Three residuals give the order only where the contraction constant C of
  // r_k+1 = C r_k^2 holds still. Measured with the predictor (16 increments,
  // 78 iterations): 10 estimates, sorted 1.13, 1.42, 1.86, 1.97, 2.01, 2.11,
  // 2.12, 2.52, 2.53, 3.44 (median 2.11). The two low ones are transients of
  // C, not a lost order: in the pass giving 1.13 the residuals run
  // 5.8e-2, 1.7e-3, 2.9e-5, 2.1e-10 (C = 0.49, 10.6, 0.24; the last triple,
  // left out as below 1e-9 r_0, gives 2.94), and in the one giving 1.42
  // 1.2e-2, 1.1e-4, 1.4e-7, 3.1e-12; the number of points on the plastic
  // branch stays the same through those iterations (counted by an
  // instrumented build: 50 and 56), so no point switches between the
  // elastic and the plastic branch there. Near the limit load the tangent
  // is nearly singular (corrections of 1 for residuals of 4), which is where
  // C moves. A tangent that is not consistent gives about 1 throughout.
  // Checked at every iteration with an instrumented Newton (plasticity.md,
  // "Newton's order on Cook's membrane"): the assembled tangent matches
  // central differences of the assembled residual along the step to
  // round-off, and R(u + t dx) - (1 - t) R(u) scales as t^2 to 1 % (t = 1,
  // 1/2, 1/4) in the passes of 1.13 and 1.42: each step leaves the pure
  // quadratic remainder, so the low estimates are the constant moving.
  EXPECT_GE(median, 1.8);
  EXPECT_GE(orders.front(), 1.1);
}


TEST(FiniteStrainPlasticity, PlaneStressKinematicBarFollowsTheLogarithmicClosedForm) {
  // One CPS4 under NLGEOM, linear kinematic hardening (yield 200, H = 1000):
  // pulled to a length of 1.2, pushed to 0.9, 20 increments per step. Uniaxial
  // stress: with the axial log strain e, the Kirchhoff stress tau follows
  // tau (1 + H/E) = s0 + H e (loading), tau = E (e - ep1) (unloading),
  // tau (1 + H/E) = H e - s0 (reverse), the Cauchy stress is
  // tau / exp((1 - 2 nu) tau / E) and PEEQ accumulates |d(e - tau/E)|.
  const tether::testing::Run run = run_deck_text(deck_file("plastic_bar_nlgeom.inp"));
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  const double E = 200000, nu = 0.3, s0 = 200, H = 1000;
  const double e_peak = std::log(1.2), tau_peak = (s0 + H * e_peak) / (1 + H / E), ep1 = e_peak - tau_peak / E;
  double worst_stress = 0, worst_peeq = 0, worst_lateral = 0;
  for (const IncrementResults& r : run.recorder.results) {
    const double u = r.step == 1 ? 0.2 * r.step_time : 0.2 - 0.3 * r.step_time;
    const double e = std::log(1 + u);
    double tau = 0, peeq = 0;
    if (r.step == 1) {
      tau = e <= s0 / E ? E * e : (s0 + H * e) / (1 + H / E);
      peeq = std::max(0.0, e - tau / E);
    } else {
      tau = std::max(E * (e - ep1), (H * e - s0) / (1 + H / E));
      peeq = ep1 + (ep1 - (e - tau / E));
    }
    const double cauchy = tau / std::exp((1 - 2 * nu) * tau / E);
    for (const PointValues& p : r.points[0]) {
      worst_stress = std::max(worst_stress, std::abs(p.stress[1] - cauchy) / s0);
      worst_lateral = std::max(worst_lateral, std::abs(p.stress[0]) / s0);
      worst_peeq = std::max(worst_peeq, std::abs(p.peeq - peeq));
    }
  }
  std::printf("finite-strain kinematic CPS4 bar: stress %.1e (of s0), lateral stress %.1e, PEEQ %.1e; final PEEQ %.4f\n",
              worst_stress, worst_lateral, worst_peeq, run.last().points[0][0].peeq);
  EXPECT_EQ(run.recorder.results.size(), 40u);
  EXPECT_LT(worst_stress, 1e-8);
  EXPECT_LT(worst_lateral, 1e-8);
  EXPECT_LT(worst_peeq, 1e-10);
}

TEST(FiniteStrainPlasticity, NeckingBarFollowsCalculix) {
  // Simo's necking bar (examples/necking_bar/make_deck.py 5 15: half model,
  // CAX8R, 1.8 % imperfection, saturation hardening), pulled 7 mm: the radius
  // at the neck against its initial value. CalculiX 2.20 on the same deck
  // (53 increments): 0.9885 at 0.525 mm, 0.9392 at 2.485 mm, 0.6714 at
  // 5.005 mm, 0.3230 at 7 mm; tether (52 increments) 0.9885, 0.9391, 0.6707,
  // 0.3214 (57 increments and 0.9885, 0.9390, 0.6706, 0.3215 before the
  // start-tangent predictor). Past the force peak (about 2.6 mm) the answer depends on the
  // increment size more than on the two codes' finite-strain formulations
  // (Hencky elasticity and yield on the Kirchhoff stress here, neo-Hookean
  // and Cauchy yield there): with increments of at most 0.005 instead of 0.02
  // CalculiX gives 0.6780 and 0.3339, tether 0.6776 and 0.3329. Tolerances:
  // 0.1 % before the neck forms, 0.5 % at 5 mm, 1 % at 7 mm. No published
  // table of this curve was found (docs/theory/plasticity.md lists the
  // sources checked), so the reference is CalculiX.
  const tether::testing::Run run = run_deck_text(deck_file("necking_bar_5x15.inp"));
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  const int neck = run.model.node_sets.at("NECK").front();
  const double r0 = 6.413 * 0.982;
  const auto ratio_at = [&](double pull) {  // linear between the increments around `pull`
    double prev_pull = 0, prev_ratio = 1;
    for (const IncrementResults& r : run.recorder.results) {
      const double d = 7 * r.step_time, q = (r0 + r.displacement[neck].x()) / r0;
      if (d >= pull - 1e-9) return prev_ratio + (q - prev_ratio) * (pull - prev_pull) / (d - prev_pull);
      prev_pull = d, prev_ratio = q;
    }
    return prev_ratio;
  };
  const double at[] = {0.525, 2.485, 5.005, 7.0}, ccx[] = {0.9885, 0.9392, 0.6714, 0.3230};
  const double tolerance[] = {0.001, 0.001, 0.005, 0.01};
  for (int k = 0; k < 4; ++k) {
    const double q = ratio_at(at[k]);
    std::printf("necking bar: pull %.3f mm, neck radius ratio %.4f (CalculiX %.4f, %+.2f %%)\n", at[k], q, ccx[k],
                100 * (q / ccx[k] - 1));
    EXPECT_NEAR(q, ccx[k], tolerance[k] * ccx[k]) << at[k];
  }
  // Newton's efficiency (bounds, not exact counts): 52 increments, 131
  // iterations, no cut-back with the start-tangent predictor in the first
  // increment and the linear extrapolation after it (57, 158 and 1 with the
  // extrapolation alone); 218, 1327
  // and 18 without it (717, 4320 and 41 before the loading tangent and the
  // settled-residual rule of docs/theory/newton.md). CalculiX: 53 increments.
  std::printf("necking bar: %d increments, %d iterations, %d cut-backs\n", run.summary.increments,
              run.summary.iterations, run.summary.cutbacks);
  EXPECT_LT(run.summary.increments, 70);
  EXPECT_LT(run.summary.iterations, 250);
}

namespace {

/// Newton's root of f (derivative df) from x.
template <class F, class DF>
double newton_root(F f, DF df, double x) {
  for (int k = 0; k < 100 && std::abs(f(x)) > 1e-15 * std::abs(x); ++k) x -= f(x) / df(x);
  return x;
}

}  // namespace

TEST(FiniteStrainPlasticity, PlaneStressStripPulledByPressureFollowsTheClosedForm) {
  // tests/analysis/decks/plastic_strip_pressure.inp: one CPS4 strip (10 x 1)
  // pulled by the follower pressure -300 on its end face under NLGEOM, so the
  // Cauchy stress is 300 exactly when the load acts on the current area
  // h0 F33 x width. Von Mises plane stress, isotropic linear hardening
  // (s0 200, H 1000): tau = p J, J = exp((1 - 2 nu) tau / E), ep = (tau - s0)/H,
  // axial stretch exp(tau/E + ep), lateral and thickness exp(-nu tau/E - ep/2).
  const tether::testing::Run run = run_deck_text(deck_file("plastic_strip_pressure.inp"));
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  const double E = 200000, nu = 0.3, s0 = 200, H = 1000, p = 300, L = 10;
  const double tau = newton_root([&](double t) { return t * std::exp(-(1 - 2 * nu) * t / E) - p; },
                                 [&](double t) { return std::exp(-(1 - 2 * nu) * t / E) * (1 - (1 - 2 * nu) * t / E); },
                                 p);
  const double ep = (tau - s0) / H, axial = std::exp(tau / E + ep), lateral = std::exp(-nu * tau / E - ep / 2);
  const IncrementResults& r = run.last();
  const double ux = r.displacement[static_cast<std::size_t>(run.node(3))].x();
  const double uy = r.displacement[static_cast<std::size_t>(run.node(3))].y();
  std::printf("strip pulled by pressure: u %.10f (closed form %.10f), lateral %.10f (%.10f), PEEQ %.10f (%.10f)\n", ux,
              L * (axial - 1), uy, lateral - 1, r.points[0][0].peeq, ep);
  EXPECT_NEAR(ux, L * (axial - 1), 1e-8 * L * (axial - 1));
  EXPECT_NEAR(uy, lateral - 1, 1e-8 * std::abs(lateral - 1));
  for (const PointValues& v : r.points[0]) {
    EXPECT_NEAR(v.stress[0], p, 1e-8 * p);
    EXPECT_NEAR(v.peeq, ep, 1e-8 * ep);
    EXPECT_NEAR(v.strain[2], 0.5 * (lateral * lateral - 1), 1e-8 * 0.5 * (1 - lateral * lateral));  // E33
  }
  // F33 = 1 would put the force p h0 (1 + uy) on the face: 5 % more stress.
  EXPECT_LT(lateral, 0.96);
}

TEST(FiniteStrainPlasticity, PlaneStressStripPulledByPressureWhileHeatedFollowsTheClosedForm) {
  // The strip above of St.Venant-Kirchhoff (E 1000, nu 0.3) with *EXPANSION
  // 1e-3 heated by 50 (stretch s = 1.05), pulled by -40: the mechanical
  // Green strain Em (uniaxial, lateral -nu Em) has the Cauchy stress
  // sqrt(1 + 2 Em) E Em / (1 - 2 nu Em) = 40; the stretches are s sqrt(1 + 2 Em)
  // and s sqrt(1 - 2 nu Em) (the thickness too).
  std::string deck = replaced(deck_file("plastic_strip_pressure.inp"), "200000, 0.3\n*PLASTIC\n200., 0.\n1200., 1.\n",
                              "1000, 0.3\n*EXPANSION\n1e-3\n");
  deck = replaced(deck, "*STEP, NLGEOM", "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nALL, 0.\n*STEP, NLGEOM");
  deck = replaced(deck, "1, P2, -300.\n", "1, P2, -40.\n*TEMPERATURE\nALL, 50.\n");
  const tether::testing::Run run = run_deck_text(deck);
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  const double E = 1000, nu = 0.3, p = 40, L = 10, s = 1.05;
  const auto sigma = [&](double e) { return std::sqrt(1 + 2 * e) * E * e / (1 - 2 * nu * e); };
  const double Em = newton_root([&](double e) { return sigma(e) - p; },
                                [&](double e) { return (sigma(e + 1e-7) - sigma(e - 1e-7)) / 2e-7; }, p / E);
  const double axial = s * std::sqrt(1 + 2 * Em), lateral = s * std::sqrt(1 - 2 * nu * Em);
  const IncrementResults& r = run.last();
  const double ux = r.displacement[static_cast<std::size_t>(run.node(3))].x();
  const double uy = r.displacement[static_cast<std::size_t>(run.node(3))].y();
  std::printf("heated strip pulled by pressure: u %.10f (closed form %.10f), lateral %.10f (%.10f)\n", ux,
              L * (axial - 1), uy, lateral - 1);
  EXPECT_NEAR(ux, L * (axial - 1), 1e-8 * L * (axial - 1));
  EXPECT_NEAR(uy, lateral - 1, 1e-8 * std::abs(lateral - 1));
  for (const PointValues& v : r.points[0]) {
    EXPECT_NEAR(v.stress[0], p, 1e-8 * p);
    EXPECT_NEAR(v.strain[2], 0.5 * (lateral * lateral - 1), 1e-8 * std::abs(0.5 * (lateral * lateral - 1)));
  }
}
