#include "tether/output/result_writer.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "tether/output/output_schedule.hpp"
#include "tether/output/restart_file.hpp"

namespace tether {

namespace {

std::filesystem::path prepared(const std::filesystem::path& directory) {
  if (!directory.empty()) std::filesystem::create_directories(directory);
  return directory;
}

bool vtu_due(const std::vector<OutputRequest>& requests, int increment, bool last_in_step) {
  const auto is_file = [](const OutputRequest& r) {
    return r.kind == OutputRequest::Kind::NodeFile || r.kind == OutputRequest::Kind::ElementFile ||
           r.kind == OutputRequest::Kind::ContactFile;
  };
  if (std::none_of(requests.begin(), requests.end(), is_file)) return true;
  return std::any_of(requests.begin(), requests.end(), [&](const OutputRequest& r) {
    return is_file(r) && is_due(r, increment, last_in_step);
  });
}

}  // namespace

ResultWriter::ResultWriter(const Model& model, const std::filesystem::path& directory, const std::string& job,
                           ResultWriterOptions options)
    : directory_(prepared(directory)),
      job_(job),
      options_(options),
      vtu_(model, options.encoding),
      pvd_(directory_ / (job + ".pvd")),
      dat_(model, directory_ / (job + ".dat")),
      status_(directory_ / (job + ".sta"), job) {}

std::filesystem::path ResultWriter::vtu_path(int step, int increment) const {
  return directory_ / fmt::format("{}_{}_{}.vtu", job_, step, increment);
}

void ResultWriter::write_increment(const IncrementResults& results, const std::vector<OutputRequest>& requests,
                                   bool last_in_step) {
  dat_.write_increment(results, requests, last_in_step);
  if (!options_.write_vtu || !vtu_due(requests, results.increment, last_in_step)) return;
  const auto file = vtu_path(results.step, results.increment);
  vtu_.write(results, file);
  pvd_.add(results.total_time, file.filename().string());
}

void ResultWriter::write_restart(const RestartState& state) {
  RestartState with_output = state;
  with_output.output_state.clear();
  dat_.save_state(with_output.output_state);
  write_restart_file(restart_path(), with_output);
}

void ResultWriter::load_output_state(std::span<const double> output_state) {
  if (!output_state.empty()) dat_.load_state(output_state);
}

void ResultWriter::write_status(const IncrementStatus& status) { status_.write(status); }

void ResultWriter::finish(bool completed, const std::string& message) { status_.finish(completed, message); }

}  // namespace tether
