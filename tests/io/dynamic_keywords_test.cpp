// *DYNAMIC, *INITIAL CONDITIONS, *DAMPING and *STEP, AMPLITUDE=: what they read and what they refuse.
#include <gtest/gtest.h>

#include "deck_test_support.hpp"

namespace tether::test {
namespace {

const std::string kDynamic = replaced(kDeck, "*STATIC", "*DYNAMIC\n0.01, 0.5");

TEST(DynamicKeywords, ReadWithTheirDefaults) {
  const Model m = read_deck_string(
      replaced(replaced(kDynamic, "*ELASTIC", "*DENSITY\n7.8e-9\n*DAMPING, BETA=1e-5\n*ELASTIC"), "*STEP",
               "*INITIAL CONDITIONS, TYPE=VELOCITY\nRIGHT, 1, 2.5\n5, 2, -1\n*STEP"),
      "ok.inp");
  const Step& s = m.steps.at(0);
  EXPECT_EQ(s.procedure, StepProcedure::ImplicitDynamic);
  EXPECT_DOUBLE_EQ(s.dynamic.alpha, -0.05);  // ABAQUS's and CalculiX's default
  EXPECT_FALSE(s.dynamic.lumped_mass);
  EXPECT_FALSE(s.ramp_loads);  // dynamic steps hold their loads from the start
  EXPECT_DOUBLE_EQ(s.initial_increment, 0.01);
  EXPECT_DOUBLE_EQ(s.period, 0.5);
  ASSERT_TRUE(m.materials.at(0).damping);
  EXPECT_DOUBLE_EQ(m.materials[0].damping->alpha, 0);
  EXPECT_DOUBLE_EQ(m.materials[0].damping->beta, 1e-5);
  ASSERT_EQ(m.initial_velocities.size(), 3u);  // two nodes of RIGHT, then node 5
  EXPECT_EQ(m.initial_velocities[2].node, m.node_index.at(5));
  EXPECT_EQ(m.initial_velocities[2].dof, 1);
  EXPECT_DOUBLE_EQ(m.initial_velocities[2].value, -1);
  EXPECT_TRUE(read_deck_string(kDeck, "ok.inp").steps.at(0).ramp_loads);  // static steps ramp
}

TEST(DynamicKeywords, ParametersAreReadOrRefusedWithAReason) {
  const Model m = read_deck_string(
      replaced(replaced(kDynamic, "*DYNAMIC", "*DYNAMIC, ALPHA=-0.2, MASS=LUMPED, DIRECT"), "*STEP",
               "*STEP, AMPLITUDE=RAMP"),
      "ok.inp");
  EXPECT_DOUBLE_EQ(m.steps[0].dynamic.alpha, -0.2);
  EXPECT_TRUE(m.steps[0].dynamic.lumped_mass);
  EXPECT_TRUE(m.steps[0].direct);
  EXPECT_TRUE(m.steps[0].ramp_loads);
  EXPECT_TRUE(m.steps[0].dynamic.redistribute_contact_mass);  // the default
  EXPECT_EQ(m.steps[0].dynamic.half_increment_tolerance, 0);  // none, and DIRECT would ignore it
  const Model h = read_deck_string(replaced(kDynamic, "*DYNAMIC", "*DYNAMIC, HAFTOL=250., CONTACT MASS=KEPT"), "ok.inp");
  EXPECT_DOUBLE_EQ(h.steps[0].dynamic.half_increment_tolerance, 250);
  EXPECT_FALSE(h.steps[0].dynamic.redistribute_contact_mass);
  const Model e = read_deck_string(replaced(kDynamic, "*DYNAMIC\n0.01, 0.5", "*DYNAMIC, EXPLICIT\n1e-6, 0.5"), "ok.inp");
  EXPECT_EQ(e.steps[0].procedure, StepProcedure::ExplicitDynamic);
  EXPECT_TRUE(e.steps[0].dynamic.lumped_mass);

  expect_deck_error_at(replaced(kDynamic, "*DYNAMIC", "*DYNAMIC, ALPHA=-0.5"), "ALPHA", {"ALPHA=-0.5", "-1/3"});
  expect_deck_error_at(replaced(kDynamic, "*DYNAMIC", "*DYNAMIC, ALPHA=0.1"), "ALPHA", {"-1/3 <= alpha <= 0"});
  expect_deck_error_at(replaced(kDynamic, "*DYNAMIC", "*DYNAMIC, HAFTOL=0"), "HAFTOL", {"HAFTOL=0", "force > 0"});
  expect_deck_error_at(replaced(kDynamic, "*DYNAMIC", "*DYNAMIC, HAFTOL=-5"), "HAFTOL", {"force > 0"});
  expect_deck_error_at(replaced(kDynamic, "*DYNAMIC\n0.01, 0.5", "*DYNAMIC, EXPLICIT, HAFTOL=10\n1e-6, 0.5"), "HAFTOL",
                       {"implicit"});
  expect_deck_error_at(replaced(kDynamic, "*DYNAMIC\n0.01, 0.5", "*DYNAMIC, EXPLICIT, CONTACT MASS=KEPT\n1e-6, 0.5"),
                       "CONTACT MASS", {"implicit"});
  expect_deck_error_at(replaced(kDynamic, "*DYNAMIC", "*DYNAMIC, CONTACT MASS=ZERO"), "CONTACT MASS", {"REDISTRIBUTED"});
  expect_deck_error_at(replaced(kDynamic, "*DYNAMIC", "*DYNAMIC, EXPLICIT, ALPHA=-0.1"), "ALPHA", {"central"});
  expect_deck_error_at(replaced(kDynamic, "*DYNAMIC\n0.01, 0.5", "*DYNAMIC, EXPLICIT"), "*DYNAMIC",
                       {"needs a data line", "increment, period"});
  expect_deck_error_at(replaced(kDynamic, "0.01, 0.5", "0.01, 0.5\n*STATIC"), "*STATIC\n*CLOAD",
                       {"second procedure", "one *STATIC or *DYNAMIC"});
  expect_deck_error_at(replaced(kDynamic, "0.01, 0.5", "0.7, 0.5"), "0.7, 0.5", {"0 < initial <= period"});
}

TEST(DynamicKeywords, InitialConditionsAndDampingRefuseWhatTheyCannotMean) {
  const auto before_step = [](const std::string& text) { return replaced(kDynamic, "*STEP", text + "\n*STEP"); };
  expect_deck_error_at(before_step("*INITIAL CONDITIONS, TYPE=STRESS\nPLATE, 1., 2."), "TYPE=STRESS",
                       {"TYPE=STRESS", "TYPE=TEMPERATURE only"});
  expect_deck_error_at(before_step("*INITIAL CONDITIONS, TYPE=VELOCITY\nRIGHT, 3, 1."), "RIGHT, 3",
                       {"in its plane only"});
  expect_deck_error_at(before_step("*INITIAL CONDITIONS, TYPE=VELOCITY\nRIGHT, 7, 0."), "RIGHT, 7", {"dof 7"});
  expect_deck_error_at(before_step("*INITIAL CONDITIONS, TYPE=VELOCITY\nNOSUCH, 1, 0."), "NOSUCH", {"NOSUCH"});
  expect_deck_error_at(before_step("*INITIAL CONDITIONS, TYPE=VELOCITY\nRIGHT, 1"), "RIGHT, 1\n",
                       {"node or node set, dof, velocity"});
  expect_deck_error_at(before_step("*INITIAL CONDITIONS"), "*INITIAL CONDITIONS", {"TYPE"});
  const auto in_material = [](const std::string& text) { return replaced(kDynamic, "*ELASTIC", text + "\n*ELASTIC"); };
  expect_deck_error_at(in_material("*DAMPING"), "*DAMPING", {"ALPHA=", "BETA="});
  expect_deck_error_at(in_material("*DAMPING, STRUCTURAL=0.02"), "*DAMPING", {"frequency-domain"});
  expect_deck_error_at(in_material("*DAMPING, ALPHA=-1"), "*DAMPING", {">= 0"});
  expect_deck_error_at(in_material("*DAMPING, ALPHA=1\n0.25, 0.75"), "0.25, 0.75", {"no data lines"});
}

TEST(DynamicKeywords, VelocityAndAccelerationOutputBelongToDynamicSteps) {
  expect_deck_error_at(replaced(kDeck, "*END STEP", "*NODE PRINT\nU, V\n*END STEP"), "*NODE PRINT",
                       {"V", "*DYNAMIC steps only", "*STATIC"});
  const Model m = read_deck_string(replaced(kDynamic, "*END STEP", "*NODE PRINT\nU, V, A\n*END STEP"), "ok.inp");
  EXPECT_EQ(m.steps[0].outputs.at(0).variables, (std::vector<std::string>{"U", "V", "A"}));
}

}  // namespace
}  // namespace tether::test
