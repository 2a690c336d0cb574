// When an output request writes: FREQUENCY in increments (explicit
// increments in explicit steps), NUMBER INTERVAL and TIME INTERVAL marks,
// TIME MARKS points, and the result files' default.

#include "tether/output/output_schedule.hpp"

#include <gtest/gtest.h>

using namespace tether;

namespace {

OutputRequest every(int frequency) {
  OutputRequest r;
  r.frequency = frequency;
  return r;
}

OutputRequest intervals(int n) {
  OutputRequest r;
  r.number_interval = n;
  return r;
}

OutputRequest time_interval(double t) {
  OutputRequest r;
  r.time_interval = t;
  return r;
}

/// A static or implicit increment of `dt` ending at `t` (period `period`).
IncrementResults increment_at(int increment, double t, double dt, double period = 1) {
  IncrementResults r;
  r.increment = increment, r.step_time = t, r.increment_size = dt, r.period = period;
  return r;
}

/// An explicit report spanning nominal increments (start, end] of `total`.
IncrementResults report(long start, long end, long total, double period = 1) {
  IncrementResults r;
  r.explicit_span = IncrementResults::ExplicitSpan{start, end, total};
  r.period = period;
  r.step_time = period * static_cast<double>(end) / static_cast<double>(total);
  return r;
}

}  // namespace

TEST(OutputSchedule, FrequencyCountsIncrementsAndTheLastAlwaysWrites) {
  EXPECT_TRUE(is_due(every(2), increment_at(4, 0.4, 0.1), false));
  EXPECT_FALSE(is_due(every(2), increment_at(3, 0.3, 0.1), false));
  EXPECT_TRUE(is_due(every(2), increment_at(3, 1.0, 0.1), true));
  EXPECT_FALSE(is_due(every(0), increment_at(3, 1.0, 0.1), true));
}

TEST(OutputSchedule, StaticIntervalsWriteAtTheFirstIncrementEndingAtOrAfterAMark) {
  // Marks at 0.25, 0.5, 0.75 (and the end).
  EXPECT_FALSE(is_due(intervals(4), increment_at(1, 0.2, 0.2), false));
  EXPECT_TRUE(is_due(intervals(4), increment_at(2, 0.3, 0.1), false));   // crosses 0.25
  EXPECT_TRUE(is_due(intervals(4), increment_at(3, 0.5, 0.2), false));   // ends on 0.5
  EXPECT_FALSE(is_due(intervals(4), increment_at(4, 0.7, 0.2), false));
  EXPECT_FALSE(is_due(intervals(4), increment_at(5, 0.5 + 1e-13, 1e-13), false));  // 0.5 was written before
  EXPECT_TRUE(is_due(time_interval(0.3), increment_at(1, 0.3, 0.3), false));
  EXPECT_FALSE(is_due(time_interval(0.3), increment_at(2, 0.5, 0.2), false));
  EXPECT_TRUE(is_due(time_interval(0.3), increment_at(3, 0.65, 0.15), false));  // crosses 0.6
  EXPECT_TRUE(is_due(time_interval(0.3), increment_at(4, 4.0, 0.1, 4.0), true));
}

TEST(OutputSchedule, ExplicitFrequencyCountsExplicitIncrements) {
  // FREQUENCY=10 over 95 nominal increments: 10, 20, ..., 90 and 95.
  const std::vector<long> marks = explicit_marks(every(10), 95, 1);
  ASSERT_EQ(marks.size(), 10U);
  EXPECT_EQ(marks.front(), 10);
  EXPECT_EQ(marks[8], 90);
  EXPECT_EQ(marks.back(), 95);
  EXPECT_TRUE(is_due(every(10), report(5, 10, 95), false));
  EXPECT_FALSE(is_due(every(10), report(10, 15, 95), false));
  EXPECT_TRUE(is_due(every(10), report(15, 25, 95), false));  // a report holding a mark inside it
  EXPECT_TRUE(is_due(every(10), report(90, 95, 95), true));
  EXPECT_TRUE(explicit_marks(every(0), 95, 1).empty());
}

TEST(OutputSchedule, ExplicitIntervalMarksAreRoundedToNominalIncrements) {
  // NUMBER INTERVAL=3 over 100 increments: 33.3 -> 33, 66.7 -> 67, 100.
  EXPECT_EQ(explicit_marks(intervals(3), 100, 2.0), (std::vector<long>{33, 67, 100}));
  EXPECT_TRUE(is_due(intervals(3), report(30, 33, 100, 2.0), false));
  EXPECT_FALSE(is_due(intervals(3), report(33, 50, 100, 2.0), false));
  EXPECT_TRUE(is_due(intervals(3), report(50, 67, 100, 2.0), false));
  // TIME INTERVAL=0.7 in a period of 2 over 100 increments (0.02 each): 35, 70, 100.
  EXPECT_EQ(explicit_marks(time_interval(0.7), 100, 2.0), (std::vector<long>{35, 70, 100}));
  EXPECT_TRUE(is_due(time_interval(0.7), report(69, 70, 100, 2.0), false));
  EXPECT_FALSE(is_due(time_interval(0.7), report(70, 71, 100, 2.0), false));
  // More intervals than increments: every increment, once.
  EXPECT_EQ(explicit_marks(intervals(8), 4, 1.0), (std::vector<long>{1, 2, 3, 4}));
}

TEST(OutputSchedule, TimeMarkPointsComeFromTimeMarksRequestsOnly) {
  Step s;
  s.period = 2;
  OutputRequest a = intervals(4);
  a.time_marks = true;
  OutputRequest b = time_interval(0.3);
  b.time_marks = true;
  s.outputs = {a, b, intervals(7)};  // the last one without TIME MARKS adds nothing
  const std::vector<double> points = time_mark_points(s);
  const std::vector<double> expected = {0.3, 0.5, 0.6, 0.9, 1.0, 1.2, 1.5, 1.8};
  ASSERT_EQ(points.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(points[i], expected[i], 1e-15);
}

TEST(OutputSchedule, ResultFilesDefaultAsAbaqusDefaultOutput) {
  // ABAQUS's default output: every increment (static), every 10th (dynamic), 20 intervals (explicit).
  EXPECT_EQ(default_file_request(StepProcedure::Static).number_interval, 0);
  EXPECT_EQ(default_file_request(StepProcedure::Static).frequency, 1);
  EXPECT_EQ(default_file_request(StepProcedure::ImplicitDynamic).frequency, 10);
  EXPECT_EQ(default_file_request(StepProcedure::ExplicitDynamic).number_interval, kExplicitDefaultIntervals);
  EXPECT_EQ(explicit_marks(default_file_request(StepProcedure::ExplicitDynamic), 1000, 1).size(), 20U);
  IncrementResults r;
  EXPECT_EQ(procedure_of(r), StepProcedure::Static);
  r.energy = EnergyTotals{};
  EXPECT_EQ(procedure_of(r), StepProcedure::ImplicitDynamic);
  r.explicit_span = IncrementResults::ExplicitSpan{0, 1, 2};
  EXPECT_EQ(procedure_of(r), StepProcedure::ExplicitDynamic);
}
