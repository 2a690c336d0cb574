// Every error path: the message names the file, the line and what was expected.
#include <gtest/gtest.h>

#include "deck_test_support.hpp"

using namespace tether;
using namespace tether::test;

// --- keywords and parameters ---

TEST(DeckErrors, UnknownKeywordListsTheAllowedOnes) {
  const std::string deck = replaced(kDeck, "*STATIC", "*STATIC\n*FOO, BAR=1");
  expect_deck_error_at(deck, "*FOO", {"unknown keyword *FOO", "*CLOAD", "*END STEP"});
  expect_deck_error_at("*NODS\n1, 0, 0\n", "*NODS", {"unknown keyword *NODS", "*NODE", "*ELEMENT"});
}

TEST(DeckErrors, LaterKeywordsAreNotSupportedYetNeverDropped) {
  for (const std::string kw : {"*FREQUENCY", "*BUCKLE"}) {
    const std::string deck = replaced(kDeck, "*CLOAD", kw + "\n1, 2\n*CLOAD");
    expect_deck_error_at(deck, kw, {kw.substr(0, kw.find(',')) + " is not supported yet"});
  }
}

TEST(DeckErrors, UnknownParameterListsTheAllowedOnes) {
  expect_deck_error_at(replaced(kDeck, "*NSET, NSET=LEFT", "*NSET, NSET=LEFT, UNSORTED"), "UNSORTED",
                       {"unknown parameter UNSORTED on *NSET", "NSET, GENERATE"});
}

TEST(DeckErrors, BadParameterValues) {
  expect_deck_error_at(replaced(kDeck, "*ELASTIC", "*ELASTIC, TYPE=ORTHOTROPIC"), "ORTHOTROPIC",
                       {"bad value 'ORTHOTROPIC' for TYPE on *ELASTIC", "ISOTROPIC"});
  expect_deck_error_at(replaced(kDeck, "*STEP", "*STEP, INC=many"), "INC=many", {"bad number 'many'", "INC"});
  expect_deck_error_at(replaced(kDeck, "*STEP", "*STEP, INC=0"), "INC=0", {"INC=0", "positive"});
  expect_deck_error_at(replaced(kDeck, "*STATIC", "*STATIC, DIRECT=YES"), "DIRECT", {"DIRECT", "takes no value"});
  expect_deck_error_at(replaced(kDeck, "*STEP", "*STEP, NAME"), "*STEP, NAME", {"NAME on *STEP needs a value"});
  expect_deck_error_at(replaced(kDeck, "*NSET, NSET=LEFT", "*NSET, NSET=LEFT, NSET=B"), "NSET=B",
                       {"given twice"});
}

TEST(DeckErrors, MissingRequiredParameter) {
  expect_deck_error_at(replaced(kDeck, "*ELEMENT, TYPE=CPE4,", "*ELEMENT,"), "*ELEMENT",
                       {"*ELEMENT requires the parameter TYPE"});
  expect_deck_error_at(replaced(kDeck, "*MATERIAL, NAME=STEEL", "*MATERIAL"), "*MATERIAL",
                       {"requires the parameter NAME"});
}

TEST(DeckErrors, KeywordOutsideItsContext) {
  expect_deck_error_at(replaced(kDeck, "*BOUNDARY", "*STATIC\n*BOUNDARY"), "*STATIC",
                       {"*STATIC is not allowed in model data", "inside a step", "*STEP first"});
  expect_deck_error_at(replaced(kDeck, "*AMPLITUDE", "*ELASTIC\n1, 0.3\n*AMPLITUDE"), "*ELASTIC\n1, 0.3\n*AMP",
                       {"*ELASTIC is not allowed", "after *MATERIAL"});
  expect_deck_error_at(replaced(kDeck, "*CLOAD", "*NODE\n7, 0, 0\n*CLOAD"), "*NODE\n7",
                       {"*NODE is not allowed inside step Step-1", "model data", "*END STEP missing"});
  expect_deck_error_at(kDeck + "*NODE\n7, 0, 0\n", "*NODE\n7", {"*NODE is not allowed between steps"});
  expect_deck_error_at(kDeck + "*CLOAD\n1, 1, 1\n", "*CLOAD\n1, 1", {"*CLOAD is not allowed between steps"});
  expect_deck_error_at(replaced(kDeck, "*CLOAD", "*STEP\n*CLOAD"), "*STEP\n*CLOAD", {"*STEP is not allowed inside step"});
}

