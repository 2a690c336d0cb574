// OP=MOD / OP=NEW across steps: each Step holds the complete lists in force.
#include <gtest/gtest.h>

#include "deck_test_support.hpp"

using namespace tether;
using namespace tether::test;

namespace {

const Prescribed* find_bc(const Step& s, int node, int dof) {
  for (const auto& p : s.boundary)
    if (p.node == node && p.dof == dof) return &p;
  return nullptr;
}

}  // namespace

TEST(StepHistory, ModelBoundaryIsInEveryStepAndOpModReplacesSameNodeDof) {
  const std::string deck = kMesh + R"(*STEP
*STATIC
*BOUNDARY
3, 1, 1, 0.1
*END STEP
*STEP
*STATIC
*BOUNDARY, OP=MOD
3, 1, 1, 0.2
6, 2, 2
*END STEP
)";
  const Model m = read_deck_string(deck, "h.inp");
  ASSERT_EQ(m.steps.size(), 2u);
  EXPECT_EQ(m.steps[0].boundary.size(), 5u);
  ASSERT_TRUE(find_bc(m.steps[0], 0, 1));  // model data: node 1, dof 2
  EXPECT_DOUBLE_EQ(find_bc(m.steps[0], 2, 0)->value, 0.1);
  EXPECT_EQ(m.steps[1].boundary.size(), 6u);
  EXPECT_DOUBLE_EQ(find_bc(m.steps[1], 2, 0)->value, 0.2);
  EXPECT_EQ(find_bc(m.steps[1], 2, 0)->where.line, line_of(deck, "3, 1, 1, 0.2"));
  ASSERT_TRUE(find_bc(m.steps[1], 5, 1));
  ASSERT_TRUE(find_bc(m.steps[1], 0, 1));
}

TEST(StepHistory, OpNewClearsInheritedEntriesOncePerStep) {
  const std::string deck = kMesh + R"(*STEP
*STATIC
*BOUNDARY
3, 1, 1, 0.1
*CLOAD
6, 2, 5
*END STEP
*STEP
*STATIC
*BOUNDARY, OP=NEW
1, 1, 2
*BOUNDARY, OP=NEW
4, 1
*END STEP
*STEP
*STATIC
*CLOAD, OP=NEW
*END STEP
)";
  const Model m = read_deck_string(deck, "new.inp");
  ASSERT_EQ(m.steps.size(), 3u);
  const Step& s2 = m.steps[1];
  EXPECT_EQ(s2.boundary.size(), 3u);  // model-level LEFT and step-1 entries removed
  EXPECT_TRUE(find_bc(s2, 0, 0));
  EXPECT_TRUE(find_bc(s2, 0, 1));
  EXPECT_TRUE(find_bc(s2, 3, 0));
  EXPECT_FALSE(find_bc(s2, 3, 1));
  EXPECT_FALSE(find_bc(s2, 2, 0));
  EXPECT_EQ(s2.cloads.size(), 1u);  // loads continue from step 1
  EXPECT_EQ(m.steps[2].boundary.size(), 3u);
  EXPECT_TRUE(m.steps[2].cloads.empty());  // OP=NEW without data removes all loads
}

TEST(StepHistory, PressuresReplaceByFaceAndDloadDsloadAreSeparateKinds) {
  const std::string deck = kMesh + R"(*STEP
*STATIC
*DLOAD
1, P3, 1.0
*DSLOAD
TOP, P, 2.0
*END STEP
*STEP
*STATIC
*DLOAD
1, P3, 5.0
2, P1, 1.5
*END STEP
*STEP
*STATIC
*DSLOAD, OP=NEW
*END STEP
)";
  const Model m = read_deck_string(deck, "p.inp");
  ASSERT_EQ(m.steps.size(), 3u);
  EXPECT_EQ(m.steps[0].pressures.size(), 3u);
  const auto& p2 = m.steps[1].pressures;
  ASSERT_EQ(p2.size(), 4u);  // DLOAD: (1,S3) replaced, (2,S1) added; DSLOAD: 2 faces
  EXPECT_DOUBLE_EQ(p2[0].magnitude, 5.0);
  EXPECT_EQ(p2[1].face.element, 1);
  EXPECT_EQ(p2[1].face.face, 0);
  EXPECT_DOUBLE_EQ(p2[2].magnitude, 2.0);
  const auto& p3 = m.steps[2].pressures;
  ASSERT_EQ(p3.size(), 2u);  // only the *DLOAD entries remain
  EXPECT_DOUBLE_EQ(p3[0].magnitude, 5.0);
}

