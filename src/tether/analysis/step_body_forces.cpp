#include "tether/analysis/step_body_forces.hpp"

#include <map>
#include <utility>

#include "tether/analysis/amplitude.hpp"
#include "tether/core/error.hpp"

namespace tether {

namespace {

using LoadKey = std::pair<int, int>;  ///< (element, kind)

LoadKey key_of(const BodyLoad& load) { return {load.element, static_cast<int>(load.kind)}; }

}  // namespace

std::vector<StepBodyLoad> step_body_loads(const Model& model, int step_index) {
  std::vector<StepBodyLoad> loads;
  std::map<LoadKey, std::pair<BodyLoad, double>> end;  // values at the end of the previous step
  double total_time = 0;
  for (int k = 0; k <= step_index; ++k) {
    const Step& step = model.steps[static_cast<std::size_t>(k)];
    loads.clear();
    std::map<LoadKey, std::size_t> seen;
    for (const BodyLoad& load : step.body_loads) {
      const auto prev = end.find(key_of(load));
      const double start = prev == end.end() ? 0.0 : prev->second.second;
      seen[key_of(load)] = loads.size();
      loads.push_back({load, RampedValue{start, load.magnitude, load.amplitude}});
    }
    for (const auto& [key, value] : end) {
      if (seen.count(key) || value.second == 0) continue;
      BodyLoad removed = value.first;  // the same load, ramped down to zero
      removed.magnitude = 0;
      removed.amplitude = -1;
      loads.push_back({removed, RampedValue{value.second, 0.0, -1}});
    }
    if (!step.ramp_loads)  // AMPLITUDE=STEP (and dynamic steps by default): the target holds from the step's start
      for (StepBodyLoad& l : loads)
        if (l.value.amplitude < 0) l.value.start = l.value.target;
    if (k == step_index) break;
    total_time += step.period;
    end.clear();
    for (const StepBodyLoad& l : loads)
      end[key_of(l.load)] = {l.load, step_magnitude(model, l.value.amplitude, l.value.start, l.value.target,
                                                    step.period, step.period, total_time)};
  }
  return loads;
}

StepBodyForces::StepBodyForces(const Discretization& discretization, int step_index)
    : model_(discretization.model()), loads_(step_body_loads(model_, step_index)) {
  forces_.reserve(loads_.size());
  for (const StepBodyLoad& l : loads_) {
    const Element& e = model_.elements[static_cast<std::size_t>(l.load.element)];
    const MaterialData& material =
        model_.materials[static_cast<std::size_t>(model_.sections[static_cast<std::size_t>(e.section)].material)];
    if (!material.density)
      throw ModelError(l.load.where.str() + ": element " + label_text(model_.instances, e.id) + " is made of material " +
                       material.name + ", which has no *DENSITY: a body load needs the density");
    std::vector<Eigen::Vector2d> x;
    for (int n : e.nodes) x.push_back(model_.coords[static_cast<std::size_t>(n)]);
    forces_.push_back(std::make_unique<BodyForce>(e.id, e.type, e.nodes, std::move(x), *material.density,
                                                  discretization.thickness(l.load.element), l.load,
                                                  discretization.dofs(), label_text(model_.instances, e.id)));
  }
}

void StepBodyForces::set_time(double step_time, double period, double total_time) {
  for (std::size_t k = 0; k < forces_.size(); ++k) {
    const RampedValue& v = loads_[k].value;
    forces_[k]->set_magnitude(step_magnitude(model_, v.amplitude, v.start, v.target, step_time, period, total_time));
  }
}

}  // namespace tether
