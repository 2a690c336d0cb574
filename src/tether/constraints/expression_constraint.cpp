#include "tether/constraints/expression_constraint.hpp"

#include "tether/constraints/expression_parser.hpp"

#include <ginac/ginac.h>

#include <algorithm>
#include <cassert>
#include <cctype>
#include <cmath>
#include <cstring>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace tether {

enum class ExpressionConstraint::Op : std::uint8_t {
  Add, Sub, Mul, Div, Pow, Atan2,  // binary: registers a and b
  Neg, Recip, Square, PowInt, Sqrt, Sin, Cos, Tan, Asin, Acos, Atan, Sinh, Cosh, Tanh, Exp, Log, Abs, Sign,
};


using namespace expression;

// ---------------------------------------------------------------------------
// GiNaC expression -> straight-line register program, sharing common
// subexpressions. Registers are numbered provisionally (inputs, constants
// tagged kConstant, results tagged kResult) and relocated by finish().

class ExpressionConstraint::Compiler {
 public:
  Compiler(std::map<ex, int, GiNaC::ex_is_less> inputs, int n_inputs)
      : memo_(std::move(inputs)), n_inputs_(n_inputs) {}

  /// Register holding the value of `e`.
  int reg(const ex& e) {
    if (const auto it = memo_.find(e); it != memo_.end()) return it->second;
    const int r = build(e);
    memo_.emplace(e, r);
    return r;
  }

  [[nodiscard]] int size() const { return static_cast<int>(program_.size()); }

  /// Moves the program into `c` with final register numbers.
  void finish(ExpressionConstraint& c) {
    const int n_constants = static_cast<int>(constants_.size());
    const auto relocate = [&](int r) {
      if (r >= kResult) return n_inputs_ + n_constants + (r - kResult);
      if (r >= kConstant) return n_inputs_ + (r - kConstant);
      return r;
    };
    for (Instruction& i : program_) {
      i.a = relocate(i.a);
      if (i.op <= Op::Atan2) i.b = relocate(i.b);
    }
    for (auto* entries : {&c.values_, &c.gradient_, &c.hessian_})
      for (Entry& e : *entries) e.reg = relocate(e.reg);
    c.n_inputs_ = n_inputs_;
    c.constants_ = std::move(constants_);
    c.program_ = std::move(program_);
  }

 private:
  static constexpr int kConstant = 1 << 28, kResult = 1 << 29;

  int emit(Op op, int a, int b = 0) {
    program_.push_back({op, a, b});
    return kResult + static_cast<int>(program_.size()) - 1;
  }
  int constant(double v) {
    constants_.push_back(v);
    return kConstant + static_cast<int>(constants_.size()) - 1;
  }
  int fold(Op op, const std::vector<int>& regs) {
    int r = regs.front();
    for (std::size_t i = 1; i < regs.size(); ++i) r = emit(op, r, regs[i]);
    return r;
  }

  /// A text of `e` that does not depend on the order GiNaC keeps operands in
  /// (an order of hashes that change from one process to the next): the
  /// operands of sums and products sorted by their own keys.
  const std::string& key(const ex& e) {
    if (const auto it = keys_.find(e); it != keys_.end()) return it->second;
    std::string k;
    const bool commutative = GiNaC::is_exactly_a<GiNaC::add>(e) || GiNaC::is_exactly_a<GiNaC::mul>(e);
    if (commutative || GiNaC::is_exactly_a<GiNaC::power>(e) || GiNaC::is_exactly_a<GiNaC::function>(e)) {
      std::vector<std::string> parts;
      for (std::size_t i = 0; i < e.nops(); ++i) parts.push_back(key(e.op(i)));
      if (commutative) std::sort(parts.begin(), parts.end());
      k = GiNaC::is_exactly_a<GiNaC::add>(e)     ? "add("
          : GiNaC::is_exactly_a<GiNaC::mul>(e)   ? "mul("
          : GiNaC::is_exactly_a<GiNaC::power>(e) ? "pow("
                                                 : GiNaC::ex_to<GiNaC::function>(e).get_name() + "(";
      for (const std::string& part : parts) k += part + ",";
      k += ")";
    } else {
      k = text(e);  // a symbol, a number, a constant such as Pi
    }
    return keys_.emplace(e, std::move(k)).first->second;
  }

