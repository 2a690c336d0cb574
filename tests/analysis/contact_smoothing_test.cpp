// SMOOTH=s in a whole analysis: a block pressed by a vertical load is pushed
// over the concave kink of a rigid faceted surface (flat, then up a 10°
// slope). Without smoothing the contact normal of each slave node jumps by
// the full 10° in the increment where the node passes the master node; with
// SMOOTH=0.2 it turns continuously, following the exact normal of the rounded
// corner (a parabola y(x) whose slope varies linearly over 0.8 < x < 1.2).
// (A concave kink, so that the stiff block keeps both nodes in contact: over a
// convex edge it would bridge, its leading node in the air.)
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>

#include "run_deck.hpp"
#include "tether/io/deck_reader.hpp"

using namespace tether;
using tether::testing::run_deck_text;

namespace {

const double kAlpha = 10 * std::numbers::pi / 180;  // slope angle beyond the kink [rad]
constexpr double kLoad = 1.0;                        // vertical load on the block [force]
constexpr double kPush = 0.8;                        // horizontal push of the block's top [length]
constexpr int kIncrements = 80;
constexpr double kBand = 0.01;                       // ≥ the hand-over band (1 % of a piece ≤ 1 long) [length]

/// Rigid master: two CPE4 with their top faces flat for 0 < x < 1 and sloping
/// up by kAlpha for 1 < x < 2 (kink at node 5 = (1, 1)). Slave: the bottom of
/// one stiff CPE4 block [0.505, 0.605] × [1, 1.05], loaded down by kLoad on its
/// top nodes, whose x is then pushed by kPush in kIncrements increments.
std::string kinked_deck(const std::string& pair_options, double block_x = 0.505) {
  std::ostringstream d;
  d.precision(17);
  d << "*NODE\n1, 0, 0\n2, 1, 0\n3, 2, 0\n4, 0, 1\n5, 1, 1\n6, 2, " << 1 + std::tan(kAlpha) << "\n";
  d << "11, " << block_x << ", 1\n12, " << block_x + 0.1 << ", 1\n13, " << block_x + 0.1 << ", 1.05\n14, " << block_x
    << ", 1.05\n";
  d << "*ELEMENT, TYPE=CPE4, ELSET=BASE\n1, 1, 2, 5, 4\n2, 2, 3, 6, 5\n";
  d << "*ELEMENT, TYPE=CPE4, ELSET=BLOCK\n11, 11, 12, 13, 14\n";
  d << "*NSET, NSET=FIXED, GENERATE\n1, 6\n*NSET, NSET=TOP\n13, 14\n";
  d << "*SURFACE, NAME=MASTER\nBASE, S3\n*SURFACE, NAME=SLAVE\n11, S1\n";
  d << "*SURFACE INTERACTION, NAME=I\n";
  d << "*CONTACT PAIR, INTERACTION=I, TYPE=NODE TO SURFACE" << pair_options << "\nSLAVE, MASTER\n";
  d << "*MATERIAL, NAME=M\n*ELASTIC\n1e5, 0.3\n";
  d << "*SOLID SECTION, ELSET=BASE, MATERIAL=M\n*SOLID SECTION, ELSET=BLOCK, MATERIAL=M\n";
  d << "*BOUNDARY\nFIXED, 1, 2\nTOP, 1\n";
  d << "*STEP\n*STATIC\n1, 1\n*CONTROLS, PARAMETERS=FIELD\n1e-10, 1e-10\n*CLOAD\n";
  d << "TOP, 2, " << -kLoad / 2 << "\n*END STEP\n";
  d << "*STEP, INC=1000\n*STATIC, DIRECT\n" << 1.0 / kIncrements << ", 1\n*CONTROLS, PARAMETERS=FIELD\n1e-10, 1e-10\n";
  d << "*BOUNDARY\nTOP, 1, 1, " << kPush << "\n*END STEP\n";
  return d.str();
}

/// Exact angle of the outward normal of the master surface at x, from +y,
/// positive towards +x (so -α on the up-slope).
double exact_angle(double x, double smoothing) {
  if (smoothing == 0) return x < 1 ? 0.0 : -kAlpha;
  // Corner piece from x = 1 - s to 1 + s (both faces 1 long in x): y(x) is a
  // parabola, its slope tan(α) (x - (1 - s)) / (2 s) varies linearly.
  const double lo = 1 - smoothing, hi = 1 + smoothing;
  if (x <= lo) return 0.0;
  if (x >= hi) return -kAlpha;
  return -std::atan(std::tan(kAlpha) * (x - lo) / (hi - lo));
}

struct History {
  double largest_angle_jump = 0;  ///< max over nodes and increments of |Δφ| [rad]
  double largest_push_jump = 0;   ///< max over increments of |ΔF_x| of the pushed nodes [force]
  /// max |φ - φ_exact(x)| over closed nodes, except those within kBand of a
  /// joint: during Newton a node that crosses a joint by less than 1 % of the
  /// segment keeps its segment, extended, until the next increment
  /// (contact.md, "hand-over hysteresis"), so its normal lags by one increment.
  double angle_error = 0;
  int near_joint = 0;             ///< samples left out of angle_error
  double final_push = 0;          ///< |F_x| at the end (exact: kLoad tan α)
  int open = 0;                   ///< open slave nodes over all increments
};

History slide(double smoothing) {
  const auto run = run_deck_text(kinked_deck(smoothing > 0 ? ", SMOOTH=" + std::to_string(smoothing) : ""));
  EXPECT_TRUE(run.summary.completed) << run.summary.message;
  History h;
  std::vector<double> previous_angle;
  double previous_push = 0;
  for (const IncrementResults& r : run.recorder.results) {
    if (r.step != 2) continue;
    double push = 0;
    for (int n : run.model.node_sets.at("TOP")) push += r.reaction[static_cast<std::size_t>(n)][0];
    std::vector<double> angle;
    for (const ContactNodeValues& v : r.contact.at(0).nodes) {
      if (v.status == ContactNodeValues::Status::Open) {
        ++h.open;
        angle.push_back(std::nan(""));
        continue;
      }
      const double phi = std::atan2(v.force.x(), v.force.y());
      const double x = run.model.coords[static_cast<std::size_t>(v.node)].x() +
                       r.displacement[static_cast<std::size_t>(v.node)].x();
      const bool near = smoothing == 0 ? std::abs(x - 1) < kBand
                                       : std::min(std::abs(x - 1 + smoothing), std::abs(x - 1 - smoothing)) < kBand;
      if (near)
        ++h.near_joint;
      else
        h.angle_error = std::max(h.angle_error, std::abs(phi - exact_angle(x, smoothing)));
      angle.push_back(phi);
    }
    if (!previous_angle.empty()) {
      for (std::size_t k = 0; k < angle.size(); ++k)
        if (!std::isnan(angle[k]) && !std::isnan(previous_angle[k]))
          h.largest_angle_jump = std::max(h.largest_angle_jump, std::abs(angle[k] - previous_angle[k]));
      h.largest_push_jump = std::max(h.largest_push_jump, std::abs(push - previous_push));
    }
    previous_angle = angle;
    previous_push = push;
    h.final_push = std::abs(push);
  }
  return h;
}

TEST(ContactSmoothing, NormalTurnsContinuouslyOverARoundedKink) {
  const History sharp = slide(0.0);
  const History smooth = slide(0.2);
  for (const auto& [name, h] : {std::pair{"unsmoothed", sharp}, std::pair{"SMOOTH=0.2", smooth}})
    std::printf("[ smooth ] %s: largest normal jump per increment %.4f rad (%.2f deg), largest push-force jump "
                "%.4f, normal vs exact %.1e rad (%d samples near a joint left out), final push %.6f (exact %.6f), "
                "open %d\n",
                name, h.largest_angle_jump, h.largest_angle_jump * 180 / std::numbers::pi, h.largest_push_jump,
                h.angle_error, h.near_joint, h.final_push, kLoad * std::tan(kAlpha), h.open);
  // Both follow the exact normal of their surface, stay closed, and end on the
  // slope with the frictionless push force P tan α.
  for (const History& h : {sharp, smooth}) {
    EXPECT_LT(h.angle_error, 1e-8);
    EXPECT_EQ(h.open, 0);
    EXPECT_NEAR(h.final_push, kLoad * std::tan(kAlpha), 1e-8);
  }
  // Unsmoothed: the normal jumps by the whole kink angle in one increment.
  EXPECT_NEAR(sharp.largest_angle_jump, kAlpha, 1e-8);
  // Smoothed: by the slope change over one increment of travel plus the
  // hand-over lag, tan α (0.01 + 0.006) / 0.4 ≈ 0.007 rad (measured 0.0073),
  // at least ten times less than the kink; so does the push force.
  EXPECT_LT(smooth.largest_angle_jump, 0.1 * kAlpha);
  EXPECT_LT(smooth.largest_push_jump, 0.1 * sharp.largest_push_jump);
}

TEST(ContactSmoothing, AdjustMovesSlaveNodesOntoTheSmoothedSurface) {
  // The block's bottom nodes at x = 0.85 and 0.95 touch the faceted flat
  // (y = 1) but lie below the rounded concave corner, y = 1 + tan α (x - 0.8)² / 0.8:
  // ADJUST moves them onto the parabola (along its normal).
  const auto parabola = [](double x) { return 1 + std::tan(kAlpha) * (x - 0.8) * (x - 0.8) / 0.8; };
  std::vector<DeckWarning> notes;
  const Model m = read_deck_string(kinked_deck(", SMOOTH=0.2, ADJUST=0.01", 0.85), "test.inp", &notes);
  for (int id : {11, 12}) {
    const Eigen::Vector2d x = m.coords[static_cast<std::size_t>(m.node_index.at(id))];
    EXPECT_GT(x.y(), 1.0 + 1e-4) << id;
    EXPECT_NEAR(x.y(), parabola(x.x()), 1e-13) << id;
  }
  ASSERT_FALSE(notes.empty());
  EXPECT_NE(notes[0].message.find("moved 2 slave node(s)"), std::string::npos) << notes[0].message;
  // Unsmoothed, the same nodes touch already: ADJUST leaves them where they are.
  const Model flat = read_deck_string(kinked_deck(", ADJUST=0.01", 0.85), "test.inp");
  EXPECT_DOUBLE_EQ(flat.coords[static_cast<std::size_t>(flat.node_index.at(11))].y(), 1.0);
}

}  // namespace
