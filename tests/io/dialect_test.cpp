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
  // CalculiX's law (tension at open gaps) is not modelled: refused in that dialect, even with K alone.
  for (const std::string data : {"1e6\n", "1e6, 1., 0.001\n"}) {
    const std::string deck = with_behavior("*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n" + data);
    try {
      read(deck, Dialect::Calculix);
      ADD_FAILURE() << "CalculiX's LINEAR law accepted";
    } catch (const InputError& e) {
      const std::string msg = e.what();
      EXPECT_NE(msg.find("d.inp:" + std::to_string(line_of(deck, "*SURFACE BEHAVIOR"))), std::string::npos) << msg;
      EXPECT_NE(msg.find("does not model yet"), std::string::npos) << msg;
      EXPECT_NE(msg.find("--dialect abaqus"), std::string::npos) << msg;
    }
  }
}
