#pragma once
/// \file Turns the model's constraint records into constraint functions.

#include <memory>

#include "tether/constraints/constraint_function.hpp"
#include "tether/dofs/dof_map.hpp"
#include "tether/model/model.hpp"

namespace tether {

/// The constraint function of `data` (Equation, Tie, Link, Slider,
/// Expression). Throws ModelError naming the deck line when it cannot be built
/// (coincident nodes), InputError for a malformed formula.
std::unique_ptr<ConstraintFunction> make_constraint_function(const Model& model, const ConstraintData& data,
                                                             const DofMap& dofs);

}  // namespace tether