TEST(DeckErrors, EndStepMissingAndStepWithoutProcedure) {
  const std::string open = kMesh + "*STEP, NAME=Open\n*STATIC\n";
  expect_deck_error(open, line_of(open, "*STEP"), {"step Open is not closed", "expected *END STEP"});
  const std::string empty = kMesh + "*STEP\n*CLOAD\n1, 1, 1\n*END STEP\n";
  expect_deck_error(empty, line_of(empty, "*STEP"), {"no procedure", "*STATIC"});
  expect_deck_error_at(replaced(kDeck, "*CLOAD", "*STATIC\n*CLOAD"), "*STATIC\n*CLOAD", {"second procedure"});
}

// --- numbers and mesh ---

TEST(DeckErrors, BadNumberNamesTheToken) {
  expect_deck_error_at(replaced(kDeck, "2, 1, 0\n", "2, 1.0.0, 0\n"), "1.0.0", {"bad number '1.0.0'", "x coordinate"});
  expect_deck_error_at(replaced(kDeck, "200e3, 0.3", "200e3, abc"), "abc", {"bad number 'abc'"});
  expect_deck_error_at(replaced(kDeck, "RIGHT, 1, 10", "RIGHT, 1, 1e999"), "1e999", {"bad number '1e999'"});
  // Control bytes are escaped (a NUL would end the message) and long tokens cut,
  // so the message still says what was expected.
  expect_deck_error_at(replaced(kDeck, "2, 1, 0\n", std::string("2, \0\x01z, 0\n", 10)), "z, 0",
                       {"bad number '\\x00\\x01z' for x coordinate: expected a real number"});
  expect_deck_error_at(replaced(kDeck, "2, 1, 0\n", "2, " + std::string(100, '7') + "x, 0\n"), "7777",
                       {"bad number '" + std::string(40, '7') + "... (101 characters)' for x coordinate"});
}

TEST(DeckErrors, NodeLabelsMustBePositiveAndFitInt) {
  expect_deck_error_at(replaced(kDeck, "1, 0, 0\n", "0, 0, 0\n"), "0, 0, 0", {"'0'", "positive integer label"});
  expect_deck_error_at(replaced(kDeck, "1, 0, 0\n", "-4, 0, 0\n"), "-4, 0, 0", {"'-4'", "positive"});
  expect_deck_error_at(replaced(kDeck, "1, 0, 0\n", "3000000000, 0, 0\n"), "3000000000",
                       {"bad number '3000000000'", "32 bits"});
}

TEST(DeckErrors, DuplicateAndMissingNodes) {
  expect_deck_error_at(replaced(kDeck, "6, 2, 1\n", "6, 2, 1\n5, 3, 3\n"), "5, 3, 3", {"duplicate node 5"});
  expect_deck_error_at(replaced(kDeck, "2, 2, 3, 6, 5", "2, 2, 3, 66, 5"), "2, 2, 3, 66, 5",
                       {"element 2 references undefined node 66"});
  expect_deck_error_at(replaced(kDeck, "LEFT, 1, 2", "44, 1, 2"), "44, 1, 2", {"undefined node 44"});
  expect_deck_error_at(replaced(kDeck, "1, 4\n*NSET", "1, 4, 9\n*NSET"), "1, 4, 9", {"undefined node 9"});
  expect_deck_error_at(replaced(kDeck, "1, 0, 0\n", "1, 0, 0, 0, 0, 0, 1, 7\n"), "1, 0, 0, 0, 0, 0, 1, 7",
                       {"expected `label, x, y[, z[, nx, ny, nz]]`"});
  expect_deck_error_at(replaced(kDeck, "1, 0, 0\n", "1, 0, 0, 0, 0, x\n"), "1, 0, 0, 0, 0, x",
                       {"bad number 'x'", "normal direction component"});
}

