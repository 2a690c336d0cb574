// Syntax CalculiX accepts and tether reads the same way: names used before the
// line that defines them (CalculiX's reading order), empty coordinates, OFFSET=0
// on *SOLID SECTION, a single-row *ELASTIC with a temperature, a lone '*',
// keywords, parameters and choices written without their blanks, and *NODE
// lines with ABAQUS's normal direction (fields 5-7).
#include <gtest/gtest.h>

#include "deck_test_support.hpp"
#include "tether/io/deck_reader.hpp"

using namespace tether;
using namespace tether::test;

namespace {

bool has_warning(const std::vector<DeckWarning>& w, const std::string& words, int line) {
  for (const auto& x : w)
    if (x.message.find(words) != std::string::npos && x.where.line == line) return true;
  return false;
}

/// Two quads written "backwards": everything that names something comes before
/// the definition, in the places CalculiX allows it.
const std::string kBackwards = R"(*HEADING
Names before definitions
*SOLID SECTION, ELSET=PLATE, MATERIAL=STEEL
1.0
*BOUNDARY, AMPLITUDE=RAMP
LEFT, 1, 2
*CONTACT PAIR, INTERACTION=SOFT
SLAVE, MASTER
*SURFACE, NAME=SLAVE, TYPE=NODE
RIGHT
*SURFACE, NAME=MASTER
E1, S1
*ELEMENT, TYPE=CPE4, ELSET=PLATE
1, 1, 2, 5, 4
2, 2, 3, 6, 5
*NSET, NSET=LEFT
1, 4
*NSET, NSET=RIGHT
3, 6
*ELSET, ELSET=E1
1
*NODE, NSET=ALL
1, 0, 0
2, 1, 0
3, 2, 0
4, 0, 1
5, 1, 1
6, 2, 1
*SURFACE INTERACTION, NAME=SOFT
*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR
1e6
*MATERIAL, NAME=STEEL
*ELASTIC
200e3, 0.3
*AMPLITUDE, NAME=RAMP
0, 0, 1, 1
*STEP
*STATIC
*CLOAD, AMPLITUDE=RAMP
RIGHT, 1, 10
*END STEP
)";

}  // namespace

TEST(CalculixSyntax, NamesMayBeUsedBeforeTheirDefinition) {
  const Model m = read_deck_string(kBackwards, "c.inp");
  ASSERT_EQ(m.n_nodes(), 6);
  ASSERT_EQ(m.n_elements(), 2);
  EXPECT_EQ(m.elements[1].nodes, (std::vector<int>{1, 2, 5, 4}));
  EXPECT_EQ(m.elements[0].section, 0);
  EXPECT_EQ(m.sections[0].material, 0);
  ASSERT_EQ(m.contact_pairs.size(), 1u);
  EXPECT_EQ(m.contact_pairs[0].interaction, "SOFT");
  EXPECT_EQ(m.contact_pairs[0].where.line, line_of(kBackwards, "SLAVE, MASTER"));
  EXPECT_EQ(m.interactions[0].behavior.law, PressureOverclosure::Law::Linear);
  ASSERT_EQ(m.steps.size(), 1u);
  ASSERT_EQ(m.steps[0].boundary.size(), 4u);
  EXPECT_EQ(m.steps[0].boundary[0].amplitude, 0);
  EXPECT_EQ(m.steps[0].cloads[0].amplitude, 0);
}

TEST(CalculixSyntax, ModelDataAfterTheStepsIsNotAllowed) {
  // CalculiX would read a *MATERIAL written after the steps before them; tether
  // keeps ABAQUS's rule that model data ends at the first *STEP, and says so.
  const std::string material = "*MATERIAL, NAME=STEEL\n*ELASTIC\n200e3, 0.3\n";
  const std::string late = replaced(kBackwards, material, "") + material;
  expect_deck_error(late, line_of(late, "*MATERIAL"), {"*MATERIAL is not allowed between steps"});
}

TEST(CalculixSyntax, ErrorsOfLateResolvedNamesNameTheReferencingLine) {
  const std::string& b = kBackwards;
  expect_deck_error_at(replaced(b, "INTERACTION=SOFT", "INTERACTION=HARDER"), "*CONTACT PAIR",
                       {"undefined INTERACTION=HARDER"});
  expect_deck_error_at(replaced(b, "MATERIAL=STEEL", "MATERIAL=STEAL"), "*SOLID SECTION", {"undefined material STEAL"});
  expect_deck_error_at(replaced(b, "*BOUNDARY, AMPLITUDE=RAMP", "*BOUNDARY, AMPLITUDE=RAMPE"), "*BOUNDARY",
                       {"undefined amplitude 'RAMPE'"});
  expect_deck_error_at(replaced(b, "SLAVE, MASTER", "SLAVE, MASTR"), "SLAVE, MASTR", {"undefined master surface 'MASTR'"});
  // Within a group the deck order holds, as in CalculiX: a set naming a later set.
  expect_deck_error_at(replaced(b, "*ELSET, ELSET=E1\n1\n", "*ELSET, ELSET=E1\nE0\n*ELSET, ELSET=E0\n1\n"), "E0\n",
                       {"undefined element set 'E0'"});
}

TEST(CalculixSyntax, MaterialOptionsStillFollowTheirMaterial) {
  // Reading by groups must not attach a misplaced option to an earlier material.
  expect_deck_error_at(replaced(kBackwards, "*STEP\n", "*DENSITY\n7.8e-9\n*STEP\n"), "*DENSITY",
                       {"*DENSITY is not allowed", "after *MATERIAL"});
}

