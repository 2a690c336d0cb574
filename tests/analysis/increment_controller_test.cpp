// IncrementController alone: sizes, growth, cut-back and its limits, the end
// of the step, and the restart round trip.

#include "tether/analysis/increment_controller.hpp"

#include <gtest/gtest.h>

using namespace tether;

namespace {

/// A step of period 1 starting at total time 10, first increment 0.1.
Step step_with(double initial = 0.1) {
  Step s;
  s.period = 1;
  s.initial_increment = initial;
  return s;
}

/// Accepts the next attempt as converged in `iterations`; returns its times.
IncrementTimes converge(IncrementController& c, int iterations) {
  const IncrementTimes t = c.next_attempt();
  c.accept(t, iterations);
  return t;
}

}  // namespace

TEST(IncrementController, FirstAttemptIsTheInitialIncrementAtTotalTime) {
  IncrementController c(step_with(), 10.0);
  const IncrementTimes t = c.next_attempt();
  EXPECT_DOUBLE_EQ(t.dt, 0.1);
  EXPECT_DOUBLE_EQ(t.step_time, 0.1);
  EXPECT_DOUBLE_EQ(t.total_time, 10.1);
  EXPECT_DOUBLE_EQ(t.period, 1.0);
  EXPECT_FALSE(t.ends_step);
  EXPECT_EQ(c.attempt(), 1);
  EXPECT_EQ(c.increment(), 0);
  EXPECT_DOUBLE_EQ(c.step_time(), 0.0);  // not accepted yet
}

TEST(IncrementController, GrowsAfterTwoEasyIncrementsInARow) {
  Step s = step_with();
  s.controls.growth_factor = 1.5;
  s.controls.easy_iterations = 5;
  IncrementController c(s, 0.0);
  converge(c, 5);
  EXPECT_DOUBLE_EQ(c.dt(), 0.1);
  EXPECT_EQ(c.easy_in_row(), 1);
  converge(c, 6);  // a hard one resets the count
  EXPECT_EQ(c.easy_in_row(), 0);
  converge(c, 3);
  EXPECT_DOUBLE_EQ(c.dt(), 0.1);
  converge(c, 3);
  EXPECT_DOUBLE_EQ(c.dt(), 0.1 * 1.5);
  EXPECT_EQ(c.easy_in_row(), 0);
  EXPECT_EQ(c.increment(), 4);
}

TEST(IncrementController, GrowthStopsAtTheMaximumIncrement) {
  Step s = step_with(0.1);
  s.max_increment = 0.12;
  IncrementController c(s, 0.0);
  converge(c, 1);
  converge(c, 1);
  EXPECT_DOUBLE_EQ(c.dt(), 0.12);
  EXPECT_DOUBLE_EQ(c.max_dt(), 0.12);
}

TEST(IncrementController, InitialIncrementIsCappedByTheMaximumAndZeroMeansThePeriod) {
  Step s = step_with(0.5);
  s.max_increment = 0.2;
  EXPECT_DOUBLE_EQ(IncrementController(s, 0).dt(), 0.2);
  Step whole = step_with(0);
  whole.period = 0;  // counts as 1
  IncrementController c(whole, 0);
  EXPECT_DOUBLE_EQ(c.period(), 1.0);
  EXPECT_DOUBLE_EQ(c.dt(), 1.0);
  EXPECT_DOUBLE_EQ(c.min_dt(), 1e-5);
}

TEST(IncrementController, CutsBackByTheFactorAndCountsAttempts) {
  Step s = step_with(0.4);
  s.controls.cutback_factor = 0.25;
  IncrementController c(s, 0.0);
  converge(c, 1);  // one easy increment ...
  (void)c.next_attempt();
  EXPECT_EQ(c.cut_back(), IncrementController::CutBack::Retry);
  EXPECT_DOUBLE_EQ(c.dt(), 0.1);
  EXPECT_EQ(c.attempt(), 2);
  EXPECT_EQ(c.easy_in_row(), 0);  // ... forgotten by the cut-back
  const IncrementTimes t = c.next_attempt();
  EXPECT_DOUBLE_EQ(t.step_time, 0.5);
  c.accept(t, 9);
  EXPECT_EQ(c.attempt(), 1);
}

TEST(IncrementController, StopsAfterTheMaximumNumberOfCutBacks) {
  Step s = step_with(0.5);
  s.controls.max_cutbacks = 2;
  s.controls.cutback_factor = 0.5;
  IncrementController c(s, 0.0);
  EXPECT_EQ(c.cut_back(), IncrementController::CutBack::Retry);
  EXPECT_EQ(c.cut_back(), IncrementController::CutBack::Retry);
  EXPECT_EQ(c.cut_back(), IncrementController::CutBack::TooManyCutBacks);
  EXPECT_DOUBLE_EQ(c.dt(), 0.125);  // unchanged by the refusal
  EXPECT_EQ(c.stop_reason(IncrementController::CutBack::TooManyCutBacks, "*STATIC"), " after 2 cut-backs");
}

