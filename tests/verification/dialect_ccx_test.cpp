// The calculix dialect against ccx on the same deck: two blocks pressed
// together through PRESSURE-OVERCLOSURE=EXPONENTIAL (c0 = 0.001, p0 = 100,
// p = 10; tests/smoke/decks/contact_exponential.inp). CalculiX's function is
// p = p0 exp(ln(100) h / c0), ABAQUS's another one, so the two dialects open
// the blocks by different amounts.
//
// Reference: ccx 2.20 (Debian calculix-ccx) on this deck, *NODE PRINT of the
// slave node 2 (x = 1/3 on the top block's bottom): u_y = -8.461832E-03.
// tether in the calculix dialect: -8.462615E-03 (the difference, 7.8e-7, is
// 0.16 % of the clearance of about 4.9e-4 there); in the abaqus dialect
// -8.337522E-03.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "analysis/run_deck.hpp"
#include "tether/output/dat_writer.hpp"

using namespace tether;

namespace {

constexpr double kCcxSlaveUy = -8.461832e-3;

tether::testing::Run run_in(Dialect dialect,
                            const std::string& deck = "/tests/smoke/decks/contact_exponential.inp") {
  tether::testing::Run run;
  run.model = read_deck(std::string(TETHER_SOURCE_DIR) + deck, nullptr, dialect);
  StaticAnalysis analysis(run.model, run.recorder, {});
  run.summary = analysis.run();
  return run;
}

}  // namespace

TEST(DialectAgainstCcx, ExponentialContactOpensAsInCalculix) {
  const auto calculix = run_in(Dialect::Calculix);
  const auto abaqus = run_in(Dialect::Abaqus);
  ASSERT_TRUE(calculix.summary.completed) << calculix.summary.message;
  ASSERT_TRUE(abaqus.summary.completed) << abaqus.summary.message;
  const double uy_calculix = calculix.last().displacement[static_cast<std::size_t>(calculix.node(2))].y();
  const double uy_abaqus = abaqus.last().displacement[static_cast<std::size_t>(abaqus.node(2))].y();
  EXPECT_NEAR(uy_calculix, kCcxSlaveUy, 2e-6);  // measured 7.8e-7
  EXPECT_GT(std::abs(uy_abaqus - kCcxSlaveUy), 1e-4);  // measured 1.24e-4: another law
  // Each slave node's gap and pressure lie on CalculiX's curve.
  const auto& pair = calculix.last().contact.at(0);
  ASSERT_FALSE(pair.nodes.empty());
  for (const auto& n : pair.nodes) {
    ASSERT_GT(n.pressure, 0);
    EXPECT_NEAR(n.gap, 0.001 * std::log(100 / n.pressure) / std::log(100.0), 1e-9);
  }
}

// CalculiX's LINEAR law `K, sigma_inf, c0` = 1000, 1, 0.001 on the same two
// blocks with nu = 0 (tests/verification/dialect/contact_linear_calculix.inp).
// Reference: ccx 2.20 on this deck, *NODE PRINT u_y of the slave nodes 1-4 at
// t = 1: -2.118510E-02, -2.096578E-02, -2.096627E-02, -2.118652E-02. tether
// in the calculix dialect: -2.118393E-02, -2.096451E-02, -2.096500E-02,
// -2.118535E-02 (1.3e-6 apart, 6e-5 of the displacement). With nu = 0.3 the
// two differ by 3.8e-5 (0.19 %): CalculiX takes each slave node's area on
// the deformed face, stretched by the lateral strain (0.39 % here), tether on
// the undeformed one. ABAQUS's p = K h (`1000.` alone, abaqus dialect) on the
// nu = 0.3 deck: -1.908780E-02 at node 2, against ccx's -2.002369E-02.
TEST(DialectAgainstCcx, LinearContactLawIsCalculixsSmoothLaw) {
  const std::string deck = "/tests/verification/dialect/contact_linear_calculix.inp";
  const auto calculix = run_in(Dialect::Calculix, deck);
  ASSERT_TRUE(calculix.summary.completed) << calculix.summary.message;
  const std::vector<std::pair<int, double>> ccx = {
      {1, -2.118510e-2}, {2, -2.096578e-2}, {3, -2.096627e-2}, {4, -2.118652e-2}};
  for (const auto& [node, uy] : ccx)
    EXPECT_NEAR(calculix.last().displacement[static_cast<std::size_t>(calculix.node(node))].y(), uy, 2e-6) << node;
  // Each slave node's pressure lies on p = K h (1/2 + atan(h/eps)/pi), eps = pi sigma_inf / K.
  const auto& pair = calculix.last().contact.at(0);
  ASSERT_FALSE(pair.nodes.empty());
  for (const auto& n : pair.nodes) {
    const double h = -n.gap, eps = std::numbers::pi * 1.0 / 1000;
    EXPECT_NEAR(n.pressure, 1000 * h * (0.5 + std::atan(h / eps) / std::numbers::pi), 1e-9);
  }
  // In the abaqus dialect the same data line is refused (sigma_inf and c0 are not ABAQUS's).
  EXPECT_THROW(run_in(Dialect::Abaqus, deck), InputError);
}

