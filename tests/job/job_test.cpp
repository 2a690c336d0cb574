// The Job facade: runs through the step driver, keeps owned increments,
// writes the result files only when asked, runs again after the model changed.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "tether/io/deck_reader.hpp"
#include "tether/job/job.hpp"

using namespace tether;
namespace fs = std::filesystem;

namespace {

/// A bar [0, 4] x [0, 1] of 4 x 2 CPS4 (thickness 0.5, E = 1000), fixed on the
/// left, pulled by F = 10 on the right in two increments: u(L) = F L / (E A).
std::string bar_deck(double young = 1000) {
  std::ostringstream d;
  d << "*NODE, NSET=ALL\n";
  for (int j = 0; j <= 2; ++j)
    for (int i = 0; i <= 4; ++i) d << j * 5 + i + 1 << ", " << i << ", " << 0.5 * j << "\n";
  d << "*ELEMENT, TYPE=CPS4, ELSET=EALL\n";
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 4; ++i) {
      const int n1 = j * 5 + i + 1;
      d << j * 4 + i + 1 << ", " << n1 << ", " << n1 + 1 << ", " << n1 + 6 << ", " << n1 + 5 << "\n";
    }
  d << "*MATERIAL, NAME=M\n*ELASTIC\n" << young << ", 0.25\n*SOLID SECTION, ELSET=EALL, MATERIAL=M\n0.5\n"
    << "*BOUNDARY\n1, 1, 2\n6, 1\n11, 1\n"
    << "*STEP\n*STATIC\n0.5, 1.0\n*CLOAD\n5, 1, 2.5\n10, 1, 5.\n15, 1, 2.5\n*NODE PRINT\nU\n*END STEP\n";
  return d.str();
}

double tip_displacement(const JobIncrement& inc) {
  return inc.results.displacement[static_cast<std::size_t>(inc.model->node_index.at(10))].x();
}

fs::path fresh_directory(const std::string& name) {
  const fs::path dir = fs::path(TETHER_BINARY_DIR) / "tests" / "job" / name;
  fs::remove_all(dir);
  return dir;
}

}  // namespace

TEST(Job, KeepsEveryConvergedIncrementAndWritesNothingWithoutOutputDirectory) {
  const fs::path before = fs::current_path();
  Job job(read_deck_string(bar_deck(), "bar.inp"));
  const JobSummary summary = job.run();
  ASSERT_TRUE(summary.completed) << summary.message;
  ASSERT_EQ(job.results().size(), 2u);
  EXPECT_EQ(job.results()[0].results.increment, 1);
  EXPECT_EQ(job.results()[1].results.increment, 2);
  EXPECT_DOUBLE_EQ(job.results()[1].results.total_time, 1.0);
  const double exact = 10.0 * 4 / (1000 * 1 * 0.5);
  EXPECT_NEAR(tip_displacement(job.results()[0]), exact / 2, 1e-12);
  EXPECT_NEAR(tip_displacement(job.results()[1]), exact, 1e-12);
  // Owned: every integration point is stored, nothing refers to the analysis.
  const IncrementResults& last = job.results().back().results;
  EXPECT_EQ(last.points.size(), 8u);
  EXPECT_EQ(last.points[0].size(), 4u);
  EXPECT_EQ(last.point_source, nullptr);
  EXPECT_NEAR(last.points[3][0].stress[0], 10.0 / 0.5, 1e-9);
  EXPECT_TRUE(job.written_files().empty());
  EXPECT_FALSE(fs::exists(before / "bar.sta"));
  EXPECT_FALSE(fs::exists(before / "bar"));
}

TEST(Job, KeepLastAndNone) {
  JobOptions last;
  last.keep = JobOptions::Keep::Last;
  Job a(read_deck_string(bar_deck(), "bar.inp"), last);
  ASSERT_TRUE(a.run().completed);
  ASSERT_EQ(a.results().size(), 1u);
  EXPECT_EQ(a.results()[0].results.increment, 2);
  JobOptions none;
  none.keep = JobOptions::Keep::None;
  Job b(read_deck_string(bar_deck(), "bar.inp"), none);
  ASSERT_TRUE(b.run().completed);
  EXPECT_TRUE(b.results().empty());
}

