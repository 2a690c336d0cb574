#include "tether/job/job.hpp"

#include <fmt/core.h>

#include <stdexcept>

#include "tether/core/error.hpp"

namespace tether {

std::string timing_line(double seconds, const SolveTiming& t) {
  return fmt::format("time {:.2f} s: contact search {:.2f}, assembly {:.2f}{}, analyse {:.2f}, factorize {:.2f} ({} "
                     "factorizations{}{}), solve {:.2f}, output {:.2f}",
                     seconds, t.contact_search, t.assembly,
                     t.held_tangents > 0 ? fmt::format(" (linear bulk's tangent held in {} of {}{})", t.held_tangents,
                                                       t.held_tangents + t.full_tangents,
                                                       t.residual_updates > 0
                                                           ? fmt::format(", its residual from it in {}", t.residual_updates)
                                                           : std::string())
                                         : std::string(),
                     t.analyse, t.factorize, t.factorizations,
                     t.sparse_factorizations > 0
                         ? fmt::format(", {} of the bulk, the rest of the contact equations only",
                                       t.sparse_factorizations)
                         : std::string(),
                     t.reused_factorizations > 0 ? fmt::format(", {} reused", t.reused_factorizations) : std::string(),
                     t.solve, t.output);
}

/// The analysis' observer: the files first, then the caller's observer; keeps
/// the converged increments.
class Job::Recorder final : public AnalysisObserver {
 public:
  JobFiles* files = nullptr;
  AnalysisObserver* user = nullptr;
  std::shared_ptr<const Model> model;  ///< the model the kept increments belong to
  JobOptions::Keep keep = JobOptions::Keep::All;
  std::vector<JobIncrement>* kept = nullptr;
  /// The last increment whose results were written (step 0: none yet).
  int written_step = 0, written_increment = 0;
  double written_time = 0;

  void on_iteration(int i, const IterationNorms& n) override {
    if (files) files->on_iteration(i, n);
    if (user) user->on_iteration(i, n);
  }
  void on_increment(const IncrementReport& r) override {
    if (files) files->on_increment(r);
    if (user) user->on_increment(r);
  }
  void on_results(const IncrementResults& r, const Step& s, bool last) override {
    if (files) {
      files->on_results(r, s, last);
      written_step = r.step, written_increment = r.increment, written_time = r.total_time;
    }
    if (keep != JobOptions::Keep::None && !r.energies_only) {  // explicit reports with nothing due: not kept
      if (keep == JobOptions::Keep::Last) kept->clear();
      kept->push_back({model, r});
      kept->back().results.point_source = nullptr;  // stored results: the points are all there
    }
    if (user) user->on_results(r, s, last);
  }
  void on_restart_state(const RestartState& s) override {
    if (files) files->on_restart_state(s);
    if (user) user->on_restart_state(s);
  }
  void on_message(const std::string& m) override {
    if (files) files->on_message(m);
    if (user) user->on_message(m);
  }
};

namespace {

/// The first line of `text` (an exception's message may carry a traceback).
std::string first_line(const std::string& text) {
  const std::string line = text.substr(0, text.find('\n'));
  return line.empty() ? "an exception without a message" : line;
}

}  // namespace

std::string Job::stopped_verdict(const std::string& what) const {
  const std::string written =
      recorder_->written_step == 0
          ? "no increment was written by this run"
          : fmt::format("last increment written: step {} increment {}, time {:g}", recorder_->written_step,
                        recorder_->written_increment, recorder_->written_time);
  return "stopped by an exception: " + first_line(what) + "; " + written;
}

Job::Job(Model model, JobOptions options) : Job(std::make_shared<Model>(std::move(model)), std::move(options)) {}

Job::Job(std::shared_ptr<Model> model, JobOptions options)
    : model_(std::move(model)), options_(std::move(options)), recorder_(std::make_unique<Recorder>()) {
  if (!model_) throw std::invalid_argument("Job: the model is null");
}

Job::~Job() = default;

Model& Job::edit_model() {
  if (analysis_)
    throw std::logic_error("the job is prepared (prepare() or resume()): run it before changing its model");
  return *model_;
}

std::string Job::name() const {
  if (!options_.name.empty()) return options_.name;
  const std::string stem = std::filesystem::path(model_->deck_path).stem().string();
  return stem.empty() ? "job" : stem;
}

void Job::prepare() {
  if (analysis_) return;
  // Kept increments refer to the model: they get a copy that later edits do not reach.
  const bool keep = options_.keep != JobOptions::Keep::None;
  std::shared_ptr<const Model> model = keep ? std::make_shared<const Model>(*model_) : model_;
  AnalysisOptions analysis = options_.analysis;
  analysis.stream_element_results = !keep;  // kept increments hold every integration point
  analysis_ = std::make_unique<StaticAnalysis>(*model, *recorder_, analysis);
  run_model_ = std::move(model);
}

void Job::resume(const RestartState& state, const std::string& file) {
  prepare();
  analysis_->resume(state, file);
  resumed_ = state;
  resumed_file_ = file;
}

void Job::log(const std::string& message) { pending_log_.push_back(message); }

void Job::open_files() {
  files_ = std::make_unique<JobFiles>(*run_model_, options_.output_dir, name(), options_.writer,
                                      resumed_ ? &resumed_->output_state : nullptr, resumed_file_);
  for (const std::string& line : pending_log_) files_->log(line);
  pending_log_.clear();
}

JobSummary Job::run(AnalysisObserver* observer) {
  const auto t0 = options_.started.value_or(std::chrono::steady_clock::now());
  prepare();
  // The prepared analysis runs once; the next run prepares a new one.
  const std::unique_ptr<StaticAnalysis> analysis = std::move(analysis_);
  const std::shared_ptr<const Model> model = run_model_;
  results_.clear();
  files_.reset();
  if (!options_.output_dir.empty()) open_files();
  resumed_.reset();
  resumed_file_.clear();
  pending_log_.clear();

  *recorder_ = Recorder{};
  recorder_->files = files_.get();
  recorder_->user = observer;
  recorder_->model = model;
  recorder_->keep = options_.keep;
  recorder_->kept = &results_;
  JobSummary summary;
  try {
    static_cast<AnalysisSummary&>(summary) = analysis->run();
  } catch (const ModelError& e) {
    if (files_) files_->writer().finish(false, e.what());
    throw;
  } catch (const ResourceError& e) {
    if (files_)
      files_->writer().finish(false, std::string(e.what()) + "; the increments that converged before have been written");
    throw;
  } catch (const std::exception& e) {  // the observer's or a constraint callback's (Python, a plug-in)
    if (files_) {
      const std::string verdict = stopped_verdict(e.what());
      files_->log(verdict);
      files_->writer().finish(false, verdict);
    }
    throw;
  }
  summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (files_) {
    files_->log(summary.message);
    files_->log(timing_line(summary.seconds, summary.timing));
    files_->writer().finish(summary.completed, summary.message);
  }
  return summary;
}

std::vector<std::filesystem::path> Job::written_files() const {
  std::vector<std::filesystem::path> out;
  if (!files_) return out;
  const ResultWriter& w = files_->writer();
  for (const std::filesystem::path& f :
       {w.pvd_path(), w.dat_path(), w.sta_path(), files_->msg_path(), w.restart_path(), w.energy_path()})
    if (std::filesystem::exists(f)) out.push_back(f);
  return out;
}

}  // namespace tether
