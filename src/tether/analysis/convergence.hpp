#pragma once
/// \file ABAQUS-like convergence test for one Newton iteration.
///
/// Force rows: the largest residual must be below R_n times the time-averaged
/// force q (ABAQUS's q-tilde). Displacement: the largest correction must be
/// below C_n times the largest displacement increment of the increment, or
/// the next correction estimated from the residual ratio must be. A residual
/// below 1e-8 q is accepted at once (linear increment; at iteration 0 only
/// when it also meets R_n). Multiplier rows
/// (constraint values f - eps*lambda, in length units for the built-in
/// constraints) must be below 1e-10 times the model size.

#include <string>

#include "tether/model/model.hpp"

namespace tether {

/// Norms of one iteration, gathered by the Newton loop.
struct IterationNorms {
  double force_residual = 0;       ///< max |r| over free displacement equations
  double multiplier_residual = 0;  ///< max |r| over multiplier equations
  double correction = 0;           ///< max |du| of the last correction (displacements)
  double increment = 0;            ///< max |u - u_start| over displacement dofs
  double previous_force_residual = 0;  ///< of the previous iteration (0 on the first)
  /// Contact (summed over the pairs; contact_closed < 0 when the model has none),
  /// as found by the search before this iteration's residual:
  int contact_closed = -1;    ///< slave nodes in contact
  int contact_changes = 0;    ///< nodes whose branch (status open/stick/slip, slip direction, friction row) changed since the previous iteration
  int contact_repaired = 0;   ///< nodes paired with another master segment
  int contact_held = 0;       ///< nodes held by the contact guards (closed, in stick, on their segment)
};

class ConvergenceCriteria {
 public:
  ConvergenceCriteria(const Controls& controls, double length_scale);

  /// True when the iteration is converged. `iteration` counts solves done so far
  /// (0 = nothing solved yet) and `force_scale` is the time-averaged force q.
  [[nodiscard]] bool converged(const IterationNorms& n, int iteration, double force_scale) const;

  /// Force tolerance R_n * q (or the absolute floor when q is zero).
  [[nodiscard]] double force_tolerance(double force_scale) const;

 private:
  Controls controls_;
  double length_scale_;
};

}  // namespace tether