TEST(DeckErrors, WrongNodeCountForTheType) {
  expect_deck_error_at(replaced(kDeck, "1, 1, 2, 5, 4", "1, 1, 2, 5"), "1, 1, 2, 5",
                       {"wrong number of nodes for CPE4", "expected 4 nodes but found 3"});
  expect_deck_error_at(replaced(kDeck, "1, 1, 2, 5, 4", "1, 1, 2, 5, 4, 3"), "1, 1, 2, 5, 4, 3",
                       {"expected 4 nodes but found 5"});
  expect_deck_error_at(replaced(kDeck, "2, 2, 3, 6, 5", "2, 2, 3,"), "2, 2, 3,", {"no continuation follows"});
  expect_deck_error_at(replaced(kDeck, "2, 2, 3, 6, 5", "1, 2, 3, 6, 5"), "1, 2, 3, 6, 5", {"duplicate element 1"});
}

TEST(DeckErrors, UnsupportedAndUnknownElementTypes) {
  expect_deck_error_at(replaced(kDeck, "TYPE=CPE4", "TYPE=CPE4R"), "CPE4R",
                       {"unsupported element type CPE4R", "hourglass", "CPE4"});
  expect_deck_error_at(replaced(kDeck, "TYPE=CPE4", "TYPE=C3D8"), "C3D8",
                       {"unsupported element type C3D8", "2D continuum", "CPE8R"});
  expect_deck_error_at(replaced(kDeck, "TYPE=CPE4", "TYPE=B21"), "B21", {"unsupported element type B21", "T3D2"});
}

TEST(DeckErrors, FamilyThatMakesARefusedHybridType) {
  // FAMILY=PLANE STRESS would turn a CPE4H into a CPS4H, which ABAQUS does not have.
  const std::string hybrid = replaced(kDeck, "TYPE=CPE4", "TYPE=CPE4H");
  expect_deck_error_at(replaced(hybrid, "*SOLID SECTION, ELSET=PLATE, MATERIAL=STEEL",
                                "*SOLID SECTION, ELSET=PLATE, MATERIAL=STEEL, FAMILY=PLANE STRESS"),
                       "*SOLID SECTION", {"FAMILY=PLANE STRESS makes element 1 (CPE4H) a CPS4H", "hybrid"});
}

TEST(DeckErrors, InvertedTriangleAndFoldedQuad) {
  expect_deck_error_at(replaced(kDeck, "1, 1, 2, 5, 4", "1, 1, 4, 5, 2"), "1, 1, 4, 5, 2",
                       {"element 1 (CPE4) is inverted", "counter-clockwise"});
  // A bow-tie: corners 2 and 5 swapped; the signed area of the polygon is zero
  // but two corner Jacobians are negative.
  expect_deck_error_at(replaced(kDeck, "2, 2, 3, 6, 5", "2, 2, 6, 3, 5"), "2, 2, 6, 3, 5",
                       {"element 2 (CPE4) is inverted or degenerate"});
  // A non-convex ("arrow") quad: positive area, one corner Jacobian negative.
  const std::string arrow = replaced(replaced(kDeck, "5, 1, 1\n", "5, 0.2, 0.2\n"), "2, 2, 3, 6, 5",
                                     "2, 2, 3, 6, 4");
  expect_deck_error_at(arrow, "1, 1, 2, 5, 4", {"element 1 (CPE4) is inverted", "corner node 5"});
  const std::string tri = R"(*NODE
1, 0, 0
2, 1, 0
3, 0, 1
*ELEMENT, TYPE=CPS3, ELSET=T
1, 1, 3, 2
*MATERIAL, NAME=M
*ELASTIC
1, 0.3
*SOLID SECTION, ELSET=T, MATERIAL=M
)";
  expect_deck_error_at(tri, "1, 1, 3, 2", {"element 1 (CPS3) is inverted"});
  const std::string flat = replaced(tri, "3, 0, 1", "3, 2, 0");
  expect_deck_error_at(replaced(flat, "1, 1, 3, 2", "1, 1, 2, 3"), "1, 1, 2, 3", {"inverted or degenerate"});
}

TEST(DeckErrors, AxisymmetricNodeAtNegativeRadius) {
  expect_deck_error_at(replaced(replaced(kDeck, "TYPE=CPE4", "TYPE=CAX4"), "1, 0, 0\n", "1, -0.5, 0\n"),
                       "1, 1, 2, 5, 4", {"radius", "r >= 0"});
}

