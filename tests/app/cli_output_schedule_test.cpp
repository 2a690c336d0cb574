// When `tether run` writes: FREQUENCY counting explicit increments, *OUTPUT's
// NUMBER INTERVAL and TIME INTERVAL (explicit and static steps), TIME MARKS,
// and an explicit step's defaults in both dialects. Read back from the .dat
// (its blocks' times) and the .pvd (the VTU files written).

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "cli_support.hpp"

namespace fs = std::filesystem;
using namespace cli_test;

namespace {

/// A steel bar of four CPE4 (side 0.01 m, rollers in y, the left end held)
/// moving at -1 m/s, in one explicit step of 1e-4 s with DIRECT increments
/// of 1e-6 s (stable: 1.7e-6 s): exactly 100 explicit increments.
std::string explicit_bar(const std::string& output) {
  return R"(*NODE, NSET=ALL
1, 0, 0
2, 0.01, 0
3, 0.02, 0
4, 0.03, 0
5, 0.04, 0
6, 0, 0.01
7, 0.01, 0.01
8, 0.02, 0.01
9, 0.03, 0.01
10, 0.04, 0.01
*NSET, NSET=LEFT
1, 6
*NSET, NSET=TIP
5, 10
*ELEMENT, TYPE=CPE4, ELSET=BAR
1, 1, 2, 7, 6
2, 2, 3, 8, 7
3, 3, 4, 9, 8
4, 4, 5, 10, 9
*MATERIAL, NAME=STEEL
*ELASTIC
2.1e11, 0.3
*DENSITY
7800
*SOLID SECTION, ELSET=BAR, MATERIAL=STEEL
1
*INITIAL CONDITIONS, TYPE=VELOCITY
TIP, 1, -1
*BOUNDARY
LEFT, 1, 1
ALL, 2, 2
*STEP
*DYNAMIC, EXPLICIT, DIRECT
1e-6, 1e-4
)" + output + "*END STEP\n";
}

/// A plate pulled in one static step of fixed increments of 0.2.
std::string static_plate(const std::string& output) {
  return R"(*NODE
1, 0, 0
2, 1, 0
3, 1, 1
4, 0, 1
*ELEMENT, TYPE=CPS4, ELSET=E
1, 1, 2, 3, 4
*MATERIAL, NAME=M
*ELASTIC
1000, 0.3
*SOLID SECTION, ELSET=E, MATERIAL=M
1
*BOUNDARY
1, 1, 2
4, 1, 1
*STEP
*STATIC, DIRECT
0.2, 1
*BOUNDARY
2, 1, 1, 0.01
3, 1, 1, 0.01
)" + output + "*END STEP\n";
}

/// Runs `deck` as JOB in a scratch folder NAME; `options` go after the deck.
fs::path run(const std::string& name, const std::string& deck, const std::string& options = "",
             std::string* out = nullptr) {
  const fs::path dir = scratch(name);
  write(dir / "job.inp", deck);
  const Result r = tether("run " + (dir / "job.inp").string() + " -o " + dir.string() + " -q --no-plot " + options);
  EXPECT_EQ(r.code, 0) << r.out;
  if (out) *out = r.out;
  return dir;
}

/// The times of the .dat's displacement blocks.
std::vector<double> dat_times(const fs::path& dir) {
  const std::string text = slurp(dir / "job.dat");
  const std::regex block(R"(displacements \(v[^)]*\) for set \S+ and time\s+(\S+))");
  std::vector<double> times;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), block); it != std::sregex_iterator(); ++it)
    times.push_back(std::stod((*it)[1]));
  return times;
}

/// The times of the VTU files listed in the .pvd.
std::vector<double> vtu_times(const fs::path& dir) {
  const std::string text = slurp(dir / "job.pvd");
  const std::regex entry(R"re(<DataSet timestep="([^"]+)")re");
  std::vector<double> times;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), entry); it != std::sregex_iterator(); ++it)
    times.push_back(std::stod((*it)[1]));
  return times;
}

