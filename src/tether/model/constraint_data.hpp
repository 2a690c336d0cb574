#pragma once
/// \file Constraints as read from a deck (`*EQUATION`, `*MPC`, `*CONSTRAINT`, `*TIE`, `*PERIODIC`): plain data.

#include <memory>
#include <string>
#include <vector>

#include "tether/core/error.hpp"
#include "tether/model/external_constraint.hpp"

namespace tether {

/// How a constraint is enforced, chosen per constraint (tether extension
/// parameters ENFORCEMENT=, EPSILON=, PENALTY=, TOLERANCE= on the keyword).
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

/// One term `coefficient * u(node, dof)` of an `*EQUATION`.
struct EquationTerm {
  int node = 0;          ///< node index
  int dof = 0;           ///< 0 = x (r), 1 = y (z)
  double coefficient = 0;
};

/// One constraint of the model.
struct ConstraintData {
  enum class Kind {
    Equation,    ///< *EQUATION: sum of terms = 0
    Tie,         ///< *MPC TIE / PIN: u_a = u_b (both components)
    Link,        ///< *MPC LINK: |x_b - x_a| constant
    Slider,      ///< *MPC SLIDER: node a on the line through b and c
    User,        ///< *CONSTRAINT, TYPE=USER: residual and stiffness from a shared library
    Expression,  ///< *CONSTRAINT, TYPE=EXPRESSION: f given as formulas
    Linear,      ///< *TIE (one slave node) / *PERIODIC (one node pair): several equations `rows`, each sum = 0
    Beam,        ///< *MPC BEAM: node a rigidly attached to node b, which gets a rotation dof
    UserMpc,     ///< *MPC, USER: ABAQUS-style user routine (MODE=DOF or NODE) in a shared library
    External,    ///< computed by the program that built the model (`external`, e.g. Python callables)
  };
  Kind kind = Kind::Equation;
  std::string name;                   ///< NAME= or generated ("EQUATION-3", "MPC-2 LINK")
  std::vector<EquationTerm> terms;    ///< Equation
  std::vector<std::vector<EquationTerm>> rows;  ///< Linear: one list of terms per equation (sum of terms = 0)
  std::vector<int> nodes;             ///< MPC / User / Expression: node indices in the order given
  std::vector<std::string> formulas;  ///< Expression: one per equation
  std::vector<SourceLocation> formula_where;  ///< Expression: the deck line of each formula
  std::string library;                ///< User: path of the shared library (relative to the deck)
  std::string symbol;                 ///< User: function name
  std::vector<double> properties;     ///< User: property list
  int n_multipliers = 1;              ///< User: multipliers the routine expects
  int flag = 0;                       ///< User: passed to the routine; UserMpc: JTYPE
  bool node_mode = false;             ///< UserMpc: MODE=NODE (several dofs of the first node), else MODE=DOF
  std::shared_ptr<const ExternalConstraint> external;  ///< External: the function (over the x, y of `nodes`)
  Enforcement enforcement;
  SourceLocation where;

  /// The node indices the constraint acts on: `nodes`, or the nodes of the terms.
  [[nodiscard]] std::vector<int> nodes_or_terms() const {
    if (!nodes.empty()) return nodes;
    std::vector<int> out;
    for (const auto& t : terms) out.push_back(t.node);
    return out;
  }
};

}  // namespace tether