  /// The operands of a sum or a product in the order of their keys, so that
  /// the program (and its round-off) is the same in every run.
  std::vector<ex> sorted_operands(const ex& e) {
    std::vector<std::pair<std::string, ex>> keyed;
    for (std::size_t i = 0; i < e.nops(); ++i) keyed.emplace_back(key(e.op(i)), e.op(i));
    std::sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<ex> out;
    for (auto& [k, operand] : keyed) out.push_back(operand);
    return out;
  }

  static bool negative_coefficient(const ex& t) {
    if (is_real_number(t)) return GiNaC::ex_to<numeric>(t).is_negative();
    if (!GiNaC::is_exactly_a<GiNaC::mul>(t)) return false;
    const ex last = t.op(t.nops() - 1);  // GiNaC keeps a mul's numeric coefficient last
    return is_real_number(last) && GiNaC::ex_to<numeric>(last).is_negative();
  }

  int build(const ex& e) {
    using GiNaC::is_exactly_a;
    if (GiNaC::is_a<GiNaC::symbol>(e)) throw std::logic_error("unexpected symbol " + text(e));
    if (is_constant(e)) {
      const ex v = e.evalf();
      if (!is_real_number(v)) throw FormulaError("its constant part '" + text(e) + "' is not a real number");
      const double d = GiNaC::ex_to<numeric>(v).to_double();
      if (!std::isfinite(d)) throw FormulaError("its constant part '" + text(e) + "' is not finite");
      return constant(d);
    }
    if (is_exactly_a<GiNaC::add>(e)) {
      std::optional<int> sum;
      for (const ex& term : sorted_operands(e)) {
        const bool negative = negative_coefficient(term);
        const int r = reg(negative ? ex(-term) : term);
        sum = !sum ? (negative ? emit(Op::Neg, r) : r) : emit(negative ? Op::Sub : Op::Add, *sum, r);
      }
      return *sum;
    }
    if (is_exactly_a<GiNaC::mul>(e)) {
      std::vector<int> numerator, denominator;
      bool negate = false;
      for (const ex& f : sorted_operands(e)) {
        if (is_real_number(f) && f.is_equal(-1)) {
          negate = true;
        } else if (is_exactly_a<GiNaC::power>(f) && is_real_number(f.op(1)) &&
                   GiNaC::ex_to<numeric>(f.op(1)).is_negative()) {
          denominator.push_back(reg(GiNaC::pow(f.op(0), -f.op(1))));
        } else {
          numerator.push_back(reg(f));
        }
      }
      int r = 0;
      if (denominator.empty()) r = fold(Op::Mul, numerator);
      else if (numerator.empty()) r = emit(Op::Recip, fold(Op::Mul, denominator));
      else r = emit(Op::Div, fold(Op::Mul, numerator), fold(Op::Mul, denominator));
      return negate ? emit(Op::Neg, r) : r;
    }
    if (is_exactly_a<GiNaC::power>(e)) {
      const ex base = e.op(0), exponent = e.op(1);
      if (!is_real_number(exponent)) return emit(Op::Pow, reg(base), reg(exponent));
      const numeric p = GiNaC::ex_to<numeric>(exponent);
      if (p.is_negative()) return emit(Op::Recip, reg(GiNaC::pow(base, -p)));
      if (p.is_integer() && p < 1000) {
        const int k = p.to_int();
        if (k == 1) return reg(base);
        return k == 2 ? emit(Op::Square, reg(base)) : emit(Op::PowInt, reg(base), k);
      }
      if (p.is_rational() && p.denom() == 2) {  // b^(k + 1/2) = b^k sqrt(b)
        const int root = emit(Op::Sqrt, reg(base));
        const numeric whole = p - numeric(1, 2);
        return whole.is_zero() ? root : emit(Op::Mul, reg(GiNaC::pow(base, whole)), root);
      }
      return emit(Op::Pow, reg(base), constant(p.to_double()));
    }
    if (is_exactly_a<GiNaC::function>(e)) {
      static const std::map<std::string, Op> kUnary = {
          {"sin", Op::Sin},   {"cos", Op::Cos},   {"tan", Op::Tan}, {"asin", Op::Asin},       {"acos", Op::Acos},
          {"atan", Op::Atan}, {"sinh", Op::Sinh}, {"cosh", Op::Cosh}, {"tanh", Op::Tanh},     {"exp", Op::Exp},
          {"log", Op::Log},   {"abs", Op::Abs},   {"tether_abs", Op::Abs}, {"tether_sign", Op::Sign}, {"csgn", Op::Sign},
      };
      const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
      if (name == "atan2" && e.nops() == 2) return emit(Op::Atan2, reg(e.op(0)), reg(e.op(1)));
      if (const auto it = kUnary.find(name); it != kUnary.end() && e.nops() == 1)
        return emit(it->second, reg(e.op(0)));
    }
    throw FormulaError("cannot evaluate '" + text(e) + "' (internal: no instruction for it)");
  }

