#pragma once
/// \file Prescribed values and loads of one step, with their start and target values.

#include <map>
#include <utility>
#include <vector>

#include "tether/dofs/dof_map.hpp"
#include "tether/model/model.hpp"

namespace tether {

/// A magnitude ramped from `start` to `target` over the step, or `target`
/// times an amplitude.
struct RampedValue {
  double start = 0;
  double target = 0;
  int amplitude = -1;
  /// A prescribed velocity (*BOUNDARY, TYPE=VELOCITY): the magnitude above
  /// is the velocity, and the dof's value is `origin` (its value at the
  /// step's start) plus the magnitude's integral over the step time.
  bool velocity = false;
  double origin = 0;
};

/// The value of prescribed dof `v` at `step_time` (step_magnitude(), or for a
/// velocity the displacement it has integrated to).
double prescribed_value(const Model& model, const RampedValue& v, double step_time, double period, double total_time);

/// False when `v` keeps its dof where the step started (nothing moves it).
bool prescribed_moves(const RampedValue& v);

/// Everything that varies with time in one step.
struct StepLoads {
  std::vector<std::pair<int, RampedValue>> prescribed;  ///< global dof -> value
  std::vector<std::pair<int, RampedValue>> forces;      ///< global dof -> concentrated force (or moment)
  std::vector<std::pair<int, int>> force_keys;          ///< parallel to forces: (node, dof) as in the deck
  std::vector<PressureLoad> pressures;                  ///< faces loaded in this step (incl. ones being removed)
  std::vector<RampedValue> pressure_values;             ///< parallel to pressures
};

/// Builds the step's loads. `u` is the state at the start of the step (start
/// values of prescribed dofs); `cload_end` and `pressure_end` hold the
/// magnitudes at the end of the previous step (loads no longer listed are
/// ramped down to zero, as ABAQUS does in a static step). With
/// Step::ramp_loads false (AMPLITUDE=STEP) a value without an amplitude starts
/// at its target: applied (or removed) at the step's start and held.
/// (node, dof) map to global unknowns through `dofs` (dof 2 is a node's
/// rotation; ModelError when the node has none).
StepLoads make_step_loads(const Step& step, const DofMap& dofs, const Eigen::VectorXd& u,
                          const std::map<std::pair<int, int>, double>& cload_end,
                          const std::map<std::pair<int, int>, double>& pressure_end);

}  // namespace tether
