#pragma once
/// \file Connects the analysis' reports to the result files and the terminal.

#include <fmt/core.h>
#include <fmt/os.h>

#include <filesystem>

#include "tether/analysis/analysis_observer.hpp"
#include "tether/output/result_writer.hpp"

namespace tether {

/// Writes results and status lines; keeps an ABAQUS-like message log
/// (`JOB.msg` next to `JOB.sta`: every iteration's norms, every attempt, and
/// messages such as cut-backs and augmented-Lagrangian updates); prints one
/// progress line per increment attempt when `progress` is set (a terminal).
class ProgressObserver final : public AnalysisObserver {
 public:
  ProgressObserver(ResultWriter& writer, bool progress)
      : writer_(writer),
        progress_(progress),
        msg_path_(std::filesystem::path(writer.sta_path()).replace_extension(".msg")),
        msg_(fmt::output_file(msg_path_.string())) {
    msg_.print("tether {} message log\n", TETHER_VERSION);
  }

  void on_iteration(int iteration, const IterationNorms& n) override {
    msg_.print("    iteration {:2d}: max force residual {:.6e}  max constraint residual {:.6e}  "
               "max correction {:.6e}  max increment {:.6e}\n",
               iteration, n.force_residual, n.multiplier_residual, n.correction, n.increment);
    if (n.contact_closed >= 0)
      msg_.print("                  contact: {} closed, {} changed status, {} re-paired{}\n", n.contact_closed,
                 n.contact_changes, n.contact_repaired,
                 n.contact_held > 0 ? fmt::format(", {} held by the contact guards", n.contact_held) : "");
  }

  void on_increment(const IncrementReport& r) override {
    if (r.attempt == 1) iterations_this_increment_ = 0;
    iterations_this_increment_ += r.iterations;
    IncrementStatus s;
    s.step = r.step;
    s.increment = r.increment;
    s.attempt = r.attempt;
    s.converged = r.converged;
    s.iterations = r.iterations;
    s.total_iterations = iterations_this_increment_;
    s.total_time = r.total_time;
    s.step_time = r.step_time;
    s.increment_size = r.increment_size;
    s.residual_norm = r.residual;
    writer_.write_status(s);
    // A failed attempt's reason follows once, in the message that cuts back
    // or in the verdict that stops the step.
    msg_.print("  step {} increment {} attempt {}: time {:.6g}, increment {:.6g}, {} iterations, {}\n", r.step,
               r.increment, r.attempt, r.total_time, r.increment_size, r.iterations,
               r.converged ? "converged" : "not converged");
    msg_.flush();
    if (progress_)
      fmt::print("step {} inc {:4d} att {} time {:.6g} dt {:.3g} iter {:2d} residual {:.3e} {}\n", r.step,
                 r.increment, r.attempt, r.total_time, r.increment_size, r.iterations, r.residual,
                 r.converged ? "" : "not converged");
  }

  void on_results(const IncrementResults& results, const Step& step, bool last_in_step) override {
    writer_.write_increment(results, step.outputs, last_in_step);
  }

  void on_restart_state(const RestartState& state) override {
    writer_.write_restart(state);
    msg_.print("  restart state written to {} (step {}, increment {}{})\n", writer_.restart_path().string(),
               state.step, state.increment, state.step_completed ? ", end of the step" : "");
  }

  void on_message(const std::string& message) override {
    msg_.print("  {}\n", message);
    if (progress_) fmt::print("  {}\n", message);
  }

  /// Writes `message` to the `.msg` only (what the caller prints itself, or
  /// keeps off the terminal).
  void log(const std::string& message) {
    msg_.print("  {}\n", message);
    msg_.flush();
  }

  [[nodiscard]] const std::filesystem::path& msg_path() const { return msg_path_; }

 private:
  ResultWriter& writer_;
  bool progress_;
  std::filesystem::path msg_path_;
  fmt::ostream msg_;
  int iterations_this_increment_ = 0;
};

}  // namespace tether
