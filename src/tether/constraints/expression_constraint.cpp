#include "tether/constraints/expression_constraint.hpp"

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

namespace {

using GiNaC::ex;
using GiNaC::numeric;

// ---------------------------------------------------------------------------
// abs with the derivative sign(x), sign(0) = 0, and sign' = 0. GiNaC's own
// abs differentiates to x/abs(x), which is 0/0 at x = 0; these give the
// subgradient 0 there instead. Registered on first use (no static registry).

unsigned sign_serial();
unsigned abs_serial();

ex sign_of(const ex& x) { return GiNaC::function(sign_serial(), x); }
ex abs_of(const ex& x) { return GiNaC::function(abs_serial(), x); }

bool is_real_number(const ex& x) {
  return GiNaC::is_exactly_a<numeric>(x) && GiNaC::ex_to<numeric>(x).is_real();
}

ex sign_eval(const ex& x) {
  if (is_real_number(x)) return numeric(GiNaC::ex_to<numeric>(x).csgn());
  return GiNaC::function(sign_serial(), x).hold();
}
ex sign_derivative(const ex&, unsigned) { return 0; }
ex abs_eval(const ex& x) {
  if (is_real_number(x)) return GiNaC::abs(GiNaC::ex_to<numeric>(x));
  return GiNaC::function(abs_serial(), x).hold();
}
ex abs_derivative(const ex& x, unsigned) { return sign_of(x); }

unsigned sign_serial() {
  static const unsigned serial = GiNaC::function::register_new(GiNaC::function_options("tether_sign", 1)
                                                                   .eval_func(sign_eval)
                                                                   .evalf_func(sign_eval)
                                                                   .derivative_func(sign_derivative));
  return serial;
}
unsigned abs_serial() {
  static const unsigned serial = GiNaC::function::register_new(GiNaC::function_options("tether_abs", 1)
                                                                   .eval_func(abs_eval)
                                                                   .evalf_func(abs_eval)
                                                                   .derivative_func(abs_derivative));
  return serial;
}

// ---------------------------------------------------------------------------
// The formula language.

/// A mistake in one formula; the constructor adds file, line and formula number.
class FormulaError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct FunctionInfo {
  const char* name;
  int arity;
  ex (*make)(const std::vector<ex>&);
};

const FunctionInfo kFunctions[] = {
    {"sin", 1, [](const std::vector<ex>& a) -> ex { return GiNaC::sin(a[0]); }},
    {"cos", 1, [](const std::vector<ex>& a) -> ex { return GiNaC::cos(a[0]); }},
    {"tan", 1, [](const std::vector<ex>& a) -> ex { return GiNaC::tan(a[0]); }},
    {"asin", 1, [](const std::vector<ex>& a) -> ex { return GiNaC::asin(a[0]); }},
    {"acos", 1, [](const std::vector<ex>& a) -> ex { return GiNaC::acos(a[0]); }},
    {"atan", 1, [](const std::vector<ex>& a) -> ex { return GiNaC::atan(a[0]); }},
    {"atan2", 2, [](const std::vector<ex>& a) -> ex { return GiNaC::atan2(a[0], a[1]); }},
    {"sinh", 1, [](const std::vector<ex>& a) -> ex { return GiNaC::sinh(a[0]); }},
    {"cosh", 1, [](const std::vector<ex>& a) -> ex { return GiNaC::cosh(a[0]); }},
    {"tanh", 1, [](const std::vector<ex>& a) -> ex { return GiNaC::tanh(a[0]); }},
    {"exp", 1, [](const std::vector<ex>& a) -> ex { return GiNaC::exp(a[0]); }},
    {"log", 1, [](const std::vector<ex>& a) -> ex { return GiNaC::log(a[0]); }},
    {"ln", 1, [](const std::vector<ex>& a) -> ex { return GiNaC::log(a[0]); }},
    {"sqrt", 1, [](const std::vector<ex>& a) -> ex { return GiNaC::sqrt(a[0]); }},
    {"abs", 1, [](const std::vector<ex>& a) -> ex { return abs_of(a[0]); }},
    {"pow", 2, [](const std::vector<ex>& a) -> ex { return GiNaC::pow(a[0], a[1]); }},
};

std::string known_functions() {
  std::string s;
  for (const auto& f : kFunctions) s += (s.empty() ? "" : ", ") + std::string(f.name);
  return s;
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

/// The symbols a formula may use.
struct Variables {
  std::span<const ExpressionNode> nodes;
  std::vector<GiNaC::symbol> displacement;  ///< U1, V1, U2, V2, ... (2 per node)
  GiNaC::symbol total_time{"T"}, step_time{"TSTEP"};

  [[nodiscard]] std::string expected() const {
    return "expected Xk, Yk, Uk, Vk for k = 1.." + std::to_string(nodes.size()) + ", T or TSTEP";
  }
};

struct Token {
  enum class Kind { Number, Name, Operator, Open, Close, Comma, End };
  Kind kind;
  std::string text;
  int column;  ///< 1-based
};

std::vector<Token> tokenize(const std::string& s) {
  std::vector<Token> tokens;
  const auto digit = [&](std::size_t i) { return i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])); };
  std::size_t i = 0;
  while (i < s.size()) {
    const char c = s[i];
    const int column = static_cast<int>(i) + 1;
    if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
    } else if (digit(i) || (c == '.' && digit(i + 1))) {
      std::size_t j = i;
      while (digit(j)) ++j;
      if (j < s.size() && s[j] == '.') ++j;
      while (digit(j)) ++j;
      if (j < s.size() && std::strchr("eEdD", s[j]) != nullptr) {
        std::size_t k = j + 1;
        if (k < s.size() && (s[k] == '+' || s[k] == '-')) ++k;
        if (digit(k)) {
          while (digit(k)) ++k;
          j = k;
        }
      }
      tokens.push_back({Token::Kind::Number, s.substr(i, j - i), column});
      i = j;
    } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      std::size_t j = i;
      while (j < s.size() && (std::isalnum(static_cast<unsigned char>(s[j])) || s[j] == '_')) ++j;
      tokens.push_back({Token::Kind::Name, s.substr(i, j - i), column});
      i = j;
    } else if (c == '*' && i + 1 < s.size() && s[i + 1] == '*') {
      tokens.push_back({Token::Kind::Operator, "**", column});
      i += 2;
    } else if (std::strchr("+-*/^", c) != nullptr) {
      tokens.push_back({Token::Kind::Operator, std::string(1, c), column});
      ++i;
    } else if (c == '(' || c == ')' || c == ',') {
      tokens.push_back({c == '(' ? Token::Kind::Open : c == ')' ? Token::Kind::Close : Token::Kind::Comma,
                        std::string(1, c), column});
      ++i;
    } else {
      throw FormulaError("unexpected character '" + std::string(1, c) + "' at column " + std::to_string(column));
    }
  }
  tokens.push_back({Token::Kind::End, "", static_cast<int>(s.size()) + 1});
  return tokens;
}

