// Contact in whole analyses: a block pressed onto a block (uniform pressure
// transmitted exactly on matching meshes), the contact patch test on
// non-matching meshes (error measured and documented), equilibrium of the
// contact force with the reactions, lift-off, soft laws and friction.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
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
                           const std::string& step_extra = "", const std::string& pair_options = "",
                           bool two_pass = false) {
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
  if (two_pass) d << "*CONTACT PAIR, INTERACTION=I, TYPE=NODE TO SURFACE" << pair_options << "\nMASTER, SLAVE\n";
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

/// Largest |p - p_exact| / p_exact over the closed slave nodes of every pair.
double pressure_error(const tether::testing::Run& run, double p) {
  double e = 0;
  for (const ContactPairValues& c : run.last().contact)
    for (const ContactNodeValues& v : c.nodes)
      if (v.status != ContactNodeValues::Status::Open) e = std::max(e, std::abs(v.pressure - p) / p);
  return e;
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

TEST(ContactAnalysis, RegularisedPenaltyAndAugmentedHardContact) {
  // Matching meshes, p = 10: every option carries the load; the gap is
  // -eps N (regularised), -N / rho (penalty), within TOLERANCE (augmented).
  // The compliance acts on nodal forces, so the end nodes (half the area)
  // penetrate half as much and the pressure is uniform only to ~2 %.
  struct Option {
    std::string parameters;
    double expected_gap_per_force;  ///< gap = -this * N (0: exact or augmented)
    double tolerance;
  };
  for (const Option& o : {Option{", EPSILON=1e-4", 1e-4, 1e-10}, Option{", ENFORCEMENT=PENALTY, PENALTY=1e5", 1e-5, 1e-10},
                          Option{", ENFORCEMENT=AUGMENTED, PENALTY=1e3, TOLERANCE=1e-9", 0, 1e-9}}) {
    const auto run =
        run_deck_text(stacked_blocks(4, 4, false, 10.0, "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD" + o.parameters + "\n"));
    ASSERT_TRUE(run.summary.completed) << o.parameters << ": " << run.summary.message;
    const ContactPairValues& c = pair_values(run);
    EXPECT_NEAR(c.total_force.y(), 10.0, 1e-6) << o.parameters;
    for (const ContactNodeValues& v : c.nodes) {
      EXPECT_NEAR(v.pressure, 10.0, o.expected_gap_per_force > 0 ? 0.2 : 1e-5) << o.parameters;
      EXPECT_NEAR(v.gap, -o.expected_gap_per_force * v.normal_force, o.tolerance) << o.parameters;
    }
  }
}

// The contact patch test: uniform pressure through a flat interface between
// non-matching meshes. One-pass node-to-segment transmits the load in
// equilibrium but not as a uniform pressure: the slave nodal forces reach the
// master through the shape functions at the projection points, which are not
// the master's consistent nodal forces (the same defect ccx shows: -14...+11 %).
// Two-pass (each surface slave of the other) over-constrains the interface.
// The test measures and documents both; it does not pretend they pass.
TEST(ContactAnalysis, PatchTestErrorOfOnePassAndTwoPassIsMeasured) {
  const std::string hard = "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD\n";
  for (const auto& [n_top, n_bottom] : {std::pair{4, 6}, std::pair{5, 3}, std::pair{7, 4}}) {
    const auto run = run_deck_text(stacked_blocks(n_top, n_bottom, false, 10.0, hard));
    ASSERT_TRUE(run.summary.completed) << run.summary.message;
    const double error = pressure_error(run, 10.0);
    std::printf("[ patch ] one-pass CPE4 %d on %d: max pressure error %.2f %%, contact force %.12f (load 10)\n", n_top,
                n_bottom, 100 * error, pair_values(run).total_force.y());
    // Equilibrium holds whatever the pressure distribution.
    EXPECT_NEAR(pair_values(run).total_force.y(), 10.0, 1e-8);
    EXPECT_NEAR(run.reaction_sum("BASE", 1), 10.0, 1e-8);
    // Measured (4 on 6, 5 on 3, 7 on 4): see the printed figures; bounded here
    // so that a change of the formulation is noticed.
    EXPECT_LT(error, 0.5);
  }
  // Two-pass HARD is refused (the end nodes of both meshes coincide, so the
  // constraints repeat each other); two-pass with a stiff LINEAR law runs.
  try {
    run_deck_text(stacked_blocks(5, 3, false, 10.0, hard, "", "", true));
    ADD_FAILURE() << "two-pass HARD contact was accepted";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("two-pass HARD contact"), std::string::npos) << e.what();
  }
  const double k = 1e7;  // penalty: overclosure p/k = 1e-6, 1e-6 of the block size
  for (bool two_pass : {false, true}) {
    const auto run = run_deck_text(stacked_blocks(5, 3, false, 10.0,
                                                  "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n" +
                                                      std::to_string(k) + "\n",
                                                  "", "", two_pass));
    ASSERT_TRUE(run.summary.completed) << run.summary.message;
    // Force on the top block: from pass 1 (top is slave) minus that on the bottom block from pass 2.
    const auto& c = run.last().contact;
    const double first = c.at(0).total_force.y(), second = two_pass ? -c.at(1).total_force.y() : 0.0;
    std::printf("[ patch ] %s CPE4 5 on 3, LINEAR K = %g: pass 1 carries %.4f, pass 2 %.4f of 10; "
                "pass-1 pressure spread %.2f %% of its mean\n",
                two_pass ? "two-pass" : "one-pass", k, first, second, 100 * pressure_error(run, first));
    EXPECT_NEAR(first + second, 10.0, 1e-6);
  }
}

TEST(ContactAnalysis, FloatingBodyIsReportedNotSolved) {
  // The top element hovers 0.01 above the bottom one and is pushed down by a
  // force: nothing holds it until contact closes (CalculiX returns 1e10
  // displacements here). tether stops at once and says why.
  const std::string deck = R"(*NODE
1, 0, 0
2, 1, 0
3, 1, 1
4, 0, 1
5, 0, 1.01
6, 1, 1.01
7, 1, 2
8, 0, 2
*ELEMENT, TYPE=CPE4, ELSET=E
1, 1, 2, 3, 4
2, 5, 6, 7, 8
*SURFACE, NAME=S
2, S1
*SURFACE, NAME=M
1, S3
*SURFACE INTERACTION, NAME=I
*CONTACT PAIR, INTERACTION=I, TYPE=NODE TO SURFACE
S, M
*MATERIAL, NAME=M
*ELASTIC
1000, 0.3
*SOLID SECTION, ELSET=E, MATERIAL=M
*BOUNDARY
1, 1, 2
2, 2
5, 1
*STEP
*STATIC
*CLOAD
7, 2, -1.
*END STEP
)";
  const auto run = run_deck_text(deck);
  EXPECT_FALSE(run.summary.completed);
  EXPECT_NE(run.summary.message.find("singular"), std::string::npos) << run.summary.message;
  EXPECT_NE(run.summary.message.find("a body held only by contact floats while its contact is open"),
            std::string::npos)
      << run.summary.message;
  EXPECT_TRUE(run.recorder.results.empty());
}

