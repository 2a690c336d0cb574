// The analysis names nodes and elements of an ABAQUS/CAE deck as its author
// knows them (`UPPER-1.7`), through label_text(): unknowns, elements and
// contact nodes (node-to-segment and mortar) and the mortar builder's errors alike.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "tether/analysis/discretization.hpp"
#include "tether/analysis/step_body_forces.hpp"
#include "tether/contact/contact_pair.hpp"
#include "tether/core/error.hpp"
#include "tether/io/deck_reader.hpp"

using namespace tether;

namespace {

const std::string kCaeDeck = std::string(TETHER_SOURCE_DIR) + "/tests/io/decks/cae/one_part_twice.inp";

Model cae_model() { return read_deck(kCaeDeck); }

/// The CAE deck with its contact pair made mortar and `edit` replaced by
/// `by` (once, after checking it is there).
Model cae_mortar_model(const std::string& edit = "", const std::string& by = "") {
  std::ifstream in(kCaeDeck);
  std::stringstream text;
  text << in.rdbuf();
  std::string deck = text.str();
  const std::string pair = "*Contact Pair, interaction=IntProp-1\n";
  deck.replace(deck.find(pair), pair.size(), "*Contact Pair, interaction=IntProp-1, type=SURFACE TO SURFACE\n");
  if (!edit.empty()) {
    const auto at = deck.find(edit);
    EXPECT_NE(at, std::string::npos) << edit;
    if (at != std::string::npos) deck.replace(at, edit.size(), by);
  }
  // One file per test and edit: ctest runs the tests of this file in parallel processes.
  static int calls = 0;
  const std::string path = ::testing::TempDir() + "/one_part_twice_mortar_" +
                           ::testing::UnitTest::GetInstance()->current_test_info()->name() + "_" +
                           std::to_string(++calls) + ".inp";
  std::ofstream(path) << deck;
  return read_deck(path);
}

/// The message of the ModelError that discretizing `model` throws ("" when none).
std::string discretization_error(const Model& model) {
  try {
    const Discretization disc(model);
  } catch (const ModelError& e) {
    return e.what();
  }
  return "";
}

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

// Pressure and body-force loads on an instance's elements are described
// with the instance's label (inside tether the upper copy's element 4 is 14),
// as analysis messages that come from them show them.
TEST(InstanceLabels, PressureAndBodyForceLoadsNameTheirElementByInstance) {
  std::ifstream in(std::string(TETHER_SOURCE_DIR) + "/tests/io/decks/cae/one_part_twice.inp");
  std::stringstream text;
  text << in.rdbuf();
  std::string deck = text.str();
  const auto add_before = [&](const std::string& anchor, const std::string& lines) {
    const auto at = deck.find(anchor);
    ASSERT_NE(at, std::string::npos) << anchor;
    deck.insert(at, lines);
  };
  add_before("*Surface Interaction", "*Density\n7.8e-9\n");
  add_before("*Restart, write", "*Dload\nUpper-1.4, P3, 5.\nUpper-1.Set-1, GRAV, 9810., 0., -1.\n");
  const Model model = read_deck_string(deck, "loads.inp");
  const Discretization disc(model);
  const auto pressures = disc.make_pressures(model.steps.at(0).pressures);
  ASSERT_EQ(pressures.size(), 1u);
  EXPECT_EQ(pressures[0]->describe(), "pressure on element UPPER-1.4 (CPE4) face S3");
  const StepBodyForces body(disc, 0);
  ASSERT_EQ(body.forces().size(), 4u);
  for (const auto& f : body.forces()) {
    const std::string d = f->describe();
    EXPECT_EQ(d.rfind("gravity on element UPPER-1.", 0), 0u) << d;
    EXPECT_EQ(d.find("element 1"), std::string::npos) << d;  // no internal label 11-14
  }
}

// The calculix dialect's node areas of a node-based slave surface name a node
// that belongs to no element as the user knows it (inside tether: 30).
TEST(InstanceLabels, NodeBasedSlaveAreaErrorNamesTheNodeByInstance) {
  std::ifstream in(std::string(TETHER_SOURCE_DIR) + "/tests/io/decks/cae/one_part_twice.inp");
  std::stringstream text;
  text << in.rdbuf();
  std::string deck = text.str();
  const auto replace = [&](const std::string& from, const std::string& to) {
    const auto at = deck.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    deck.replace(at, from.size(), to);
  };
  replace("      9,           1.,           1.\n", "      9,           1.,           1.\n     20,           2.,           2.\n");
  replace("*End Assembly", "*Nset, nset=Loose, instance=Upper-1\n 1, 20\n*Surface, type=NODE, name=LooseSurface\n"
                           "Loose\n*End Assembly");
  replace("Slave, Master", "LooseSurface, Master");
  const Model model = read_deck_string(deck, "loose.inp", nullptr, Dialect::Calculix);
  try {
    const Discretization disc(model);
    FAIL() << "expected a ModelError";
  } catch (const ModelError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("node UPPER-1.20 of node-based slave surface"), std::string::npos) << what;
  }
}

TEST(InstanceLabels, MortarContactNodesAreNamedByTheirLabelNotTheirIndex) {
  const Model model = cae_mortar_model();
  const Discretization disc(model);
  ASSERT_EQ(disc.mortar_pairs().size(), 1u);
  const auto nodes = disc.mortar_pairs()[0]->nodes();
  ASSERT_EQ(nodes.size(), 3u);  // the bottom of Upper-1: its nodes 1, 2, 3
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const std::string text = nodes[k]->describe();
    EXPECT_NE(text.find(", slave node UPPER-1." + std::to_string(k + 1)), std::string::npos) << text;
  }
}

// The mortar builder's errors about a node name it by its label too: Upper-1's
// node 2 on three slave faces (the bottoms of elements 1 and 2 and the right
// side of element 1), and its node 1 on both surfaces (the left side of
// element 1 added to the master surface).
TEST(InstanceLabels, MortarBuilderErrorsNameNodesByTheirLabel) {
  const std::string three_faces = discretization_error(cae_mortar_model(
      "*Surface, type=ELEMENT, name=Slave\n_Slave_S1, S1\n",
      "*Elset, elset=_Slave_S2, internal, instance=Upper-1\n 1\n"
      "*Surface, type=ELEMENT, name=Slave\n_Slave_S1, S1\n_Slave_S2, S2\n"));
  EXPECT_NE(three_faces.find("node UPPER-1.2 is on 3 faces of the slave surface"), std::string::npos) << three_faces;
  const std::string shared = discretization_error(cae_mortar_model(
      "*Surface, type=ELEMENT, name=Master\n_Master_S3, S3\n",
      "*Elset, elset=_Master_S4, internal, instance=Upper-1\n 1\n"
      "*Surface, type=ELEMENT, name=Master\n_Master_S3, S3\n_Master_S4, S4\n"));
  EXPECT_NE(shared.find("node UPPER-1.1 belongs to both the slave surface"), std::string::npos) << shared;
}

}  // namespace
