// Streamed results (AnalysisOptions::stream_element_results, what `tether run`
// uses: no per-point values kept, element points computed on demand) against
// stored results (every point kept). The two code paths are compared with each
// other on the same run, not against stored files: they must write the same
// bytes, since streaming only changes when values are computed, not how.

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "output/tiny_model.hpp"
#include "tether/analysis/static_analysis.hpp"
#include "tether/io/deck_reader.hpp"
#include "tether/output/dat_writer.hpp"
#include "tether/output/output_schedule.hpp"
#include "tether/output/result_writer.hpp"
#include "tether/output/vtu_writer.hpp"

namespace tether {
namespace {

using test::fresh_directory;
using test::read_text;
using test::synthetic_results;
using test::tiny_model;

const std::string kSource = TETHER_SOURCE_DIR;

/// Writes every converged increment, as the program does, and keeps the results.
class WritingObserver final : public AnalysisObserver {
 public:
  explicit WritingObserver(ResultWriter& writer) : writer_(writer) {}
  void on_results(const IncrementResults& r, const Step& step, bool last) override {
    writer_.write_increment(r, step.outputs, last);
    if (check) check(r);
    results.push_back(r);
  }
  std::function<void(const IncrementResults&)> check;
  std::vector<IncrementResults> results;

 private:
  ResultWriter& writer_;
};

/// Runs `deck` writing into `dir`; returns the results handed to the observer.
std::vector<IncrementResults> run_writing(const Model& model, const std::filesystem::path& dir, bool stream,
                                          VtuEncoding encoding,
                                          std::function<void(const IncrementResults&)> check = {}) {
  ResultWriterOptions writer_options;
  writer_options.encoding = encoding;
  ResultWriter writer(model, dir, "hertz", writer_options);
  WritingObserver observer(writer);
  observer.check = std::move(check);
  AnalysisOptions options;
  options.stream_element_results = stream;
  const AnalysisSummary summary = StaticAnalysis(model, observer, options).run();
  writer.finish(summary.completed, summary.message);
  EXPECT_TRUE(summary.completed) << summary.message;
  return observer.results;
}

TEST(StreamedResults, HertzRunWritesTheSameFilesAsStoredResults) {
  // The example Hertz deck: contact, *EL PRINT of an element set (points on
  // demand), *NODE PRINT, a .vtu per increment (cell stress from the means).
  const Model model = read_deck(kSource + "/examples/hertz/hertz.inp");
  for (const VtuEncoding encoding : {VtuEncoding::Base64, VtuEncoding::Ascii}) {
    const std::string tag = encoding == VtuEncoding::Ascii ? "ascii" : "binary";
    const auto stored_dir = fresh_directory("streamed_results_stored_" + tag);
    const auto streamed_dir = fresh_directory("streamed_results_streamed_" + tag);
    const auto stored = run_writing(model, stored_dir, false, encoding);
    const auto streamed = run_writing(model, streamed_dir, true, encoding);
    ASSERT_EQ(stored.size(), streamed.size());
    ASSERT_FALSE(stored.empty());
    int files = 0, vtu = 0;
    for (const auto& entry : std::filesystem::directory_iterator(stored_dir)) {
      const auto name = entry.path().filename();
      ASSERT_TRUE(std::filesystem::exists(streamed_dir / name)) << name;
      // Compared as a whole; a mismatch is reported by name (the files are large).
      EXPECT_TRUE(read_text(entry.path()) == read_text(streamed_dir / name)) << tag << ": " << name << " differs";
      ++files;
      vtu += name.extension() == ".vtu";
    }
    EXPECT_EQ(vtu, static_cast<int>(stored.size())) << tag;
    EXPECT_GE(files, vtu + 3) << tag;  // .pvd, .dat, .sta
    EXPECT_NE(read_text(stored_dir / "hertz.dat").find("stresses (elem, integ.pnt."), std::string::npos);
  }
}

TEST(StreamedResults, ObserverGetsMeanStressesAndPointsOnDemand) {
  const Model model = read_deck(kSource + "/examples/hertz/hertz.inp");
  const auto stored = run_writing(model, fresh_directory("streamed_results_points_a"), false, VtuEncoding::Base64);
  std::size_t increment = 0;
  const auto streamed = run_writing(
      model, fresh_directory("streamed_results_points_b"), true, VtuEncoding::Base64,
      [&](const IncrementResults& r) {
        ASSERT_LT(increment, stored.size());
        const IncrementResults& s = stored[increment++];
        EXPECT_TRUE(r.points.empty());
        ASSERT_NE(r.point_source, nullptr);
        ASSERT_EQ(r.element_stress.size(), model.elements.size());
        ASSERT_EQ(s.points.size(), model.elements.size());
        EXPECT_TRUE(s.element_stress.empty());
        EXPECT_EQ(s.point_source, nullptr);
        std::vector<PointValues> buffer;
        for (std::size_t e = 0; e < model.elements.size(); ++e) {
          const auto& points = element_points(r, e, buffer);
          ASSERT_EQ(points.size(), s.points[e].size()) << e;
          for (std::size_t k = 0; k < points.size(); ++k) {
            EXPECT_EQ(points[k].x, s.points[e][k].x) << e;
            EXPECT_EQ(points[k].stress, s.points[e][k].stress) << e;
            EXPECT_EQ(points[k].strain, s.points[e][k].strain) << e;
          }
          EXPECT_EQ(r.element_stress[e], mean_stress(s.points[e])) << e;
        }
        EXPECT_EQ(r.nodal_stress, s.nodal_stress);
        EXPECT_EQ(r.nodal_strain, s.nodal_strain);
        EXPECT_EQ(r.displacement, s.displacement);
      });
  EXPECT_EQ(streamed.size(), stored.size());
  EXPECT_EQ(increment, stored.size());
}

/// Points of synthetic results, served on demand.
class StoredPoints final : public ElementPointSource {
 public:
  explicit StoredPoints(std::vector<std::vector<PointValues>> points) : points_(std::move(points)) {}
  void points(int element, std::vector<PointValues>& out) const override {
    out = points_[static_cast<std::size_t>(element)];
  }

