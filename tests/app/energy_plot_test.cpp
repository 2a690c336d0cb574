// `tether run` draws the energy history of dynamic steps into JOB_energy.png.

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "cli_support.hpp"

namespace fs = std::filesystem;
using namespace cli_test;

namespace {

/// One CPE4 vibrating freely on its bottom edge: an implicit dynamic step.
const char* kVibration = R"(*NODE
1, 0, 0
2, 1, 0
3, 1, 1
4, 0, 1
*ELEMENT, TYPE=CPE4, ELSET=E
1, 1, 2, 3, 4
*MATERIAL, NAME=M
*ELASTIC
1000., 0.3
*DENSITY
1.
*SOLID SECTION, ELSET=E, MATERIAL=M
*BOUNDARY
1, 1, 2
2, 1, 2
*INITIAL CONDITIONS, TYPE=VELOCITY
3, 1, 1.
4, 1, 1.
*STEP
*DYNAMIC
0.01, 0.2
*END STEP
)";

bool is_png(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string signature(8, '\0');
  in.read(signature.data(), 8);
  return in && signature == std::string("\x89PNG\r\n\x1a\n", 8) && fs::file_size(path) > 1000;
}

TEST(EnergyPlot, ADynamicRunDrawsItsEnergiesAndNamesThePlot) {
  const fs::path dir = scratch("energy_plot");
  write(dir / "vibration.inp", kVibration);
  const Result r = tether("run " + (dir / "vibration.inp").string() + " -o " + (dir / "out").string());
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_TRUE(is_png(dir / "out" / "vibration_energy.png")) << r.out;
  EXPECT_NE(r.out.find("vibration_energy.csv"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("vibration_energy.png"), std::string::npos) << r.out;

  // --no-plot: the CSV only, and the earlier run's plot is gone.
  const Result bare = tether("run --no-plot " + (dir / "vibration.inp").string() + " -o " + (dir / "out").string());
  ASSERT_EQ(bare.code, 0) << bare.out;
  EXPECT_FALSE(fs::exists(dir / "out" / "vibration_energy.png"));
  EXPECT_TRUE(fs::exists(dir / "out" / "vibration_energy.csv"));
}

TEST(EnergyPlot, WithoutMatplotlibTheRunSaysSoAndSucceeds) {
  // A python3 that cannot import matplotlib: an empty PYTHONPATH shadowed by
  // a matplotlib package that raises ImportError.
  const fs::path dir = scratch("energy_plot_no_matplotlib");
  fs::create_directories(dir / "shadow" / "matplotlib");
  write(dir / "shadow" / "matplotlib" / "__init__.py", "raise ImportError('shadowed for the test')\n");
  write(dir / "vibration.inp", kVibration);
  const Result r = tether("run " + (dir / "vibration.inp").string() + " -o " + (dir / "out").string(),
                          "PYTHONPATH=" + (dir / "shadow").string());
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("warning: no energy plot"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("has no matplotlib"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(dir / "out" / "vibration_energy.png"));
}

}  // namespace
