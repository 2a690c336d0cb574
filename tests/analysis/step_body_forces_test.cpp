// Body loads over several steps: each step starts from the value the previous
// one ended with, removed loads ramp down to zero, amplitudes scale the
// target; and a static analysis follows them.
#include <gtest/gtest.h>

#include "analysis/run_deck.hpp"
#include "tether/analysis/step_body_forces.hpp"
#include "tether/io/deck_reader.hpp"

using namespace tether;

namespace {

/// One CPS4 column element (1 x 2, density 3) held at its base.
const std::string kColumn = R"(*NODE
1, 0, 0
2, 1, 0
3, 1, 2
4, 0, 2
*ELEMENT, TYPE=CPS4, ELSET=E
1, 1, 2, 3, 4
*NSET, NSET=BASE
1, 2
*NSET, NSET=TOP
3, 4
*MATERIAL, NAME=M
*ELASTIC
1000, 0
*DENSITY
3
*SOLID SECTION, ELSET=E, MATERIAL=M
*AMPLITUDE, NAME=HALF
0, 0, 2, 0.5
*BOUNDARY
BASE, 1, 2
)";

std::string steps(const std::string& body) { return kColumn + body; }

}  // namespace

TEST(StepBodyLoads, EachStepStartsWhereThePreviousEnded) {
  const Model m = read_deck_string(steps(R"(*STEP
*STATIC
*DLOAD
E, GRAV, 10, 0, -1
*END STEP
*STEP
*STATIC
*DLOAD, OP=NEW
*END STEP
*STEP
*STATIC
0.5, 2.
*DLOAD, AMPLITUDE=HALF
E, GRAV, 4, 0, -1
E, CENTRIF, 9, 0, 0, 0, 0, 0, 1
*END STEP
*STEP
*STATIC
*DLOAD
E, CENTRIF, 16, 0, 0, 0, 0, 0, 1
*END STEP
)"),
                                   "s.inp");
  const auto s1 = step_body_loads(m, 0);
  ASSERT_EQ(s1.size(), 1u);
  EXPECT_EQ(s1[0].value.start, 0);
  EXPECT_EQ(s1[0].value.target, 10);
  const auto s2 = step_body_loads(m, 1);  // removed: from 10 down to 0
  ASSERT_EQ(s2.size(), 1u);
  EXPECT_EQ(s2[0].value.start, 10);
  EXPECT_EQ(s2[0].value.target, 0);
  EXPECT_EQ(s2[0].value.amplitude, -1);
  const auto s3 = step_body_loads(m, 2);
  ASSERT_EQ(s3.size(), 2u);
  EXPECT_EQ(s3[0].value.start, 0);  // the removal ended at zero
  EXPECT_EQ(s3[0].value.amplitude, 0);
  EXPECT_EQ(s3[1].load.kind, BodyLoad::Kind::Centrifugal);
  // Step 4 inherits GRAV with its amplitude; CENTRIF is modified (OP=MOD) and
  // starts from 9 times the amplitude at the end of step 3 (step time 2: 0.5).
  const auto s4 = step_body_loads(m, 3);
  ASSERT_EQ(s4.size(), 2u);
  EXPECT_EQ(s4[0].load.kind, BodyLoad::Kind::Gravity);
  EXPECT_EQ(s4[0].value.amplitude, 0);
  EXPECT_EQ(s4[1].value.start, 4.5);
  EXPECT_EQ(s4[1].value.target, 16);
  EXPECT_EQ(s4[1].value.amplitude, -1);
}

TEST(StepBodyLoads, AStaticAnalysisRampsGravityOnAndOff) {
  const auto run = tether::testing::run_deck_text(steps(R"(*STEP
*STATIC
*DLOAD
E, GRAV, 10, 0, -1
*END STEP
*STEP
*STATIC
0.5, 1.
*DLOAD, OP=NEW
*END STEP
)"));
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  const auto& results = run.recorder.results;
  ASSERT_EQ(results.size(), 3u);
  const double weight = 3 * 10 * 1 * 2;  // rho g V
  const auto top_u = [&](const IncrementResults& r) { return r.displacement[static_cast<std::size_t>(run.node(3))].y(); };
  double base = 0;
  for (int n : run.model.node_sets.at("BASE")) base += results[0].reaction[static_cast<std::size_t>(n)].y();
  EXPECT_NEAR(base, weight, 1e-9 * weight);
  // Step 2 ramps the gravity down: half of it at its first increment, none at its end.
  EXPECT_LT(top_u(results[0]), 0);
  EXPECT_NEAR(top_u(results[1]), 0.5 * top_u(results[0]), 1e-12);
  EXPECT_NEAR(top_u(results[2]), 0, 1e-14);
}
