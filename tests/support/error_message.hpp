#pragma once
// Test helper: the message of the exception a callable throws.

#include <string>

#include "tether/core/error.hpp"

namespace tether::testing {

/// what() of the ModelError `f` throws, or "(no ModelError)".
template <class F>
std::string model_error_of(F&& f) {
  try {
    f();
  } catch (const ModelError& e) {
    return e.what();
  }
  return "(no ModelError)";
}

}  // namespace tether::testing
