// The analysis names nodes and elements of an ABAQUS/CAE deck as its author
// knows them (`UPPER-1.7`), through label_text(): unknowns, elements and
// contact nodes alike.
#include <gtest/gtest.h>

#include <string>

#include "tether/analysis/discretization.hpp"
#include "tether/contact/contact_pair.hpp"
#include "tether/io/deck_reader.hpp"

using namespace tether;

namespace {

Model cae_model() { return read_deck(std::string(TETHER_SOURCE_DIR) + "/tests/io/decks/cae/one_part_twice.inp"); }

TEST(InstanceLabels, UnknownsAndElementsOfAnInstanceCarryItsName) {
  const Model model = cae_model();
  const Discretization disc(model);
  // Inside tether the upper copy's node 7 is 17 and its element 4 is 14.
  const int node = model.node_index.at(17);
  EXPECT_EQ(disc.dofs().describe(DofMap::displacement(node, 1)), "node UPPER-1.7 dof 2");
  EXPECT_EQ(disc.dofs().describe(DofMap::displacement(model.node_index.at(7), 0)), "node LOWER-1.7 dof 1");
  const int element = model.element_index.at(14);
  EXPECT_EQ(disc.elements()[static_cast<std::size_t>(element)]->describe(), "element UPPER-1.4 (CPE4)");
}

TEST(InstanceLabels, ContactNodesAreNamedByTheirLabelNotTheirIndex) {
  const Model model = cae_model();
  const Discretization disc(model);
  ASSERT_EQ(disc.contact_pairs().size(), 1u);
  const auto nodes = disc.contact_pairs()[0]->nodes();
  ASSERT_EQ(nodes.size(), 3u);  // the bottom of Upper-1: its nodes 1, 2, 3
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const std::string text = nodes[k]->describe();
    EXPECT_NE(text.find(", slave node UPPER-1." + std::to_string(k + 1)), std::string::npos) << text;
  }
}

}  // namespace
