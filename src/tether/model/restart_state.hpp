#pragma once
/// \file The state saved for a restart (`*RESTART, WRITE`): everything the
/// step loop needs to continue an analysis from its last converged increment
/// exactly as an uninterrupted run would. Plain data; StaticAnalysis fills it
/// (restart_state()) and continues from it (resume()); output/restart_file
/// writes and reads it (binary, doubles bitwise).

#include <cstdint>
#include <string>
#include <vector>

namespace tether {

/// What identifies the model a state belongs to. A state is only continued by
/// a deck whose fingerprint is equal (the load history only up to the saved step).
struct RestartFingerprint {
  std::int64_t nodes = 0;
  std::int64_t elements = 0;
  std::int64_t dofs = 0;           ///< all unknowns: displacements, rotations, multipliers
  std::int64_t multipliers = 0;
  std::int64_t contributions = 0;  ///< elements, constraints, user constraints, contact pairs
  std::uint64_t nodes_hash = 0;    ///< node labels and reference coordinates (bitwise)
  std::uint64_t elements_hash = 0; ///< element labels, types and connectivity
  std::uint64_t history_hash = 0;  ///< steps 1..history_steps: their load history (see restart_fingerprint())
  std::int64_t history_steps = 0;
};

/// A load magnitude carried from one step to the next ((node, dof) or (element, face)).
struct CarriedLoad {
  std::int64_t first = 0, second = 0;
  double value = 0;
};

/// The saved state of one contribution (Contribution::save_state), by its
/// index in the discretization's order: elements, constraints, user
/// constraints, contact pairs. Stateless contributions have no record.
struct ContributionState {
  std::int64_t index = 0;
  std::vector<double> values;
};

struct RestartState {
  std::string written_by;  ///< "tether <version>" (information)
  std::string deck;        ///< the deck of the run that wrote it (information)
  RestartFingerprint fingerprint;

  // --- position: the last converged increment ---
  int step = 0;                 ///< 1-based step of the last converged increment
  int increment = 0;            ///< its number within that step
  bool step_completed = false;  ///< true: the step ended there; continue with step + 1
  double step_time = 0;         ///< at that increment
  double step_start_time = 0;   ///< total time at the start of the step
  double total_time = 0;
  // --- time stepping of the step in progress (used when !step_completed) ---
  double dt = 0;                ///< size of the next increment
  int easy_in_row = 0;          ///< easy increments in a row (growth after two)
  double averaged_force = 0;    ///< time average of the force scale q over the step's increments
  int n_averaged = 0;
  /// Static steps: the displacement change of the last converged increment
  /// (displacement dofs; empty at a step's start) and its size, which the
  /// next increment's predictor extrapolates.
  std::vector<double> predictor_increment;
  double predictor_dt = 0;
  // --- counters of the whole analysis (so logs and summaries continue) ---
  int steps_completed = 0;
  int increments = 0;
  int iterations = 0;
  int cutbacks = 0;

  std::vector<double> u;             ///< all unknowns at the last converged increment
  std::vector<double> u_step_start;  ///< ... at the start of the step (start values of prescribed dofs)
  std::vector<CarriedLoad> cload_end;     ///< (node, dof) -> magnitude at the end of the previous step
  std::vector<CarriedLoad> pressure_end;  ///< (element, face) -> magnitude at the end of the previous step
  std::vector<ContributionState> contributions;
  /// Dynamic steps: velocities, accelerations, HHT's residual and the energy
  /// bookkeeping (MotionState::save); empty before the first dynamic step.
  std::vector<double> motion;
  /// The result writer's own history (the .dat CDIS sums): filled by the
  /// writer when it writes the file, opaque to the analysis; may be empty.
  std::vector<double> output_state;
};

}  // namespace tether