TEST(ContactAnalysis, AdjustClosesAnInitialGapStressFree) {
  // The floating deck above with ADJUST=0.02: the hovering face is moved onto
  // the bottom element before the analysis, so the force is carried at once.
  std::string deck = R"(*NODE
1, 0, 0
2, 1, 0
3, 1, 1
4, 0, 1
5, 0, 1.01
6, 1, 1.01
7, 1, 2
8, 0, 2
*ELEMENT, TYPE=CPE4, ELSET=E
1, 1, 2, 3, 4
2, 5, 6, 7, 8
*SURFACE, NAME=S
2, S1
*SURFACE, NAME=M
1, S3
*SURFACE INTERACTION, NAME=I
*CONTACT PAIR, INTERACTION=I, TYPE=NODE TO SURFACE, ADJUST=0.02
S, M
*MATERIAL, NAME=M
*ELASTIC
1000, 0.3
*SOLID SECTION, ELSET=E, MATERIAL=M
*BOUNDARY
1, 1, 2
2, 2
5, 1
*STEP
*STATIC
*CLOAD
7, 2, -1.
8, 2, -1.
*END STEP
)";
  std::vector<DeckWarning> notes;
  tether::testing::Run run;
  run.model = read_deck_string(deck, "adjust.inp", &notes);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].message.find("moved 2 slave node(s)"), std::string::npos) << notes[0].message;
  EXPECT_DOUBLE_EQ(run.model.coords[run.node(5)].y(), 1.0);
  EXPECT_DOUBLE_EQ(run.model.coords[run.node(7)].y(), 2.0);  // not a slave node
  StaticAnalysis analysis(run.model, run.recorder);
  run.summary = analysis.run();
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  EXPECT_NEAR(pair_values(run).total_force.y(), 2.0, 1e-10);
}