/// An exact rational from a decimal literal ("0.1" is 1/10, "2" stays an
/// integer, so x^0.5 is recognised as a square root and x^2 as a square).
ex number(const Token& t) {
  const std::string& s = t.text;
  std::string digits;
  long exponent = 0;
  std::size_t i = 0;
  for (; i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])); ++i) digits += s[i];
  if (i < s.size() && s[i] == '.') {
    for (++i; i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])); ++i, --exponent) digits += s[i];
  }
  if (i < s.size()) {  // exponent part
    const std::string e = s.substr(i + 1);
    if (e.size() > 6) throw FormulaError("number '" + s + "' at column " + std::to_string(t.column) + " is out of range");
    exponent += std::stol(e);
  }
  digits.erase(0, std::min(digits.find_first_not_of('0'), digits.size()));
  if (digits.empty()) return 0;
  if (exponent > 400 || exponent + static_cast<long>(digits.size()) < -400)
    throw FormulaError("number '" + s + "' at column " + std::to_string(t.column) + " is out of range");
  return numeric(digits.c_str()) * numeric(10).power(numeric(exponent));
}

bool is_constant(const ex& e) {
  if (GiNaC::is_a<GiNaC::symbol>(e)) return false;
  for (std::size_t i = 0; i < e.nops(); ++i)
    if (!is_constant(e.op(i))) return false;
  return true;
}

