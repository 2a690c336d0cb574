#pragma once
/// \file The body loads (`*DLOAD` GRAV, CENTRIF) of one step: their ramps over
/// the step and one BodyForce contribution per loaded element and kind.
///
/// Everything here follows from the model alone: the value a load starts a
/// step from is its value at the end of the previous step, which the model
/// determines (the target times the amplitude at the step's end, or the
/// target). So nothing is carried between steps or saved for a restart.

#include <memory>
#include <vector>

#include "tether/analysis/discretization.hpp"
#include "tether/analysis/step_loads.hpp"
#include "tether/elements/body_force.hpp"
#include "tether/model/model.hpp"

namespace tether {

/// One body load of a step and its magnitude over the step.
struct StepBodyLoad {
  BodyLoad load;
  RampedValue value;  ///< of load.magnitude (g or omega^2)
};

/// The body loads in force in step `step_index` (0-based), with their start
/// values (the values at the end of the previous step) and targets. A load of
/// the previous step that this step no longer lists is ramped down to zero,
/// as ABAQUS does in a static step (entries with target 0 and no amplitude).
/// Loads are identified by (element, kind).
std::vector<StepBodyLoad> step_body_loads(const Model& model, int step_index);

/// The BodyForce contributions of one step and their magnitudes.
class StepBodyForces {
 public:
  /// Throws ModelError naming the *DLOAD line when an element's material has
  /// no *DENSITY (the reader refuses such decks first), or the element's mass
  /// cannot be integrated.
  StepBodyForces(const Discretization& discretization, int step_index);

  /// One per loaded element and kind, in the order of step_body_loads().
  [[nodiscard]] const std::vector<std::unique_ptr<BodyForce>>& forces() const { return forces_; }
  [[nodiscard]] const std::vector<StepBodyLoad>& loads() const { return loads_; }

  /// Sets every magnitude at this time of the step (as the step's other loads:
  /// step_magnitude()).
  void set_time(double step_time, double period, double total_time);

 private:
  const Model& model_;
  std::vector<StepBodyLoad> loads_;
  std::vector<std::unique_ptr<BodyForce>> forces_;
};

}  // namespace tether
