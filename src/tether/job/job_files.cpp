#include "tether/job/job_files.hpp"

#include <fmt/core.h>

namespace tether {

namespace {

bool load_history(ResultWriter& writer, const std::vector<double>* output_state, const std::string& restart_file) {
  if (!output_state) return false;
  try {
    writer.load_output_state(*output_state);
  } catch (const std::runtime_error& e) {
    throw InputError(SourceLocation{restart_file, 0}, e.what());
  }
  return true;
}

}  // namespace

JobFiles::JobFiles(const Model& model, const std::filesystem::path& directory, const std::string& job,
                   ResultWriterOptions options, const std::vector<double>* output_state,
                   const std::string& restart_file)
    : writer_(model, directory, job, options),
      history_loaded_(load_history(writer_, output_state, restart_file)),
      msg_path_(std::filesystem::path(writer_.sta_path()).replace_extension(".msg")),
      msg_(fmt::output_file(msg_path_.string())) {
  msg_.print("tether {} message log\n", TETHER_VERSION);
}

void JobFiles::on_iteration(int iteration, const IterationNorms& n) {
  msg_.print("    iteration {:2d}: max force residual {:.6e}  max constraint residual {:.6e}  "
             "max correction {:.6e}  max increment {:.6e}\n",
             iteration, n.force_residual, n.multiplier_residual, n.correction, n.increment);
  if (n.contact_closed >= 0)
    msg_.print("                  contact: {} closed, {} changed status, {} re-paired{}\n", n.contact_closed,
               n.contact_changes, n.contact_repaired,
               n.contact_held > 0 ? fmt::format(", {} held by the contact guards", n.contact_held) : "");
}

void JobFiles::on_increment(const IncrementReport& r) {
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
}

void JobFiles::on_results(const IncrementResults& results, const Step& step, bool last_in_step) {
  writer_.write_increment(results, step.outputs, last_in_step);
}

void JobFiles::on_restart_state(const RestartState& state) {
  writer_.write_restart(state);
  msg_.print("  restart state written to {} (step {}, increment {}{})\n", writer_.restart_path().string(), state.step,
             state.increment, state.step_completed ? ", end of the step" : "");
}

void JobFiles::on_message(const std::string& message) { msg_.print("  {}\n", message); }

void JobFiles::log(const std::string& message) {
  msg_.print("  {}\n", message);
  msg_.flush();
}

}  // namespace tether
