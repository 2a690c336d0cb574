// Bolt pretension (*PRE-TENSION SECTION) against the joint diagram: two
// plates clamped by a bolt between a fixed base and a rigid head, every strip
// a 1D bar (nu = 0, u_x = 0), so the finite-element answer is exact.
// Plane strain: k_joint = E_p w_p / L = 1000 * 2 / 2, k_bolt = E_b w_b / L = 3000 * 1 / 2.
// Axisymmetric: k_joint = 1000 pi (3^2 - 1^2) / 2, k_bolt = 3000 pi 0.5^2 / 2.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <iterator>
#include <string>

#include "analysis/run_deck.hpp"
#include "tether/output/pretension_report.hpp"

using namespace tether;

namespace {

constexpr double kPreload = 10, kSeparating = 4;  // [force]
constexpr double kRelative = 1e-10;

/// The joint's stiffnesses [force/length].
struct Joint {
  double joint = 1000, bolt = 1500;
};

std::string deck_text(const std::string& name = "bolt_joint.inp") {
  std::ifstream in(std::string(TETHER_SOURCE_DIR) + "/tests/analysis/decks/" + name);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto pos = text.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  if (pos != std::string::npos) text.replace(pos, from.size(), to);
  return text;
}

double reaction_y(const tether::testing::Run& run, const IncrementResults& r, const std::string& set) {
  double sum = 0;
  for (int n : run.model.node_sets.at(set)) sum += r.reaction[static_cast<std::size_t>(n)].y();
  return sum;
}

/// Checks both steps of the joint: the preload exactly, then the stiffness-ratio share of the separating load.
void expect_joint_diagram(const tether::testing::Run& run, const Joint& k = {}) {
  const double k_joint = k.joint, k_bolt = k.bolt;
  ASSERT_EQ(run.recorder.results.size(), 2u);
  const PretensionSection& section = run.model.pretension_sections.at(0);
  const IncrementResults& preload = run.recorder.results[0];
  const IncrementResults& loaded = run.recorder.results[1];

  const BoltState s1 = bolt_state(section, preload);
  EXPECT_NEAR(s1.force, kPreload, kRelative * kPreload);
  const double tightening = kPreload / k_bolt + kPreload / k_joint;  // the bolt stretches, the plates shorten
  EXPECT_NEAR(s1.tightening, tightening, kRelative * tightening);
  EXPECT_NEAR(reaction_y(run, preload, "PLATE_BOTTOM"), kPreload, kRelative * kPreload);
  EXPECT_NEAR(reaction_y(run, preload, "BOLT_BOTTOM"), -kPreload, kRelative * kPreload);

  const double share = k_bolt / (k_bolt + k_joint);  // 0.6 in plane strain
  const double bolt = kPreload + share * kSeparating, joint = kPreload - (1 - share) * kSeparating;
  const BoltState s2 = bolt_state(section, loaded);
  EXPECT_NEAR(s2.force, bolt, kRelative * bolt);
  EXPECT_NEAR(s2.tightening, tightening, kRelative * tightening);  // held by *BOUNDARY, FIXED
  EXPECT_NEAR(reaction_y(run, loaded, "PLATE_BOTTOM"), joint, kRelative * bolt);
  EXPECT_NEAR(reaction_y(run, loaded, "BOLT_BOTTOM"), -bolt, kRelative * bolt);
  const double head = kSeparating / (k_bolt + k_joint);
  EXPECT_NEAR(loaded.displacement[static_cast<std::size_t>(run.node(9))].y() -
                  preload.displacement[static_cast<std::size_t>(run.node(9))].y(),
              head, kRelative * head);
}

TEST(Pretension, BoltForceIsThePreloadThenGrowsByTheBoltsShareOfTheSeparatingLoad) {
  expect_joint_diagram(tether::testing::run_deck_text(deck_text()));
}

TEST(Pretension, AxisymmetricBoltCarriesTheSameDiagramWithRingAreas) {
  constexpr double pi = std::numbers::pi;
  expect_joint_diagram(tether::testing::run_deck_text(deck_text("bolt_joint_cax.inp")),
                       {1000 * pi * (9 - 1) / 2, 3000 * pi * 0.25 / 2});
}

// The plates as two bodies pressed together by the bolt (HARD contact at
// y = 1, exact): while the joint stays closed they act as the bonded stack.
TEST(Pretension, PlatesInContactAreClampedLikeTheBondedStack) {
  std::string deck = replaced(deck_text(), "26, 4., 2.\n", "26, 4., 2.\n14, 0., 1.\n15, 1., 1.\n16, 2., 1.\n");
  deck = replaced(deck, "3, 4, 5, 8, 7\n4, 5, 6, 9, 8\n", "3, 14, 15, 8, 7\n4, 15, 16, 9, 8\n");
  deck = replaced(deck, "*MATERIAL, NAME=PLATE_STEEL",
                  "*SURFACE, NAME=UPPER_BOTTOM\n3, S1\n4, S1\n*SURFACE, NAME=LOWER_TOP\n1, S3\n2, S3\n"
                  "*SURFACE INTERACTION, NAME=FACES\n*CONTACT PAIR, INTERACTION=FACES\nUPPER_BOTTOM, LOWER_TOP\n"
                  "*MATERIAL, NAME=PLATE_STEEL");
  const tether::testing::Run run = tether::testing::run_deck_text(deck);
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  ASSERT_EQ(run.model.contact_pairs.size(), 1u);
  expect_joint_diagram(run);
  const auto& contact = run.recorder.results[1].contact.at(0).nodes;
  double pressed = 0;
  for (const auto& n : contact) pressed += n.normal_force;
  EXPECT_NEAR(pressed, kPreload - (1 - 0.6) * kSeparating, 1e-9);  // the plates' share of the clamp, 8.4
}

// A bolt of triangles: the near-side triangle 13 touches the cut at one corner
// only (node 24); it must take the duplicate node too, or it would keep the
// halves welded there and carry part of the preload past the cut.
TEST(Pretension, TriangleTouchingTheCutAtACornerGoesWithItsSide) {
  std::string deck = replaced(deck_text(), "*ELEMENT, TYPE=CPE4, ELSET=BOLT\n11, 21, 22, 24, 23\n12, 23, 24, 26, 25\n",
                              "*ELEMENT, TYPE=CPE3, ELSET=BOLT\n11, 21, 24, 23\n13, 21, 22, 24\n"
                              "12, 23, 24, 26\n14, 23, 26, 25\n");
  deck = replaced(deck, "*SURFACE, NAME=CUT, TYPE=ELEMENT\n11, S3\n", "*SURFACE, NAME=CUT, TYPE=ELEMENT\n11, S2\n");
  const tether::testing::Run run = tether::testing::run_deck_text(deck);
  const Model& m = run.model;
  const auto& pairs = m.pretension_sections.at(0).pairs;
  ASSERT_EQ(pairs.size(), 2u);
  const Element& corner = m.elements[static_cast<std::size_t>(m.element_index.at(13))];
  const int original24 = m.node_index.at(24);
  for (const auto& [a, b] : pairs)
    if (a == original24) EXPECT_EQ(corner.nodes[2], b) << "element 13 still uses the far side's node 24";
  expect_joint_diagram(run);
}

}  // namespace