  std::map<ex, int, GiNaC::ex_is_less> memo_;
  std::map<ex, std::string, GiNaC::ex_is_less> keys_;  ///< key() of every expression seen
  int n_inputs_;
  std::vector<double> constants_;
  std::vector<Instruction> program_;
};

// ---------------------------------------------------------------------------

ExpressionConstraint::ExpressionConstraint(std::vector<std::string> formulas, std::vector<ExpressionNode> nodes,
                                           SourceLocation where, std::string description,
                                           std::vector<SourceLocation> formula_locations)
    : formulas_(std::move(formulas)),
      nodes_(std::move(nodes)),
      description_(description.empty() ? "*CONSTRAINT, TYPE=EXPRESSION" : std::move(description)) {
  if (formulas_.empty()) throw InputError(where, description_ + ": no formula given");
  if (nodes_.empty()) throw InputError(where, description_ + ": no nodes given");
  for (const ExpressionNode& node : nodes_) dofs_.insert(dofs_.end(), node.dofs.begin(), node.dofs.end());
  const int n = static_cast<int>(dofs_.size());
  const int m = static_cast<int>(formulas_.size());

  Variables vars{nodes_, {}};
  std::map<ex, int, GiNaC::ex_is_less> inputs;
  for (std::size_t k = 1; k <= nodes_.size(); ++k)
    for (const char* c : {"U", "V"}) {
      vars.displacement.emplace_back(c + std::to_string(k));
      inputs.emplace(vars.displacement.back(), static_cast<int>(inputs.size()));
    }
  inputs.emplace(vars.total_time, n);
  inputs.emplace(vars.step_time, n + 1);
  Compiler compiler(std::move(inputs), n + 2);

  std::vector<std::vector<ex>> gradient(m, std::vector<ex>(n));
  const auto fail = [&](int k, const std::string& what) {
    const SourceLocation& at = formula_locations.size() == formulas_.size() ? formula_locations[k] : where;
    return InputError(at, "in formula " + std::to_string(k + 1) + " of " + description_ + ": " + what);
  };
  // f and the gradient first, so that evaluate() without Hessians runs a prefix of the program.
  for (int k = 0; k < m; ++k) {
    try {
      const ex f = expression::parse(formulas_[k], vars);
      values_.push_back({k, 0, 0, compiler.reg(f)});
      bool depends = false;
      for (int j = 0; j < n; ++j) {
        gradient[k][j] = f.diff(vars.displacement[j]);
        if (gradient[k][j].is_zero()) continue;
        depends = true;
        gradient_.push_back({k, 0, j, compiler.reg(gradient[k][j])});
        if (!is_constant(gradient[k][j])) linear_ = false;
      }
      if (!depends)
        throw FormulaError("it does not depend on any displacement U1.." + std::string("V") + std::to_string(n / 2) +
                           " (its gradient is identically zero)");
    } catch (const FormulaError& e) {
      throw fail(k, e.what());
    } catch (const std::exception& e) {  // GiNaC: division by zero, logarithmic pole, ...
      throw fail(k, std::string("cannot be evaluated with the nodes' reference coordinates: ") + e.what());
    }
  }
  n_first_order_ = compiler.size();
  if (!linear_) {
    for (int k = 0; k < m; ++k) {
      try {
        for (int i = 0; i < n; ++i)
          for (int j = i; j < n; ++j) {
            if (is_constant(gradient[k][i])) break;
            const ex h = gradient[k][i].diff(vars.displacement[j]);
            if (!h.is_zero()) hessian_.push_back({k, i, j, compiler.reg(h)});
          }
      } catch (const FormulaError& e) {
        throw fail(k, e.what());
      } catch (const std::exception& e) {
        throw fail(k, std::string("its second derivatives cannot be evaluated: ") + e.what());
      }
    }
  }
  compiler.finish(*this);
}