TEST(IncrementController, StopsBelowTheMinimumIncrement) {
  Step s = step_with(0.1);
  s.min_increment = 0.03;
  s.controls.cutback_factor = 0.25;
  IncrementController c(s, 0.0);
  EXPECT_EQ(c.cut_back(), IncrementController::CutBack::BelowMinimum);  // 0.025 < 0.03
  EXPECT_EQ(c.stop_reason(IncrementController::CutBack::BelowMinimum, "*STATIC"),
            "; the increment would fall below the minimum 0.03");
  s.min_increment = 0.025;  // exactly the minimum is allowed
  IncrementController d(s, 0.0);
  EXPECT_EQ(d.cut_back(), IncrementController::CutBack::Retry);
}

TEST(IncrementController, DefaultMinimumIsAFractionOfThePeriod) {
  Step s = step_with(0.1);
  s.period = 2;
  s.controls.cutback_factor = 0.1;
  s.controls.max_cutbacks = 10;
  IncrementController c(s, 0.0);
  EXPECT_DOUBLE_EQ(c.min_dt(), 2e-5);
  for (int k = 0; k < 3; ++k) ASSERT_EQ(c.cut_back(), IncrementController::CutBack::Retry) << k;  // 1e-4
  EXPECT_EQ(c.cut_back(), IncrementController::CutBack::BelowMinimum);                            // 1e-5
  EXPECT_EQ(c.stop_reason(IncrementController::CutBack::BelowMinimum, "*STATIC"),
            "; the increment would fall below the minimum 2e-05");
}

TEST(IncrementController, FixedIncrementsNeitherGrowNorCutBack) {
  Step s = step_with(0.25);
  s.direct = true;
  IncrementController c(s, 0.0);
  for (int k = 0; k < 3; ++k) converge(c, 1);
  EXPECT_DOUBLE_EQ(c.dt(), 0.25);
  EXPECT_EQ(c.easy_in_row(), 0);
  EXPECT_EQ(c.cut_back(), IncrementController::CutBack::FixedIncrements);
  EXPECT_DOUBLE_EQ(c.dt(), 0.25);
  EXPECT_EQ(c.stop_reason(IncrementController::CutBack::FixedIncrements, "*STATIC"),
            " with fixed increments (*STATIC, DIRECT)");
  EXPECT_EQ(c.stop_reason(IncrementController::CutBack::Retry, "*STATIC"), "");
}

TEST(IncrementController, CountsIncrementsAgainstInc) {
  Step s = step_with(0.1);
  s.max_increments = 3;
  IncrementController c(s, 0.0);
  for (int k = 0; k < 3; ++k) {
    EXPECT_FALSE(c.out_of_increments());
    converge(c, 9);
  }
  EXPECT_TRUE(c.out_of_increments());
  EXPECT_EQ(c.max_increments(), 3);
  EXPECT_FALSE(c.finished());
}

TEST(IncrementController, LastIncrementIsClampedToThePeriod) {
  // 0.3 + 0.3 + 0.3 leaves 0.1: the last increment is clamped to it.
  IncrementController c(step_with(0.3), 5.0);
  for (int k = 0; k < 3; ++k) EXPECT_FALSE(converge(c, 9).ends_step);
  const IncrementTimes last = c.next_attempt();
  EXPECT_NEAR(last.dt, 0.1, 1e-15);
  EXPECT_DOUBLE_EQ(last.step_time, 1.0);
  EXPECT_DOUBLE_EQ(last.total_time, 6.0);
  EXPECT_TRUE(last.ends_step);
  c.accept(last, 9);
  EXPECT_TRUE(c.finished());
  EXPECT_NEAR(c.dt(), 0.1, 1e-15);  // the clamp sticks
}

TEST(IncrementController, SliverLeftAtTheEndIsTakenIntoTheLastIncrement) {
  // After 0.5 - 1e-10 of a period of 1, the same increment would leave
  // 2e-10 (< 1e-9 of the period): the increment takes it.
  IncrementController c(step_with(0.5 - 1e-10), 0.0);
  converge(c, 9);
  const IncrementTimes last = c.next_attempt();
  EXPECT_DOUBLE_EQ(last.dt, 0.5 + 1e-10);
  EXPECT_TRUE(last.ends_step);
  c.accept(last, 9);
  EXPECT_TRUE(c.finished());
  // 1e-8 left is not a sliver: one more increment.
  IncrementController d(step_with(0.5 - 1e-8), 0.0);
  converge(d, 9);
  EXPECT_FALSE(converge(d, 9).ends_step);
  EXPECT_TRUE(d.next_attempt().ends_step);
}

