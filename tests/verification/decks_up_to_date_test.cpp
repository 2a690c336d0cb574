// The committed decks are what tools/make_verification_decks.py writes: regenerate
// them into the build tree and compare the text (the generators are plain
// Python, so the output is deterministic). Skipped without a python3.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(VerificationDecks, MatchTheirGenerators) {
  if (std::system("command -v python3 > /dev/null 2>&1") != 0) GTEST_SKIP() << "python3 not found";
  const fs::path source = fs::path(TETHER_SOURCE_DIR);
  const fs::path out = fs::path(TETHER_BINARY_DIR) / "tests" / "verification" / "regenerated_decks";
  fs::remove_all(out);
  const std::string command = "python3 \"" + (source / "tools" / "make_verification_decks.py").string() + "\" \"" +
                              out.string() + "\" > /dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  int compared = 0;
  for (const auto& entry : fs::directory_iterator(out)) {
    const fs::path committed = source / "tests" / "verification" / "decks" / entry.path().filename();
    ASSERT_TRUE(fs::exists(committed)) << committed << " is generated but not committed";
    EXPECT_EQ(slurp(entry.path()), slurp(committed))
        << committed << " differs from what tools/make_verification_decks.py writes: rerun it "
        << "(and tools/ccx_reference.py for ccx_* decks)";
    ++compared;
  }
  EXPECT_GE(compared, 20);
}

}  // namespace
