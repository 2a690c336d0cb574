// *EXPANSION, *INITIAL CONDITIONS TYPE=TEMPERATURE, *TEMPERATURE and the
// temperature table of *ELASTIC: what the reader stores, and file:line errors.
#include <gtest/gtest.h>

#include "io/deck_test_support.hpp"

using namespace tether;
using namespace tether::test;

namespace {

const std::string kThermal = replaced(kMesh, "200e3, 0.3\n", R"(200e3, 0.3, 0
150e3, 0.25, 400
*EXPANSION, ZERO=20
1e-5, 0
2e-5, 400
)") + R"(*INITIAL CONDITIONS, TYPE=TEMPERATURE
ALL, 20
1, 30
*STEP
*STATIC
*TEMPERATURE, AMPLITUDE=RAMP
LEFT, 100
4, 120
*END STEP
*STEP
*STATIC
*TEMPERATURE, OP=NEW
2, 50
*END STEP
)";

}  // namespace

TEST(ThermalKeywords, TablesInitialAndStepTemperaturesAreStored) {
  const Model m = read_deck_string(kThermal, "thermal.inp");
  const MaterialData& steel = m.materials.at(0);
  ASSERT_TRUE(steel.elastic && steel.expansion);
  EXPECT_EQ(steel.elastic->table_temperature, (std::vector<double>{0, 400}));
  EXPECT_EQ(steel.elastic->table_young, (std::vector<double>{200e3, 150e3}));
  EXPECT_EQ(steel.elastic->table_poisson, (std::vector<double>{0.3, 0.25}));
  EXPECT_DOUBLE_EQ(steel.elastic->young, 200e3);
  EXPECT_DOUBLE_EQ(steel.expansion->zero, 20);
  EXPECT_EQ(steel.expansion->alpha, (std::vector<double>{1e-5, 2e-5}));
  ASSERT_EQ(m.initial_temperatures.size(), 6u);  // one per node, node 1's second value winning
  for (const NodeTemperature& t : m.initial_temperatures)
    EXPECT_DOUBLE_EQ(t.value, m.node_ids[static_cast<std::size_t>(t.node)] == 1 ? 30 : 20);
  const StepTemperatureData& s1 = m.steps.at(0).temperatures;
  ASSERT_EQ(s1.values.size(), 2u);  // nodes 1 and 4, node 4's second line winning
  EXPECT_FALSE(s1.reset);
  for (const NodeTemperature& t : s1.values) {
    EXPECT_EQ(t.amplitude, 0);
    EXPECT_DOUBLE_EQ(t.value, m.node_ids[static_cast<std::size_t>(t.node)] == 4 ? 120 : 100);
  }
  EXPECT_TRUE(m.steps.at(1).temperatures.reset);
  EXPECT_EQ(m.steps.at(1).temperatures.values.size(), 1u);
  EXPECT_TRUE(m.has_temperatures());
}

TEST(ThermalKeywords, BadInputNamesItsLine) {
  expect_deck_error_at(replaced(kThermal, "ZERO=20", "ZERO=hot"), "ZERO=hot", {"ZERO"});
  expect_deck_error_at(replaced(kThermal, "2e-5, 400", "2e-5, 0"), "2e-5, 0",
                       {"*EXPANSION temperature", "strictly increasing"});
  expect_deck_error_at(replaced(kThermal, "2e-5, 400", "2e-5"), "2e-5\n", {"needs a temperature on each"});
  expect_deck_error_at(replaced(kThermal, "4, 120", "99, 120"), "99, 120", {"99"});
  expect_deck_error_at(replaced(kThermal, "1, 30", "1, warm"), "1, warm", {"temperature", "warm"});
  expect_deck_error_at(replaced(kThermal, "*TEMPERATURE, AMPLITUDE=RAMP", "*TEMPERATURE, AMPLITUDE=NONE"),
                       "AMPLITUDE=NONE", {"NONE"});
  expect_deck_error_at(replaced(kThermal, "*TEMPERATURE, OP=NEW", "*TEMPERATURE, FILE=old.odb"), "FILE=old.odb",
                       {"FILE="});
  expect_deck_error_at(replaced(kThermal, "150e3, 0.25, 400", "150e3, 0.25"), "150e3, 0.25",
                       {"`E, nu, temperature`"});
  expect_deck_error_at(replaced(kThermal, "1e-5, 0\n", "1e-5, 0\n*EXPANSION\n1e-5\n"), "*EXPANSION\n1e-5\n",
                       {"already has *EXPANSION"});
}

TEST(ThermalKeywords, TemperaturesWithoutExpansionAreWarnedAbout) {
  const std::string deck = kMesh + "*STEP\n*STATIC\n*TEMPERATURE\nALL, 100\n*END STEP\n";
  std::vector<DeckWarning> warnings;
  (void)read_deck_string(deck, "plain.inp", &warnings);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].where.line, line_of(deck, "*TEMPERATURE"));
  EXPECT_NE(warnings[0].message.find("no material has *EXPANSION"), std::string::npos);
  std::vector<DeckWarning> none;
  (void)read_deck_string(kThermal, "thermal.inp", &none);
  EXPECT_TRUE(none.empty());
}

TEST(ThermalKeywords, ElasticTableWithoutTemperaturesFollowsTheDialect) {
  // Rows at -100 and 100: ABAQUS reads the table at T = 0 (interpolated),
  // CalculiX at its first row; both say which.
  const std::string deck = replaced(kMesh, "200e3, 0.3\n", "300e3, 0.3, -100\n100e3, 0.3, 100\n") +
                           "*STEP\n*STATIC\n*CLOAD\nRIGHT, 1, 10\n*END STEP\n";
  std::vector<DeckWarning> abaqus_warnings, calculix_warnings;
  const Model abaqus = read_deck_string(deck, "t.inp", &abaqus_warnings, Dialect::Abaqus);
  const Model calculix = read_deck_string(deck, "t.inp", &calculix_warnings, Dialect::Calculix);
  EXPECT_EQ(abaqus.materials[0].elastic->table_young.size(), 2u);
  EXPECT_TRUE(calculix.materials[0].elastic->table_young.empty());
  EXPECT_DOUBLE_EQ(calculix.materials[0].elastic->young, 300e3);
  ASSERT_EQ(abaqus_warnings.size(), 1u);
  EXPECT_NE(abaqus_warnings[0].message.find("interpolated at temperature 0"), std::string::npos);
  ASSERT_EQ(calculix_warnings.size(), 1u);
  EXPECT_NE(calculix_warnings[0].message.find("first row, as CalculiX does"), std::string::npos);
  // A table starting at or above 0 reads its first row either way: nothing to say.
  std::vector<DeckWarning> none;
  (void)read_deck_string(replaced(deck, "-100", "0"), "t.inp", &none, Dialect::Calculix);
  EXPECT_TRUE(none.empty());
}
