// Contact in whole analyses: a block pressed onto a block (uniform pressure
// transmitted exactly on matching meshes), the contact patch test on
// non-matching meshes (error measured and documented), equilibrium of the
// contact force with the reactions, lift-off, soft laws and friction.

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "run_deck.hpp"
#include "support/block_mesh.hpp"

using namespace tether;
using tether::testing::Block;
using tether::testing::run_deck_text;

namespace {

constexpr double kE = 1000, kNu = 0.3;

/// Top block [0,1]x[1,2] (slave: its bottom) on bottom block [0,1]x[0,1]
/// (master: its top); pressure `p` on the top, bottom on rollers, one node
/// of each block held in x. `interaction` goes after *SURFACE INTERACTION.
std::string stacked_blocks(int n_top, int n_bottom, bool quadratic, double p, const std::string& interaction,
                           const std::string& step_extra = "", const std::string& pair_options = "") {
  const Block top{0, 1, 1, 2, n_top, 2, quadratic, 1, 1, "TOP"};
  const Block bottom{0, 1, 0, 1, n_bottom, 2, quadratic, 1001, 1001, "BOTTOM"};
  std::ostringstream d;
  d.precision(17);
  top.write(d);
  bottom.write(d);
  top.write_surface(d, "SLAVE", 0);
  bottom.write_surface(d, "MASTER", 2);
  top.write_surface(d, "LOADED", 2);
  d << "*SURFACE INTERACTION, NAME=I\n" << interaction;
  d << "*CONTACT PAIR, INTERACTION=I, TYPE=NODE TO SURFACE" << pair_options << "\nSLAVE, MASTER\n";
  d << "*MATERIAL, NAME=M\n*ELASTIC\n" << kE << ", " << kNu << "\n";
  d << "*SOLID SECTION, ELSET=TOP, MATERIAL=M\n*SOLID SECTION, ELSET=BOTTOM, MATERIAL=M\n";
  d << "*NSET, NSET=BASE\n";
  for (int i = 0; i <= bottom.nx * bottom.step(); ++i) d << bottom.grid(i, 0) << "\n";
  d << "*BOUNDARY\nBASE, 2\n" << bottom.grid(0, 0) << ", 1\n" << top.grid(0, top.ny * top.step()) << ", 1\n";
  d << "*STEP\n*STATIC\n0.5, 1\n*CONTROLS, PARAMETERS=FIELD\n1e-10, 1e-10\n" << step_extra;
  d << "*DLOAD\n";
  for (int k = 0; k < top.nx; ++k) d << top.element(k, top.ny - 1) << ", P3, " << p << "\n";
  d << "*END STEP\n";
  return d.str();
}

const ContactPairValues& pair_values(const tether::testing::Run& run) { return run.last().contact.at(0); }

TEST(ContactAnalysis, MatchingBlocksTransmitUniformPressureExactly) {
  for (bool quadratic : {false, true}) {
    const auto run = run_deck_text(stacked_blocks(4, 4, quadratic, 10.0, "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD\n"));
    ASSERT_TRUE(run.summary.completed) << run.summary.message;
    const ContactPairValues& c = pair_values(run);
    ASSERT_EQ(c.nodes.size(), quadratic ? 9u : 5u);
    for (const ContactNodeValues& v : c.nodes) {
      EXPECT_NEAR(v.pressure, 10.0, 1e-9) << "node " << run.model.node_ids[v.node];
      EXPECT_NEAR(v.gap, 0.0, 1e-12);
      EXPECT_NE(v.status, ContactNodeValues::Status::Open);
    }
    // Contact force on the top block = -applied load = reaction at the base.
    EXPECT_NEAR(c.total_force.y(), 10.0, 1e-9);
    EXPECT_NEAR(run.reaction_sum("BASE", 1), 10.0, 1e-9);
    EXPECT_NEAR(c.total_force.x(), 0.0, 1e-10);
  }
}

}  // namespace
