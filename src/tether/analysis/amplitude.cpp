#include "tether/analysis/amplitude.hpp"

#include <algorithm>
#include <vector>

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

double amplitude_integral(const Amplitude& amplitude, double from, double to, double step_start_total) {
  const double shift = amplitude.total_time ? step_start_total : 0.0;
  const double a = from + shift, b = to + shift;  // in the table's own time
  const auto& ts = amplitude.times;
  if (ts.empty() || !(b > a)) return 0.0;
  // Breakpoints inside (a, b): the integrand is linear between them.
  std::vector<double> knots{a};
  for (double t : ts)
    if (t > a && t < b) knots.push_back(t);
  knots.push_back(b);
  const auto value = [&](double t) { return amplitude_value(amplitude, t, t); };
  double sum = 0;
  for (std::size_t k = 1; k < knots.size(); ++k)
    sum += 0.5 * (value(knots[k - 1]) + value(knots[k])) * (knots[k] - knots[k - 1]);
  return sum;
}

double step_magnitude_integral(const Model& model, int amplitude, double start, double target, double step_time,
                               double period, double total_time) {
  if (step_time <= 0) return 0.0;
  if (amplitude >= 0)
    return target * amplitude_integral(model.amplitudes[amplitude], 0.0, step_time, total_time - step_time);
  if (!(period > 0)) return target * step_time;
  const double ramp = std::min(step_time, period);  // the linear part, then held at target
  return start * ramp + (target - start) * ramp * ramp / (2 * period) + target * (step_time - ramp);
}

}  // namespace tether