// Output requests stay in force in later steps until a step requests the
// same kind again, which replaces all of that kind (ABAQUS: "output requests
// apply to the step in which they are defined and to all subsequent steps
// until they are respecified"; CalculiX: the first *NODE PRINT of a step
// wipes out the earlier ones).
TEST(StepHistory, OutputRequestsCarryOverUntilTheirKindIsRequestedAgain) {
  const std::string deck = kMesh +
                           "*STEP\n*STATIC\n*NODE PRINT\nU\n*EL PRINT\nS\n*END STEP\n"
                           "*STEP\n*STATIC\n*END STEP\n"
                           "*STEP\n*STATIC\n*NODE PRINT, FREQUENCY=0\nU\n*END STEP\n";
  const Model m = read_deck_string(deck, "o.inp");
  using K = OutputRequest::Kind;
  ASSERT_EQ(m.steps[0].outputs.size(), 2u);
  ASSERT_EQ(m.steps[1].outputs.size(), 2u);
  EXPECT_EQ(m.steps[1].outputs[0].kind, K::NodePrint);
  EXPECT_EQ(m.steps[1].outputs[1].kind, K::ElementPrint);
  ASSERT_EQ(m.steps[2].outputs.size(), 2u);  // its own *NODE PRINT (off), the *EL PRINT carried twice
  EXPECT_EQ(m.steps[2].outputs[0].frequency, 0);
  EXPECT_EQ(m.steps[2].outputs[1].kind, K::ElementPrint);
}

TEST(StepHistory, VelocityRequestsAreNotCarriedIntoAStaticStep) {
  const std::string deck = replaced(kMesh, "200e3, 0.3\n", "200e3, 0.3\n*DENSITY\n1.\n") +
                           "*STEP\n*DYNAMIC\n0.1, 1.\n*NODE PRINT\nU, V\n*NODE FILE\nA\n*END STEP\n"
                           "*STEP\n*STATIC\n*END STEP\n";
  std::vector<DeckWarning> warnings;
  const Model m = read_deck_string(deck, "v.inp", &warnings);
  ASSERT_EQ(m.steps[1].outputs.size(), 1u);  // U kept; the request of A alone is dropped
  EXPECT_EQ(m.steps[1].outputs[0].variables, (std::vector<std::string>{"U"}));
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[0].message.find("not carried"), std::string::npos) << warnings[0].message;
}

TEST(StepHistory, OpNewInModelDataWarns) {
  const std::string deck = replaced(kDeck, "*BOUNDARY\nLEFT", "*BOUNDARY, OP=NEW\nLEFT");
  std::vector<DeckWarning> warnings;
  (void)read_deck_string(deck, "w.inp", &warnings);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].message.find("OP=NEW"), std::string::npos);
}

TEST(StepHistory, SetsMayBeDefinedInsideAStepAsCalculixAllows) {
  const std::string deck = replaced(kDeck, "*CLOAD", "*NSET, NSET=TIP\n6\n*CLOAD\nTIP, 2, -1\n*CLOAD");
  const Model m = read_deck_string(deck, "s.inp");
  EXPECT_EQ(m.node_sets.at("TIP"), (std::vector<int>{5}));
  EXPECT_EQ(m.steps.at(0).cloads.size(), 3u);
}

// NLGEOM, as in ABAQUS and CalculiX, stays on once a step sets it: a later
// step without the parameter keeps it, and ABAQUS never turns it off again.
TEST(StepHistory, NlgeomCarriesToLaterStepsAndStaysOn) {
  const std::string deck = kMesh + R"(*STEP
*STATIC
*END STEP
*STEP, NLGEOM
*STATIC
*END STEP
*STEP
*STATIC
*END STEP
*STEP, NLGEOM=NO
*STATIC
*END STEP
*STEP, NLGEOM=YES
*STATIC
*END STEP
)";
  std::vector<DeckWarning> warnings;
  const Model m = read_deck_string(deck, "h.inp", &warnings);
  ASSERT_EQ(m.steps.size(), 5u);
  EXPECT_FALSE(m.steps[0].nlgeom);
  EXPECT_TRUE(m.steps[1].nlgeom);
  EXPECT_TRUE(m.steps[2].nlgeom);  // omitted: carried
  EXPECT_TRUE(m.steps[3].nlgeom);  // NLGEOM=NO after NLGEOM: stays on
  EXPECT_TRUE(m.steps[4].nlgeom);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].where.line, line_of(deck, "*STEP, NLGEOM=NO"));
  EXPECT_NE(warnings[0].message.find("stays on"), std::string::npos) << warnings[0].message;
  EXPECT_NE(warnings[0].message.find("CalculiX"), std::string::npos) << warnings[0].message;
}

TEST(StepHistory, NlgeomNoBeforeAnyNlgeomStepIsLinearWithoutWarning) {
  const std::string deck = kMesh + R"(*STEP, NLGEOM=NO
*STATIC
*END STEP
*STEP
*STATIC
*END STEP
)";
  std::vector<DeckWarning> warnings;
  const Model m = read_deck_string(deck, "h.inp", &warnings);
  ASSERT_EQ(m.steps.size(), 2u);
  EXPECT_FALSE(m.steps[0].nlgeom);
  EXPECT_FALSE(m.steps[1].nlgeom);
  EXPECT_TRUE(warnings.empty());
}
