#pragma once
/// \file The result files of a job: what `tether run` writes into its output
/// directory, as an AnalysisObserver.

#include <fmt/os.h>

#include <filesystem>
#include <string>

#include "tether/analysis/analysis_observer.hpp"
#include "tether/output/result_writer.hpp"

namespace tether {

/// Writes a job's results and logs into one directory: the ResultWriter's
/// files (`JOB.pvd` and `.vtu`s, `JOB.dat`, `JOB.sta`, `JOB.rst`) and an
/// ABAQUS-like message log `JOB.msg` beside the `.sta` (every iteration's
/// norms, every attempt, messages such as cut-backs and augmented-Lagrangian
/// updates). The constructor creates or truncates the files (see
/// ResultWriter); the Model must outlive the object and not change.
/// Errors: those of ResultWriter, std::system_error when the log cannot be opened.
class JobFiles final : public AnalysisObserver {
 public:
  /// `output_state` (restart, may be null): the writer's history saved in the
  /// restart state, loaded before the log is opened; InputError naming
  /// `restart_file` when it is malformed.
  JobFiles(const Model& model, const std::filesystem::path& directory, const std::string& job,
           ResultWriterOptions options, const std::vector<double>* output_state = nullptr,
           const std::string& restart_file = "");

  void on_iteration(int iteration, const IterationNorms& norms) override;
  void on_increment(const IncrementReport& report) override;
  void on_results(const IncrementResults& results, const Step& step, bool last_in_step) override;
  void on_restart_state(const RestartState& state) override;
  void on_message(const std::string& message) override;

  /// Writes `message` to the `.msg` as one indented line.
  void log(const std::string& message);

  [[nodiscard]] ResultWriter& writer() { return writer_; }
  [[nodiscard]] const ResultWriter& writer() const { return writer_; }
  [[nodiscard]] const std::filesystem::path& msg_path() const { return msg_path_; }

 private:
  ResultWriter writer_;
  bool history_loaded_;  ///< (initialization order: the history is loaded before the log opens)
  std::filesystem::path msg_path_;
  fmt::ostream msg_;
  int iterations_this_increment_ = 0;  ///< over the attempts of the current increment (the .sta's total)
};

}  // namespace tether
