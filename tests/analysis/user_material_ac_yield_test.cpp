// AC YIELD with a user material: tether cannot see whether a UMAT yields,
// so it writes 0 there and the deck reader says so; a *PLASTIC material in
// the same model still gets its flags.
#include <gtest/gtest.h>

#include <string>

#include "run_deck.hpp"

using namespace tether;

namespace {

/// Two CPE4 side by side (element 1: the J2 UMAT example, element 2:
/// *PLASTIC with the same constants), pulled to twice the yield strain.
std::string two_bars() {
  return std::string(R"(*NODE, NSET=ALL
1, 0, 0
2, 1, 0
3, 2, 0
4, 0, 1
5, 1, 1
6, 2, 1
*ELEMENT, TYPE=CPE4, ELSET=USER
1, 1, 2, 5, 4
*ELEMENT, TYPE=CPE4, ELSET=BUILTIN
2, 2, 3, 6, 5
*NSET, NSET=TOP
4, 5, 6
*NSET, NSET=BOTTOM
1, 2, 3
*MATERIAL, NAME=UMATJ2
*USER MATERIAL, CONSTANTS=4, LIBRARY=)") +
         TETHER_J2_UMAT + R"(
200000., 0.3, 240., 1000.
*DEPVAR
5
*MATERIAL, NAME=STEEL
*ELASTIC
200000, 0.3
*PLASTIC
240., 0.
1240., 1.
*SOLID SECTION, ELSET=USER, MATERIAL=UMATJ2
1.
*SOLID SECTION, ELSET=BUILTIN, MATERIAL=STEEL
1.
*BOUNDARY
BOTTOM, 2, 2
1, 1, 1
*STEP
*STATIC, DIRECT
0.5, 1.
*BOUNDARY
TOP, 2, 2, 0.0025
*EL PRINT
AC YIELD
*END STEP
)";
}

}  // namespace

TEST(UserMaterial, AcYieldIsZeroForAUmatWithAWarningAndSetForPlasticInTheSameModel) {
  std::vector<DeckWarning> warnings;
  const Model model = read_deck_string(two_bars(), "umat_ac_yield.inp", &warnings);
  int about_umat = 0;
  for (const DeckWarning& w : warnings)
    if (w.message.find("AC YIELD is written as 0 at the points of user material UMATJ2") != std::string::npos) {
      ++about_umat;
      EXPECT_EQ(w.where.line, 40);  // the data line naming AC YIELD
    }
  EXPECT_EQ(about_umat, 1);
  const tether::testing::Run run = tether::testing::run_deck_text(two_bars());
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  const IncrementResults& last = run.last();
  // Both yield (the UMAT's stress is on its hardened surface), only the built-in one says so.
  EXPECT_GT(last.points[0][0].stress[1], 240);
  for (const PointValues& p : last.points[0]) EXPECT_EQ(p.ac_yield, 0);
  for (const PointValues& p : last.points[1]) EXPECT_EQ(p.ac_yield, 1);
  EXPECT_EQ(last.element_ac_yield, (std::vector<double>{0.0, 1.0}));
}
