#pragma once
/// \file Temperatures as read from a deck (`*INITIAL CONDITIONS, TYPE=TEMPERATURE`,
/// `*TEMPERATURE`) and the interface through which elements read nodal
/// temperatures during an analysis. Plain data; the evaluation over time is
/// in analysis/step_temperatures.hpp. See docs/theory/thermal_stress.md.

#include <vector>

#include "tether/core/error.hpp"

namespace tether {

/// One node's temperature: an initial value, or a step's target value.
struct NodeTemperature {
  int node = 0;        ///< node index
  double value = 0;    ///< [temperature]
  int amplitude = -1;  ///< index into Model::amplitudes or -1 (step values only)
  SourceLocation where;
};

/// The `*TEMPERATURE` data of one step. Nodes not listed keep the
/// temperature they had at the end of the previous step (their initial
/// temperature before the first step), as in ABAQUS; with `reset` (OP=NEW)
/// they return to their initial temperature instead, over the step like a
/// removed load.
struct StepTemperatureData {
  std::vector<NodeTemperature> values;  ///< one entry per node (the last given wins)
  bool reset = false;                   ///< OP=NEW in this step
};

/// Nodal temperatures during an analysis, as a pure function of time: what a
/// continuum element reads to compute its thermal strain and its
/// temperature-dependent elastic constants.
class NodalTemperatureField {
 public:
  virtual ~NodalTemperatureField() = default;
  /// Temperature of node `node` (index) at the given step and total times
  /// (the step is the one that started at total_time - step_time).
  [[nodiscard]] virtual double current(int node, double step_time, double total_time) const = 0;
  /// Initial temperature of node `node` (0 when none was given).
  [[nodiscard]] virtual double initial(int node) const = 0;
};

}  // namespace tether