TEST(Job, WritesTheFilesOfTetherRunWithOutputDirectory) {
  const fs::path dir = fresh_directory("written");
  JobOptions options;
  options.output_dir = dir;
  Job job(read_deck_string(bar_deck(), "bar.inp"), options);
  job.log("a line logged before the run");
  ASSERT_TRUE(job.run().completed);
  EXPECT_EQ(job.name(), "bar");
  EXPECT_EQ(job.written_files().size(), 4u);  // .pvd .dat .sta .msg (no restart requested)
  for (const char* file : {"bar.pvd", "bar.dat", "bar.sta", "bar.msg", "bar_1_1.vtu", "bar_1_2.vtu"})
    EXPECT_TRUE(fs::exists(dir / file)) << file;
  std::ifstream msg(dir / "bar.msg");
  const std::string log((std::istreambuf_iterator<char>(msg)), std::istreambuf_iterator<char>());
  EXPECT_NE(log.find("  a line logged before the run\n"), std::string::npos);
  EXPECT_NE(log.find("  analysis complete\n  time "), std::string::npos);
  std::ifstream sta(dir / "bar.sta");
  const std::string status((std::istreambuf_iterator<char>(sta)), std::istreambuf_iterator<char>());
  EXPECT_NE(status.find("COMPLETED"), std::string::npos) << status;
  // ... and keeps the increments beside the files.
  EXPECT_EQ(job.results().size(), 2u);
}

TEST(Job, AnObserverExceptionClosesTheStaAndMsgWithTheLastIncrementWritten) {
  // The observer throws after the second increment converged, before its results are written.
  struct Throwing final : AnalysisObserver {
    void on_increment(const IncrementReport& r) override {
      if (r.increment == 2) throw std::runtime_error("observer gave up\n(a second line, not in the verdict)");
    }
  } observer;
  const fs::path dir = fresh_directory("observer_exception");
  JobOptions options;
  options.output_dir = dir;
  Job job(read_deck_string(bar_deck(), "bar.inp"), options);
  EXPECT_THROW(job.run(&observer), std::runtime_error);
  EXPECT_EQ(job.results().size(), 1u);
  const std::string verdict =
      "stopped by an exception: observer gave up; last increment written: step 1 increment 1, time 0.5";
  std::ifstream sta(dir / "bar.sta");
  const std::string status((std::istreambuf_iterator<char>(sta)), std::istreambuf_iterator<char>());
  EXPECT_NE(status.find(" THE ANALYSIS HAS NOT BEEN COMPLETED: " + verdict + "\n"), std::string::npos) << status;
  std::ifstream msg(dir / "bar.msg");
  const std::string log((std::istreambuf_iterator<char>(msg)), std::istreambuf_iterator<char>());
  EXPECT_NE(log.find("  " + verdict + "\n"), std::string::npos) << log;
}

TEST(Job, RunsAgainWithTheEditedModelAndKeepsTheOldModelWithOldResults) {
  Job job(read_deck_string(bar_deck(), "bar.inp"));
  ASSERT_TRUE(job.run().completed);
  const JobIncrement first = job.results().back();
  job.edit_model().materials[0].elastic->young = 2000;
  for (ConcentratedLoad& load : job.edit_model().steps[0].cloads) load.magnitude *= 1.5;
  ASSERT_TRUE(job.run().completed);
  ASSERT_EQ(job.results().size(), 2u);
  // Linear: twice as stiff under 1.5 times the load -> 3/4 of the displacement.
  EXPECT_EQ(first.model->materials[0].elastic->young, 1000);
  EXPECT_EQ(job.results().back().model->materials[0].elastic->young, 2000);
  EXPECT_NEAR(tip_displacement(job.results().back()) / tip_displacement(first), 0.75, 1e-12);
}

TEST(Job, ModelCannotChangeBetweenPrepareAndRun) {
  Job job(read_deck_string(bar_deck(), "bar.inp"));
  job.prepare();
  EXPECT_THROW((void)job.edit_model(), std::logic_error);
  ASSERT_TRUE(job.run().completed);
  EXPECT_NO_THROW((void)job.edit_model());
}

TEST(Job, ModelErrorAtPrepareTouchesNoFile) {
  const fs::path dir = fresh_directory("refused");
  JobOptions options;
  options.output_dir = dir;
  Job job(read_deck_string(bar_deck(), "bar.inp"), options);
  // Both *ELASTIC and *HYPERELASTIC: read fine, refused by the discretization.
  job.edit_model().materials[0].neo_hooke = MaterialData::NeoHooke{100, 0.01};
  EXPECT_THROW(job.prepare(), ModelError);
  EXPECT_THROW(job.run(), ModelError);
  EXPECT_FALSE(fs::exists(dir));
}

TEST(Job, ResultsSummaryMatchesTheIncrementsReported) {
  class Count final : public AnalysisObserver {
   public:
    int increments = 0, results = 0;
    void on_increment(const IncrementReport&) override { ++increments; }
    void on_results(const IncrementResults&, const Step&, bool) override { ++results; }
  } count;
  Job job(read_deck_string(bar_deck(), "bar.inp"));
  const JobSummary summary = job.run(&count);
  EXPECT_EQ(count.increments, 2);
  EXPECT_EQ(count.results, summary.increments);
  EXPECT_EQ(static_cast<int>(job.results().size()), summary.increments);
  EXPECT_GE(summary.seconds, 0);
}
