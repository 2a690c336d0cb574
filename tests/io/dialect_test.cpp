// Dialects: where ABAQUS and CalculiX give the same data different meanings,
// the deck is read with the meaning of the dialect asked for, never silently
// with the other one.
#include <gtest/gtest.h>

#include "deck_test_support.hpp"

using namespace tether;
using namespace tether::test;

namespace {

bool has_warning(const std::vector<DeckWarning>& w, const std::string& words) {
  for (const auto& x : w)
    if (x.message.find(words) != std::string::npos) return true;
  return false;
}

const std::string kContact =
    "*SURFACE, NAME=SLAVE, TYPE=NODE\nRIGHT\n*SURFACE, NAME=MASTER\nE1, S1\n*SURFACE INTERACTION, NAME=SI\n";

std::string with_behavior(const std::string& behavior) {
  return replaced(kDeck, "*STEP", kContact + behavior + "*CONTACT PAIR, INTERACTION=SI\nSLAVE, MASTER\n*STEP");
}

Model read(const std::string& deck, Dialect d, std::vector<DeckWarning>* w = nullptr) {
  return read_deck_string(deck, "d.inp", w, d);
}

}  // namespace

TEST(Dialect, TheModelRecordsItAndAbaqusIsTheDefault) {
  EXPECT_EQ(read_deck_string(kDeck, "d.inp").dialect, Dialect::Abaqus);
  EXPECT_EQ(read(kDeck, Dialect::Calculix).dialect, Dialect::Calculix);
  EXPECT_EQ(parse_dialect("calculix"), Dialect::Calculix);
  EXPECT_EQ(parse_dialect("nastran"), std::nullopt);
  EXPECT_EQ(dialect_name(Dialect::Abaqus), "abaqus");
}

TEST(Dialect, NlgeomNoAfterAnNlgeomStepStaysOnInAbaqusAndTurnsOffInCalculix) {
  const std::string deck = replaced(kDeck, "*STEP\n", "*STEP, NLGEOM\n") +
                           "*STEP, NLGEOM=NO\n*STATIC\n*END STEP\n*STEP\n*STATIC\n*END STEP\n";
  std::vector<DeckWarning> w;
  const Model abaqus = read(deck, Dialect::Abaqus, &w);
  EXPECT_TRUE(abaqus.steps[1].nlgeom);
  EXPECT_TRUE(abaqus.steps[2].nlgeom);
  EXPECT_TRUE(has_warning(w, "stays on, as in ABAQUS"));
  w.clear();
  const Model calculix = read(deck, Dialect::Calculix, &w);
  EXPECT_TRUE(calculix.steps[0].nlgeom);
  EXPECT_FALSE(calculix.steps[1].nlgeom);
  EXPECT_FALSE(calculix.steps[2].nlgeom);  // a step without the parameter keeps the previous setting
  EXPECT_FALSE(has_warning(w, "stays on"));
}

TEST(Dialect, ExponentialLawTakesTheDialectsFunction) {
  const std::string deck = with_behavior("*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=EXPONENTIAL\n0.001, 100.\n");
  EXPECT_EQ(read(deck, Dialect::Abaqus).interactions[0].behavior.meaning, Dialect::Abaqus);
  const Model m = read(deck, Dialect::Calculix);
  EXPECT_EQ(m.interactions[0].behavior.meaning, Dialect::Calculix);
  EXPECT_DOUBLE_EQ(m.interactions[0].behavior.c0, 0.001);
}

TEST(Dialect, HardContactStaysExactAndTheCalculixDialectSaysSo) {
  const std::string deck = with_behavior("*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD\n");
  std::vector<DeckWarning> w;
  EXPECT_EQ(read(deck, Dialect::Calculix, &w).interactions[0].behavior.law, PressureOverclosure::Law::Hard);
  EXPECT_TRUE(has_warning(w, "enforced exactly (Lagrange multipliers) in the calculix dialect too"));
  EXPECT_TRUE(has_warning(w, "K = 50 E"));
  w.clear();
  read(deck, Dialect::Abaqus, &w);
  EXPECT_FALSE(has_warning(w, "K = 50 E"));
}

TEST(Dialect, LinearLawIsNeverReadWithTheWrongMeaning) {
  // ABAQUS's LINEAR is the slope K alone.
  const Model m = read(with_behavior("*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n1e6\n"), Dialect::Abaqus);
  EXPECT_EQ(m.interactions[0].behavior.law, PressureOverclosure::Law::Linear);
  EXPECT_EQ(m.interactions[0].behavior.c0, 0);
  // CalculiX's second and third fields are not an offset: refused, with the reason.
  const std::string calculix_data = with_behavior("*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n1e6, 1., 0.001\n");
  try {
    read(calculix_data, Dialect::Abaqus);
    ADD_FAILURE() << "sigma_inf and c0 accepted in the abaqus dialect";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("d.inp:" + std::to_string(line_of(calculix_data, "1e6, 1., 0.001"))), std::string::npos) << msg;
    EXPECT_NE(msg.find("not an offset"), std::string::npos) << msg;
    EXPECT_EQ(msg.find("K, 0, c0"), std::string::npos) << msg;
  }
  // The abaqus-dialect refusal points to the calculix dialect.
  try {
    read(calculix_data, Dialect::Abaqus);
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--dialect calculix"), std::string::npos) << e.what();
  }
}

