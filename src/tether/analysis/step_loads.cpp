#include "tether/analysis/step_loads.hpp"

#include "tether/analysis/amplitude.hpp"
#include "tether/core/error.hpp"

namespace tether {

namespace {

/// Global unknown of (node, dof); dof 2 is the in-plane rotation.
int global_dof(const DofMap& dofs, int node, int dof, const SourceLocation& where) {
  if (dof < kDofsPerNode) return dofs.displacement(node, dof);
  const int rotation = dofs.rotation(node);
  if (rotation < 0)
    throw ModelError(where.str() + ": node " + dofs.node_name(node) +
                     " has no rotation (dof 6): only the reference node of an *MPC BEAM has one");
  return rotation;
}

}  // namespace

double prescribed_value(const Model& model, const RampedValue& v, double step_time, double period, double total_time) {
  if (!v.velocity) return step_magnitude(model, v.amplitude, v.start, v.target, step_time, period, total_time);
  return v.origin + step_magnitude_integral(model, v.amplitude, v.start, v.target, step_time, period, total_time);
}

bool prescribed_moves(const RampedValue& v) {
  if (v.velocity) return v.target != 0 || (v.amplitude < 0 && v.start != 0);
  return v.amplitude < 0 ? v.start != v.target : v.target != 0;
}

StepLoads make_step_loads(const Step& step, const DofMap& dofs, const Eigen::VectorXd& u,
                          const std::map<std::pair<int, int>, double>& cload_end,
                          const std::map<std::pair<int, int>, double>& pressure_end) {
  StepLoads loads;
  std::map<int, RampedValue> prescribed;
  for (const Prescribed& p : step.boundary) {
    const int dof = global_dof(dofs, p.node, p.dof, p.where);
    if (p.fixed)  // *BOUNDARY, FIXED: held at the value the step starts from
      prescribed[dof] = RampedValue{u[dof], u[dof], -1};
    else if (p.velocity)  // applied at once and held without an amplitude (ABAQUS's STEP), in every kind of step
      prescribed[dof] = RampedValue{p.value, p.value, p.amplitude, true, u[dof]};
    else
      prescribed[dof] = RampedValue{u[dof], p.value, p.amplitude};
  }
  loads.prescribed.assign(prescribed.begin(), prescribed.end());

  std::map<std::pair<int, int>, RampedValue> forces;
  for (const ConcentratedLoad& c : step.cloads) {
    const auto key = std::make_pair(c.node, c.dof);
    auto [it, fresh] = forces.try_emplace(key);
    if (fresh) {
      const auto prev = cload_end.find(key);
      it->second.start = prev == cload_end.end() ? 0.0 : prev->second;
    }
    it->second.target += c.magnitude;  // repeated lines on one dof add up
    it->second.amplitude = c.amplitude;
  }
  for (const auto& [key, value] : cload_end)
    if (!forces.count(key) && value != 0) forces[key] = RampedValue{value, 0.0, -1};
  std::map<std::pair<int, int>, SourceLocation> where;
  for (const ConcentratedLoad& c : step.cloads) where[{c.node, c.dof}] = c.where;
  for (const auto& [key, value] : forces) {
    loads.forces.emplace_back(global_dof(dofs, key.first, key.second, where[key]), value);
    loads.force_keys.push_back(key);
  }

  std::map<std::pair<int, int>, std::size_t> seen;
  for (const PressureLoad& p : step.pressures) {
    const auto key = std::make_pair(p.face.element, p.face.face);
    const auto prev = pressure_end.find(key);
    const double start = prev == pressure_end.end() ? 0.0 : prev->second;
    if (auto it = seen.find(key); it != seen.end()) {
      loads.pressure_values[it->second].target += p.magnitude;
      continue;
    }
    seen[key] = loads.pressures.size();
    loads.pressures.push_back(p);
    loads.pressure_values.push_back(RampedValue{start, p.magnitude, p.amplitude});
  }
  for (const auto& [key, value] : pressure_end) {
    if (seen.count(key) || value == 0) continue;
    PressureLoad removed;
    removed.face = ElementFace{key.first, key.second};
    loads.pressures.push_back(removed);
    loads.pressure_values.push_back(RampedValue{value, 0.0, -1});
  }
  const auto hold = [](RampedValue& v) {
    if (v.amplitude < 0) v.start = v.target;
  };
  if (!step.ramp_prescribed)  // the target holds from the step's start (see Step::ramp_prescribed)
    for (auto& [dof, v] : loads.prescribed) hold(v);
  if (!step.ramp_loads) {  // AMPLITUDE=STEP: the target holds from the step's start
    for (auto& [dof, v] : loads.forces) hold(v);
    for (RampedValue& v : loads.pressure_values) hold(v);
  }
  return loads;
}

}  // namespace tether
