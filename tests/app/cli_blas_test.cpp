// tether run's choice of OpenBLAS kernels (restart_with_better_blas_kernels).

#include <gtest/gtest.h>

#include <regex>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "tether/solvers/blas_kernels.hpp"

namespace {

/// The kernel names OpenBLAS printed ("Core: NAME" lines with OPENBLAS_VERBOSE=2), in order.
std::vector<std::string> cores(const std::string& out) {
  std::vector<std::string> names;
  const std::regex line("Core: (\\S+)");
  for (auto it = std::sregex_iterator(out.begin(), out.end(), line); it != std::sregex_iterator(); ++it)
    names.push_back((*it)[1]);
  return names;
}

}  // namespace

// Without OPENBLAS_CORETYPE, the program runs with the kernels
// better_blas_kernels() names when OpenBLAS chose its generic ones (it starts
// again once: two "Core:" lines), and with OpenBLAS's own choice otherwise.
// On a CPU OpenBLAS 0.3.21 does not know (Intel family 6 model 207) the old
// program ran with Prescott's kernels.
TEST(CliBlas, GenericKernelsAreReplacedOnACpuThatHasBetterOnes) {
  const cli_test::Result r = cli_test::tether("--version", "-u OPENBLAS_CORETYPE OPENBLAS_VERBOSE=2");
  ASSERT_EQ(r.code, 0) << r.out;
  const std::vector<std::string> names = cores(r.out);
  if (names.empty()) GTEST_SKIP() << "the BLAS is not OpenBLAS (or prints nothing): " << r.out;
  // In this (test) process OpenBLAS chose as the program's first start does,
  // unless the test runs with OPENBLAS_CORETYPE set.
  const std::string better = std::getenv("OPENBLAS_CORETYPE") ? "" : tether::better_blas_kernels();
  if (better.empty()) {
    EXPECT_EQ(names.size(), 1u) << r.out;  // Prescott here means a CPU without AVX2 and FMA
  } else {
    ASSERT_EQ(names.size(), 2u) << r.out;
    EXPECT_EQ(names[0], "Prescott");
    EXPECT_EQ(names[1], better);
  }
}

// A user's OPENBLAS_CORETYPE is respected, the generic kernels included: no second start.
TEST(CliBlas, TheUsersChoiceStands) {
  const cli_test::Result r = cli_test::tether("--version", "OPENBLAS_CORETYPE=Prescott OPENBLAS_VERBOSE=2");
  ASSERT_EQ(r.code, 0) << r.out;
  const std::vector<std::string> names = cores(r.out);
  if (names.empty()) GTEST_SKIP() << "the BLAS is not OpenBLAS: " << r.out;
  ASSERT_EQ(names.size(), 1u) << r.out;
  EXPECT_EQ(names.front(), "Prescott");
}

// better_blas_kernels() names kernels only in place of the generic ones.
TEST(BlasKernels, OnlyTheGenericKernelsAreReplaced) {
  const std::string in_use = tether::blas_kernels_in_use();
  const std::string better = tether::better_blas_kernels();
  if (in_use != "Prescott") EXPECT_EQ(better, "") << in_use;
  if (!better.empty()) EXPECT_TRUE(better == "SkylakeX" || better == "Haswell") << better;
}
