#pragma once
/// \file The one way to run an analysis, for the `tether` program, C++
/// programs and the Python module: a model in, result files and owned result
/// snapshots out.
///
///     Job job(read_deck("plate.inp"), {.output_dir = "out"});
///     const JobSummary summary = job.run();
///     const IncrementResults& last = job.results().back().results;
///
/// The Job runs the model's steps with the step driver (StaticAnalysis, which
/// picks each step's procedure), writes with `output_dir` set the same files
/// as `tether run` (JobFiles), forwards every report to an optional observer
/// and keeps the results of converged increments (JobOptions::keep). See
/// docs/python.md for the Python side.

#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tether/analysis/static_analysis.hpp"
#include "tether/job/job_files.hpp"
#include "tether/model/model.hpp"
#include "tether/output/result_writer.hpp"

namespace tether {

struct JobOptions {
  /// Solver choices; `stream_element_results` is set by the Job (streamed
  /// when no increment is kept).
  AnalysisOptions analysis;
  /// Where the result files go (created when needed; this job's earlier files
  /// there are replaced, see ResultWriter); empty: nothing is written.
  std::filesystem::path output_dir;
  /// Stem of the file names (JOB.dat, JOB.pvd, ...); empty: the deck's stem,
  /// or "job" for a model not read from a file.
  std::string name;
  ResultWriterOptions writer;
  /// Which converged increments results() keeps: all of them (each holds every
  /// integration point), the last one only, or none (what `tether run` does:
  /// its results are only written).
  enum class Keep { All, Last, None };
  Keep keep = Keep::All;
  /// Start of the clock of the `.msg`'s timing line; default: when run() starts.
  std::optional<std::chrono::steady_clock::time_point> started;
};

/// How a run went: the analysis' summary and its wall-clock time.
struct JobSummary : AnalysisSummary {
  double seconds = 0;  ///< from JobOptions::started (or the start of run()) to the end [s]
};

/// One converged increment kept by a Job: owned results (every integration
/// point stored, no point source) and the model they were computed for.
struct JobIncrement {
  std::shared_ptr<const Model> model;
  IncrementResults results;
};

/// "time 1.23 s: contact search ..., assembly ..., ...": the timing line of
/// the `.msg` and of `tether run`'s summary.
std::string timing_line(double seconds, const SolveTiming& timing);

class Job {
 public:
  /// Takes the model (move it in, or copy it).
  explicit Job(Model model, JobOptions options = {});
  /// Shares the model with the caller: changes the caller makes between runs
  /// are seen by the next run (the Python module's way). Not null.
  explicit Job(std::shared_ptr<Model> model, JobOptions options = {});
  Job(const Job&) = delete;
  Job& operator=(const Job&) = delete;
  ~Job();

  /// The model the next run() solves.
  [[nodiscard]] const Model& model() const { return *model_; }
  /// The model to change before the next run() (material constants, loads,
  /// step data: a parameter study without reading the deck again). Increments
  /// kept from earlier runs keep a copy of the model they were computed for.
  /// Between prepare() (or resume()) and run() the model cannot change (the
  /// prepared analysis would not see it): std::logic_error.
  [[nodiscard]] Model& edit_model();

  [[nodiscard]] const JobOptions& options() const { return options_; }
  [[nodiscard]] JobOptions& options() { return options_; }

  /// Discretizes the model now rather than at run() (ModelError for a model
  /// that cannot be solved as posed), so that a refused model touches no
  /// file. Optional.
  void prepare();

  /// Continues the next run from a restart state instead of the beginning
  /// (see StaticAnalysis::resume; InputError naming `file` when the state does
  /// not belong to the model). The result files continue the state's output
  /// history. Prepares the job.
  void resume(const RestartState& state, const std::string& file);

  /// A line for the `.msg`, written when the files are opened (at the start of
  /// the next run, before the analysis reports); ignored without output_dir.
  void log(const std::string& message);

  /// Runs the analysis (all steps, or the rest after resume()): opens the
  /// files when writing, reports to `observer` (after the files) and keeps
  /// the increments. Never throws because the model does not converge or a
  /// step cannot be solved: the summary says why it stopped. Throws
  /// ModelError / ResourceError (after closing the `.sta` with the reason),
  /// InputError for a bad output request, and rethrows any other exception
  /// of the run (the observer's, a constraint callback's) after closing the
  /// `.sta` and the `.msg` with the verdict "stopped by an exception: <first
  /// line of what()>; last increment written: step S increment I, time T";
  /// after an exception results() holds the increments kept until then. A Job can run
  /// again: each run starts from the beginning with the model as it is then
  /// and replaces the kept increments and the files.
  JobSummary run(AnalysisObserver* observer = nullptr);

  /// The kept increments of the last run, in order.
  [[nodiscard]] const std::vector<JobIncrement>& results() const { return results_; }
  /// Moves the kept increments out (results() is empty afterwards).
  [[nodiscard]] std::vector<JobIncrement> take_results() {
    std::vector<JobIncrement> out = std::move(results_);
    results_.clear();
    return out;
  }

  /// The result files of the last run that exist (`.pvd`, `.dat`, `.sta`,
  /// `.msg`, `.rst`); empty without output_dir.
  [[nodiscard]] std::vector<std::filesystem::path> written_files() const;

  /// Name of the files (see JobOptions::name).
  [[nodiscard]] std::string name() const;

 private:
  class Recorder;
  /// Creates the files and the writer's history (restart), logs what waits.
  void open_files();
  /// The verdict of a run stopped by an exception with message `what`.
  [[nodiscard]] std::string stopped_verdict(const std::string& what) const;

  std::shared_ptr<Model> model_;            ///< the model the next run solves
  std::shared_ptr<const Model> run_model_;  ///< the prepared analysis' model: model_, or a copy when increments are kept
  JobOptions options_;
  std::unique_ptr<Recorder> recorder_;        ///< the observer of the analysis
  std::unique_ptr<StaticAnalysis> analysis_;  ///< prepared, not yet run
  std::optional<RestartState> resumed_;
  std::string resumed_file_;
  std::unique_ptr<JobFiles> files_;
  std::vector<std::string> pending_log_;
  std::vector<JobIncrement> results_;
};

}  // namespace tether
