#include <gtest/gtest.h>

#include <stdexcept>

#include "tether/model/label_map.hpp"
#include "tether/model/model.hpp"

using namespace tether;

TEST(LabelMap, FindsDenseSparseAndNegativeLabels) {
  LabelMap m;
  EXPECT_TRUE(m.empty());
  EXPECT_TRUE(m.emplace(1, 0));
  EXPECT_TRUE(m.emplace(2, 1));
  EXPECT_TRUE(m.emplace(1000000000, 2));  // far beyond the count: kept sparse
  EXPECT_TRUE(m.emplace(-7, 3));          // negative: sparse
  EXPECT_TRUE(m.emplace(0, 4));
  EXPECT_FALSE(m.emplace(2, 9));          // already stored: unchanged, as std::unordered_map
  EXPECT_EQ(m.size(), 5u);
  EXPECT_EQ(m.at(1), 0);
  EXPECT_EQ(m.at(2), 1);
  EXPECT_EQ(m.at(1000000000), 2);
  EXPECT_EQ(m.at(-7), 3);
  EXPECT_EQ(m.at(0), 4);
  EXPECT_EQ(m.count(3), 0u);
  EXPECT_EQ(m.count(-7), 1u);
  EXPECT_THROW((void)m.at(3), std::out_of_range);
  EXPECT_THROW((void)m.at(999999999), std::out_of_range);
  EXPECT_TRUE(m.find(5) == m.end());
  const auto it = m.find(1000000000);
  ASSERT_FALSE(it == m.end());
  EXPECT_EQ(it->first, 1000000000);
  EXPECT_EQ(it->second, 2);
}

TEST(LabelMap, MovesSparseLabelsIntoTheDenseArrayAsItGrows) {
  LabelMap m;
  m.emplace(5000, 0);  // beyond 2 n + 1024 while empty: sparse
  for (int label = 1; label <= 4000; ++label) m.emplace(label, label);
  EXPECT_EQ(m.size(), 4001u);
  EXPECT_EQ(m.at(5000), 0);  // found wherever it is now
  EXPECT_EQ(m.at(4000), 4000);
  m[6000] = 7;  // operator[] inserts, then assigns
  EXPECT_EQ(m.at(6000), 7);
  EXPECT_EQ(m.size(), 4002u);
  m[6000] = 8;  // ... or assigns an existing label
  EXPECT_EQ(m.at(6000), 8);
  EXPECT_EQ(m.size(), 4002u);
}

// The per-element records of the model and of the discretization are kept
// small (docs/performance.md, "ContinuumElement and the model's tables made
// smaller"): 115k of each at the 230k-dof Hertz deck.
TEST(ModelMemory, ElementRecordsStaySmall) {
  EXPECT_EQ(sizeof(ElementType), 24u);
  EXPECT_LE(sizeof(Element), 64u);  // the deck line an index and a line (a SourceLocation was 40 bytes)
  EXPECT_EQ(sizeof(DeckLine), 8u);
}

// A DeckLine is a file index into Model::source_files and a line:
// Model::location gives back the SourceLocation it was made from.
TEST(ModelMemory, DeckLinesGiveBackTheirFileAndLine) {
  Model m;
  const DeckLine a = m.deck_line({"deck.inp", 12}), b = m.deck_line({"/some/where/mesh_of_a_long_name.inp", 3});
  const DeckLine c = m.deck_line({"deck.inp", 40});
  EXPECT_EQ(m.source_files, (std::vector<std::string>{"deck.inp", "/some/where/mesh_of_a_long_name.inp"}));
  EXPECT_EQ(a.file, c.file);
  EXPECT_EQ(m.location(a).str(), "deck.inp:12");
  EXPECT_EQ(m.location(b).str(), "/some/where/mesh_of_a_long_name.inp:3");
  EXPECT_EQ(m.location(c).str(), "deck.inp:40");
  EXPECT_EQ(m.location(DeckLine{}).str(), SourceLocation{}.str());  // an element made without a deck line
  EXPECT_EQ(m.location(m.deck_line({"", 0})).str(), "");
}

TEST(ElementType, InternedTypesAreSharedAndEqual) {
  const ElementType cpe4 = *find_element_type("CPE4");
  const ElementType& a = intern_element_type(cpe4);
  const ElementType& b = intern_element_type(*find_element_type("cpe4"));
  EXPECT_EQ(&a, &b);
  EXPECT_EQ(a.name, "CPE4");
  EXPECT_EQ(a.n_nodes, 4);
  ElementType stress = cpe4;  // another family under the same name: its own entry
  stress.family = Family::PlaneStress;
  const ElementType& c = intern_element_type(stress);
  EXPECT_NE(&a, &c);
  EXPECT_EQ(c.family, Family::PlaneStress);
  EXPECT_EQ(a.family, Family::PlaneStrain);
}