std::string text(const ex& e) {
  std::ostringstream s;
  s << e;
  return s.str();
}

/// A constant as a short number ("-1.1", "0.333333"), anything else as GiNaC prints it.
std::string short_text(const ex& e) {
  if (is_constant(e) && is_real_number(e.evalf())) {
    std::ostringstream s;
    s << GiNaC::ex_to<numeric>(e.evalf()).to_double();
    return s.str();
  }
  return text(e);
}

class Parser {
 public:
  Parser(const std::string& text, const Variables& vars) : tokens_(tokenize(text)), vars_(vars) {}

  ex parse() {
    if (tokens_.front().kind == Token::Kind::End) throw FormulaError("the formula is empty");
    ex e = expression();
    if (peek().kind != Token::Kind::End) unexpected(peek(), "an operator or the end of the formula");
    return e;
  }

 private:
  const Token& peek() const { return tokens_[pos_]; }
  const Token& next() { return tokens_[pos_ < tokens_.size() - 1 ? pos_++ : pos_]; }
  bool at_operator(const char* a, const char* b = nullptr) const {
    const Token& t = peek();
    return t.kind == Token::Kind::Operator && (t.text == a || (b != nullptr && t.text == b));
  }

  [[noreturn]] static void unexpected(const Token& t, const std::string& expected) {
    if (t.kind == Token::Kind::End)
      throw FormulaError("unexpected end of the formula at column " + std::to_string(t.column) + " (expected " +
                         expected + ")");
    throw FormulaError("unexpected token '" + t.text + "' at column " + std::to_string(t.column) + " (expected " +
                       expected + ")");
  }

  // expression := term (('+' | '-') term)*
  ex expression() {
    ex e = term();
    while (at_operator("+", "-")) e = next().text == "+" ? e + term() : e - term();
    return e;
  }
  // term := unary (('*' | '/') unary)*
  ex term() {
    ex e = unary();
    while (at_operator("*", "/")) e = next().text == "*" ? e * unary() : e / unary();
    return e;
  }
  // unary := ('+' | '-') unary | power
  ex unary() {
    if (at_operator("+", "-")) return next().text == "+" ? unary() : -unary();
    return power();
  }
  // power := primary (('^' | '**') unary)?    (right associative: 2^3^2 = 2^9; -x^2 = -(x^2))
  ex power() {
    ex base = primary();
    if (at_operator("^", "**")) {
      const Token op = next();
      const ex exponent = unary();
      return real_valued(GiNaC::pow(base, exponent), op, {base, exponent});
    }
    return base;
  }
  // primary := number | name | name '(' arguments ')' | '(' expression ')'
  ex primary() {
    const Token& t = next();
    switch (t.kind) {
      case Token::Kind::Number:
        return number(t);
      case Token::Kind::Open: {
        ex e = expression();
        if (peek().kind != Token::Kind::Close) {
          if (peek().kind == Token::Kind::End)
            throw FormulaError("missing ')' to close the '(' at column " + std::to_string(t.column));
          unexpected(peek(), "an operator or ')'");
        }
        next();
        return e;
      }
      case Token::Kind::Name:
        return peek().kind == Token::Kind::Open ? call(t) : variable(t);
      default:
        unexpected(t, "a number, variable, function or '('");
    }
  }