TEST(DeckErrors, GenerateRangesAreCheckedBeforeAllocating) {
  expect_deck_error_at(replaced(kDeck, "*NSET, NSET=LEFT\n1, 4", "*NSET, NSET=LEFT, GENERATE\n1, 2000000000"),
                       "1, 2000000000", {"GENERATE range", "at most 100000000"});
  expect_deck_error_at(replaced(kDeck, "*NSET, NSET=LEFT\n1, 4", "*NSET, NSET=LEFT, GENERATE\n1, 1000"),
                       "1, 1000", {"only 6 are defined"});
  expect_deck_error_at(replaced(kDeck, "*NSET, NSET=LEFT\n1, 4", "*NSET, NSET=LEFT, GENERATE\n4, 1"), "4, 1",
                       {"first <= last"});
  expect_deck_error_at(replaced(kDeck, "*NSET, NSET=LEFT\n1, 4", "*NSET, NSET=LEFT, GENERATE\n1, 4, 0"), "1, 4, 0",
                       {"increment"});
}

// --- undefined names ---

TEST(DeckErrors, UndefinedSetMaterialAmplitudeSurface) {
  expect_deck_error_at(replaced(kDeck, "LEFT, 1, 2", "LEFTY, 1, 2"), "LEFTY", {"undefined node set 'LEFTY'"});
  expect_deck_error_at(replaced(kDeck, "ELSET=PLATE, MATERIAL", "ELSET=PLATES, MATERIAL"), "PLATES",
                       {"undefined element set 'PLATES'"});
  expect_deck_error_at(replaced(kDeck, "MATERIAL=STEEL", "MATERIAL=IRON"), "MATERIAL=IRON",
                       {"undefined material IRON", "*MATERIAL, NAME=IRON"});
  expect_deck_error_at(replaced(kDeck, "*CLOAD", "*CLOAD, AMPLITUDE=SLOW"), "SLOW", {"undefined amplitude 'SLOW'"});
  expect_deck_error_at(replaced(kDeck, "*CLOAD\nRIGHT, 1, 10", "*DSLOAD\nBOTTOM, P, 1"), "BOTTOM",
                       {"undefined surface 'BOTTOM'"});
  expect_deck_error_at(replaced(kDeck, "*CLOAD\nRIGHT, 1, 10", "*DLOAD\nE9, P1, 1"), "E9", {"undefined element set 'E9'"});
  expect_deck_error_at(replaced(kDeck, "*CLOAD\nRIGHT, 1, 10", "*NODE PRINT, NSET=NOPE\nU"), "NOPE",
                       {"undefined node set 'NOPE'"});
}

// --- sections and materials ---

TEST(DeckErrors, ElementWithoutSectionAndInTwoSections) {
  const std::string e1_only = replaced(kDeck, "ELSET=PLATE, MATERIAL", "ELSET=E1, MATERIAL");
  expect_deck_error_at(e1_only, "2, 2, 3, 6, 5", {"element 2 (CPE4) has no section", "*SOLID SECTION"});
  const std::string twice = replaced(kDeck, "*AMPLITUDE", "*SOLID SECTION, ELSET=E1, MATERIAL=STEEL\n*AMPLITUDE");
  expect_deck_error_at(twice, "ELSET=E1, MATERIAL", {"element 1 is in two sections", "bad.inp:"});
}

TEST(DeckErrors, MaterialWithoutElasticData) {
  const std::string deck = replaced(kDeck, "*ELASTIC\n200e3, 0.3", "*DENSITY\n7.8e-9");
  expect_deck_error_at(deck, "*MATERIAL", {"material STEEL has no elastic data", "*ELASTIC"});
  expect_deck_error_at(replaced(kDeck, "200e3, 0.3", "200e3, 0.3\n*ELASTIC\n1, 0.2"), "*ELASTIC\n1, 0.2",
                       {"already has elastic data"});
  expect_deck_error_at(replaced(kDeck, "*SOLID SECTION", "*MATERIAL, NAME=steel\n*SOLID SECTION"),
                       "NAME=steel", {"duplicate material STEEL"});
}