TEST(ContactAnalysis, SlipThatKeepsReversingIsHeldInStick) {
  // Two bodies squeezed with the top held in x: the Poisson expansions differ,
  // the friction force at the two closed nodes is small and of either sign,
  // and the semi-smooth Newton alternated between slip to the left and to the
  // right forever (no open/closed change, so the open/closed guard did not
  // see it). The friction guard holds such nodes in stick until convergence.
  const std::string deck = R"(*NODE
1, 0, 0
2, 1, 0
3, 2, 0
4, 0, 1
5, 1, 1
6, 2, 1
11, 0.5, 1
12, 1.0, 1
13, 1.5, 1.05
14, 0.5, 2
15, 1.0, 2
16, 1.5, 2
*ELEMENT, TYPE=CPE4, ELSET=LOWER
1, 1, 2, 5, 4
2, 2, 3, 6, 5
*ELEMENT, TYPE=CPE4, ELSET=UPPER
11, 11, 12, 15, 14
12, 12, 13, 16, 15
*ELSET, ELSET=EALL
LOWER, UPPER
*NSET, NSET=BOT
1, 2, 3
*NSET, NSET=TOP
14, 15, 16
*SURFACE, NAME=LTOP
1, S3
2, S3
*SURFACE, NAME=UBOT
11, S1
12, S1
*MATERIAL, NAME=STEEL
*ELASTIC
200000, 0.3
*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL
*SURFACE INTERACTION, NAME=SI
*FRICTION
0.2
*CONTACT PAIR, INTERACTION=SI, TYPE=NODE TO SURFACE
UBOT, LTOP
*BOUNDARY
BOT, 1, 2
*STEP, NLGEOM
*STATIC
0.5, 1.0
*BOUNDARY
TOP, 1, 1, 0
TOP, 2, 2, -0.001
*END STEP
*STEP, NLGEOM
*STATIC
0.5, 1.0
*BOUNDARY
TOP, 1, 1, 0.01
TOP, 2, 2, -0.001
*END STEP
)";
  const auto run = run_deck_text(deck);
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  EXPECT_EQ(run.summary.cutbacks, 0);
  // Step 2 slides the top by 0.01: both closed nodes slip at T = mu N.
  for (const ContactNodeValues& v : pair_values(run).nodes) {
    if (v.status == ContactNodeValues::Status::Open) continue;
    EXPECT_EQ(v.status, ContactNodeValues::Status::Slip);
    EXPECT_NEAR(std::abs(v.tangential_force), 0.2 * v.normal_force, 1e-9 * v.normal_force);
  }
}