 private:
  std::vector<std::vector<PointValues>> points_;
};

TEST(StreamedResults, WritersTakeMeansAndASourceInsteadOfPoints) {
  Model model = tiny_model();
  OutputRequest el_print;
  el_print.kind = OutputRequest::Kind::ElementPrint;
  el_print.set = "QUADS";
  el_print.variables = {"S", "E"};
  const IncrementResults stored = synthetic_results(model, 1, 1, 1.0, 1.0);
  IncrementResults streamed = stored;
  const StoredPoints source(streamed.points);
  for (const auto& points : streamed.points) streamed.element_stress.push_back(mean_stress(points));
  streamed.points.clear();
  streamed.point_source = &source;
  for (const VtuEncoding encoding : {VtuEncoding::Base64, VtuEncoding::Ascii}) {
    std::ostringstream a, b;
    VtuWriter(model, encoding).write(stored, a);
    VtuWriter(model, encoding).write(streamed, b);
    EXPECT_EQ(a.str(), b.str());
  }
  const auto dir = fresh_directory("streamed_results_dat");
  DatWriter(model, dir / "a.dat").write_increment(stored, {el_print}, true);
  DatWriter(model, dir / "b.dat").write_increment(streamed, {el_print}, true);
  EXPECT_NE(read_text(dir / "a.dat").find("stresses (elem, integ.pnt."), std::string::npos);
  EXPECT_EQ(read_text(dir / "a.dat"), read_text(dir / "b.dat"));
  // Neither points nor a source: EL PRINT cannot be written.
  streamed.point_source = nullptr;
  EXPECT_THROW(DatWriter(model, dir / "c.dat").write_increment(streamed, {el_print}, true), std::invalid_argument);
}

TEST(StreamedResults, StaticIncrementsBuildElementFieldsOnlyWhenTheFilesAreDue) {
  // The example Hertz deck with result files at every 2nd increment: the
  // streamed results carry nodal averages and element means exactly then
  // (equal to the stored run's), else none, and the points always.
  Model model = read_deck(kSource + "/examples/hertz/hertz.inp");
  OutputRequest files;
  files.kind = OutputRequest::Kind::NodeFile;
  files.variables = {"U", "S"};
  files.frequency = 2;
  files.schedule_given = true;
  for (Step& step : model.steps) step.outputs.push_back(files);
  const auto stored = run_writing(model, fresh_directory("streamed_results_due_a"), false, VtuEncoding::Base64);
  std::size_t increment = 0;
  int with_fields = 0;
  run_writing(model, fresh_directory("streamed_results_due_b"), true, VtuEncoding::Base64,
              [&](const IncrementResults& r) {
                ASSERT_LT(increment, stored.size());
                const IncrementResults& s = stored[increment++];
                EXPECT_TRUE(s.element_fields);
                ASSERT_NE(r.point_source, nullptr);
                const bool due = r.increment % 2 == 0 || increment == stored.size();
                EXPECT_EQ(r.element_fields, due) << "increment " << r.increment;
                if (due) {
                  ++with_fields;
                  EXPECT_EQ(r.nodal_stress, s.nodal_stress);
                  EXPECT_EQ(r.element_stress.size(), model.elements.size());
                } else {
                  EXPECT_TRUE(r.nodal_stress.empty());
                  EXPECT_TRUE(r.element_stress.empty());
                  std::ostringstream vtu;
                  EXPECT_THROW(VtuWriter(model, VtuEncoding::Base64).write(r, vtu), std::invalid_argument);
                }
                EXPECT_EQ(r.displacement, s.displacement);
                EXPECT_EQ(r.multipliers.size(), s.multipliers.size());
                std::vector<PointValues> buffer;
                for (std::size_t e = 0; e < model.elements.size(); e += 7)
                  EXPECT_EQ(element_points(r, e, buffer).size(), s.points[e].size()) << e;
              });
  EXPECT_EQ(increment, stored.size());
  EXPECT_GE(with_fields, 1);
}

TEST(StreamedResults, ImplicitDynamicIncrementsBuildElementFieldsOnlyWhenTheFilesAreDue) {
  // The implicit bar-impact example asks for no result file, so its files
  // follow the implicit default (every 10th increment and the step's last):
  // the streamed results carry nodal averages and element means exactly then,
  // equal to the stored run's, and velocities, accelerations, energies and
  // the points always.
  const Model model = read_deck(kSource + "/examples/dyn_bar_impact/bar_impact_implicit.inp");
  const auto stored = run_writing(model, fresh_directory("streamed_results_dyn_a"), false, VtuEncoding::Base64);
  std::size_t increment = 0;
  int with_fields = 0;
  run_writing(model, fresh_directory("streamed_results_dyn_b"), true, VtuEncoding::Base64,
              [&](const IncrementResults& r) {
                ASSERT_LT(increment, stored.size());
                const IncrementResults& s = stored[increment++];
                EXPECT_TRUE(s.element_fields);
                ASSERT_TRUE(r.energy.has_value());
                const bool due = r.increment % kImplicitDynamicDefaultFrequency == 0 || increment == stored.size();
                EXPECT_EQ(r.element_fields, due) << "increment " << r.increment;
                if (due) {
                  ++with_fields;
                  EXPECT_EQ(r.nodal_stress, s.nodal_stress);
                  EXPECT_EQ(r.element_stress.size(), model.elements.size());
                } else {
                  EXPECT_TRUE(r.nodal_stress.empty());
                  EXPECT_TRUE(r.element_stress.empty());
                }
                EXPECT_EQ(r.displacement, s.displacement);
                EXPECT_EQ(r.velocity, s.velocity);
                EXPECT_EQ(r.acceleration, s.acceleration);
                EXPECT_EQ(r.energy->strain, s.energy->strain);
                EXPECT_EQ(r.energy->kinetic, s.energy->kinetic);
              });
  EXPECT_EQ(increment, stored.size());
  EXPECT_GE(with_fields, 2);
  EXPECT_LT(with_fields, static_cast<int>(stored.size()) / 2);
}

}  // namespace
}  // namespace tether