/// Expects `times` to be `expected` (to 1e-9 relative of the last).
void expect_times(const std::vector<double>& times, const std::vector<double>& expected) {
  ASSERT_EQ(times.size(), expected.size());
  for (std::size_t i = 0; i < times.size(); ++i) EXPECT_NEAR(times[i], expected[i], 1e-9 * expected.back()) << i;
}

}  // namespace

// FREQUENCY=7 on *NODE PRINT counts explicit increments (increments 7, 14,
// ..., 98 and the last, 100), as ABAQUS/Explicit and CalculiX count them;
// *OUTPUT, FIELD, NUMBER INTERVAL=4 writes four VTU files.
TEST(CliOutputSchedule, ExplicitFrequencyCountsExplicitIncrementsAndIntervalsSplitTheStep) {
  const fs::path dir = run("explicit_schedule", explicit_bar("*NODE PRINT, NSET=TIP, FREQUENCY=7\nU\n"
                                                             "*OUTPUT, FIELD, NUMBER INTERVAL=4\n*NODE OUTPUT\nU, V\n"));
  std::vector<double> expected;
  for (int k = 7; k < 100; k += 7) expected.push_back(k * 1e-6);
  expected.push_back(1e-4);
  expect_times(dat_times(dir), expected);
  expect_times(vtu_times(dir), {2.5e-5, 5e-5, 7.5e-5, 1e-4});
}

// TIME INTERVAL=3e-5 in the explicit step: 3e-5, 6e-5, 9e-5 and the end.
TEST(CliOutputSchedule, ExplicitTimeIntervalWritesAtItsMultiples) {
  const fs::path dir = run("explicit_time_interval",
                           explicit_bar("*OUTPUT, HISTORY, TIME INTERVAL=3e-5\n*NODE OUTPUT, NSET=TIP\nU\n"));
  expect_times(dat_times(dir), {3e-5, 6e-5, 9e-5, 1e-4});
}

// Without FREQUENCY or an interval an explicit step writes as ABAQUS/Explicit's
// default output does (abaqus dialect: 20 equal intervals to the result files,
// 200 to the .dat, here every one of the 100 increments), or at every explicit
// increment (calculix dialect, with a warning).
TEST(CliOutputSchedule, ExplicitDefaultsFollowTheDialect) {
  const std::string deck = explicit_bar("*NODE PRINT, NSET=TIP\nU\n");
  const fs::path abaqus = run("explicit_default_abaqus", deck);
  std::vector<double> twenty;
  for (int i = 1; i <= 20; ++i) twenty.push_back(i * 5e-6);
  EXPECT_EQ(dat_times(abaqus).size(), 100U);
  expect_times(vtu_times(abaqus), twenty);
  const fs::path field = run("explicit_default_field", explicit_bar("*NODE FILE\nU\n"));
  expect_times(vtu_times(field), twenty);
  std::string out;
  const fs::path calculix = run("explicit_default_calculix", deck, "--dialect calculix", &out);
  EXPECT_EQ(dat_times(calculix).size(), 100U);
  EXPECT_NE(slurp(calculix / "job.msg").find("writes at every explicit increment, as CalculiX does"),
            std::string::npos);
}

// In a static step TIME INTERVAL=0.3 writes at the first increment ending at
// or after each mark (0.4, 0.6 and 1.0, which passes 0.9 and ends the step);
// with TIME MARKS=YES the increments end on the marks.
TEST(CliOutputSchedule, StaticTimeIntervalWithAndWithoutTimeMarks) {
  const fs::path after = run("static_time_interval",
                             static_plate("*OUTPUT, FIELD, TIME INTERVAL=0.3\n*NODE OUTPUT\nU\n"));
  expect_times(vtu_times(after), {0.4, 0.6, 1.0});
  const fs::path marks = run("static_time_marks",
                             static_plate("*OUTPUT, FIELD, TIME INTERVAL=0.3, TIME MARKS=YES\n*NODE OUTPUT\nU\n"));
  expect_times(vtu_times(marks), {0.3, 0.6, 0.9, 1.0});
  EXPECT_NE(slurp(marks / "job.sta").find("0.5"), std::string::npos);  // 0.3 + 0.2: the size is kept
}