// A node-based slave surface in the calculix dialect: each node's area is the
// one CalculiX gives it, the area of the master face it projects onto, on the
// current face (ccx's springforc_n2f.f: the 2D node lies on no face of its
// expanded mesh; co + vold, no NLGEOM here). The master faces are 0.5 long
// before loading, so about 1/2 for each of the four slave nodes (against 1/6,
// 1/3, 1/3, 1/6 on the element faces and 1 each in the abaqus dialect).
// Reference: ccx 2.20 on tests/verification/dialect/contact_node_slave_calculix.inp,
// u_y of nodes 1-4 at t = 1; tether agrees to 2e-11 (1e-9 of u; it was 6.4e-6
// with the area on the undeformed face).
TEST(DialectAgainstCcx, NodeBasedSlaveTakesCalculixsNodeAreas) {
  const auto calculix = run_in(Dialect::Calculix, "/tests/verification/dialect/contact_node_slave_calculix.inp");
  ASSERT_TRUE(calculix.summary.completed) << calculix.summary.message;
  const std::vector<std::pair<int, double>> ccx = {
      {1, -1.579518e-2}, {2, -1.674203e-2}, {3, -1.674308e-2}, {4, -1.579818e-2}};
  for (const auto& [node, uy] : ccx)
    EXPECT_NEAR(calculix.last().displacement[static_cast<std::size_t>(calculix.node(node))].y(), uy, 2e-8) << node;
  const auto& pair = calculix.last().contact.at(0);
  ASSERT_EQ(pair.nodes.size(), 4u);
  for (const auto& n : pair.nodes) {
    EXPECT_NEAR(n.normal_force / n.pressure, 0.5, 5e-3 * 0.5);  // the face, moved by the load
    EXPECT_GT(std::abs(n.normal_force / n.pressure - 0.5), 1e-6);
  }
}

namespace {

/// One of the decks tests/verification/dialect/contact_node_slave_*_calculix.inp
/// with ccx 2.20's answer at t = 1: u_y and contact pressure of the slave nodes
/// 1, 2, ... (*NODE PRINT, *CONTACT PRINT) and the area each node takes.
struct NodeSlaveCase {
  const char* deck;
  std::vector<double> uy;        ///< ccx's u_y of slave nodes 1.. [length]
  std::vector<double> pressure;  ///< ccx's contact pressure of slave nodes 1.. [stress]
  double (*area)(double r);      ///< CalculiX's area at a slave node at x = r on the undeformed face [length²], tether's full circle for CAX
  double tolerance_uy;           ///< |tether - ccx| allowed in u_y
  double tolerance_p;            ///< |tether - ccx| / ccx allowed in each pressure
};

const double kSin1 = std::sin(std::numbers::pi / 180), kCos1 = std::cos(std::numbers::pi / 180);

// Master faces 0.5 long and horizontal. Plane: 2 t |y'| = 0.5. CAX4 (corners
// of the 2° wedge at r cos 1°): 180 x 4 sin 1° r cos 1° x 0.25. CAX8 (its
// mid-layer corners at r): 180 x 4 sin 1° r x 0.25.
const std::vector<NodeSlaveCase> kNodeSlaveCases = {
    {"contact_node_slave_cpe8_calculix.inp",
     {-9.312345e-3, -1.151782e-2, -1.190572e-2, -1.241312e-2, -1.190387e-2, -1.151329e-2, -9.304962e-3},
     {2.441934, 3.201945, 2.850967, 3.082334, 2.850357, 3.202124, 2.442323},
     [](double) { return 0.5; }, 2e-8, 1e-5},
    {"contact_node_slave_cax4_calculix.inp",
     {-1.315247e-2, -1.445623e-2, -1.371847e-2, -1.080153e-2},
     {5.013518, 5.640321, 5.445703, 4.200263},
     [](double r) { return 180 * kSin1 * kCos1 * r; }, 8e-6, 5e-4},
    {"contact_node_slave_cax8_calculix.inp",
     {-1.026738e-2, -1.213189e-2, -1.223135e-2, -1.251170e-2, -1.178785e-2, -1.117065e-2, -8.739308e-3},
     {2.561666, 3.265329, 2.893333, 3.100187, 2.838078, 3.156061, 2.345257},
     [](double r) { return 180 * kSin1 * r; }, 2e-8, 1e-5},
};

}  // namespace

