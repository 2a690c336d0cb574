#include "tether/io/numbers.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>

namespace tether::deck {

namespace {

[[noreturn]] void bad_number(std::string_view token, const SourceLocation& where, std::string_view what,
                             std::string_view expected) {
  throw InputError(where, "bad number '" + std::string(token) + "' for " + std::string(what) + ": expected " +
                              std::string(expected));
}

}  // namespace

double parse_real(std::string_view token, const SourceLocation& where, std::string_view what) {
  std::string s(token);
  if (!s.empty() && s.front() == '+') s.erase(0, 1);
  for (char& c : s)  // Fortran exponent 1.0D3
    if (c == 'd' || c == 'D') c = 'E';
  double value = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (s.empty() || ec != std::errc() || end != s.data() + s.size() || !std::isfinite(value))
    bad_number(token, where, what, "a real number");
  return value;
}

int parse_int(std::string_view token, const SourceLocation& where, std::string_view what) {
  std::string_view s = token;
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  long long value = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (s.empty() || ec != std::errc() || end != s.data() + s.size() ||
      value > std::numeric_limits<int>::max() || value < std::numeric_limits<int>::min())
    bad_number(token, where, what, "an integer that fits 32 bits");
  return static_cast<int>(value);
}

int parse_label(std::string_view token, const SourceLocation& where, std::string_view what) {
  const int value = parse_int(token, where, what);
  if (value <= 0)
    throw InputError(where, "bad " + std::string(what) + " '" + std::string(token) +
                                "': expected a positive integer label");
  return value;
}

bool is_integer_token(std::string_view token) {
  if (!token.empty() && (token.front() == '+' || token.front() == '-')) token.remove_prefix(1);
  if (token.empty()) return false;
  for (char c : token)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  return true;
}

std::string to_upper(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

std::string format_number(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

}  // namespace tether::deck
