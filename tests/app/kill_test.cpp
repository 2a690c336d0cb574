// Crash safety: an analysis killed (SIGKILL) at random moments leaves a valid
// .pvd whose every listed .vtu is complete, and a complete restart file
// (each is written to a temporary file and renamed).

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <random>
#include <regex>
#include <sstream>
#include <thread>

#include "tether/core/error.hpp"
#include "tether/output/restart_file.hpp"

namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// A strip of nx x ny CPE4 elements stretched in 400 fixed NLGEOM increments:
/// long enough (seconds) to be killed in the middle.
std::string long_deck(int nx, int ny) {
  std::ostringstream d;
  d << "*NODE, NSET=ALL\n";
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) d << j * (nx + 1) + i + 1 << ", " << 4.0 * i / nx << ", " << 1.0 * j / ny << "\n";
  d << "*ELEMENT, TYPE=CPE4, ELSET=E\n";
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int n1 = j * (nx + 1) + i + 1;
      d << j * nx + i + 1 << ", " << n1 << ", " << n1 + 1 << ", " << n1 + nx + 2 << ", " << n1 + nx + 1 << "\n";
    }
  d << "*NSET, NSET=LEFT, GENERATE\n1, " << ny * (nx + 1) + 1 << ", " << nx + 1 << "\n";
  d << "*NSET, NSET=RIGHT, GENERATE\n" << nx + 1 << ", " << (ny + 1) * (nx + 1) << ", " << nx + 1 << "\n";
  d << "*MATERIAL, NAME=R\n*HYPERELASTIC, NEO HOOKE\n1., 0.1\n*SOLID SECTION, ELSET=E, MATERIAL=R\n"
    << "*BOUNDARY\nLEFT, 1, 2\n*RESTART, WRITE, FREQUENCY=1\n*STEP, NLGEOM, INC=1000\n*STATIC, DIRECT\n0.0025, 1.\n"
    << "*BOUNDARY\nRIGHT, 1, 1, 2.\n*END STEP\n";
  return d.str();
}

/// Checks the .pvd and every file it lists; returns the number of datasets.
int check_results(const fs::path& dir, const std::string& job) {
  const fs::path pvd = dir / (job + ".pvd");
  if (!fs::exists(pvd)) return 0;  // killed before the first increment
  const std::string text = slurp(pvd);
  EXPECT_NE(text.find("</VTKFile>"), std::string::npos) << "truncated .pvd:\n" << text;
  const std::regex dataset("file=\"([^\"]+)\"");
  int count = 0;
  for (std::sregex_iterator it(text.begin(), text.end(), dataset), end; it != end; ++it) {
    const fs::path vtu = dir / (*it)[1].str();
    EXPECT_TRUE(fs::exists(vtu)) << vtu;
    const std::string body = slurp(vtu);
    EXPECT_NE(body.find("</VTKFile>"), std::string::npos) << "incomplete " << vtu;
    ++count;
  }
  // The restart state, when one has been written, is complete (it decodes:
  // magic, length and checksum) and at most one increment behind the last
  // listed one (it is written after the increment's results).
  if (fs::exists(dir / (job + ".rst"))) {
    try {
      const tether::RestartState state = tether::read_restart_file(dir / (job + ".rst"));
      EXPECT_GE(state.increment, count - 1) << "the restart state lags behind the results";
    } catch (const tether::InputError& e) {
      ADD_FAILURE() << "incomplete restart file: " << e.what();
    }
  }
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().extension() == ".vtu") {
      const std::string body = slurp(entry.path());
      EXPECT_NE(body.find("</VTKFile>"), std::string::npos) << "a .vtu in place is incomplete: " << entry.path();
    }
  return count;
}

}  // namespace

TEST(CrashSafety, KilledAnalysisLeavesOnlyCompleteIncrements) {
  const fs::path dir = fs::path(TETHER_BINARY_DIR) / "tests" / "app" / "scratch" / "kill";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "long.inp") << long_deck(60, 15);
  std::mt19937 rng(2026);
  std::uniform_int_distribution<int> delay_ms(50, 1500);
  int killed_with_results = 0;
  for (int trial = 0; trial < 6; ++trial) {
    const fs::path out = dir / ("out" + std::to_string(trial));
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      const std::string deck = (dir / "long.inp").string(), target = out.string();
      execl(TETHER_CLI, "tether", "run", deck.c_str(), "-o", target.c_str(), "-q", static_cast<char*>(nullptr));
      _exit(127);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms(rng)));
    const bool still_running = kill(pid, SIGKILL) == 0;
    int status = 0;
    waitpid(pid, &status, 0);
    const int datasets = check_results(out, "long");
    if (still_running && WIFSIGNALED(status) && datasets > 0) ++killed_with_results;
  }
  // The test means something only if some runs were killed mid-way with results on disk.
  EXPECT_GE(killed_with_results, 2) << "the analysis finished too early or wrote nothing before the kills";
}
