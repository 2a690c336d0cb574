#include "tether/output/status_writer.hpp"

#include <gtest/gtest.h>

#include "output/tiny_model.hpp"

namespace tether {
namespace {

TEST(StatusWriter, OneFlushedLinePerAttemptAndAVerdict) {
  const auto file = test::fresh_directory("sta") / "job.sta";
  StatusWriter sta(file, "job");
  sta.write({1, 1, 1, true, 3, 3, 0.1, 0.1, 0.1, 1.5e-9});
  sta.write({1, 2, 1, false, 16, 16, 0.3, 0.3, 0.2, 4.0});
  // Read while the writer is still open: every line must already be on disk.
  const std::string before = test::read_text(file);
  EXPECT_NE(before.find(" SUMMARY OF JOB INFORMATION:\n"), std::string::npos);
  EXPECT_NE(before.find("\n     1     1    1     3        3  0.100000E+00  0.100000E+00  0.100000E+00  0.150000E-08\n"),
            std::string::npos)
      << before;
  EXPECT_NE(before.find("\n     1     2    1U   16       16  0.300000E+00  0.300000E+00  0.200000E+00  0.400000E+01\n"),
            std::string::npos)
      << before;
  sta.write({1, 2, 2, true, 4, 20, 0.15, 0.15, 0.05, 2e-10});
  sta.finish(false, "increment 0.0125 below the minimum 0.05 in step 1");
  sta.finish(true, "");  // ignored
  const std::string text = test::read_text(file);
  EXPECT_NE(text.find("\n     1     2    2     4       20"), std::string::npos) << text;
  EXPECT_EQ(text.substr(text.rfind('\n', text.size() - 2) + 1),
            " THE ANALYSIS HAS NOT BEEN COMPLETED: increment 0.0125 below the minimum 0.05 in step 1\n");
}

TEST(StatusWriter, CompletedVerdict) {
  const auto file = test::fresh_directory("sta_ok") / "job.sta";
  {
    StatusWriter sta(file, "job");
    sta.finish(true, "");
  }
  const std::string text = test::read_text(file);
  EXPECT_EQ(text.substr(text.size() - 41), " THE ANALYSIS HAS COMPLETED SUCCESSFULLY\n");
}

}  // namespace
}  // namespace tether
