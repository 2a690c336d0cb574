#pragma once
/// \file `*CONSTRAINT, TYPE=EXPRESSION`: a constraint f(u, t) = 0 written as a formula.
///
/// Each formula is parsed once (by a small recursive-descent parser of our own,
/// so that errors can name the offending token and column), turned into a
/// GiNaC expression with the nodes' reference coordinates substituted, and
/// differentiated exactly, once and twice, with respect to the displacement
/// variables. f, the gradient and the Hessians are then compiled into one
/// straight-line register program with common subexpressions shared, which
/// evaluate() runs numerically: no finite differences and no symbolic work
/// during the solve. See docs/expression_constraints.md.
///
/// Variables (case-insensitive, like everything in an ABAQUS deck), with k the
/// 1-based position of a node in the constraint's node list:
///   Xk, Yk  reference coordinates of node k [length] (constants),
///   Uk, Vk  displacement components of node k [length] (the unknowns),
///   T       total time, TSTEP  step time.
/// Functions: sin cos tan asin acos atan atan2(y,x) sinh cosh tanh exp
/// log (= ln, natural) sqrt abs pow(a,b); operators + - * / ^ (also **);
/// constant pi.
///
/// Construction uses GiNaC, which is not thread-safe: build constraints on one
/// thread. evaluate() does not touch GiNaC and may run on many threads.

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "tether/constraints/constraint_function.hpp"
#include "tether/core/error.hpp"

namespace tether {

/// One node a formula refers to: its position k (1-based) in the constraint's
/// node list gives the variable names Xk, Yk, Uk, Vk.
struct ExpressionNode {
  int label = 0;                                     ///< node label in the deck (for messages)
  Eigen::Vector2d reference = Eigen::Vector2d::Zero();  ///< reference coordinates [length]
  std::array<int, 2> dofs{};                         ///< global x and y displacement dofs
};

class ExpressionConstraint final : public ConstraintFunction {
 public:
  /// `formulas`: one string per equation (m >= 1). `where` is the deck line
  /// of the keyword; `formula_locations`, when given (one per formula), is
  /// the deck line of each formula and is used in its messages instead.
  /// `description` names the constraint in messages, e.g.
  /// "*CONSTRAINT, TYPE=EXPRESSION" or "*CONSTRAINT NAME=hinge".
  ///
  /// Throws InputError naming the file, line, formula and offending token when
  /// a formula is empty or does not parse, uses an unknown variable or
  /// function, refers to a node number outside 1..nodes.size(), has a
  /// non-real or infinite constant part (e.g. 1/(X1-X2) with X1 = X2), or
  /// does not depend on any displacement.
  ExpressionConstraint(std::vector<std::string> formulas, std::vector<ExpressionNode> nodes, SourceLocation where,
                       std::string description, std::vector<SourceLocation> formula_locations = {});

  /// The x and y dofs of every node, in node order (2 per node).
  [[nodiscard]] std::span<const int> dofs() const override { return dofs_; }
  [[nodiscard]] int n_equations() const override { return static_cast<int>(formulas_.size()); }
  /// Runs the compiled program; values where a derivative does not exist
  /// (sqrt or log at 0, ...) come out non-finite, as the formula says.
  void evaluate(const ConstraintInput& in, ConstraintOutput& out, bool need_hessian) const override;
  /// True when every gradient entry is a constant (f affine in the U/V
  /// variables, with coefficients that depend neither on them nor on time).
  [[nodiscard]] bool linear() const override { return linear_; }
  [[nodiscard]] std::string describe() const override { return description_; }

  [[nodiscard]] const std::vector<std::string>& formulas() const { return formulas_; }
  /// Instructions in the compiled program (f and gradient, then Hessians).
  [[nodiscard]] int n_instructions() const { return static_cast<int>(program_.size()); }

 private:
  enum class Op : std::uint8_t;  ///< operations of the compiled program (defined in the .cpp)
  struct Instruction {
    Op op;
    int a = 0, b = 0;  ///< operand registers (b: the exponent of an integer power)
  };
  struct Entry {
    int equation, row, column, reg;  ///< out.f / gradient / hessian entry <- register
  };
  class Compiler;  ///< GiNaC expressions -> program (in the .cpp, so GiNaC stays private)

  std::vector<std::string> formulas_;
  std::vector<ExpressionNode> nodes_;
  std::string description_;
  std::vector<int> dofs_;
  bool linear_ = true;

  // Registers: [u (n), total time, step time, constants..., instruction results...].
  int n_inputs_ = 0;
  std::vector<double> constants_;
  std::vector<Instruction> program_;
  int n_first_order_ = 0;  ///< leading instructions enough for f and the gradient
  std::vector<Entry> values_, gradient_, hessian_;  ///< hessian_: upper triangle (row <= column)
};

}  // namespace tether