TEST(DeckErrors, ElasticConstantsOutOfRange) {
  expect_deck_error_at(replaced(kDeck, "200e3, 0.3", "200e3, 0.5"), "200e3, 0.5", {"nu", "-1 < nu < 0.5"});
  expect_deck_error_at(replaced(kDeck, "200e3, 0.3", "200e3, -1"), "200e3, -1", {"-1 < nu < 0.5"});
  expect_deck_error_at(replaced(kDeck, "200e3, 0.3", "0, 0.3"), "0, 0.3", {"E > 0"});
  expect_deck_error_at(replaced(kDeck, "200e3, 0.3", "-5, 0.3"), "-5, 0.3", {"E > 0"});
  expect_deck_error_at(replaced(kDeck, "200e3, 0.3", "200e3, 0.3, 20\n100e3, 0.3, 10"), "100e3, 0.3, 10",
                       {"*ELASTIC temperature", "strictly increasing"});
  expect_deck_error_at(replaced(kDeck, "200e3, 0.3", "200e3, 0.3, hot"), "200e3, 0.3, hot", {"temperature"});
  expect_deck_error_at(replaced(kDeck, "200e3, 0.3", "200e3, 0.3, 20, 1"), "200e3, 0.3, 20, 1",
                       {"expected `E, nu`[, temperature]"});
  expect_deck_error_at(replaced(kDeck, "*ELASTIC\n", "*ELASTIC\n*DENSITY\n"), "*ELASTIC",
                       {"*ELASTIC needs a data line", "`E, nu`"});
}

TEST(DeckErrors, HyperelasticNeedsNeoHookeAndCompressibility) {
  const std::string neo = replaced(kDeck, "*ELASTIC\n200e3, 0.3", "*HYPERELASTIC, NEO HOOKE\n1.0, 0");
  expect_deck_error_at(neo, "1.0, 0", {"D1 = 0", "incompressible", "D1 > 0"});
  expect_deck_error_at(replaced(neo, "1.0, 0", "-1, 0.1"), "-1, 0.1", {"C10 > 0"});
  expect_deck_error_at(replaced(neo, "NEO HOOKE", "MOONEY-RIVLIN"), "MOONEY", {"unknown parameter MOONEY-RIVLIN",
                                                                                "NEO HOOKE"});
  expect_deck_error_at(replaced(neo, ", NEO HOOKE", ""), "*HYPERELASTIC", {"without NEO HOOKE"});
}

TEST(DeckErrors, PlasticTableNamesTheBadLine) {
  const std::string plastic = replaced(kDeck, "200e3, 0.3", "200e3, 0.3\n*PLASTIC\n250, 0\n300, 0.02\n320, 0.01");
  expect_deck_error_at(plastic, "320, 0.01", {"*PLASTIC plastic strain 0.01", "greater than the previous"});
  expect_deck_error_at(replaced(plastic, "250, 0\n", "-250, 0\n"), "-250, 0", {"yield stress > 0"});
  expect_deck_error_at(replaced(plastic, "250, 0\n", "250, 0.001\n"), "250, 0.001", {"expected 0"});
  expect_deck_error_at(replaced(plastic, "300, 0.02", "300, 0.02, 20"), "300, 0.02, 20", {"temperature"});
  expect_deck_error_at(replaced(plastic, "320, 0.01", "320, 0.04\n*CYCLIC HARDENING\n250, 0"), "*CYCLIC HARDENING",
                       {"*CYCLIC HARDENING", "needs a *PLASTIC, HARDENING=COMBINED"});
  const std::string combined = replaced(replaced(plastic, "*PLASTIC", "*PLASTIC, HARDENING=COMBINED"), "320, 0.01",
                                        "320, 0.04\n*CYCLIC HARDENING\n250, 0\n260, 0");
  expect_deck_error_at(combined, "260, 0", {"*CYCLIC HARDENING plastic strain 0", "greater than the previous"});
  expect_deck_error_at(replaced(combined, "*CYCLIC HARDENING", "*CYCLIC HARDENING, PARAMETERS"), "*CYCLIC HARDENING",
                       {"PARAMETERS"});
  expect_deck_error_at(replaced(plastic, "320, 0.01", "320, 0.04\n*PLASTIC\n1, 0"), "*PLASTIC\n1, 0",
                       {"already has *PLASTIC"});
}