TEST(IncrementController, RestartStateRoundTrips) {
  Step s = step_with(0.1);
  IncrementController c(s, 3.0);
  converge(c, 1);
  converge(c, 1);  // grown
  converge(c, 1);
  RestartState state;
  c.save(state);
  EXPECT_EQ(state.increment, 3);
  EXPECT_DOUBLE_EQ(state.step_start_time, 3.0);
  IncrementController d(s, 99.0);
  d.restore(state);
  EXPECT_EQ(d.increment(), c.increment());
  EXPECT_EQ(d.step_time(), c.step_time());
  EXPECT_EQ(d.dt(), c.dt());
  EXPECT_EQ(d.easy_in_row(), c.easy_in_row());
  EXPECT_EQ(d.step_start_time(), 3.0);
  EXPECT_EQ(d.min_dt(), c.min_dt());
  // Both continue identically.
  const IncrementTimes a = converge(c, 1), b = converge(d, 1);
  EXPECT_EQ(a.step_time, b.step_time);
  EXPECT_EQ(a.total_time, b.total_time);
  EXPECT_EQ(c.dt(), d.dt());
}

TEST(IncrementController, AProceduresEstimateSetsTheNextIncrementWithinTheBounds) {
  Step s = step_with();
  s.period = 10;  // no clamping to the step's end here
  s.max_increment = 0.3;
  s.min_increment = 0.01;
  s.controls.growth_factor = 1.5;
  IncrementController c(s, 0.0);
  c.accept(c.next_attempt(), 20, 1.2);  // grows by the estimate, however many iterations
  EXPECT_DOUBLE_EQ(c.dt(), 0.12);
  c.accept(c.next_attempt(), 1, 1.0);  // held, however easy
  EXPECT_DOUBLE_EQ(c.dt(), 0.12);
  c.accept(c.next_attempt(), 1, 4.0);  // at most the growth factor
  EXPECT_DOUBLE_EQ(c.dt(), 0.18);
  c.accept(c.next_attempt(), 1, 1.5);  // at most the maximum
  EXPECT_DOUBLE_EQ(c.dt(), 0.27);
  c.accept(c.next_attempt(), 1, 1.5);
  EXPECT_DOUBLE_EQ(c.dt(), 0.3);
  static_cast<void>(c.next_attempt());
  EXPECT_EQ(c.cut_back(0.4), IncrementController::CutBack::Retry);  // the estimate, not the controls' 0.25
  EXPECT_DOUBLE_EQ(c.dt(), 0.12);
  EXPECT_EQ(c.cut_back(), IncrementController::CutBack::Retry);
  EXPECT_DOUBLE_EQ(c.dt(), 0.12 * s.controls.cutback_factor);
}

TEST(IncrementController, ImplicitDynamicsGrowsOnlyWithHaftol) {
  Step s = step_with();
  s.procedure = StepProcedure::ImplicitDynamic;
  EXPECT_DOUBLE_EQ(IncrementController(s, 0.0).max_dt(), 0.1);  // no error estimate: never above the initial
  s.dynamic.half_increment_tolerance = 100;
  EXPECT_DOUBLE_EQ(IncrementController(s, 0.0).max_dt(), 1.0);
}

TEST(IncrementController, IncrementsEndOnTimePointsWithoutShrinkingTheSize) {
  Step s = step_with(0.3);
  s.direct = true;  // no growth
  s.time_points = {0.25, 0.5};
  IncrementController c(s, 0.0);
  EXPECT_DOUBLE_EQ(converge(c, 1).step_time, 0.25);  // 0.3 would pass the point
  EXPECT_DOUBLE_EQ(c.dt(), 0.3);                     // the size growth and cut-back start from is kept
  EXPECT_DOUBLE_EQ(converge(c, 1).step_time, 0.5);
  EXPECT_DOUBLE_EQ(converge(c, 1).step_time, 0.8);
  const IncrementTimes last = converge(c, 1);
  EXPECT_DOUBLE_EQ(last.step_time, 1.0);
  EXPECT_TRUE(last.ends_step);
}

TEST(IncrementController, AnIncrementEndingJustShortOfATimePointLandsOnIt) {
  Step s = step_with(0.25 - 1e-12);
  s.time_points = {0.25};
  IncrementController c(s, 0.0);
  EXPECT_DOUBLE_EQ(converge(c, 1).step_time, 0.25);
}

TEST(IncrementController, ACutBackStartsFromAShortenedAttempt) {
  Step s = step_with(0.4);
  s.time_points = {0.1};
  IncrementController c(s, 0.0);
  EXPECT_DOUBLE_EQ(c.next_attempt().dt, 0.1);
  ASSERT_EQ(c.cut_back(), IncrementController::CutBack::Retry);
  EXPECT_DOUBLE_EQ(c.dt(), 0.1 * s.controls.cutback_factor);  // not 0.4 times the factor: that would retry 0.1
}

TEST(IncrementController, TimeMarksOfOutputRequestsArePointsOfStaticSteps) {
  Step s = step_with(0.3);
  OutputRequest r;
  r.kind = OutputRequest::Kind::NodePrint;
  r.number_interval = 4;
  r.time_marks = true;
  s.outputs.push_back(r);
  IncrementController c(s, 0.0);
  EXPECT_DOUBLE_EQ(converge(c, 1).step_time, 0.25);
  EXPECT_DOUBLE_EQ(converge(c, 1).step_time, 0.5);
  EXPECT_DOUBLE_EQ(converge(c, 1).step_time, 0.75);
  EXPECT_DOUBLE_EQ(converge(c, 1).step_time, 1.0);
}