// Quadratic and axisymmetric elements: each slave node of the node-based
// surface takes the area of the master face it projects onto, on the current
// face, as in ccx 2.20 on the same decks (its figures in each case above).
// Measured |tether - ccx| in u_y: CPE8 2e-9, CAX8 1e-9 (ccx's last printed
// digit: they were 1.2e-5 and 1.1e-5 with the area on the undeformed face),
// CAX4 5.9e-6 (4.1e-4 of u: ccx's C3D8 wedge of straight chords, whose
// applied load is 2.0e-4 below the ring's and whose u_x differs by 0.5 %;
// 2.3e-6 before, by a cancellation); in the pressures 9.4e-7, 6.1e-7 and
// 3.9e-4 of the largest. Each node's area (N / p) is within 0.5 % of the
// closed form on the undeformed face and not equal to it: the master face
// moved (its exact value on the current face: tests/contact/contact_node_test.cpp).
TEST(DialectAgainstCcx, NodeBasedSlaveOnQuadraticAndAxisymmetricElements) {
  for (const NodeSlaveCase& c : kNodeSlaveCases) {
    SCOPED_TRACE(c.deck);
    const auto run = run_in(Dialect::Calculix, std::string("/tests/verification/dialect/") + c.deck);
    ASSERT_TRUE(run.summary.completed) << run.summary.message;
    for (std::size_t k = 0; k < c.uy.size(); ++k) {
      const int node = static_cast<int>(k) + 1;
      EXPECT_NEAR(run.last().displacement[static_cast<std::size_t>(run.node(node))].y(), c.uy[k], c.tolerance_uy) << node;
    }
    const auto& pair = run.last().contact.at(0);
    ASSERT_EQ(pair.nodes.size(), c.uy.size());
    for (std::size_t k = 0; k < pair.nodes.size(); ++k) {
      const auto& n = pair.nodes[k];
      const double r = run.model.coords[static_cast<std::size_t>(run.node(static_cast<int>(k) + 1))].x();
      EXPECT_NEAR(n.normal_force / n.pressure, c.area(r), 5e-3 * c.area(r)) << k + 1;
      EXPECT_GT(std::abs(n.normal_force / n.pressure - c.area(r)), 1e-6 * c.area(r)) << k + 1;
      EXPECT_NEAR(n.pressure, c.pressure[k], c.tolerance_p * c.pressure[k]) << k + 1;
    }
  }
}