TEST(DeckErrors, PlasticTemperatureTableNamesTheBadLine) {
  const std::string plastic = replaced(kDeck, "200e3, 0.3",
                                       "200e3, 0.3\n*PLASTIC\n250, 0, 20\n300, 0.02, 20\n150, 0, 400\n200, 0.03, 400");
  expect_deck_error_at(replaced(plastic, "150, 0, 400", "150, 0, 10"), "150, 0, 10",
                       {"*PLASTIC temperature 10", "expected the temperatures to increase", "previous is 20"});
  expect_deck_error_at(replaced(plastic, "150, 0, 400", "150, 0.01, 400"), "150, 0.01, 400",
                       {"*PLASTIC plastic strain 0.01 on the first line of temperature 400", "expected 0"});
  expect_deck_error_at(replaced(plastic, "200, 0.03, 400", "200, 0.03"), "200, 0.03\n",
                       {"gives no temperature on this line", "every line or none"});
  expect_deck_error_at(replaced(plastic, "250, 0, 20\n", "250, 0\n"), "300, 0.02, 20",
                       {"gives a temperature (20) on this line but not on the first"});
  expect_deck_error_at(replaced(plastic, "200, 0.03, 400", "200, 0, 400"), "200, 0, 400",
                       {"*PLASTIC plastic strain 0", "greater than the previous line's (0)"});
  expect_deck_error_at(replaced(plastic, "150, 0, 400", "-150, 0, 400"), "-150, 0, 400", {"yield stress > 0"});
  expect_deck_error_at(replaced(plastic, "150, 0, 400", "150, 0, hot"), "150, 0, hot", {"*PLASTIC temperature"});
  // *CYCLIC HARDENING reads the same table.
  const std::string combined = replaced(replaced(plastic, "*PLASTIC", "*PLASTIC, HARDENING=COMBINED"),
                                        "200, 0.03, 400", "200, 0.03, 400\n*CYCLIC HARDENING\n250, 0, 20\n240, 0, 5");
  expect_deck_error_at(combined, "240, 0, 5", {"*CYCLIC HARDENING temperature 5", "increase"});
}

TEST(DeckErrors, SectionThicknessAndDensity) {
  expect_deck_error_at(replaced(kDeck, "MATERIAL=STEEL\n1.0", "MATERIAL=STEEL\n-1.0"), "-1.0", {"thickness > 0"});
  expect_deck_error_at(replaced(kDeck, "200e3, 0.3", "200e3, 0.3\n*DENSITY\n0"), "\n0\n",
                       {"rho > 0"});
}

// --- history data ---

TEST(DeckErrors, BoundaryDofs) {
  expect_deck_error_at(replaced(kDeck, "LEFT, 1, 2", "LEFT, 5, 6"), "LEFT, 5, 6", {"rotation", "dof 1 or 2"});
  expect_deck_error_at(replaced(kDeck, "LEFT, 1, 2", "LEFT, 2, 1"), "LEFT, 2, 1", {"bad dof range"});
  expect_deck_error_at(replaced(kDeck, "LEFT, 1, 2", "LEFT, 1, 7"), "LEFT, 1, 7", {"bad dof range"});
  expect_deck_error_at(replaced(kDeck, "LEFT, 1, 2", "LEFT, 3, 3, 0.1"), "LEFT, 3, 3, 0.1", {"out-of-plane dof 3"});
  expect_deck_error_at(replaced(kDeck, "LEFT, 1, 2", "LEFT, FIXED"), "LEFT, FIXED",
                       {"bad boundary type 'FIXED'", "ENCASTRE"});
}

