// The hybrid CPE4H with a user material (*USER MATERIAL, the worked J2 UMAT of
// examples/user_material): the material sees the mean-dilatation strain and
// keeps its history as with any element, so the run matches the built-in
// *PLASTIC on the same mesh. The Lame cylinder of
// tests/analysis/decks/lame_cpe4h_nu4999.inp with nu = 0.3, linear hardening
// (H = 1000) and the bore pressure 200 (> the elastic limit 104).
#include <gtest/gtest.h>

#include <cmath>

#include "run_deck.hpp"

using namespace tether;
using tether::testing::replaced;

namespace {

std::string plastic_cylinder(const std::string& material) {
  std::string d = tether::testing::analysis_deck("lame_cpe4h_nu4999.inp");
  d = replaced(d, "*ELASTIC\n200000, 0.4999\n", material);
  d = replaced(d, "*STATIC\n1., 1.\n", "*STATIC\n0.1, 1.\n*CONTROLS, PARAMETERS=FIELD\n1e-12, 1e-12\n");
  return replaced(d, "BORE, P, 100", "BORE, P, 200");
}

}  // namespace

TEST(HybridUserMaterial, J2UmatOnCpe4hMatchesPlastic) {
  const auto builtin = tether::testing::run_deck_text(
      plastic_cylinder("*ELASTIC\n200000, 0.3\n*PLASTIC\n240., 0.\n1240., 1.\n"));
  const auto user = tether::testing::run_deck_text(plastic_cylinder(
      std::string("*USER MATERIAL, CONSTANTS=4, LIBRARY=") + TETHER_J2_UMAT + "\n200000., 0.3, 240., 1000.\n"
      "*DEPVAR\n5\n"));
  ASSERT_TRUE(builtin.summary.completed) << builtin.summary.message;
  ASSERT_TRUE(user.summary.completed) << user.summary.message;
  ASSERT_EQ(builtin.recorder.results.size(), user.recorder.results.size());
  const IncrementResults &a = builtin.last(), &b = user.last();
  double u_scale = 0, worst_u = 0, worst_s = 0, peeq = 0;
  for (const auto& u : a.displacement) u_scale = std::max(u_scale, u.cwiseAbs().maxCoeff());
  for (std::size_t n = 0; n < a.displacement.size(); ++n)
    worst_u = std::max(worst_u, (a.displacement[n] - b.displacement[n]).cwiseAbs().maxCoeff() / u_scale);
  for (std::size_t e = 0; e < a.points.size(); ++e)
    for (std::size_t q = 0; q < a.points[e].size(); ++q) {
      peeq = std::max(peeq, a.points[e][q].peeq);
      for (int c = 0; c < 4; ++c)
        worst_s = std::max(worst_s, std::abs(a.points[e][q].stress[c] - b.points[e][q].stress[c]) / 240);
    }
  std::printf("CPE4H, J2 UMAT against *PLASTIC: displacements %.2e, stresses %.2e (relative); PEEQ %.3g\n", worst_u,
              worst_s, peeq);
  EXPECT_GT(peeq, 1e-3);
  EXPECT_LT(worst_u, 1e-10);
  EXPECT_LT(worst_s, 1e-10);
  // One pressure per element: the hydrostatic stress of the four points agree (plastic flow is isochoric).
  for (const auto& element : b.points) {
    const auto p = [](const PointValues& v) { return (v.stress[0] + v.stress[1] + v.stress[2]) / 3; };
    for (const PointValues& v : element) EXPECT_NEAR(p(v), p(element[0]), 1e-9 * 200);
  }
}
