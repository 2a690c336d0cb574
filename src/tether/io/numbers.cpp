#include "tether/io/numbers.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>

namespace tether::deck {

namespace {

/// The token as a message shows it: at most 40 characters, control and
/// non-ASCII bytes as \xNN (a NUL byte would end the message on a terminal).
std::string printable(std::string_view token) {
  constexpr std::size_t kShown = 40;
  std::string out;
  for (std::size_t i = 0; i < token.size() && i < kShown; ++i) {
    const auto c = static_cast<unsigned char>(token[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
      continue;
    }
    constexpr char kHex[] = "0123456789ABCDEF";
    out += "\\x";
    out += kHex[c >> 4];
    out += kHex[c & 0xf];
  }
  if (token.size() > kShown) out += "... (" + std::to_string(token.size()) + " characters)";
  return out;
}

[[noreturn]] void bad_number(std::string_view token, const SourceLocation& where, std::string_view what,
                             std::string_view expected) {
  throw InputError(where, "bad number '" + printable(token) + "' for " + std::string(what) + ": expected " +
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
    throw InputError(where, "bad " + std::string(what) + " '" + printable(token) +
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

std::string format_number_exact(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

}  // namespace tether::deck