TEST(DeckErrors, LoadDofsAndFaces) {
  expect_deck_error_at(replaced(kDeck, "RIGHT, 1, 10", "RIGHT, 3, 10"), "RIGHT, 3, 10", {"bad load dof 3", "1 or 2"});
  expect_deck_error_at(replaced(kDeck, "RIGHT, 1, 10", "RIGHT, 1"), "RIGHT, 1", {"`node_or_nset, dof, magnitude`"});
  expect_deck_error_at(replaced(kDeck, "*CLOAD\nRIGHT, 1, 10", "*DLOAD\n1, P5, 1"), "P5", {"bad face 'P5'", "P1..P4"});
  expect_deck_error_at(replaced(kDeck, "*CLOAD\nRIGHT, 1, 10", "*DLOAD\n1, BX, 1"), "BX", {"bad face 'BX'"});
  expect_deck_error_at(replaced(kDeck, "PLATE, S3", "PLATE, S0"), "PLATE, S0", {"bad face 'S0'", "S1..S4"});
  const std::string node_surface = replaced(replaced(kDeck, "*SURFACE, NAME=TOP\nPLATE, S3",
                                                     "*SURFACE, NAME=TOP, TYPE=NODE\nLEFT"),
                                            "*CLOAD\nRIGHT, 1, 10", "*DSLOAD\nTOP, P, 1");
  expect_deck_error_at(node_surface, "TOP, P, 1", {"node surface", "TYPE=ELEMENT"});
  expect_deck_error_at(replaced(kDeck, "*CLOAD\nRIGHT, 1, 10", "*DSLOAD\nTOP, TRVEC, 1"), "TRVEC",
                       {"bad load type 'TRVEC'"});
}

TEST(DeckErrors, AmplitudeTables) {
  expect_deck_error_at(replaced(kDeck, "0, 0, 1, 1", "0, 0, 1"), "0, 0, 1\n", {"odd number of values", "pairs"});
  expect_deck_error_at(replaced(kDeck, "0, 0, 1, 1", "0, 0, 1, 1\n1, 2"), "1, 2\n", {"does not increase"});
  expect_deck_error_at(replaced(kDeck, "*AMPLITUDE, NAME=RAMP", "*AMPLITUDE, NAME=RAMP, DEFINITION=SMOOTH STEP"),
                       "SMOOTH", {"bad value 'SMOOTH STEP' for DEFINITION", "TABULAR"});
}

TEST(DeckErrors, StaticAndControlsData) {
  expect_deck_error_at(replaced(kDeck, "*STATIC", "*STATIC\n2, 1"), "\n2, 1\n", {"0 < initial <= period"});
  expect_deck_error_at(replaced(kDeck, "*STATIC", "*STATIC\n0.1, -1"), "0.1, -1", {"period > 0"});
  expect_deck_error_at(replaced(kDeck, "*CLOAD", "*CONTROLS\n*CLOAD"), "*CONTROLS", {"PARAMETERS=FIELD"});
  expect_deck_error_at(replaced(kDeck, "*CLOAD", "*CONTROLS, PARAMETERS=FIELD\n-1\n*CLOAD"), "-1\n",
                       {"R_n = -1", "> 0"});
  expect_deck_error_at(replaced(kDeck, "*CLOAD", "*CONTROLS, PARAMETERS=TIME INCREMENTATION\n,,,0\n*CLOAD"),
                       ",,,0", {"IC = 0", "positive"});
  expect_deck_error_at(replaced(kDeck, "*CLOAD", "*CONTROLS, PARAMETERS=TIME INCREMENTATION\n,\n2\n*CLOAD"),
                       "\n2\n", {"Df = 2", "0 < Df < 1"});
}

TEST(DeckErrors, OutputRequests) {
  expect_deck_error_at(replaced(kDeck, "*CLOAD", "*NODE OUTPUT\nU\n*CLOAD"), "*NODE OUTPUT",
                       {"must follow *OUTPUT"});
  expect_deck_error_at(replaced(kDeck, "*CLOAD", "*OUTPUT\n*CLOAD"), "*OUTPUT", {"FIELD or HISTORY"});
  expect_deck_error_at(replaced(kDeck, "*CLOAD", "*NODE PRINT\n*CLOAD"), "*NODE PRINT", {"needs a data line", "U, RF"});
  expect_deck_error_at(replaced(kDeck, "*CLOAD", "*EL PRINT, FREQUENCY=-1\nS\n*CLOAD"), "*EL PRINT",
                       {"FREQUENCY=-1", ">= 0"});
}