  ex variable(const Token& t) {
    const std::string name = lower(t.text);
    const std::string at = "' at column " + std::to_string(t.column);
    if (name == "pi") return GiNaC::Pi;
    if (name == "t") return vars_.total_time;
    if (name == "tstep") return vars_.step_time;
    if (name.size() >= 2 && std::strchr("xyuv", name[0]) != nullptr &&
        std::all_of(name.begin() + 1, name.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); })) {
      const std::string digits = name.substr(1);
      const std::size_t n_nodes = vars_.nodes.size();
      const std::size_t k = digits.size() > 9 ? 0 : std::stoul(digits);
      if (k < 1 || k > n_nodes)
        throw FormulaError("node number " + digits + " in '" + t.text + at + " is out of range: the constraint has " +
                           std::to_string(n_nodes) + " node" + (n_nodes == 1 ? "" : "s") + " (k = 1.." +
                           std::to_string(n_nodes) + ")");
      const ExpressionNode& node = vars_.nodes[k - 1];
      switch (name[0]) {
        case 'x': return numeric(node.reference.x());
        case 'y': return numeric(node.reference.y());
        case 'u': return vars_.displacement[2 * (k - 1)];
        default: return vars_.displacement[2 * (k - 1) + 1];
      }
    }
    for (const auto& f : kFunctions)
      if (name == f.name)
        throw FormulaError("function '" + t.text + at + " needs its argument" + (f.arity == 1 ? "" : "s") +
                           " in parentheses, e.g. " + f.name + (f.arity == 1 ? "(U1)" : "(V1, U1)"));
    throw FormulaError("unknown variable '" + t.text + at + " (" + vars_.expected() + ")");
  }

  ex call(const Token& t) {
    const std::string name = lower(t.text);
    const FunctionInfo* f = nullptr;
    for (const auto& candidate : kFunctions)
      if (name == candidate.name) f = &candidate;
    if (f == nullptr) {
      std::string what = "unknown function '" + t.text + "' at column " + std::to_string(t.column) + " (known: " +
                         known_functions() + ")";
      try {
        variable(t);  // a variable followed by '(' (implicit multiplication is not supported)
        what = "'" + t.text + "' at column " + std::to_string(t.column) +
               " is a variable, not a function: write '*' to multiply";
      } catch (const FormulaError&) {
      }
      throw FormulaError(what);
    }
    next();  // '('
    std::vector<ex> arguments;
    if (peek().kind != Token::Kind::Close) {
      arguments.push_back(expression());
      while (peek().kind == Token::Kind::Comma) {
        next();
        arguments.push_back(expression());
      }
    }
    if (peek().kind != Token::Kind::Close) {
      if (peek().kind == Token::Kind::End)
        throw FormulaError("missing ')' to close the argument list of '" + t.text + "' at column " +
                           std::to_string(t.column));
      unexpected(peek(), "an operator, ',' or ')'");
    }
    next();
    if (static_cast<int>(arguments.size()) != f->arity)
      throw FormulaError("function '" + t.text + "' at column " + std::to_string(t.column) + " takes " +
                         std::to_string(f->arity) + " argument" + (f->arity == 1 ? "" : "s") + ", got " +
                         std::to_string(arguments.size()));
    return real_valued(f->make(arguments), t, arguments);
  }

  /// `e` unless it is a constant that is not a real number (log(-1), sqrt(X1 - X2) with X1 < X2, ...);
  /// `operands` are those of the operation token `t` applies to, for the message.
  static ex real_valued(const ex& e, const Token& t, const std::vector<ex>& operands) {
    if (!is_constant(e) || is_real_number(e.evalf())) return e;
    std::string values;
    for (const ex& o : operands) values += (values.empty() ? "" : ", ") + short_text(o);
    throw FormulaError("'" + t.text + "' at column " + std::to_string(t.column) + " has no real value for " +
                       (operands.size() == 1 ? "the argument " : "the operands ") + values);
  }

  std::vector<Token> tokens_;
  std::size_t pos_ = 0;
  const Variables& vars_;
};

}  // namespace

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
      for (std::size_t i = 0; i < e.nops(); ++i) {
        const bool negative = negative_coefficient(e.op(i));
        const int r = reg(negative ? ex(-e.op(i)) : e.op(i));
        sum = !sum ? (negative ? emit(Op::Neg, r) : r) : emit(negative ? Op::Sub : Op::Add, *sum, r);
      }
      return *sum;
    }
    if (is_exactly_a<GiNaC::mul>(e)) {
      std::vector<int> numerator, denominator;
      bool negate = false;
      for (std::size_t i = 0; i < e.nops(); ++i) {
        const ex f = e.op(i);
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
      const ex f = Parser(formulas_[k], vars).parse();
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
