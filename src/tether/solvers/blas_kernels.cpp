#include "tether/solvers/blas_kernels.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <strings.h>

namespace tether {

std::string blas_kernels_in_use() {
  // Looked up at run time: the program links a BLAS, not necessarily OpenBLAS.
  using Corename = char* (*)();
  const auto corename = reinterpret_cast<Corename>(dlsym(RTLD_DEFAULT, "openblas_get_corename"));
  if (!corename) return {};
  const char* name = corename();
  return name ? std::string(name) : std::string();
}

std::string better_blas_kernels() {
  const std::string in_use = blas_kernels_in_use();
  if (in_use.empty() || strcasecmp(in_use.c_str(), "Prescott") != 0) return {};
#if defined(__x86_64__) && defined(__GNUC__)
  // __builtin_cpu_supports checks the operating system's support (XCR0) for
  // the AVX and AVX-512 registers as well as the CPUID bits.
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
      __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512vl"))
    return "SkylakeX";
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) return "Haswell";
#endif
  return {};
}

void restart_with_better_blas_kernels(char** argv) {
#if defined(__linux__)
  if (std::getenv("OPENBLAS_CORETYPE")) return;  // the user's choice, or this is the restarted run
  const std::string kernels = better_blas_kernels();
  if (kernels.empty()) return;
  if (setenv("OPENBLAS_CORETYPE", kernels.c_str(), 1) != 0) return;
  execv("/proc/self/exe", argv);
  unsetenv("OPENBLAS_CORETYPE");  // the exec failed: go on as before
#else
  (void)argv;
#endif
}

}  // namespace tether
