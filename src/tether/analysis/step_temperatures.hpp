#pragma once
/// \file Nodal temperatures over the steps of an analysis (`*INITIAL
/// CONDITIONS, TYPE=TEMPERATURE` and `*TEMPERATURE`), as ABAQUS applies them.
///
/// Before the first step every node has its initial temperature (0 when none
/// is given). In a step, a node listed by `*TEMPERATURE` goes to its value:
/// value * a(t) with an amplitude, else ramped from its temperature at the
/// start of the step over the step period (AMPLITUDE=RAMP, the default of
/// static steps) or applied at the step's start (AMPLITUDE=STEP, the default
/// of dynamic steps). A node not listed keeps its temperature; with OP=NEW it
/// returns to its initial temperature in the same way. The temperatures are a
/// pure function of the times, so cut-backs and restarts need no state.

#include <vector>

#include "tether/model/model.hpp"

namespace tether {

class StepTemperatures final : public NodalTemperatureField {
 public:
  /// `model` must outlive the object; the step start times are the sums of
  /// the earlier steps' periods.
  explicit StepTemperatures(const Model& model);

  /// The step is the last one that starts at or before total_time - step_time
  /// (before the first step: the initial temperatures).
  [[nodiscard]] double current(int node, double step_time, double total_time) const override;
  [[nodiscard]] double initial(int node) const override { return initial_[static_cast<std::size_t>(node)]; }

  /// All nodal temperatures at the times (for output), indexed by node.
  [[nodiscard]] std::vector<double> all(double step_time, double total_time) const;

 private:
  /// Temperature of `node` in step k at the given step time.
  [[nodiscard]] double in_step(std::size_t k, int node, double step_time, double total_time) const;

  const Model& model_;
  std::vector<double> initial_;                  ///< per node
  std::vector<double> step_start_;               ///< total time at the start of each step
  std::vector<std::vector<double>> start_;       ///< per step, per node: temperature at the step's start
  std::vector<std::vector<int>> listed_;         ///< per step, per node: index into the step's values or -1 (empty: none)
};

}  // namespace tether
