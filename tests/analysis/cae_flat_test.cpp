// An ABAQUS/CAE-style deck (parts, placed instances, qualified names) solves
// to the same displacements as the same model written flat.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "analysis/run_deck.hpp"
#include "tether/output/dat_writer.hpp"

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

/// tests/io/decks/cae/one_part_twice.inp written flat: the upper copy's nodes
/// and elements numbered 11-19 and 11-14, 1 higher.
const std::string kFlatTwice = R"(*NODE
1, 0., 0.
2, 0.5, 0.
3, 1., 0.
4, 0., 0.5
5, 0.5, 0.5
6, 1., 0.5
7, 0., 1.
8, 0.5, 1.
9, 1., 1.
11, 0., 1.
12, 0.5, 1.
13, 1., 1.
14, 0., 1.5
15, 0.5, 1.5
16, 1., 1.5
17, 0., 2.
18, 0.5, 2.
19, 1., 2.
*ELEMENT, TYPE=CPE4, ELSET=ALL
1, 1, 2, 5, 4
2, 2, 3, 6, 5
3, 4, 5, 8, 7
4, 5, 6, 9, 8
11, 11, 12, 15, 14
12, 12, 13, 16, 15
13, 14, 15, 18, 17
14, 15, 16, 19, 18
*NSET, NSET=BOTTOM
1, 2, 3
*NSET, NSET=LID
17, 18, 19
*SURFACE, NAME=SLAVE
11, S1
12, S1
*SURFACE, NAME=MASTER
3, S3
4, S3
*MATERIAL, NAME=STEEL
*ELASTIC
200000., 0.3
*SOLID SECTION, ELSET=ALL, MATERIAL=STEEL
1.
*SURFACE INTERACTION, NAME=HARD
*CONTACT PAIR, INTERACTION=HARD
SLAVE, MASTER
*STEP
*STATIC
0.5, 1., 1e-05, 1.
*BOUNDARY
BOTTOM, ENCASTRE
LID, 2, 2, -0.01
18, 1, 1
*END STEP
)";

std::string text_of(const std::filesystem::path& file) {
  std::ifstream in(file);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace

TEST(CaeDeck, TwoInstancesOfOnePartInContactSolveLikeTheModelWrittenFlat) {
  const auto cae = tether::testing::run_deck_file(std::string(TETHER_SOURCE_DIR) + "/tests/io/decks/cae/one_part_twice.inp");
  const auto flat = tether::testing::run_deck_text(kFlatTwice);
  ASSERT_TRUE(cae.summary.completed) << cae.summary.message;
  ASSERT_TRUE(flat.summary.completed) << flat.summary.message;
  for (int label : {1, 2, 3, 4, 5, 6, 7, 8, 9, 11, 12, 13, 14, 15, 16, 17, 18, 19}) {
    const Eigen::Vector2d a = cae.last().displacement[static_cast<std::size_t>(cae.node(label))];
    const Eigen::Vector2d b = flat.last().displacement[static_cast<std::size_t>(flat.node(label))];
    EXPECT_NEAR((a - b).norm(), 0, 1e-12) << "node " << label;
  }
  // The lid's push goes through the contact into the lower copy.
  EXPECT_LT(cae.last().displacement[static_cast<std::size_t>(cae.node(8))].y(), -1e-3);
  EXPECT_NEAR(cae.reaction_sum("LOWER-1.BOTTOM", 1), -cae.reaction_sum("UPPER-1.TOP", 1), 1e-6);
}

TEST(CaeDeck, DatRowsOfAnInstanceSetCarryThePartLabels) {
  const auto cae = tether::testing::run_deck_file(std::string(TETHER_SOURCE_DIR) + "/tests/io/decks/cae/one_part_twice.inp");
  ASSERT_TRUE(cae.summary.completed) << cae.summary.message;
  const auto dir = std::filesystem::path(TETHER_BINARY_DIR) / "tests" / "analysis" / "cae_dat";
  std::filesystem::create_directories(dir);
  {
    DatWriter dat(cae.model, dir / "job.dat");
    dat.write_increment(cae.last(), cae.model.steps[0].outputs, true);
  }
  const std::string text = text_of(dir / "job.dat");
  // Upper-1's lid is nodes 17-19 inside tether, 7-9 of the part; its elements 11-14 are 1-4.
  const auto block = text.find("displacements (vx,vy,vz) for set UPPER-1.TOP");
  ASSERT_NE(block, std::string::npos) << text;
  EXPECT_NE(text.find("\n         7 ", block), std::string::npos) << text;
  EXPECT_EQ(text.find("\n        17 ", block), std::string::npos) << text;
  const auto stresses = text.find("for set UPPER-1.SET-1");
  ASSERT_NE(stresses, std::string::npos) << text;
  EXPECT_NE(text.find("\n         1   1 ", stresses), std::string::npos) << text;
  EXPECT_EQ(text.find("\n        11   1 ", stresses), std::string::npos) << text;
}

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
