#include "tether/analysis/step_temperatures.hpp"

#include <algorithm>
#include <cmath>

#include "tether/analysis/amplitude.hpp"

namespace tether {

StepTemperatures::StepTemperatures(const Model& model)
    : model_(model), initial_(static_cast<std::size_t>(model.n_nodes()), 0.0) {
  for (const NodeTemperature& t : model.initial_temperatures) initial_[static_cast<std::size_t>(t.node)] = t.value;
  double time = 0;
  std::vector<double> temperature = initial_;
  for (std::size_t k = 0; k < model.steps.size(); ++k) {
    const Step& step = model.steps[k];
    step_start_.push_back(time);
    start_.push_back(temperature);
    std::vector<int> listed;
    if (!step.temperatures.values.empty()) {
      listed.assign(initial_.size(), -1);
      for (std::size_t i = 0; i < step.temperatures.values.size(); ++i)
        listed[static_cast<std::size_t>(step.temperatures.values[i].node)] = static_cast<int>(i);
    }
    listed_.push_back(std::move(listed));
    for (int n = 0; n < model.n_nodes(); ++n)
      temperature[static_cast<std::size_t>(n)] = in_step(k, n, step.period, time + step.period);
    time += step.period;
  }
}

double StepTemperatures::in_step(std::size_t k, int node, double step_time, double total_time) const {
  const Step& step = model_.steps[k];
  const auto n = static_cast<std::size_t>(node);
  const double start = start_[k][n];
  const int i = listed_[k].empty() ? -1 : listed_[k][n];
  if (i < 0 && !step.temperatures.reset) return start;
  double target = initial_[n];
  int amplitude = -1;
  if (i >= 0) {
    const NodeTemperature& t = step.temperatures.values[static_cast<std::size_t>(i)];
    target = t.value, amplitude = t.amplitude;
  }
  if (amplitude < 0 && !step.ramp_loads) return target;  // AMPLITUDE=STEP: applied at the step's start
  return step_magnitude(model_, amplitude, start, target, step_time, step.period, total_time);
}

double StepTemperatures::current(int node, double step_time, double total_time) const {
  if (step_start_.empty()) return initial(node);
  const double begin = total_time - step_time;
  const double tolerance = 1e-9 * std::max(1.0, std::abs(total_time));
  const auto after = std::upper_bound(step_start_.begin(), step_start_.end(), begin + tolerance);
  if (after == step_start_.begin()) return initial(node);
  return in_step(static_cast<std::size_t>(after - step_start_.begin() - 1), node, step_time, total_time);
}

std::vector<double> StepTemperatures::all(double step_time, double total_time) const {
  std::vector<double> t(initial_.size());
  for (std::size_t n = 0; n < t.size(); ++n) t[n] = current(static_cast<int>(n), step_time, total_time);
  return t;
}

}  // namespace tether
