#pragma once
/// \file Status file (`.sta`): one line per increment attempt, like ABAQUS's
/// and CalculiX's `.sta`, flushed line by line so it can be followed with
/// `tail -f` while the analysis runs.

#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

namespace tether {

/// One attempt at an increment, as reported by the step loop.
struct IncrementStatus {
  int step = 1;               ///< 1-based
  int increment = 1;          ///< 1-based within the step
  int attempt = 1;            ///< 1 = first try; attempt - 1 cut-backs preceded it
  bool converged = true;      ///< false: the attempt failed and is followed by a cut-back
  int iterations = 0;         ///< Newton iterations of this attempt
  int total_iterations = 0;   ///< Newton iterations of all attempts of this increment so far
  double total_time = 0;      ///< at the end of the increment (attempted)
  double step_time = 0;       ///< at the end of the increment (attempted)
  double increment_size = 0;  ///< step-time increment of this attempt
  double residual_norm = 0;   ///< final residual norm of this attempt [force]
};

/// Writes the `.sta` file:
///
///     tether 0.1.0  job NAME
///     SUMMARY OF JOB INFORMATION:
///      STEP   INC  ATT  ITRS  TOTITRS     TOT TIME    STEP TIME     INC TIME     RESIDUAL
///         1     1    1     3        3  0.100000E+00 ...
///         1     2    1U   16       16  ...            (unconverged attempt: cut back)
///     THE ANALYSIS HAS COMPLETED SUCCESSFULLY
///
/// Times and the residual use Fortran E13.6 (` 0.100000E+01`), as ccx's
/// `.sta`. The last line is either `THE ANALYSIS HAS COMPLETED SUCCESSFULLY`
/// or `THE ANALYSIS HAS NOT BEEN COMPLETED: <reason>`.
class StatusWriter {
 public:
  /// Creates (truncates) `file` and writes the header, which names the
  /// dialect the deck was read in when one is given ("abaqus", "calculix").
  /// Throws std::runtime_error when the file cannot be created.
  StatusWriter(std::filesystem::path file, const std::string& job, std::string_view dialect = "");

  /// Appends one line and flushes.
  void write(const IncrementStatus& status);

  /// Appends the final line and flushes; later calls do nothing.
  void finish(bool completed, const std::string& message);

  [[nodiscard]] const std::filesystem::path& file() const { return file_; }

 private:
  std::filesystem::path file_;
  std::ofstream out_;
  bool finished_ = false;
};

}  // namespace tether
