#include "tether/model/results.hpp"

#include <cmath>

namespace tether {

double von_mises(const Tensor4& s) {
  const double dxy = s[0] - s[1], dyz = s[1] - s[2], dzx = s[2] - s[0];
  return std::sqrt(0.5 * (dxy * dxy + dyz * dyz + dzx * dzx) + 3.0 * s[3] * s[3]);
}

Tensor4 mean_stress(const std::vector<PointValues>& points) {
  Tensor4 mean{};
  if (points.empty()) return mean;
  for (const auto& p : points)
    for (int c = 0; c < 4; ++c) mean[c] += p.stress[c];
  for (double& c : mean) c /= static_cast<double>(points.size());
  return mean;
}

const std::vector<PointValues>& element_points(const IncrementResults& results, std::size_t element,
                                               std::vector<PointValues>& buffer) {
  if (element < results.points.size()) return results.points[element];
  buffer.clear();
  if (results.point_source) results.point_source->points(static_cast<int>(element), buffer);
  return buffer;
}

}  // namespace tether
