#pragma once
/// \file One sequential MUMPS instance (double precision), owned RAII-style:
/// the private plumbing shared by MumpsSolver and MumpsSchur. Not installed.
///
/// MUMPS numbers its controls and information from 1 as in its manual
/// (ICNTL(7), INFOG(28)); icntl() and infog() take those numbers.

#include <dmumps_c.h>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "tether/core/error.hpp"

namespace tether::detail {

struct MumpsInstance {
  DMUMPS_STRUC_C id{};

  /// `sym`: 0 unsymmetric (LU), 1 symmetric positive definite, 2 general symmetric (LDLT, 2x2 pivots).
  explicit MumpsInstance(int sym) {
    id.comm_fortran = -987654;  // MUMPS' "use comm world" for the sequential library
    id.par = 1;                 // the host works
    id.sym = sym;
    id.job = -1;
    dmumps_c(&id);
    icntl(1) = -1;  // no error, diagnostic or global output streams
    icntl(2) = -1;
    icntl(3) = -1;
    icntl(4) = 0;
    icntl(14) = 40;  // working space relaxation [%]
    icntl(24) = 1;   // detect null pivots (report the singular equation instead of failing)
  }
  ~MumpsInstance() {
    id.job = -2;
    dmumps_c(&id);
  }
  MumpsInstance(const MumpsInstance&) = delete;
  MumpsInstance& operator=(const MumpsInstance&) = delete;

  int& icntl(int i) { return id.icntl[i - 1]; }
  [[nodiscard]] int infog(int i) const { return id.infog[i - 1]; }

  /// Resident memory of this process now [MB] (Linux /proc; 0 when unknown).
  static double resident_mb() {
    std::ifstream statm("/proc/self/statm");
    long pages_total = 0, pages_resident = 0;
    if (!(statm >> pages_total >> pages_resident)) return 0;
    return static_cast<double>(pages_resident) * static_cast<double>(sysconf(_SC_PAGESIZE)) / 1e6;
  }

  /// The directory out-of-core factors go to: $TMPDIR, else /tmp. Throws
  /// ResourceError naming it when it is missing, not a writable directory,
  /// or too long a path for MUMPS (255 characters).
  static std::string scratch_directory() {
    const char* tmpdir = std::getenv("TMPDIR");
    const std::string dir = tmpdir && *tmpdir ? tmpdir : "/tmp";
    const std::string origin = tmpdir && *tmpdir ? " ($TMPDIR)" : "";
    auto refuse = [&](const std::string& why) {
      throw ResourceError("the temporary directory '" + dir + "'" + origin + " for out-of-core factors " + why +
                          ": set TMPDIR to a writable directory, or raise or drop --memory");
    };
    std::error_code ec;
    if (!std::filesystem::is_directory(dir, ec)) refuse("does not exist or is not a directory");
    if (access(dir.c_str(), W_OK | X_OK) != 0) refuse("is not writable");
    if (dir.size() > 255) refuse("has a path longer than MUMPS accepts (255 characters)");
    return dir;
  }

  /// Between an analysis and a factorization: keeps the factors in core
  /// unless MUMPS' estimate for an in-core factorization (INFOG(17) [MB])
  /// exceeds what the process leaves of `budget_mb` (0: no limit); then they
  /// go out of core (ICNTL(22) = 1) to files in scratch_directory(), which
  /// MUMPS deletes when the instance ends. The memory this instance still
  /// holds from its previous factorization (INFOG(22)) is freed by the next
  /// one, so it is not counted as used: otherwise a run near the budget
  /// would alternate between in core and out of core.
  void plan_memory(double budget_mb) {
    const double held = factorized ? std::max(0, infog(22)) : 0.0;
    icntl(22) = 0;
    if (budget_mb <= 0 || infog(17) <= budget_mb - std::max(0.0, resident_mb() - held)) return;
    const std::string dir = scratch_directory();
    icntl(22) = 1;
    std::snprintf(id.ooc_tmpdir, sizeof id.ooc_tmpdir, "%s", dir.c_str());
    std::snprintf(id.ooc_prefix, sizeof id.ooc_prefix, "tether%ld_", static_cast<long>(getpid()));
  }

  /// After a factorization: throws SolverError naming the first equation
  /// (0-based) with a null pivot when MUMPS found any (ICNTL(24) = 1).
  void throw_if_null_pivots() const {
    if (infog(28) <= 0) return;
    const int eq = id.pivnul_list ? id.pivnul_list[0] - 1 : -1;
    throw SolverError("the stiffness matrix is singular (MUMPS found " + std::to_string(infog(28)) + " zero pivot(s))",
                      eq);
  }

  /// Runs `job` (1 analysis, 2 factorization, 3 solve); throws SolverError on
  /// a MUMPS error. Retries a factorization with more working space when
  /// MUMPS asks for it (INFOG(1) = -9, -8).
  void run(int job) {
    id.job = job;
    if (job == 2) factorized = false;  // the previous factors go with this call
    dmumps_c(&id);
    for (int retry = 0; retry < 3 && job == 2 && (infog(1) == -9 || infog(1) == -8); ++retry) {
      icntl(14) *= 2;
      id.job = job;
      dmumps_c(&id);
    }
    const char* phase = job == 1 ? "analysis" : job == 2 ? "factorization" : "solve";
    // -90: out-of-core I/O failed (disk full, directory removed meanwhile): not a property of the matrix.
    if (infog(1) == -90 && icntl(22) == 1)
      throw ResourceError(std::string("MUMPS could not write or read its out-of-core factors in '") + id.ooc_tmpdir +
                          "' during the " + phase + " (INFOG(1) = -90): is the disk full? Free space there, set "
                          "TMPDIR to another directory, or raise or drop --memory");
    if (infog(1) < 0)
      throw SolverError("MUMPS " + std::string(phase) + " failed (INFOG(1) = " + std::to_string(infog(1)) +
                        ", INFOG(2) = " + std::to_string(infog(2)) + ")");
    if (job == 2) factorized = true;
  }

  bool factorized = false;  ///< the last factorization succeeded (its factors are held)
};

}  // namespace tether::detail
