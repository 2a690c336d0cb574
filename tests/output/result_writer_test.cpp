#include "tether/output/result_writer.hpp"

#include <gtest/gtest.h>

#include "output/tiny_model.hpp"

namespace tether {
namespace {

using test::synthetic_results;
using test::tiny_model;

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (auto pos = text.find(what); pos != std::string::npos; pos = text.find(what, pos + 1)) ++n;
  return n;
}

TEST(ResultWriter, WritesAllFilesOfAJob) {
  const Model model = tiny_model();
  const auto dir = test::fresh_directory("result_writer") / "sub" / "dir";  // created by the writer
  OutputRequest u{OutputRequest::Kind::NodePrint, "LEFT", {"U"}, 1, false, false, {}};
  {
    ResultWriter writer(model, dir, "beam");
    EXPECT_EQ(writer.pvd_path(), dir / "beam.pvd");
    EXPECT_EQ(writer.dat_path(), dir / "beam.dat");
    EXPECT_EQ(writer.sta_path(), dir / "beam.sta");
    EXPECT_EQ(writer.vtu_path(2, 7), dir / "beam_2_7.vtu");
    for (int step = 1; step <= 2; ++step)
      for (int inc = 1; inc <= 2; ++inc) {
        const double time = step - 1 + 0.5 * inc;
        writer.write_status({step, inc, 1, true, 2, 2, time, 0.5 * inc, 0.5, 1e-10});
        writer.write_increment(synthetic_results(model, step, inc, time, time), {u}, inc == 2);
        // After every increment the collection on disk is complete.
        const std::string pvd = test::read_text(dir / "beam.pvd");
        EXPECT_EQ(count(pvd, "<DataSet "), 2 * (step - 1) + inc);
        EXPECT_EQ(pvd.substr(pvd.size() - 11), "</VTKFile>\n");
        EXPECT_EQ(test::count_temporary_files(dir), 0);
      }
    writer.finish(true, "");
  }
  for (const char* f : {"beam_1_1.vtu", "beam_1_2.vtu", "beam_2_1.vtu", "beam_2_2.vtu"})
    EXPECT_TRUE(std::filesystem::exists(dir / f)) << f;
  const std::string pvd = test::read_text(dir / "beam.pvd");
  EXPECT_NE(pvd.find("timestep=\"1.5\" group=\"\" part=\"0\" file=\"beam_2_1.vtu\""), std::string::npos) << pvd;
  EXPECT_EQ(count(test::read_text(dir / "beam.dat"), "displacements (vx,vy,vz) for set LEFT"), 4);
  const std::string sta = test::read_text(dir / "beam.sta");
  EXPECT_EQ(count(sta, "\n     "), 4);
  EXPECT_NE(sta.find("THE ANALYSIS HAS COMPLETED SUCCESSFULLY"), std::string::npos);
}

TEST(ResultWriter, FileRequestsSetTheVtuFrequency) {
  const Model model = tiny_model();
  const auto dir = test::fresh_directory("result_writer_frequency");
  OutputRequest file{OutputRequest::Kind::NodeFile, "", {"U"}, 3, false, false, {}};
  {
    ResultWriter writer(model, dir, "job");
    for (int inc = 1; inc <= 7; ++inc)
      writer.write_increment(synthetic_results(model, 1, inc, 0.1 * inc, 1.0), {file}, inc == 7);
  }
  std::vector<std::string> written;
  for (int inc = 1; inc <= 7; ++inc)
    if (std::filesystem::exists(dir / ("job_1_" + std::to_string(inc) + ".vtu"))) written.push_back(std::to_string(inc));
  EXPECT_EQ(written, (std::vector<std::string>{"3", "6", "7"}));
  EXPECT_EQ(count(test::read_text(dir / "job.pvd"), "<DataSet "), 3);
  EXPECT_EQ(test::read_text(dir / "job.dat"), "");  // no print requests
}

TEST(ResultWriter, VtuCanBeSwitchedOff) {
  const Model model = tiny_model();
  const auto dir = test::fresh_directory("result_writer_no_vtu");
  {
    ResultWriter writer(model, dir, "job", {VtuEncoding::Base64, false});
    writer.write_increment(synthetic_results(model, 1, 1, 1.0, 1.0), {}, true);
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "job_1_1.vtu"));
  EXPECT_FALSE(std::filesystem::exists(dir / "job.pvd"));
}

}  // namespace
}  // namespace tether