/// Top block pressed by `p`, then its top edge pushed in x by `slide` (step 2,
/// in `increments` equal increments); every node of the bottom block is fixed
/// (a rigid flat), so the contact normal stays vertical.
std::string sliding_block(double p, double slide, int increments, const std::string& interaction,
                          const std::string& pair_options = "") {
  const Block top{0, 1, 1, 1.5, 4, 1, false, 1, 1, "TOP"};
  const Block bottom{0, 2, 0, 1, 6, 2, false, 1001, 1001, "BOTTOM"};
  std::ostringstream d;
  d.precision(17);
  top.write(d);
  bottom.write(d);
  top.write_surface(d, "SLAVE", 0);
  bottom.write_surface(d, "MASTER", 2);
  d << "*SURFACE INTERACTION, NAME=I\n" << interaction;
  d << "*CONTACT PAIR, INTERACTION=I, TYPE=NODE TO SURFACE" << pair_options << "\nSLAVE, MASTER\n";
  d << "*MATERIAL, NAME=M\n*ELASTIC\n" << kE << ", " << kNu << "\n";
  d << "*SOLID SECTION, ELSET=TOP, MATERIAL=M\n*SOLID SECTION, ELSET=BOTTOM, MATERIAL=M\n";
  d << "*NSET, NSET=BASE, GENERATE\n" << bottom.grid(0, 0) << ", " << bottom.grid(bottom.nx, bottom.ny) << "\n";
  d << "*NSET, NSET=PUSHED\n";
  for (int i = 0; i <= top.nx; ++i) d << top.grid(i, top.ny) << "\n";
  d << "*BOUNDARY\nBASE, 1, 2\nPUSHED, 1\n";
  d << "*STEP\n*STATIC\n1, 1\n*CONTROLS, PARAMETERS=FIELD\n1e-10, 1e-10\n*DLOAD\n";
  for (int k = 0; k < top.nx; ++k) d << top.element(k, 0) << ", P3, " << p << "\n";
  d << "*END STEP\n";
  d << "*STEP, INC=1000\n*STATIC, DIRECT\n" << 1.0 / increments << ", 1\n*CONTROLS, PARAMETERS=FIELD\n1e-10, 1e-10\n";
  d << "*BOUNDARY\nPUSHED, 1, 1, " << slide << "\n*END STEP\n";
  return d.str();
}

struct FrictionRun {
  double fx = 0, fy = 0;  ///< reaction of the pushed edge in x, contact normal force total
  int stick = 0, slip = 0, open = 0;
  double friction = 0;    ///< sum of the tangential contact forces
};

FrictionRun friction_after(const tether::testing::Run& run, std::size_t result) {
  FrictionRun f;
  const IncrementResults& r = run.recorder.results.at(result);
  for (int n : run.model.node_sets.at("PUSHED")) f.fx += r.reaction[n][0];
  for (const ContactNodeValues& v : r.contact.at(0).nodes) {
    f.fy += v.normal_force;
    f.friction += v.tangential_force;
    f.stick += v.status == ContactNodeValues::Status::Stick;
    f.slip += v.status == ContactNodeValues::Status::Slip;
    f.open += v.status == ContactNodeValues::Status::Open;
  }
  return f;
}

TEST(ContactAnalysis, BlockSticksBelowMuNAndSlidesAtMuN) {
  const double mu = 0.3, p = 10;
  for (const char* friction : {"*FRICTION\n0.3\n", "*FRICTION\n0.3, 20000\n"}) {
    const auto run = run_deck_text(sliding_block(p, 0.05, 50, friction));
    ASSERT_TRUE(run.summary.completed) << run.summary.message;
    // Step 1 (pressure, top edge held): no tangential load, all closed.
    const FrictionRun pressed = friction_after(run, 0);
    EXPECT_NEAR(pressed.fy, p * 1.0, 1e-9);
    EXPECT_EQ(pressed.open, 0);
    // First increment of the push: the block sticks (T well below mu N).
    const FrictionRun start = friction_after(run, 1);
    EXPECT_LT(std::abs(start.fx), 0.5 * mu * start.fy) << friction;
    EXPECT_GT(start.stick, 0) << friction;
    EXPECT_NEAR(start.friction, -start.fx, 1e-9 * p) << friction;
    // End: the whole interface slides; the push force is mu N.
    const FrictionRun end = friction_after(run, run.recorder.results.size() - 1);
    // The push tips the block: its trailing corner may lift; every other node slides.
    EXPECT_LE(end.open, 1) << friction;
    EXPECT_EQ(end.slip + end.open, 5) << friction << ": " << end.stick << " nodes stick";
    EXPECT_NEAR(std::abs(end.fx), mu * end.fy, 1e-6 * mu * end.fy) << friction;
    EXPECT_NEAR(end.fy, p * 1.0, 1e-6 * p) << friction;
    // Sliding dissipates mu N times the slip.
    EXPECT_GT(run.last().contact.at(0).dissipation, 0.0) << friction;
  }
}

