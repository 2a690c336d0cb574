#include "tether/output/atomic_file.hpp"

#include <gtest/gtest.h>

#include "output/tiny_model.hpp"

namespace tether {
namespace {

TEST(AtomicFile, TargetAppearsOnlyAtCommit) {
  const auto dir = test::fresh_directory("atomic_commit");
  const auto target = dir / "a.txt";
  {
    AtomicFile file(target);
    file.stream() << "new content\n";
    EXPECT_FALSE(std::filesystem::exists(target));
    EXPECT_TRUE(std::filesystem::exists(file.temporary()));
    file.commit();
  }
  EXPECT_EQ(test::read_text(target), "new content\n");
  EXPECT_EQ(test::count_temporary_files(dir), 0);
}

TEST(AtomicFile, AbandonedWriteLeavesTheOldFileAndNoTemporary) {
  const auto dir = test::fresh_directory("atomic_abandon");
  const auto target = dir / "a.txt";
  { std::ofstream(target) << "old\n"; }
  try {
    AtomicFile file(target);
    file.stream() << "half written";
    throw std::runtime_error("simulated failure while writing");
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(test::read_text(target), "old\n");
  EXPECT_EQ(test::count_temporary_files(dir), 0);
}

TEST(AtomicFile, UnwritableDirectoryIsReported) {
  EXPECT_THROW(AtomicFile(std::filesystem::path(TETHER_BINARY_DIR) / "no" / "such" / "dir" / "x.vtu"),
               std::runtime_error);
}

}  // namespace
}  // namespace tether
