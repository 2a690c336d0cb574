#pragma once
/// \file The first iteration of an increment whose prescribed values move and
/// which has no extrapolation to start from: the start-of-increment tangent
/// applied to the prescribed values' change (as CalculiX and ABAQUS take it).
/// See docs/theory/newton.md, "The start-tangent predictor".

#include <Eigen/Core>

#include "tether/analysis/increment_problem.hpp"
#include "tether/analysis/step_system.hpp"

namespace tether {

/// True when the predictor applies to `system`: a nonlinear bulk
/// (!bulk_linear(): for a linear one Newton's first iteration is already
/// exact) and no contact (contact pairs keep iteration statistics and active
/// sets that an evaluation at the start state would disturb).
[[nodiscard]] bool start_tangent_predictor_applies(const StepSystem& system);

/// `u` holds the converged state `u_start` with the prescribed (and
/// dependent) dofs moved to their values at the end of the increment, the
/// free dofs unchanged; `external` the nodal forces at the end of the
/// increment, `time` its times. Moves the free dofs by the solution of
///   K_ff(u_start) du_f = -(r_f(u_start) + [K(u_start) du_p]_f),
/// the linearisation at the converged state of the residual at the end of
/// the increment, with du_p = u - u_start on the prescribed dofs: the whole
/// body follows the prescribed values (the start tangent) instead of the
/// elements next to them taking all of their change. Returns false, `u`
/// unchanged, when nothing prescribed moves or the start tangent is singular.
/// Uses the step's assembler and linear solver (analysed here on the
/// assembler's pattern, the one Newton factorizes next). Element failures
/// (ModelError) propagate.
bool apply_start_tangent_predictor(StepSystem& system, const IncrementTime& time, const Eigen::VectorXd& u_start,
                                   const Eigen::VectorXd& external, Eigen::VectorXd& u);

}  // namespace tether
