#include "tether/analysis/amplitude.hpp"

#include <algorithm>

namespace tether {

double amplitude_value(const Amplitude& amplitude, double step_time, double total_time) {
  const double t = amplitude.total_time ? total_time : step_time;
  const auto& ts = amplitude.times;
  const auto& vs = amplitude.values;
  if (ts.empty()) return 0.0;
  if (t <= ts.front()) return vs.front();
  if (t >= ts.back()) return vs.back();
  const auto k = static_cast<std::size_t>(std::upper_bound(ts.begin(), ts.end(), t) - ts.begin());
  const double w = (t - ts[k - 1]) / (ts[k] - ts[k - 1]);
  return (1 - w) * vs[k - 1] + w * vs[k];
}

double step_magnitude(const Model& model, int amplitude, double start, double target, double step_time,
                      double period, double total_time) {
  if (amplitude >= 0) return target * amplitude_value(model.amplitudes[amplitude], step_time, total_time);
  const double w = period > 0 ? std::clamp(step_time / period, 0.0, 1.0) : 1.0;
  return start + (target - start) * w;
}

}  // namespace tether
