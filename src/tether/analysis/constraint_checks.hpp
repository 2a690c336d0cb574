#pragma once
/// \file Checks of the constraint set before a step is solved.
///
/// Caught here, with the constraints named: a constraint row whose gradient
/// vanishes on the free dofs (all its dofs prescribed, or f flat at the
/// start state), two linear constraints that are multiples of each other on
/// the free dofs (duplicate ties), and more multiplier equations than free
/// displacement dofs. Subtler dependence (a combination of several
/// constraints) is caught by the factorization, which names the multiplier.

#include <Eigen/Core>

#include "tether/analysis/discretization.hpp"
#include "tether/assembly/equation_map.hpp"

namespace tether {

/// Throws ModelError naming the constraint(s) and their deck lines.
void check_constraints(const Discretization& discretization, const EquationMap& equations,
                       const EvaluationState& state);

}  // namespace tether