// Bad schedules are refused with the line.
TEST(CliOutputSchedule, ConflictingOrInvalidSchedulesAreRefused) {
  const fs::path dir = scratch("schedule_errors");
  const auto check = [&](const std::string& output, const std::string& expected) {
    write(dir / "bad.inp", static_plate(output));
    const Result r = tether("check " + (dir / "bad.inp").string());
    EXPECT_NE(r.code, 0) << output;
    EXPECT_NE(r.out.find(expected), std::string::npos) << r.out;
  };
  check("*OUTPUT, FIELD, FREQUENCY=2, NUMBER INTERVAL=4\n*NODE OUTPUT\nU\n", "at most one of FREQUENCY");
  check("*OUTPUT, FIELD, NUMBER INTERVAL=0\n*NODE OUTPUT\nU\n", "NUMBER INTERVAL=0");
  check("*OUTPUT, FIELD, TIME INTERVAL=-1\n*NODE OUTPUT\nU\n", "TIME INTERVAL=-1");
  check("*OUTPUT, FIELD, TIME MARKS=YES\n*NODE OUTPUT\nU\n", "TIME MARKS applies to");
}

// A report at which no request is due builds only the nodal values and the
// energies: the energy CSV (every report) is the same, digit for digit, as
// when every report builds the results of every element (*EL FILE,
// FREQUENCY=1), plastic dissipation included (the bar, held at its left end
// while moving at 1 m/s, yields at 10 MPa under a Mises stress of about 27 MPa).
TEST(CliOutputSchedule, ReportsWithNothingDueGiveTheSameEnergies) {
  std::string plastic = explicit_bar("");
  const std::string elastic = "*ELASTIC\n2.1e11, 0.3\n";
  plastic.replace(plastic.find(elastic), elastic.size(), elastic + "*PLASTIC\n10e6, 0\n20e6, 0.1\n");
  const std::string tip = "TIP, 1, -1\n";
  plastic.replace(plastic.find(tip), tip.size(), "ALL, 1, -1\n");  // the whole bar moves
  std::string every = plastic;
  const std::string end = "*END STEP\n";
  every.replace(every.find(end), end.size(), "*EL FILE, FREQUENCY=1\nS, PEEQ\n" + end);
  const fs::path light = run("energies_light", plastic);
  const fs::path full = run("energies_full", every);
  const std::string csv = slurp(light / "job_energy.csv");
  EXPECT_EQ(csv, slurp(full / "job_energy.csv"));
  EXPECT_EQ(vtu_times(light).size(), 20U);
  EXPECT_EQ(vtu_times(full).size(), 100U);
  // The bar did yield: ALLPD (the 9th column) of the last row is positive.
  const std::string last = csv.substr(csv.rfind('\n', csv.size() - 2) + 1);
  std::vector<std::string> fields;
  std::size_t at = 0;
  for (std::size_t comma; (comma = last.find(',', at)) != std::string::npos; at = comma + 1)
    fields.push_back(last.substr(at, comma - at));
  ASSERT_GE(fields.size(), 9U);
  EXPECT_GT(std::stod(fields[8]), 0);
}

// With no file request the result files follow ABAQUS/Standard's default
// output of a dynamic step: every 10th increment (and the last).
TEST(CliOutputSchedule, ImplicitDynamicResultFilesDefaultToEveryTenthIncrement) {
  std::string deck = explicit_bar("*NODE PRINT, NSET=TIP\nU\n");
  const std::string step = "*DYNAMIC, EXPLICIT, DIRECT\n1e-6, 1e-4\n";
  deck.replace(deck.find(step), step.size(), "*DYNAMIC, DIRECT\n1e-6, 2.5e-5\n");
  const fs::path dir = run("implicit_default", deck);
  expect_times(vtu_times(dir), {1e-5, 2e-5, 2.5e-5});
  EXPECT_EQ(dat_times(dir).size(), 25U);  // the print request: every increment
}
