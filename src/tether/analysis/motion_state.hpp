#pragma once
/// \file What dynamic steps carry from increment to increment and from step to
/// step: velocities, accelerations and the energy bookkeeping.

#include <Eigen/Core>
#include <span>
#include <vector>

#include "tether/model/results.hpp"

namespace tether {

struct MotionState {
  /// A dynamic step has started: v holds the initial velocities (or those of
  /// the previous dynamic step), and the energy balance has its baseline.
  bool started = false;
  Eigen::VectorXd v;  ///< velocities over all unknowns (0 at multipliers) [length/time]
  Eigen::VectorXd a;  ///< accelerations over all unknowns (0 at multipliers) [length/time^2]
  /// HHT: the out-of-balance force S(u) - f_ext of the last converged state
  /// (without inertia and damping), over all unknowns [force].
  Eigen::VectorXd static_residual;
  /// The forces doing work at the last converged state: applied nodal forces,
  /// pressure resultants and reactions at prescribed dofs [force].
  Eigen::VectorXd work_force;
  /// The damping forces C v at the last converged state, over all unknowns [force].
  Eigen::VectorXd damping_force;
  EnergyTotals energy;       ///< at the last converged state
  double balance_start = 0;  ///< ETOTAL at the start of the first dynamic step

  /// Restart: appends the whole state to `out` (empty when no dynamic step has started).
  void save(std::vector<double>& out) const;
  /// Restart: reads what save() wrote for a model of `n_dofs` unknowns; false
  /// when `in` is not such a record (nothing is changed then).
  bool load(std::span<const double> in, Eigen::Index n_dofs);
};

}  // namespace tether
