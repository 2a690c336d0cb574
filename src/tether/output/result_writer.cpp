#include "tether/output/result_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>

#include "tether/output/output_schedule.hpp"
#include "tether/output/restart_file.hpp"

namespace tether {

namespace {

/// True for "JOB_<step>_<increment>.vtu".
bool is_increment_vtu(const std::string& name, const std::string& job) {
  if (name.size() <= job.size() + 5 || name.compare(0, job.size() + 1, job + "_") != 0 || !name.ends_with(".vtu"))
    return false;
  const std::string middle = name.substr(job.size() + 1, name.size() - job.size() - 5);
  const auto sep = middle.find('_');
  const auto digits = [](std::string_view t) {
    return !t.empty() && std::all_of(t.begin(), t.end(), [](char c) { return c >= '0' && c <= '9'; });
  };
  return sep != std::string::npos && digits(std::string_view(middle).substr(0, sep)) &&
         digits(std::string_view(middle).substr(sep + 1));
}

/// Removes what an earlier run of `job` left in `directory` and this run would
/// not replace: its .vtu files, .pvd, restart file and energy history.
void remove_earlier_results(const std::filesystem::path& directory, const std::string& job) {
  namespace fs = std::filesystem;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(directory.empty() ? fs::path(".") : directory, ec))
    if (entry.is_regular_file() && is_increment_vtu(entry.path().filename().string(), job)) fs::remove(entry.path());
  for (const char* extension : {".pvd", ".rst", "_energy.csv", "_energy.png"}) fs::remove(directory / (job + extension));
}

std::filesystem::path prepared(const std::filesystem::path& directory, const std::string& job) {
  if (!directory.empty()) std::filesystem::create_directories(directory);
  remove_earlier_results(directory, job);
  return directory;
}

}  // namespace

ResultWriter::ResultWriter(const Model& model, const std::filesystem::path& directory, const std::string& job,
                           ResultWriterOptions options)
    : directory_(prepared(directory, job)),
      job_(job),
      options_(options),
      vtu_(model, options.encoding),
      pvd_(directory_ / (job + ".pvd")),
      dat_(model, directory_ / (job + ".dat")),
      status_(directory_ / (job + ".sta"), job, dialect_name(model.dialect)) {}

std::filesystem::path ResultWriter::vtu_path(int step, int increment) const {
  return directory_ / fmt::format("{}_{}_{}.vtu", job_, step, increment);
}

void ResultWriter::write_increment(const IncrementResults& results, const std::vector<OutputRequest>& requests,
                                   bool last_in_step) {
  dat_.write_increment(results, requests, last_in_step);
  if (results.energy) write_energy_row(results);
  if (!options_.write_vtu || !files_due(requests, procedure_of(results), results, last_in_step)) return;
  const auto file = vtu_path(results.step, results.increment);
  vtu_.write(results, file);
  pvd_.add(results.total_time, file.filename().string());
}

void ResultWriter::write_energy_row(const IncrementResults& results) {
  const auto file = energy_path();
  const bool fresh = !energy_started_;
  std::ofstream out(file, fresh ? std::ios::trunc : std::ios::app);
  if (fresh) out << "step,increment,time,ALLKE,ALLSE,ALLWK,ALLFD,ALLVD,ALLPD,NUMERICAL,ETOTAL\n";
  const EnergyTotals& e = *results.energy;
  out << fmt::format("{},{},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n", results.step,
                     results.increment, results.total_time, e.kinetic, e.strain, e.work, e.friction, e.viscous,
                     e.plastic, e.numerical, e.total);
  if (!out) throw std::runtime_error("error while writing '" + file.string() + "' (disk full?)");
  energy_started_ = true;
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