void ExpressionConstraint::evaluate(const ConstraintInput& in, ConstraintOutput& out, bool need_hessian) const {
  const std::size_t n = dofs_.size();
  assert(static_cast<std::size_t>(in.u.size()) == n);
  thread_local std::vector<double> registers;
  const std::size_t first_result = static_cast<std::size_t>(n_inputs_) + constants_.size();
  registers.resize(first_result + program_.size());
  double* r = registers.data();
  std::copy(in.u.data(), in.u.data() + n, r);
  r[n] = in.total_time;
  r[n + 1] = in.step_time;
  std::copy(constants_.begin(), constants_.end(), r + n_inputs_);

  const std::size_t count = need_hessian ? program_.size() : static_cast<std::size_t>(n_first_order_);
  double* result = r + first_result;
  for (std::size_t i = 0; i < count; ++i) {
    const Instruction& ins = program_[i];
    const double a = r[ins.a];
    double y = 0;
    switch (ins.op) {
      case Op::Add: y = a + r[ins.b]; break;
      case Op::Sub: y = a - r[ins.b]; break;
      case Op::Mul: y = a * r[ins.b]; break;
      case Op::Div: y = a / r[ins.b]; break;
      case Op::Pow: y = std::pow(a, r[ins.b]); break;
      case Op::Atan2: y = std::atan2(a, r[ins.b]); break;
      case Op::Neg: y = -a; break;
      case Op::Recip: y = 1 / a; break;
      case Op::Square: y = a * a; break;
      case Op::PowInt: y = std::pow(a, ins.b); break;
      case Op::Sqrt: y = std::sqrt(a); break;
      case Op::Sin: y = std::sin(a); break;
      case Op::Cos: y = std::cos(a); break;
      case Op::Tan: y = std::tan(a); break;
      case Op::Asin: y = std::asin(a); break;
      case Op::Acos: y = std::acos(a); break;
      case Op::Atan: y = std::atan(a); break;
      case Op::Sinh: y = std::sinh(a); break;
      case Op::Cosh: y = std::cosh(a); break;
      case Op::Tanh: y = std::tanh(a); break;
      case Op::Exp: y = std::exp(a); break;
      case Op::Log: y = std::log(a); break;
      case Op::Abs: y = std::abs(a); break;
      case Op::Sign: y = static_cast<double>((a > 0) - (a < 0)); break;
    }
    result[i] = y;
  }

  for (const Entry& e : values_) out.f[e.equation] = r[e.reg];
  for (const Entry& e : gradient_) out.gradient(e.equation, e.column) = r[e.reg];
  if (!need_hessian) return;
  for (const Entry& e : hessian_) {
    Eigen::MatrixXd& h = out.hessian[static_cast<std::size_t>(e.equation)];
    h(e.row, e.column) = r[e.reg];
    h(e.column, e.row) = r[e.reg];
  }
}

}  // namespace tether
