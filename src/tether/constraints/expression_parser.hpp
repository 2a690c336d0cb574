#pragma once
/// \file Internal to ExpressionConstraint (not installed): the formula
/// language on GiNaC — variables, parse errors and the parser.

#include <ginac/ginac.h>

#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "tether/constraints/expression_constraint.hpp"

namespace tether::expression {

using GiNaC::ex;
using GiNaC::numeric;

/// A mistake in one formula; ExpressionConstraint adds file, line and formula number.
class FormulaError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The symbols a formula may use.
struct Variables {
  std::span<const ExpressionNode> nodes;
  std::vector<GiNaC::symbol> displacement;  ///< U1, V1, U2, V2, ... (2 per node)
  GiNaC::symbol total_time{"T"}, step_time{"TSTEP"};

  [[nodiscard]] std::string expected() const {
    return "expected Xk, Yk, Uk, Vk for k = 1.." + std::to_string(nodes.size()) + ", T or TSTEP";
  }
};

/// The GiNaC expression of `formula`; reference coordinates Xk, Yk are
/// replaced by their numbers. Throws FormulaError naming the bad token.
ex parse(const std::string& formula, const Variables& vars);

/// True when `e` contains no symbol.
bool is_constant(const ex& e);
/// True for a real GiNaC number.
bool is_real_number(const ex& x);
/// `e` as GiNaC prints it.
std::string text(const ex& e);

}  // namespace tether::expression
