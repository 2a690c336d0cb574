// *DLOAD GRAV and CENTRIF: what they read, OP=MOD/NEW, and every error path.
#include <gtest/gtest.h>

#include "deck_test_support.hpp"

using namespace tether;
using namespace tether::test;

namespace {

const std::string kDense = replaced(kDeck, "200e3, 0.3\n", "200e3, 0.3\n*DENSITY\n7.8e-9\n");

std::string with_dload(const std::string& lines, const std::string& base = kDense) {
  return replaced(base, "*END STEP", "*DLOAD\n" + lines + "*END STEP");
}

}  // namespace

TEST(BodyLoadKeywords, ReadsGravityAndCentrifugalLoadsPerElement) {
  const Model m = read_deck_string(
      with_dload("PLATE, GRAV, 9810., 0, -2\nE1, CENTRIF, 1e4, 0.5, 0.25, 0, 0, 0, 3\n"), "b.inp");
  const auto& loads = m.steps[0].body_loads;
  ASSERT_EQ(loads.size(), 3u);  // GRAV on elements 1 and 2, CENTRIF on element 1
  EXPECT_EQ(loads[0].kind, BodyLoad::Kind::Gravity);
  EXPECT_EQ(loads[0].element, 0);
  EXPECT_EQ(loads[1].element, 1);
  EXPECT_DOUBLE_EQ(loads[0].magnitude, 9810.);
  EXPECT_EQ(loads[0].direction, Eigen::Vector3d(0, -1, 0));  // normalized
  EXPECT_EQ(loads[2].kind, BodyLoad::Kind::Centrifugal);
  EXPECT_DOUBLE_EQ(loads[2].magnitude, 1e4);
  EXPECT_EQ(loads[2].point, Eigen::Vector3d(0.5, 0.25, 0));
  EXPECT_EQ(loads[2].direction, Eigen::Vector3d(0, 0, 1));
  EXPECT_EQ(loads[2].where.line, line_of(with_dload("PLATE, GRAV, 9810., 0, -2\nE1, CENTRIF"), "E1, CENTRIF"));
  EXPECT_TRUE(m.steps[0].pressures.empty());
}

TEST(BodyLoadKeywords, PressuresAndBodyLoadsShareOneDloadAndItsOperations) {
  const std::string two_steps =
      with_dload("PLATE, GRAV, 1, 0, -1\nE1, P1, 5\n") +
      "*STEP\n*STATIC\n*DLOAD, AMPLITUDE=RAMP\nE1, GRAV, 2, 0, -1\n*END STEP\n"
      "*STEP\n*STATIC\n*DLOAD, OP=NEW\n*END STEP\n";
  const Model m = read_deck_string(two_steps, "b.inp");
  ASSERT_EQ(m.steps.size(), 3u);
  EXPECT_EQ(m.steps[0].pressures.size(), 1u);
  ASSERT_EQ(m.steps[1].body_loads.size(), 2u);  // element 1 replaced, element 2 inherited
  EXPECT_DOUBLE_EQ(m.steps[1].body_loads[0].magnitude, 2);
  EXPECT_EQ(m.steps[1].body_loads[0].amplitude, 0);
  EXPECT_DOUBLE_EQ(m.steps[1].body_loads[1].magnitude, 1);
  EXPECT_EQ(m.steps[1].pressures.size(), 1u);
  EXPECT_TRUE(m.steps[2].body_loads.empty());  // OP=NEW removes both kinds
  EXPECT_TRUE(m.steps[2].pressures.empty());
}

TEST(BodyLoadKeywords, BadBodyLoadsNameTheirLine) {
  expect_deck_error_at(with_dload("PLATE, GRAV, 9.81, 0, -1\n", kDeck), "PLATE, GRAV",
                       {"GRAV on element 1 needs the density of its material STEEL", "*DENSITY"});
  expect_deck_error_at(with_dload("PLATE, GRAV, 9.81\n"), "PLATE, GRAV", {"expected `element_or_elset, GRAV, g, dx, dy"});
  expect_deck_error_at(with_dload("PLATE, GRAV, 9.81, 0, 0, 0\n"), "PLATE, GRAV", {"GRAV direction is zero"});
  expect_deck_error_at(with_dload("PLATE, GRAV, 9.81, 0, -1, 1\n"), "PLATE, GRAV", {"out-of-plane (z) component"});
  expect_deck_error_at(with_dload("PLATE, GRAV, g, 0, -1\n"), "PLATE, GRAV", {"bad number 'g'", "gravity magnitude"});
  expect_deck_error_at(with_dload("PLATE, CENTRIF, 100, 0, 0, 0, 0, 0\n"), "PLATE, CENTRIF",
                       {"expected `element_or_elset, CENTRIF, omega^2, px, py, pz, ax, ay, az`"});
  expect_deck_error_at(with_dload("PLATE, CENTRIF, -100, 0, 0, 0, 0, 0, 1\n"), "PLATE, CENTRIF",
                       {"expected omega^2 >= 0"});
  expect_deck_error_at(with_dload("PLATE, CENTRIF, 100, 0, 0, 0, 0, 1, 0\n"), "PLATE, CENTRIF",
                       {"CENTRIF axis must be the z axis", "element 1 (CPE4) of PLATE"});
  expect_deck_error_at(with_dload("PLATE, CENTRIF, 100, 0, 0, 0, 0, 0, 0\n"), "PLATE, CENTRIF", {"CENTRIF axis is zero"});
  expect_deck_error_at(with_dload("PLATE, GRAV, 9.81, 0, -1\nE1, GRAV, 9.81, 1, 0\n"), "E1, GRAV",
                       {"GRAV in another direction", "one gravity load per element", "bad.inp:"});
  expect_deck_error_at(with_dload("PLATE, GRAV, 9.81, 0, -1, 0, 7\n"), "PLATE, GRAV", {"expected"});
  expect_deck_error_at(with_dload("E1, P1, 5, 6\n"), "E1, P1", {"expected `element_or_elset, P1..P4, magnitude`"});
}

TEST(BodyLoadKeywords, AxisymmetricCentrifugalLoadsSpinAboutTheSymmetryAxis) {
  std::string cax = replaced(kDense, "TYPE=CPE4", "TYPE=CAX4");
  const Model m = read_deck_string(with_dload("PLATE, CENTRIF, 100, 0, 5, 0, 0, -1, 0\n", cax), "b.inp");
  EXPECT_EQ(m.steps[0].body_loads[0].direction, Eigen::Vector3d(0, -1, 0));
  expect_deck_error_at(with_dload("PLATE, CENTRIF, 100, 0, 0, 0, 0, 0, 1\n", cax), "PLATE, CENTRIF",
                       {"must spin about the symmetry axis"});
  expect_deck_error_at(with_dload("PLATE, CENTRIF, 100, 1, 0, 0, 0, 1, 0\n", cax), "PLATE, CENTRIF",
                       {"must spin about the symmetry axis"});
}