// Reactions of an axisymmetric model: tether's results are full-circle
// totals (as ABAQUS's); ccx 2.20's .dat gives its 2-degree segment, 1/180 of
// them, and the calculix dialect prints them so (DatWriter). Reference: ccx
// on tests/verification/dialect/cax4_ring_reaction.inp, total RF_y of BOT
// -5.234925E-01 (nodes 1, 2: -2.326633E-01, -2.908291E-01); tether's full
// circle -94.24778 = -30 pi, / 180 = -0.5235988 (0.02 % from ccx, whose
// segment has straight chords).
TEST(DialectAgainstCcx, AxisymmetricReactionsAre180TimesCalculixsSegment) {
  const auto run = run_in(Dialect::Calculix, "/tests/verification/dialect/cax4_ring_reaction.inp");
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  const double total = run.last().reaction[static_cast<std::size_t>(run.node(1))].y() +
                       run.last().reaction[static_cast<std::size_t>(run.node(2))].y();
  EXPECT_NEAR(total, -30 * std::numbers::pi, 1e-9);
  EXPECT_NEAR(total / kCalculixAxisymmetricSegments, -5.234925e-1, 3e-4 * 0.5235);
}

// What the calculix dialect does not model is refused when the analysis is
// built: CalculiX's LINEAR law on a mortar pair, an area on a node-based
// slave's data line (CalculiX has no such field), a slave (node-based or
// element faces) of plane elements against axisymmetric master faces (ccx's
// spring acts on one 2° segment of the master and the whole thickness of the
// slave), a node-based slave node in no element, SMOOTH on a pair with a
// node-based slave.
TEST(DialectAgainstCcx, UnmodelledCalculixCasesAreRefused) {
  std::ifstream in(std::string(TETHER_SOURCE_DIR) + "/tests/verification/dialect/contact_node_slave_calculix.inp");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto outcome = [](const std::string& deck) {
    try {
      const Model model = read_deck_string(deck, "d.inp", nullptr, Dialect::Calculix);
      tether::testing::Run run;
      StaticAnalysis analysis(model, run.recorder, {});
      return analysis.run().completed ? std::string("completed") : std::string("failed");
    } catch (const ModelError& e) {
      return std::string(e.what());
    }
  };
  const auto edit = [](std::string s, const std::string& from, const std::string& to) {
    const auto at = s.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return at == std::string::npos ? s : s.replace(at, from.size(), to);
  };
  const std::string node_slave = "*SURFACE, NAME=SLAVE, TYPE=NODE\nSLAVEN\n";
  const std::string face_slave = "*SURFACE, NAME=SLAVE\n1, S1\n2, S1\n3, S1\n";
  EXPECT_EQ(outcome(text), "completed");
  EXPECT_NE(outcome(edit(text, "SLAVEN\n*SURFACE, NAME=MASTER", "SLAVEN, 0.5\n*SURFACE, NAME=MASTER"))
                .find("has no area field"),
            std::string::npos);
  const std::string mortar = edit(edit(text, node_slave, face_slave), "TYPE=NODE TO SURFACE", "TYPE=SURFACE TO SURFACE");
  EXPECT_NE(outcome(mortar).find("not modelled for mortar pairs"), std::string::npos) << outcome(mortar);
  const std::string mixed = edit(text, "*ELEMENT, TYPE=CPE4, ELSET=BOTTOM", "*ELEMENT, TYPE=CAX4, ELSET=BOTTOM");
  EXPECT_NE(outcome(mixed).find("180-fold apart"), std::string::npos) << outcome(mixed);
  const std::string mixed_faces = edit(edit(text, node_slave, face_slave), "*ELEMENT, TYPE=CPE4, ELSET=BOTTOM",
                                     "*ELEMENT, TYPE=CAX4, ELSET=BOTTOM");
  EXPECT_NE(outcome(mixed_faces).find("mix axisymmetric and plane"), std::string::npos) << outcome(mixed_faces);
  const std::string lone = edit(edit(text, "*NSET, NSET=SLAVEN\n1, 2, 3, 4", "*NSET, NSET=SLAVEN\n1, 2, 3, 4, 77"), "*NODE\n1001, 0, 0\n",
                                "*NODE\n77, 0.5, 1.1\n*NODE\n1001, 0, 0\n");
  EXPECT_NE(outcome(lone).find("belongs to no element"), std::string::npos) << outcome(lone);
  // SMOOTH would replace the master faces whose area the node takes by other segments.
  const std::string smooth = edit(text, "TYPE=NODE TO SURFACE", "TYPE=NODE TO SURFACE, SMOOTH=0.2");
  EXPECT_NE(outcome(smooth).find("SMOOTH on a pair whose slave surface"), std::string::npos) << outcome(smooth);
}
