// An ABAQUS/CAE-style deck (parts, placed instances, qualified names) solves
// to the same displacements as the same model written flat.
#include <gtest/gtest.h>

#include "analysis/run_deck.hpp"

using namespace tether;

namespace {

/// tests/io/decks/cae/two_instances.inp written without parts: the upper
/// instance's nodes where its translation and rotation put them.
const std::string kFlat = R"(*NODE
1, 0, 0
2, 1, 0
3, 1, 1
4, 0, 1
11, 1, 1
12, 1, 2
13, 0, 2
14, 0, 1
*ELEMENT, TYPE=CPS4, ELSET=LOWER
1, 1, 2, 3, 4
*ELEMENT, TYPE=CPS4, ELSET=UPPER
11, 11, 12, 13, 14
*NSET, NSET=BOTTOM
1, 2
*NSET, NSET=TIED
11, 14
*SURFACE, NAME=TOP
1, S3
*MATERIAL, NAME=STEEL
*ELASTIC
200000., 0.3
*SOLID SECTION, ELSET=LOWER, MATERIAL=STEEL
1.
*SOLID SECTION, ELSET=UPPER, MATERIAL=STEEL
1.
*STEP
*STATIC
*BOUNDARY
BOTTOM, ENCASTRE
TIED, 1, 2
*DSLOAD
TOP, P, 1.
*END STEP
)";

}  // namespace

TEST(CaeDeck, SolvesLikeTheSameModelWrittenFlat) {
  const auto cae = tether::testing::run_deck_file(std::string(TETHER_SOURCE_DIR) + "/tests/io/decks/cae/two_instances.inp");
  const auto flat = tether::testing::run_deck_text(kFlat);
  ASSERT_TRUE(cae.summary.completed) << cae.summary.message;
  ASSERT_TRUE(flat.summary.completed) << flat.summary.message;
  double largest = 0;
  for (int label : {1, 2, 3, 4, 11, 12, 13, 14}) {
    const Eigen::Vector2d a = cae.last().displacement[static_cast<std::size_t>(cae.node(label))];
    const Eigen::Vector2d b = flat.last().displacement[static_cast<std::size_t>(flat.node(label))];
    EXPECT_NEAR((a - b).norm(), 0, 1e-15) << "node " << label;
    largest = std::max(largest, b.norm());
  }
  EXPECT_GT(largest, 1e-6);  // the load moves the lower part
}