TEST(CalculixSyntax, EmptyOrMissingNodeCoordinatesAreZero) {
  const Model m = read_deck_string(replaced(replaced(kDeck, "2, 1, 0\n", "2, 1\n"), "4, 0, 1\n", "4, , 1,\n"), "c.inp");
  EXPECT_DOUBLE_EQ(m.coords[1].x(), 1.0);
  EXPECT_DOUBLE_EQ(m.coords[1].y(), 0.0);
  EXPECT_DOUBLE_EQ(m.coords[3].x(), 0.0);
  EXPECT_DOUBLE_EQ(m.coords[3].y(), 1.0);
  const Model bare = read_deck_string(replaced(kDeck, "1, 0, 0\n", "1\n"), "c.inp");
  EXPECT_DOUBLE_EQ(bare.coords[0].norm(), 0.0);
  expect_deck_error_at(replaced(kDeck, "2, 1, 0\n", "2, one\n"), "2, one", {"bad number 'one'", "x coordinate"});
}

TEST(CalculixSyntax, SolidSectionOffsetZeroOnly) {
  const Model m = read_deck_string(replaced(kDeck, "MATERIAL=STEEL", "MATERIAL=STEEL, OFFSET=0."), "c.inp");
  EXPECT_DOUBLE_EQ(m.sections[0].thickness, 1.0);
  expect_deck_error_at(replaced(kDeck, "MATERIAL=STEEL", "MATERIAL=STEEL, OFFSET=0.5"), "OFFSET=0.5",
                       {"OFFSET=0.5", "expected OFFSET=0"});
}

TEST(CalculixSyntax, SingleRowElasticWithATemperatureHoldsAtEveryTemperature) {
  const Model m = read_deck_string(replaced(kDeck, "200e3, 0.3", "200e3, 0.3, 20."), "c.inp");
  ASSERT_TRUE(m.materials[0].elastic);
  EXPECT_DOUBLE_EQ(m.materials[0].elastic->young, 200e3);
  EXPECT_DOUBLE_EQ(m.materials[0].elastic->poisson, 0.3);
  const Model d = read_deck_string(replaced(kDeck, "200e3, 0.3\n", "200e3, 0.3\n*DENSITY\n7.8e-9, 20.\n"), "c.inp");
  EXPECT_DOUBLE_EQ(d.materials[0].density.value(), 7.8e-9);
}

TEST(CalculixSyntax, LoneStarLineIsSkippedWithAWarning) {
  std::vector<DeckWarning> warnings;
  const std::string deck = replaced(kDeck, "*MATERIAL", "*\n*MATERIAL");
  const Model m = read_deck_string(deck, "c.inp", &warnings);
  EXPECT_EQ(m.materials.size(), 1u);
  EXPECT_TRUE(has_warning(warnings, "lone '*' line is ignored", line_of(deck, "*\n*MATERIAL")));
  expect_deck_error_at(replaced(kDeck, "*MATERIAL", "*\n1, 2\n*MATERIAL"), "1, 2\n*MAT",
                       {"data line under a lone '*'"});
  expect_deck_error_at(replaced(kDeck, "*MATERIAL", "*, NAME=X\n*MATERIAL"), "*, NAME", {"empty keyword"});
}

// CalculiX removes every blank of a keyword line before it reads it, so its
// decks may write *SOLIDSECTION, *ENDSTEP, TYPE=NODETOSURFACE: tether reads
// them as the keywords, parameters and choices they spell.
TEST(CalculixSyntax, KeywordsParametersAndChoicesWithoutTheirBlanks) {
  std::string deck = replaced(kBackwards, "*SOLID SECTION,", "*SOLIDSECTION,");
  deck = replaced(deck, "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR", "*SURFACEBEHAVIOR,PRESSURE-OVERCLOSURE=LINEAR");
  deck = replaced(deck, "*CONTACT PAIR, INTERACTION=SOFT", "*CONTACTPAIR, INTERACTION=SOFT, TYPE=NODETOSURFACE");
  deck = replaced(deck, "*END STEP", "*ENDSTEP");
  const Model m = read_deck_string(deck, "c.inp");
  const Model reference = read_deck_string(kBackwards, "c.inp");
  ASSERT_EQ(m.steps.size(), reference.steps.size());
  ASSERT_EQ(m.contact_pairs.size(), 1U);
  EXPECT_EQ(m.sections.size(), reference.sections.size());
  EXPECT_TRUE(m.contact_pairs[0].node_to_surface);
  ASSERT_EQ(m.interactions.size(), reference.interactions.size());
  // A name that spells no keyword even without blanks is still unknown.
  EXPECT_THROW(read_deck_string(replaced(kBackwards, "*SOLID SECTION,", "*SOLIDSECTON,"), "c.inp"), InputError);
}

// ABAQUS's *NODE lines may carry a normal direction (fields 5-7, for shells
// and beams); CalculiX ignores it. tether ignores it with one warning.
TEST(CalculixSyntax, NodeNormalDirectionFieldsAreIgnoredWithAWarning) {
  std::vector<DeckWarning> warnings;
  const Model m = read_deck_string(replaced(replaced(kDeck, "2, 1, 0\n", "2, 1, 0, , 0.\n"), "4, 0, 1\n",
                                            "4, 0, 1, 0, 0, 0, 1\n"),
                                   "c.inp", &warnings);
  EXPECT_EQ(m.coords[static_cast<std::size_t>(m.node_index.at(2))], Eigen::Vector2d(1, 0));
  EXPECT_EQ(m.coords[static_cast<std::size_t>(m.node_index.at(4))], Eigen::Vector2d(0, 1));
  int n = 0;
  for (const auto& w : warnings) n += w.message.find("normal direction") != std::string::npos;
  EXPECT_EQ(n, 1);
}