TEST(Dialect, LinearLawIsCalculixsWithItsDefaultsInTheCalculixDialect) {
  const auto law = [](const std::string& data, std::vector<DeckWarning>* w = nullptr) {
    return read(with_behavior("*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n" + data), Dialect::Calculix, w)
        .interactions[0]
        .behavior;
  };
  const PressureOverclosure full = law("1e6, 2., 0.005\n");
  EXPECT_EQ(full.law, PressureOverclosure::Law::Linear);
  EXPECT_EQ(full.meaning, Dialect::Calculix);
  EXPECT_EQ(full.stiffness, 1e6);
  EXPECT_EQ(full.sigma_inf, 2.0);
  EXPECT_EQ(full.reach_factor, 0.005);
  EXPECT_EQ(full.c0, 0);  // c0 is the reach factor, never an offset
  // Fields by position; empty or <= 0 take CalculiX's defaults (K, sigma_inf from E by the analysis; c0 1e-3).
  const PressureOverclosure skipped = law("1e6, , 0.004\n");
  EXPECT_EQ(skipped.sigma_inf, 0);
  EXPECT_EQ(skipped.reach_factor, 0.004);
  EXPECT_EQ(law("1e6\n").reach_factor, 1e-3);
  std::vector<DeckWarning> w;
  const PressureOverclosure none = law("", &w);  // no data line, as CalculiX allows
  EXPECT_EQ(none.stiffness, 0);
  EXPECT_TRUE(has_warning(w, "50 E"));
  EXPECT_EQ(law("-5., -1.\n").stiffness, 0);
  // Bad input: file:line.
  const std::string four = with_behavior("*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n1e6, 1., 0.001, 7.\n");
  expect_deck_error(four, line_of(four, "1e6, 1., 0.001, 7."), {"three values at most"}, Dialect::Calculix);
  const std::string text = with_behavior("*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n1e6, x\n");
  expect_deck_error(text, line_of(text, "1e6, x"), {"*SURFACE BEHAVIOR value"}, Dialect::Calculix);
}

TEST(Dialect, PrintFrequencyIsPerRequestInAbaqusAndOneForAllPrintsInCalculix) {
  // ccx 2.20 on this pattern (NLGEOM, ten increments): a FREQUENCY on any one
  // print request is that of all of them (*NODE PRINT, *EL PRINT, *CONTACT
  // PRINT), the last one given wins, and it stays in force in later steps.
  const std::string deck = kMesh + R"(*STEP
*STATIC
*NODE PRINT, NSET=RIGHT, FREQUENCY=3
U
*EL PRINT, ELSET=PLATE
S
*NODE FILE
U
*OUTPUT, HISTORY, FREQUENCY=5
*NODE OUTPUT, NSET=LEFT
U
*END STEP
*STEP
*STATIC
*NODE PRINT, NSET=RIGHT
U
*EL PRINT, ELSET=PLATE, FREQUENCY=2
S
*NODE PRINT, NSET=LEFT
RF
*END STEP
)";
  const auto frequencies = [](const Step& s) {
    std::vector<int> f;
    for (const OutputRequest& r : s.outputs) f.push_back(r.frequency);
    return f;
  };
  const Model abaqus = read(deck, Dialect::Abaqus);
  EXPECT_EQ(frequencies(abaqus.steps[0]), (std::vector<int>{3, 1, 1, 5}));
  EXPECT_EQ(frequencies(abaqus.steps[1]), (std::vector<int>{1, 2, 1, 1}));  // + step 1's *NODE FILE, carried
  const Model calculix = read(deck, Dialect::Calculix);
  EXPECT_EQ(frequencies(calculix.steps[0]), (std::vector<int>{3, 3, 1, 5}));  // *NODE FILE, *OUTPUT keep theirs
  EXPECT_EQ(frequencies(calculix.steps[1]), (std::vector<int>{2, 2, 2, 1}));
  // Carried into a step that gives none: its own *NODE PRINT, then step 2's
  // *EL PRINT and *NODE FILE (requests of a kind a step does not give carry over).
  const std::string carried = deck + "*STEP\n*STATIC\n*NODE PRINT, NSET=RIGHT\nU\n*END STEP\n";
  EXPECT_EQ(frequencies(read(carried, Dialect::Calculix).steps[2]), (std::vector<int>{2, 2, 1}));
  EXPECT_EQ(frequencies(read(carried, Dialect::Abaqus).steps[2]), (std::vector<int>{1, 2, 1}));
}

// *CONTACT PRINT, SET= (CalculiX's test deck thread.inp): ccx 2.20 warns
// "parameter not recognized" and prints all slave nodes; the calculix dialect
// does the same, the abaqus dialect refuses it at its line.
TEST(Dialect, ContactPrintSetIsIgnoredWithAWarningInCalculixAndRefusedInAbaqus) {
  const std::string deck = replaced(with_behavior("*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=EXPONENTIAL\n0.001, 100.\n"),
                                    "*END STEP", "*CONTACT PRINT, SET=RIGHT\nCSTR\n*END STEP");
  std::vector<DeckWarning> w;
  const Model m = read(deck, Dialect::Calculix, &w);
  EXPECT_TRUE(has_warning(w, "SET=RIGHT on *CONTACT PRINT is ignored, as ccx does"));
  ASSERT_FALSE(m.steps.empty());
  EXPECT_EQ(m.steps[0].outputs.back().kind, OutputRequest::Kind::ContactPrint);
  expect_deck_error(deck, line_of(deck, "*CONTACT PRINT, SET=RIGHT"), {"no parameter SET", "calculix dialect"});
}
