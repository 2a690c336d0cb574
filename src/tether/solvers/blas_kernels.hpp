#pragma once
/// \file Which OpenBLAS kernels the process runs, and a better choice when
/// OpenBLAS fell back to its generic ones.
///
/// An OpenBLAS built with DYNAMIC_ARCH (Debian's) picks its kernels from the
/// CPU model when it is loaded. A model newer than the library knows gets the
/// generic "Prescott" kernels (SSE3, no FMA): OpenBLAS 0.3.21 (Debian 12) on an
/// Intel Xeon of family 6, model 207 (Emerald Rapids), which has AVX-512. Every
/// dense kernel of the sparse and dense factorizations and of the triangular
/// sweeps then runs at a fraction of the machine's speed: on the 230k-dof
/// Hertz deck, 9.07 s of CPU with Prescott against 7.64 s with SkylakeX
/// (docs/performance.md). OpenBLAS reads its choice from the environment
/// variable OPENBLAS_CORETYPE only while it is loaded, i.e. before main(), so
/// a program that wants other kernels must start again with it set
/// (restart_with_better_blas_kernels()).
///
/// The kernels differ in the order of their sums: results change in the last
/// bits, not more (the same factorizations, pivots and iterations).

#include <string>

namespace tether {

/// OpenBLAS's name of the kernels in use ("Prescott", "SkylakeX", ...), or
/// empty when the BLAS is not OpenBLAS (no openblas_get_corename symbol).
[[nodiscard]] std::string blas_kernels_in_use();

/// The OPENBLAS_CORETYPE to ask for when OpenBLAS runs its generic kernels
/// ("Prescott") on a CPU that has (with the operating system's support)
/// AVX-512 F, DQ, BW and VL ("SkylakeX") or AVX2 and FMA ("Haswell"); empty
/// otherwise: another BLAS, kernels OpenBLAS chose for a CPU it knows, or a
/// CPU without them.
[[nodiscard]] std::string better_blas_kernels();

/// When OPENBLAS_CORETYPE is not set and better_blas_kernels() names some,
/// sets it and replaces the process by a new run of the same program with
/// the same arguments (execv of /proc/self/exe, Linux only). Returns only
/// when nothing is to be done or the exec failed (the run then goes on with
/// the kernels it has). Call it first in main(), before any output. A user's
/// OPENBLAS_CORETYPE (Prescott included) is left alone; set it when running
/// the program under a tool that does not follow exec (valgrind without
/// --trace-children=yes), else the restarted run escapes the tool.
void restart_with_better_blas_kernels(char** argv);

}  // namespace tether
