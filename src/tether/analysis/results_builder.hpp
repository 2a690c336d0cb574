#pragma once
/// \file Collects the results of a converged increment from the elements.

#include "tether/analysis/discretization.hpp"
#include "tether/assembly/equation_map.hpp"
#include "tether/model/results.hpp"

namespace tether {

/// Displacements and reactions per node, integration-point values per element
/// and nodal averages of the values extrapolated from each element.
/// `residual` is the full residual (reactions are read at prescribed dofs).
IncrementResults build_results(const Discretization& discretization, const EvaluationState& state,
                               const Eigen::VectorXd& residual, const EquationMap& equations);

}  // namespace tether
