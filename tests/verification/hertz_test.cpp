// Plane-strain Hertz contact (issue #4, section 7): half-cylinder R = 10 mm on
// an elastic block, E = 200 000 MPa, nu = 0.3, P = 2000 N/mm, under pure load
// control (the cylinder touches at one point and is held by contact alone).
// Exact: a = sqrt(4 P R / (pi E*)), p0 = 2 P / (pi a), E* = E / (2 (1 - nu^2))
// (elastic block; a = 0.4814 mm, p0 = 2645 MPa) or E / (1 - nu^2) (rigid flat).
// Decks from tools/make_hertz_deck.py (gmsh) at about 25k dofs, written into
// the build tree. Peak pressure and half-width are fitted from the nodal
// pressures: p^2 = p0^2 (1 - x^2 / a^2) is linear in x^2 (least squares over
// the nodes with p > 0.3 max p). Tolerance 1 % (issue); measured errors are
// printed. Skipped without python3/gmsh.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <numbers>

#include "verification_support.hpp"

namespace fs = std::filesystem;
using namespace tether;

namespace {

constexpr double kR = 10, kE = 200000, kNu = 0.3, kP = 2000;

struct HertzFit {
  double p0 = 0, a = 0, peak = 0;
};

HertzFit fit(const tether::testing::Run& run) {
  const IncrementResults& r = run.last();
  const ContactPairValues& c = r.contact.at(0);
  HertzFit f;
  for (const auto& v : c.nodes) f.peak = std::max(f.peak, v.pressure);
  double s0 = 0, s1 = 0, s2 = 0, t0 = 0, t1 = 0;  // least squares p^2 = A + B x^2
  for (const auto& v : c.nodes) {
    if (v.pressure <= 0.3 * f.peak) continue;
    const double x = run.model.coords[v.node].x() + r.displacement[v.node].x();
    const double z = x * x, w = v.pressure * v.pressure;
    s0 += 1, s1 += z, s2 += z * z, t0 += w, t1 += z * w;
  }
  const double B = (s0 * t1 - s1 * t0) / (s0 * s2 - s1 * s1), A = (t0 - B * s1) / s0;
  f.p0 = std::sqrt(A);
  f.a = std::sqrt(-A / B);
  return f;
}

/// Generates the deck (cached in the build tree) and runs it; `mortar`:
/// the same deck with TYPE=SURFACE TO SURFACE (mortar contact).
tether::testing::Run run_hertz(const std::string& name, const std::string& options, bool mortar = false) {
  if (std::system("command -v python3 > /dev/null 2>&1 && command -v gmsh > /dev/null 2>&1") != 0)
    throw std::runtime_error("skip");
  const fs::path dir = fs::path(TETHER_BINARY_DIR) / "tests" / "verification" / "hertz";
  fs::create_directories(dir);
  const fs::path deck = dir / (name + ".inp");
  if (!fs::exists(deck)) {
    const std::string command = "python3 \"" + std::string(TETHER_SOURCE_DIR) + "/tools/make_hertz_deck.py\" " +
                                options + " --no-seat \"" + deck.string() + "\" > /dev/null";
    if (std::system(command.c_str()) != 0) throw std::runtime_error("generator failed: " + command);
  }
  if (!mortar) return tether::testing::run_deck_file(deck.string());
  std::ifstream in(deck);
  std::stringstream text;
  text << in.rdbuf();
  std::string deck_text = text.str();
  const std::string from = "TYPE=NODE TO SURFACE", to = "TYPE=SURFACE TO SURFACE";
  const auto at = deck_text.find(from);
  if (at == std::string::npos) throw std::runtime_error("no node-to-surface pair in " + deck.string());
  return tether::testing::run_deck_text(deck_text.replace(at, from.size(), to));
}

/// `tolerance` for p0 and the peak, `width_tolerance` (default: the same) for a.
void check(const std::string& name, const std::string& options, double e_star, double tolerance, bool mortar = false,
           double width_tolerance = 0) {
  tether::testing::Run run;
  try {
    run = run_hertz(name, options, mortar);
  } catch (const std::runtime_error& e) {
    if (std::string(e.what()) == "skip") GTEST_SKIP() << "python3 or gmsh not found";
    FAIL() << e.what();
  }
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  const double a = std::sqrt(4 * kP * kR / (std::numbers::pi * e_star)), p0 = 2 * kP / (std::numbers::pi * a);
  const HertzFit f = fit(run);
  std::printf("[ hertz ] %s%s: p0 %.2f (exact %.2f, %+.3f %%), peak nodal %.2f (%+.3f %%), a %.5f (exact %.5f, %+.3f %%), "
              "%d increments, %d iterations\n",
              name.c_str(), mortar ? " (mortar)" : "", f.p0, p0, 100 * (f.p0 / p0 - 1), f.peak, 100 * (f.peak / p0 - 1), f.a, a,
              100 * (f.a / a - 1), run.summary.increments, run.summary.iterations);
  EXPECT_NEAR(f.p0 / p0, 1, tolerance);
  EXPECT_NEAR(f.peak / p0, 1, tolerance);
  EXPECT_NEAR(f.a / a, 1, width_tolerance > 0 ? width_tolerance : tolerance);
  // The contact force carries the half-model load exactly (equilibrium of the cylinder).
  EXPECT_NEAR(run.last().contact.at(0).total_force.y(), kP / 2, 1e-6 * kP);
  // Newton: every increment within 8 iterations.
  for (const IncrementReport& inc : run.recorder.increments) EXPECT_LE(inc.iterations, 8) << "increment " << inc.increment;
}

TEST(Hertz, Cpe4OnElasticBlock25k) { check("hertz_cpe4_25k", "--dofs 25k --element CPE4", kE / (2 * (1 - kNu * kNu)), 0.01); }

TEST(Hertz, Cpe8OnElasticBlock25k) { check("hertz_cpe8_25k", "--dofs 25k --element CPE8", kE / (2 * (1 - kNu * kNu)), 0.01); }

TEST(Hertz, Cpe4OnRigidFlat25k) { check("hertz_cpe4_rigid_25k", "--dofs 25k --element CPE4 --rigid-flat", kE / (1 - kNu * kNu), 0.01); }

// Mortar contact (TYPE=SURFACE TO SURFACE) on the same decks: the dual
// multipliers are the nodal pressures. p0 and the peak within 0.5 % (the
// issue's figure; measured -0.04 % CPE4, -0.06 % CPE8); the fitted half-width
// within 1 %: measured -0.58 % (CPE4) and -0.42 % (CPE8), where node-to-surface
// gives -0.50 % and +0.17 % on the same meshes.
TEST(Hertz, MortarCpe4OnElasticBlock25k) {
  check("hertz_cpe4_25k", "--dofs 25k --element CPE4", kE / (2 * (1 - kNu * kNu)), 0.005, true, 0.01);
}

TEST(Hertz, MortarCpe8OnElasticBlock25k) {
  check("hertz_cpe8_25k", "--dofs 25k --element CPE8", kE / (2 * (1 - kNu * kNu)), 0.005, true, 0.01);
}

// From the initial point contact on coarse quadratic faces: the touching
// slave node's weighted gap is then a small positive discretisation
// quantity (mean gap 2e-11 mm at 2k dofs, 6e-13 at 3k, falling as h^6),
// above round-off; the node still counts as closed, as node-to-surface closes
// it (docs/theory/mortar.md, "Enforcement"). Before, no node was closed at the
// first iteration and the 3k run stopped at t = 0 on a singular matrix, the 2k
// run with the LINEAR law on a growing residual. Both must now agree with
// node-to-surface on the same deck: p0 within 0.2 % and a within 0.5 %
// (measured 3k: mortar p0 +0.50 %, a +2.14 %; node-to-surface +0.53 %,
// +2.28 %; 2k LINEAR: -4.51 % / +12.19 % against -4.52 % / +12.59 %, a soft
// law, so not Hertz's), and the 3k HARD run Hertz's closed form within the
// coarse mesh's reach (about 2.4 faces over a): p0 within 1 %, a within 4 %.
void check_point_contact(const std::string& name, const std::string& options, bool hard) {
  tether::testing::Run nts, mortar;
  try {
    nts = run_hertz(name, options);
    mortar = run_hertz(name, options, true);
  } catch (const std::runtime_error& e) {
    if (std::string(e.what()) == "skip") GTEST_SKIP() << "python3 or gmsh not found";
    FAIL() << e.what();
  }
  ASSERT_TRUE(nts.summary.completed) << nts.summary.message;
  ASSERT_TRUE(mortar.summary.completed) << mortar.summary.message;
  const HertzFit m = fit(mortar), n = fit(nts);
  const double e_star = kE / (2 * (1 - kNu * kNu));
  const double a = std::sqrt(4 * kP * kR / (std::numbers::pi * e_star)), p0 = 2 * kP / (std::numbers::pi * a);
  std::printf("[ hertz ] %s: mortar p0 %+.3f %%, a %+.3f %%, %d iterations; node-to-surface p0 %+.3f %%, a %+.3f %%, %d iterations\n",
              name.c_str(), 100 * (m.p0 / p0 - 1), 100 * (m.a / a - 1), mortar.summary.iterations, 100 * (n.p0 / p0 - 1),
              100 * (n.a / a - 1), nts.summary.iterations);
  EXPECT_NEAR(m.p0 / n.p0, 1, 0.002);
  EXPECT_NEAR(m.a / n.a, 1, 0.005);
  if (hard) {
    EXPECT_NEAR(m.p0 / p0, 1, 0.01);
    EXPECT_NEAR(m.a / a, 1, 0.04);
  }
  EXPECT_NEAR(mortar.last().contact.at(0).total_force.y(), kP / 2, 1e-6 * kP);
  for (const IncrementReport& inc : mortar.recorder.increments) EXPECT_LE(inc.iterations, 8) << "increment " << inc.increment;
}

TEST(Hertz, MortarCpe8FromPointContact3k) { check_point_contact("hertz_cpe8_3k", "--dofs 3k --element CPE8", true); }

TEST(Hertz, MortarCpe8LinearLawFromPointContact2k) {
  check_point_contact("hertz_cpe8_linear_2k", "--dofs 2k --element CPE8 --linear 1e6", false);
}

}  // namespace
