#pragma once
/// \file Names of the enforcement methods (the struct is model data).

#include <string>

#include "tether/model/constraint_data.hpp"

namespace tether {

/// "LAGRANGE", "PENALTY", "AUGMENTED LAGRANGE", "ELIMINATION".
std::string to_string(Enforcement::Method method);

}  // namespace tether
