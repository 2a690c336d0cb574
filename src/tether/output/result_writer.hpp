#pragma once
/// \file The one object the analysis talks to for output: ParaView files,
/// the `.dat` report and the `.sta` status file of a job.

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "tether/model/model.hpp"
#include "tether/model/restart_state.hpp"
#include "tether/model/results.hpp"
#include "tether/output/dat_writer.hpp"
#include "tether/output/pvd_writer.hpp"
#include "tether/output/status_writer.hpp"
#include "tether/output/vtu_writer.hpp"

namespace tether {

/// Choices of the result files.
struct ResultWriterOptions {
  VtuEncoding encoding = VtuEncoding::Base64;  ///< Ascii for debugging only
  bool write_vtu = true;                       ///< false: no .vtu/.pvd at all
};

/// Writes all result files of one job into one directory:
/// - `DIR/JOB_<step>_<increment>.vtu` per written increment and the
///   collection `DIR/JOB.pvd` listing them with their total times (both
///   replaced atomically, so the `.pvd` is valid at every moment);
/// - `DIR/JOB.dat`: `*NODE PRINT` / `*EL PRINT` / `*CONTACT PRINT` output in
///   CalculiX's layout (see DatWriter);
/// - `DIR/JOB.sta`: one line per increment attempt and a final verdict;
/// - `DIR/JOB_energy.csv`: the energies of dynamic increments;
/// - `DIR/JOB.rst`: the restart state (`*RESTART, WRITE`), replaced atomically.
///
/// A `.vtu` is written for every increment, unless the step's requests
/// contain `*NODE FILE` / `*EL FILE` / `*CONTACT FILE` (or `*CONTACT
/// OUTPUT`) entries: then only when one of them is due (see is_due(); the
/// last increment of a step always is, unless all have FREQUENCY=0). The
/// `.vtu` always holds every field (the CONTACT_* arrays whenever the model
/// has contact pairs); the variables listed under these keywords do not
/// select fields.
///
/// The constructor creates DIR when needed, truncates JOB.dat and JOB.sta and
/// removes what an earlier run of JOB left there (JOB_<s>_<i>.vtu, JOB.pvd,
/// JOB.rst), so that the directory holds this run's results only; files of
/// other jobs are left alone. A restart therefore needs a directory of its own
/// (`tether run --restart` picks one).
/// The Model must outlive the writer and not change. Errors: std::runtime_error
/// (I/O), InputError (bad print request), std::invalid_argument (results
/// sized wrongly for the mesh).
class ResultWriter {
 public:
  ResultWriter(const Model& model, const std::filesystem::path& directory, const std::string& job,
               ResultWriterOptions options = {});

  /// Writes one converged increment. `requests` are the step's output
  /// requests (Step::outputs); `last_in_step` marks the step's final
  /// increment, which every request with FREQUENCY > 0 writes.
  void write_increment(const IncrementResults& results, const std::vector<OutputRequest>& requests,
                       bool last_in_step);

  /// Replaces `DIR/JOB.rst` with `state` and this writer's own history
  /// (RestartState::output_state), atomically (see write_restart_file).
  void write_restart(const RestartState& state);

  /// Restart: continues the history a writer saved with write_restart (the
  /// .dat CDIS sums); std::runtime_error when `output_state` is malformed.
  void load_output_state(std::span<const double> output_state);

  /// Appends one line to the `.sta` file (converged or cut-back attempt).
  void write_status(const IncrementStatus& status);

  /// Writes the final `.sta` line: completed, or why the analysis stopped
  /// (`message`). Call once, also after an error; later calls do nothing.
  void finish(bool completed, const std::string& message);

  /// Path of the `.vtu` written for (step, increment).
  [[nodiscard]] std::filesystem::path vtu_path(int step, int increment) const;
  [[nodiscard]] const std::filesystem::path& pvd_path() const { return pvd_.file(); }
  [[nodiscard]] const std::filesystem::path& dat_path() const { return dat_.file(); }
  [[nodiscard]] const std::filesystem::path& sta_path() const { return status_.file(); }
  /// `DIR/JOB_energy.csv`: one row per converged increment of a dynamic step
  /// (step, increment, total time, ALLKE, ALLSE, ALLWK, ALLFD, ALLVD,
  /// NUMERICAL, ETOTAL; EnergyTotals), written from the first such increment on.
  [[nodiscard]] std::filesystem::path energy_path() const { return directory_ / (job_ + "_energy.csv"); }
  [[nodiscard]] std::filesystem::path restart_path() const { return directory_ / (job_ + ".rst"); }

 private:
  /// Appends the increment's energies to energy_path() (creating it at the first).
  void write_energy_row(const IncrementResults& results);

  std::filesystem::path directory_;
  std::string job_;
  ResultWriterOptions options_;
  VtuWriter vtu_;
  PvdWriter pvd_;
  DatWriter dat_;
  StatusWriter status_;
  bool energy_started_ = false;  ///< energy_path() has been created by this writer
};

}  // namespace tether
