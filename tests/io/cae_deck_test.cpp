// ABAQUS/CAE decks: parts, an assembly of placed instances, names qualified
// by instance, and the CAE-only keywords and parameters.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "deck_test_support.hpp"

using namespace tether;
using namespace tether::test;

namespace {

const std::string kCaeDeck = decks_dir() + "/cae/two_instances.inp";

std::string deck_text() {
  std::ifstream in(kCaeDeck);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace

TEST(CaeDeck, InstancesArePlacedAndTheirNamesQualified) {
  std::vector<DeckWarning> warnings;
  const Model m = read_deck(kCaeDeck, &warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front().message;
  ASSERT_EQ(m.n_nodes(), 8);
  ASSERT_EQ(m.n_elements(), 2);
  // Upper-1: translated by (1, 1), then turned by 90 degrees about z through (1, 1).
  const auto at = [&](int label) { return m.coords[static_cast<std::size_t>(m.node_index.at(label))]; };
  EXPECT_NEAR((at(11) - Eigen::Vector2d(1, 1)).norm(), 0, 1e-15);
  EXPECT_NEAR((at(12) - Eigen::Vector2d(1, 2)).norm(), 0, 1e-15);
  EXPECT_NEAR((at(13) - Eigen::Vector2d(0, 2)).norm(), 0, 1e-15);
  EXPECT_NEAR((at(3) - Eigen::Vector2d(1, 1)).norm(), 0, 0);  // Lower-1 is not moved
  EXPECT_EQ(m.element_sets.at("LOWER-1.SET-1"), (std::vector<int>{0}));
  EXPECT_EQ(m.element_sets.at("UPPER-1.SET-1"), (std::vector<int>{1}));
  EXPECT_EQ(m.node_sets.at("LOWER-1.BOTTOM").size(), 2u);
  EXPECT_EQ(m.node_sets.at("TIED"), (std::vector<int>{m.node_index.at(11), m.node_index.at(14)}));
  EXPECT_EQ(m.surfaces.at("TOP").faces.size(), 1u);
  EXPECT_EQ(m.sections.size(), 2u);
  EXPECT_EQ(m.elements[1].section, 1);
  ASSERT_EQ(m.steps.size(), 1u);
  EXPECT_EQ(m.steps[0].boundary.size(), 8u);  // Lower-1.Bottom encastre (2 x 2), Tied (2 x 2)
  EXPECT_EQ(m.steps[0].pressures.size(), 1u);
  EXPECT_EQ(m.steps[0].restart_frequency, 0);
  // Errors keep the deck's own lines.
  EXPECT_EQ(m.elements[1].where.line, line_of(deck_text(), "11, 11, 12, 13, 14"));
}

TEST(CaeDeck, BadStructureNamesItsLine) {
  const std::string cae = deck_text();
  expect_deck_error_at(replaced(cae, "part=Upper", "part=Uper"), "*Instance, name=Upper-1",
                       {"*INSTANCE UPPER-1 of undefined part UPER"});
  expect_deck_error_at(replaced(cae, "1.,           1.,           1.,          90.", "1.,           2.,           1.,          90."),
                       "          90.", {"is not along z"});
  expect_deck_error_at(replaced(cae, "*End Part\n*Assembly", "*Assembly"), "*Part, name=Upper",
                       {"*PART UPPER is not closed"});
  expect_deck_error_at(replaced(cae, "instance=Upper-1", "instance=Upper-9"), "*Nset, nset=Tied",
                       {"INSTANCE=UPPER-9 on *NSET names no *INSTANCE"});
  expect_deck_error_at(replaced(kDeck, "*NSET, NSET=LEFT", "*NSET, NSET=LEFT, INSTANCE=A"), "*NSET, NSET=LEFT",
                       {"INSTANCE= on *NSET outside *ASSEMBLY"});
  expect_deck_error_at(replaced(kDeck, "*HEADING", "*PREPRINT, ECHO=MAYBE\n*HEADING"), "*PREPRINT",
                       {"bad value 'MAYBE' for ECHO"});
}

TEST(CaeDeck, TwoInstancesOfOnePartGetDistinctLabelsNamedByInstance) {
  const std::string path = decks_dir() + "/cae/one_part_twice.inp";
  const Model m = read_deck(path);
  ASSERT_EQ(m.n_nodes(), 18);
  ASSERT_EQ(m.n_elements(), 8);
  ASSERT_EQ(m.instances.size(), 2u);
  EXPECT_EQ(m.instances[0].offset, 0);   // Lower-1 keeps the part's labels 1-9
  EXPECT_EQ(m.instances[1].offset, 10);  // Upper-1: 11-19
  EXPECT_EQ(label_text(m.instances, 15), "UPPER-1.5");
  EXPECT_EQ(label_text(m.instances, 5), "LOWER-1.5");
  const auto at = [&](int label) { return m.coords[static_cast<std::size_t>(m.node_index.at(label))]; };
  EXPECT_NEAR((at(19) - Eigen::Vector2d(1, 2)).norm(), 0, 1e-15);
  EXPECT_EQ(m.elements[static_cast<std::size_t>(m.element_index.at(14))].nodes[2], m.node_index.at(19));
  EXPECT_EQ(m.node_sets.at("UPPER-1.TOP"),
            (std::vector<int>{m.node_index.at(17), m.node_index.at(18), m.node_index.at(19)}));
  const Surface& slave = m.surfaces.at("SLAVE");
  ASSERT_EQ(slave.faces.size(), 2u);
  EXPECT_EQ(m.elements[static_cast<std::size_t>(slave.faces[0].element)].id, 11);
  // Lower-1.Bottom encastre (3 x 2), Upper-1.Top along y (3), Upper-1.8 along x (internal node 18).
  ASSERT_EQ(m.steps[0].boundary.size(), 10u);
  EXPECT_EQ(m.steps[0].boundary.back().node, m.node_index.at(18));
  // *Output, field, variable=PRESELECT: U, RF, S, E and, with contact, CSTR, CDIS; history: nothing more;
  // then the *Node Print and *El Print.
  using K = OutputRequest::Kind;
  std::vector<K> kinds;
  for (const OutputRequest& r : m.steps[0].outputs) kinds.push_back(r.kind);
  EXPECT_EQ(kinds, (std::vector<K>{K::NodeFile, K::ElementFile, K::ContactFile, K::NodePrint, K::ElementPrint}));
}

TEST(CaeDeck, MessagesNameNodesAndElementsByInstance) {
  std::ifstream in(decks_dir() + "/cae/one_part_twice.inp");
  const std::string deck((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  expect_deck_error_at(replaced(deck, "Upper-1.8, 1, 1", "Upper-1.99, 1, 1"), "Upper-1.99",
                       {"undefined node or element UPPER-1.99", "labels 1-9"});
  // Inside the instance's range but not a node of it: named as the user knows it.
  const std::string gap = replaced(deck, "      9,           1.,           1.\n",
                                   "      9,           1.,           1.\n     20,           2.,           2.\n");
  expect_deck_error_at(replaced(gap, "Upper-1.8, 1, 1", "Upper-1.15, 1, 1"), "Upper-1.15",
                       {"undefined node UPPER-1.15"});
  // A part keyword whose labels tether would not move for the second instance.
  expect_deck_error_at(replaced(deck, "*End Part", "*Equation\n2\n7, 1, 1., 9, 1, -1.\n*End Part"), "*Equation",
                       {"*EQUATION inside a *PART instanced more than once", "UPPER-1"});
  expect_deck_error_at(replaced(deck, "1, 1, 2, 5, 4", "1, 1, 4, 5, 2"), "1, 1, 4, 5, 2",
                       {"element LOWER-1.1 (CPE4) is inverted", "corner node LOWER-1."});
  // A *TIE warning lists the untied slave nodes by instance (inside tether the upper copy's 7-9 are 17-19).
  std::string tie = replaced(deck, "*Elset, elset=_Slave_S1, internal, instance=Upper-1\n 1, 2\n*Surface, type=ELEMENT, name=Slave\n_Slave_S1, S1\n",
                             "*Elset, elset=_Slave_S1, internal, instance=Upper-1\n 1, 2\n*Elset, elset=_Slave_S3, internal, "
                             "instance=Upper-1\n 3, 4\n*Surface, type=ELEMENT, name=Slave\n_Slave_S1, S1\n_Slave_S3, S3\n");
  tie = replaced(tie, "*Surface Interaction, name=IntProp-1\n*Contact Pair, interaction=IntProp-1\nSlave, Master\n",
                 "*Tie, name=Glue\nSlave, Master\n");
  std::vector<DeckWarning> warnings;
  (void)read_deck_string(tie, "tie.inp", &warnings);
  std::string text;
  for (const DeckWarning& w : warnings) text += w.message + "\n";
  EXPECT_NE(text.find("are not tied: UPPER-1.7, UPPER-1.8, UPPER-1.9"), std::string::npos) << text;
  // A bad face of an instance's element (inside tether the upper copy's element 4 is 14).
  expect_deck_error_at(replaced(deck, "*Restart, write", "*Dload\nUpper-1.4, P7, 5.\n*Restart, write"),
                       "Upper-1.4, P7", {"bad face 'P7' for element UPPER-1.4 (CPE4)"});
}
