#include "tether/output/fortran_format.hpp"

#include <fmt/format.h>

#include <cassert>
#include <cmath>
#include <cstdlib>

namespace tether {

std::string fortran_e(double value, int digits) {
  assert(digits >= 1 && digits <= 17);
  if (std::isnan(value)) return "NaN";
  if (std::isinf(value)) return value > 0 ? "Infinity" : "-Infinity";
  if (value == 0.0) return fmt::format("{}0.{}E+00", std::signbit(value) ? "-" : "", std::string(digits, '0'));
  // d.ddddddE+xx with `digits` significant digits, then shift the point left:
  // 0.dddddddE+(xx+1). Rounding is done once, by fmt.
  const std::string c = fmt::format("{:.{}E}", std::abs(value), digits - 1);
  const auto e_pos = c.find('E');
  std::string mantissa;
  mantissa.reserve(digits);
  mantissa += c[0];
  if (digits > 1) mantissa.append(c, 2, e_pos - 2);
  const int exponent = std::atoi(c.c_str() + e_pos + 1) + 1;
  return fmt::format("{}0.{}E{}{:02d}", value < 0 ? "-" : "", mantissa, exponent < 0 ? '-' : '+',
                     std::abs(exponent));
}

}  // namespace tether