TEST(ContactAnalysis, FrictionlessBlockNeedsNoPush) {
  const auto run = run_deck_text(sliding_block(10, 0.05, 5, ""));
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  const FrictionRun end = friction_after(run, run.recorder.results.size() - 1);
  EXPECT_NEAR(end.fx, 0.0, 1e-9);
  EXPECT_NEAR(end.fy, 10.0, 1e-9);
  EXPECT_EQ(end.slip, 5);
}

TEST(ContactAnalysis, SmallSlidingKeepsTheFirstPairingFiniteSlidingFollows) {
  // The top block slides by 0.6 (almost two master segments of 1/3). With
  // finite sliding every slave node moves on to other master faces; SMALL
  // SLIDING keeps the faces found at the start (extended past their ends).
  for (const bool small : {false, true}) {
    const auto run = run_deck_text(sliding_block(10, 0.6, 20, "", small ? ", SMALL SLIDING" : ""));
    ASSERT_TRUE(run.summary.completed) << run.summary.message;
    const auto& first = run.recorder.results.front().contact.at(0).nodes;
    const auto& last = run.last().contact.at(0).nodes;
    int changed = 0;
    for (std::size_t k = 0; k < first.size(); ++k) changed += first[k].master_element != last[k].master_element;
    if (small)
      EXPECT_EQ(changed, 0);
    else
      EXPECT_EQ(changed, static_cast<int>(first.size()));
    // Frictionless: the push needs no force either way.
    double fx = 0;
    for (int n : run.model.node_sets.at("PUSHED")) fx += run.last().reaction[n][0];
    EXPECT_NEAR(fx, 0.0, 1e-8) << (small ? "small sliding" : "finite sliding");
  }
}

}  // namespace

// A node-based slave surface has no faces to give its nodes an area: each
// node's area is the second field of its *SURFACE, TYPE=NODE line (default 1,
// as in ABAQUS), and the pressure output is the normal force over it. The
// area used to be read and ignored. Two blocks, the upper pressed down by
// 1 + 1: each of its two bottom nodes carries N = 1.
TEST(ContactAnalysis, NodeBasedSlavePressureIsTheForceOverTheNodeArea) {
  const auto deck = [](const std::string& slave_lines) {
    return R"(*NODE
1, 0, 0
2, 1, 0
3, 1, 1
4, 0, 1
5, 0, 1
6, 1, 1
7, 1, 2
8, 0, 2
*ELEMENT, TYPE=CPE4, ELSET=E
1, 1, 2, 3, 4
2, 5, 6, 7, 8
*SURFACE, NAME=S, TYPE=NODE
)" + slave_lines + R"(
*SURFACE, NAME=M
1, S3
*SURFACE INTERACTION, NAME=I
*CONTACT PAIR, INTERACTION=I, TYPE=NODE TO SURFACE
S, M
*MATERIAL, NAME=M
*ELASTIC
1000, 0.3
*SOLID SECTION, ELSET=E, MATERIAL=M
*BOUNDARY
1, 1, 2
2, 2
5, 1
*STEP
*STATIC
*CLOAD
7, 2, -1.
8, 2, -1.
*END STEP
)";
  };
  const auto unit = run_deck_text(deck("5\n6"));
  const auto given = run_deck_text(deck("5, 0.25\n6, 0.5"));
  ASSERT_TRUE(unit.summary.completed) << unit.summary.message;
  ASSERT_TRUE(given.summary.completed) << given.summary.message;
  for (const auto* run : {&unit, &given}) {
    const ContactPairValues& pair = run->last().contact.at(0);
    EXPECT_TRUE(pair.node_based);
    ASSERT_EQ(pair.nodes.size(), 2u);
    for (const ContactNodeValues& v : pair.nodes) {
      EXPECT_NEAR(v.normal_force, 1.0, 1e-9);
      const double area = run == &unit ? 1.0 : (v.node == run->node(5) ? 0.25 : 0.5);
      EXPECT_NEAR(v.pressure, v.normal_force / area, 1e-12);
    }
  }
}
