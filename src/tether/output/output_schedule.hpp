#pragma once
/// \file When an output request is due.

#include "tether/model/model.hpp"

namespace tether {

/// True when `request` writes at increment `increment` (1-based, within its
/// step): never when its frequency is 0 or less; otherwise at every
/// frequency-th increment and always at the last increment of the step.
bool is_due(const OutputRequest& request, int increment, bool last_in_step);

}  // namespace tether
