// survey_deck(): every refusal of a deck in one scan, with its line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "deck_test_support.hpp"
#include "tether/io/deck_survey.hpp"

using namespace tether;
using namespace tether::test;

namespace {

std::string written(const std::string& name, const std::string& text) {
  const auto dir = std::filesystem::path(TETHER_BINARY_DIR) / "tests" / "io" / "survey";
  std::filesystem::create_directories(dir);
  const auto path = dir / name;
  std::ofstream(path) << text;
  return path.string();
}

}  // namespace

TEST(DeckSurvey, FindsEveryRefusalPastTheFirst) {
  std::string deck = replaced(kDeck, "TYPE=CPE4", "TYPE=C3D8");
  deck = replaced(deck, "*NSET, NSET=LEFT", "*NSET, NSET=LEFT, UNSORTED");
  deck = replaced(deck, "*ELASTIC", "*ELASTIC, TYPE=ORTHOTROPIC");
  deck = replaced(deck, "*STATIC", "*FREQUENCY\n*FOO");
  deck = replaced(deck, "*STEP\n", "*STEP, NLGEOM\n*\n");  // a bare choice and a lone '*' are fine
  const auto refusals = survey_deck(written("needs.inp", deck));
  ASSERT_EQ(refusals.size(), 5u);
  const std::vector<std::pair<Refusal::Kind, std::string>> expected = {
      {Refusal::Kind::ElementType, "C3D8"},
      {Refusal::Kind::Parameter, "*NSET, UNSORTED"},
      {Refusal::Kind::ParameterValue, "*ELASTIC, TYPE=ORTHOTROPIC"},
      {Refusal::Kind::Procedure, "*FREQUENCY"},
      {Refusal::Kind::Keyword, "*FOO"}};
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(refusals[i].kind, expected[i].first) << i;
    EXPECT_EQ(refusals[i].what, expected[i].second) << i;
  }
  EXPECT_EQ(refusals[3].where.line, line_of(deck, "*FREQUENCY"));
  EXPECT_EQ(refusal_kind_name(Refusal::Kind::ParameterValue), "parameter value");
  EXPECT_TRUE(survey_deck(written("good.inp", kDeck)).empty());
}

TEST(DeckSurvey, GmshLineElementsAreNotRefused) {
  const std::string deck = replaced(kDeck, "*NSET, NSET=LEFT", "*ELEMENT, TYPE=T3D2, ELSET=EDGE\n9, 1, 4\n*NSET, NSET=LEFT");
  EXPECT_TRUE(survey_deck(written("gmsh_lines.inp", deck)).empty());
}

TEST(DeckSurvey, ADeckThatCannotBeLexedIsOneUnreadableRefusal) {
  const auto r = survey_deck(written("include.inp", "*NODE\n*INCLUDE, INPUT=missing_nodes.inp\n"));
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].kind, Refusal::Kind::Unreadable);
  EXPECT_NE(r[0].what.find("cannot open *INCLUDE file 'missing_nodes.inp'"), std::string::npos) << r[0].what;
  EXPECT_EQ(r[0].where.line, 2);
}
