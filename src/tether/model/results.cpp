#include "tether/model/results.hpp"

#include <cmath>

namespace tether {

double von_mises(const Tensor4& s) {
  const double dxy = s[0] - s[1], dyz = s[1] - s[2], dzx = s[2] - s[0];
  return std::sqrt(0.5 * (dxy * dxy + dyz * dyz + dzx * dzx) + 3.0 * s[3] * s[3]);
}

}  // namespace tether
