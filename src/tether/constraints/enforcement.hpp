#pragma once
/// \file How a constraint is enforced, chosen per constraint.

#include <string>

namespace tether {

/// Enforcement method and its parameters.
struct Enforcement {
  enum class Method {
    Lagrange,     ///< multipliers as unknowns; f - epsilon*lambda = 0 (regularised when epsilon > 0)
    Penalty,      ///< energy rho/2 |f|^2: the force is lambda = rho f, no extra unknowns
    Augmented,    ///< penalty rho plus Uzawa updates lambda += rho f until |f| <= tolerance
    Elimination,  ///< dependent dofs written in terms of independent ones (linear constraints)
  };
  Method method = Method::Lagrange;
  double epsilon = 0;      ///< regularisation [f units / multiplier units], >= 0
  double penalty = 0;      ///< rho [multiplier units / f units], > 0 for Penalty and Augmented
  double tolerance = 0;    ///< Augmented: |f| that ends the Uzawa updates [f units]; 0 = 1e-8 * model size
  int max_updates = 100;   ///< Augmented: Uzawa updates per increment before giving up
};

/// "LAGRANGE", "PENALTY", "AUGMENTED LAGRANGE", "ELIMINATION".
std::string to_string(Enforcement::Method method);

}  // namespace tether
