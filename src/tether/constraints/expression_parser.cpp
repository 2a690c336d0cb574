// The formula language of *CONSTRAINT, TYPE=EXPRESSION: tokens, a recursive
// descent parser onto GiNaC expressions, and tether's sign/abs functions.
#include "tether/constraints/expression_parser.hpp"

#include <cctype>
#include <cmath>
#include <cstring>
#include <optional>
#include <sstream>

namespace tether::expression {

namespace {


// ---------------------------------------------------------------------------
// abs with the derivative sign(x), sign(0) = 0, and sign' = 0. GiNaC's own
// abs differentiates to x/abs(x), which is 0/0 at x = 0; these give the
// subgradient 0 there instead. Registered on first use (no static registry).

unsigned sign_serial();
unsigned abs_serial();

ex sign_of(const ex& x) { return GiNaC::function(sign_serial(), x); }
ex abs_of(const ex& x) { return GiNaC::function(abs_serial(), x); }

bool real_number(const ex& x) {
  return GiNaC::is_exactly_a<numeric>(x) && GiNaC::ex_to<numeric>(x).is_real();
}

ex sign_eval(const ex& x) {
  if (real_number(x)) return numeric(GiNaC::ex_to<numeric>(x).csgn());
  return GiNaC::function(sign_serial(), x).hold();
}
ex sign_derivative(const ex&, unsigned) { return 0; }
ex abs_eval(const ex& x) {
  if (real_number(x)) return GiNaC::abs(GiNaC::ex_to<numeric>(x));
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

/// base^exponent. Built as a temporary `power`, not with GiNaC::pow(): pow()
/// puts the new object on the heap and then evaluates it, and when the
/// evaluation throws (0^0: std::domain_error; 0^-1: GiNaC::pole_error)
/// GiNaC 1.8's ex::construct_from_basic() leaves before deleting it, so it is
/// lost (40 bytes a formula). A temporary is destroyed by the unwinding.
ex raised(const ex& base, const ex& exponent) { return GiNaC::power(base, exponent); }

/// `e`, or its value as a number when all its operands are numbers (pi,
/// sqrt(2), sin(1), 2*pi). Applied to every result of the parser, so that
/// each constant of a formula is a number as soon as it is formed: GiNaC
/// would otherwise keep it symbolic and evaluate it only later, in evalf(),
/// and a constant that is exactly 0 there (sqrt(2)*sqrt(3) - sqrt(6)) as a
/// denominator makes GiNaC's power::evalf() throw with terms of its own in
/// flight, lost. As a number, such a 0 is seen when the power is built (a
/// division by zero, reported) and nothing is lost. O(operands) per call.
ex settled(const ex& e) {
  if (GiNaC::is_exactly_a<numeric>(e) || GiNaC::is_a<GiNaC::symbol>(e)) return e;
  for (std::size_t i = 0; i < e.nops(); ++i)
    if (!GiNaC::is_exactly_a<numeric>(e.op(i))) return e;
  return e.evalf();
}

// ---------------------------------------------------------------------------
// The formula language.


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
    {"pow", 2, [](const std::vector<ex>& a) -> ex { return raised(a[0], a[1]); }},
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

bool constant(const ex& e) {
  if (GiNaC::is_a<GiNaC::symbol>(e)) return false;
  for (std::size_t i = 0; i < e.nops(); ++i)
    if (!constant(e.op(i))) return false;
  return true;
}

std::string printed(const ex& e) {
  std::ostringstream s;
  s << e;
  return s.str();
}

/// A constant as a short number ("-1.1", "0.333333"), anything else as GiNaC prints it.
std::string short_text(const ex& e) {
  if (constant(e) && real_number(e.evalf())) {
    std::ostringstream s;
    s << GiNaC::ex_to<numeric>(e.evalf()).to_double();
    return s.str();
  }
  return printed(e);
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
    while (at_operator("+", "-")) e = settled(next().text == "+" ? e + term() : e - term());
    return e;
  }
  // term := unary (('*' | '/') unary)*
  ex term() {
    ex e = unary();
    while (at_operator("*", "/")) e = settled(next().text == "*" ? e * unary() : e / unary());
    return e;
  }
  // unary := ('+' | '-') unary | power
  ex unary() {
    if (at_operator("+", "-")) return next().text == "+" ? unary() : settled(-unary());
    return power();
  }
  // power := primary (('^' | '**') unary)?    (right associative: 2^3^2 = 2^9; -x^2 = -(x^2))
  ex power() {
    ex base = primary();
    if (at_operator("^", "**")) {
      const Token op = next();
      const ex exponent = unary();
      refuse_zero_base(base, exponent, op);
      return settled(real_valued(raised(base, exponent), op, {base, exponent}));
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
    if (name == "pi") return settled(GiNaC::Pi);
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
    if (name == "pow") refuse_zero_base(arguments[0], arguments[1], t);
    return settled(real_valued(f->make(arguments), t, arguments));
  }

  /// Refuses base^exponent (power token `t`: '^', '**' or pow) for a zero
  /// base with an exponent that is not a number, i.e. depends on a
  /// displacement or the time (0^U1, 0^T; constants are numbers by now, see
  /// settled()): its derivative contains log(0) and 0^-1, on which GiNaC's
  /// differentiation throws with a term of its own in flight, lost. A numeric
  /// exponent is left to GiNaC: 0^2 = 0, 0^0 and 0^-1 throw (reported).
  static void refuse_zero_base(const ex& base, const ex& exponent, const Token& t) {
    if (GiNaC::is_exactly_a<numeric>(base) && base.is_zero() && !GiNaC::is_exactly_a<numeric>(exponent))
      throw FormulaError("'" + t.text + "' at column " + std::to_string(t.column) +
                         " raises 0 to a power that is not a number (" + short_text(exponent) +
                         "): its derivative is undefined");
  }

  /// `e` unless it is a constant that is not a real number (log(-1), sqrt(X1 - X2) with X1 < X2, ...);
  /// `operands` are those of the operation token `t` applies to, for the message.
  static ex real_valued(const ex& e, const Token& t, const std::vector<ex>& operands) {
    if (!constant(e) || real_number(e.evalf())) return e;
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

ex parse(const std::string& formula, const Variables& vars) { return Parser(formula, vars).parse(); }
bool is_constant(const ex& e) { return constant(e); }
bool is_real_number(const ex& x) { return real_number(x); }
std::string text(const ex& e) { return printed(e); }

}  // namespace tether::expression
