#include "tether/analysis/restart.hpp"

#include <bit>
#include <set>

namespace tether {

namespace {

/// FNV-1a 64 over values fed one by one (doubles bitwise).
class Hash {
 public:
  void add(std::uint64_t v) {
    for (int k = 0; k < 8; ++k) h_ = (h_ ^ ((v >> (8 * k)) & 0xff)) * 1099511628211ull;
  }
  void add_int(std::int64_t v) { add(static_cast<std::uint64_t>(v)); }
  void add_double(double v) { add(std::bit_cast<std::uint64_t>(v)); }
  void add_text(std::string_view s) {
    add(s.size());
    for (unsigned char c : s) h_ = (h_ ^ c) * 1099511628211ull;
  }
  [[nodiscard]] std::uint64_t value() const { return h_; }

 private:
  std::uint64_t h_ = 14695981039346656037ull;
};

/// The step's body loads (GRAV, CENTRIF) and *TEMPERATURE data, and the
/// amplitudes they use into `amplitudes`.
void add_body_loads_and_temperatures(Hash& history, const Step& s, std::set<int>& amplitudes) {
  history.add(s.body_loads.size());
  for (const BodyLoad& b : s.body_loads) {
    history.add_int(static_cast<int>(b.kind)), history.add_int(b.element), history.add_double(b.magnitude);
    for (int i = 0; i < 3; ++i) history.add_double(b.direction[i]), history.add_double(b.point[i]);
    history.add_int(b.amplitude);
    amplitudes.insert(b.amplitude);
  }
  history.add(s.temperatures.values.size());
  history.add_int(s.temperatures.reset ? 1 : 0);
  for (const NodeTemperature& t : s.temperatures.values) {
    history.add_int(t.node), history.add_double(t.value), history.add_int(t.amplitude);
    amplitudes.insert(t.amplitude);
  }
}

}  // namespace

RestartFingerprint restart_fingerprint(const Model& model, const Discretization& discretization, int contributions,
                                       int history_steps) {
  RestartFingerprint f;
  f.nodes = model.n_nodes();
  f.elements = model.n_elements();
  f.dofs = discretization.dofs().n_dofs();
  f.multipliers = discretization.dofs().n_multipliers();
  f.contributions = contributions;

  Hash nodes;
  for (int n = 0; n < model.n_nodes(); ++n) {
    nodes.add_int(model.node_ids[static_cast<std::size_t>(n)]);
    nodes.add_double(model.coords[static_cast<std::size_t>(n)].x());
    nodes.add_double(model.coords[static_cast<std::size_t>(n)].y());
  }
  f.nodes_hash = nodes.value();

  Hash elements;
  for (const Element& e : model.elements) {
    elements.add_int(e.id);
    elements.add_text(e.type.name);
    elements.add(e.nodes.size());
    for (int n : e.nodes) elements.add_int(n);
  }
  f.elements_hash = elements.value();

  Hash history;
  std::set<int> amplitudes;
  history.add(model.initial_temperatures.size());
  for (const NodeTemperature& t : model.initial_temperatures) history.add_int(t.node), history.add_double(t.value);
  const int n_steps = std::min(history_steps, static_cast<int>(model.steps.size()));
  for (int k = 0; k < n_steps; ++k) {
    const Step& s = model.steps[static_cast<std::size_t>(k)];
    history.add_int(s.nlgeom ? 1 : 0);
    history.add_double(s.period);
    history.add_int((s.ramp_loads ? 1 : 0) + (s.ramp_prescribed ? 2 : 0));
    history.add(s.boundary.size());
    for (const Prescribed& p : s.boundary) {
      history.add_int(p.node), history.add_int(p.dof), history.add_double(p.value), history.add_int(p.amplitude);
      history.add_int((p.fixed ? 1 : 0) + (p.velocity ? 2 : 0));  // FIXED, TYPE=VELOCITY
    }
    add_body_loads_and_temperatures(history, s, amplitudes);
    history.add(s.cloads.size());
    for (const ConcentratedLoad& c : s.cloads)
      history.add_int(c.node), history.add_int(c.dof), history.add_double(c.magnitude), history.add_int(c.amplitude);
    history.add(s.pressures.size());
    for (const PressureLoad& p : s.pressures)
      history.add_int(p.face.element), history.add_int(p.face.face), history.add_double(p.magnitude),
          history.add_int(p.amplitude);
    for (const Prescribed& p : s.boundary) amplitudes.insert(p.amplitude);
    for (const ConcentratedLoad& c : s.cloads) amplitudes.insert(c.amplitude);
    for (const PressureLoad& p : s.pressures) amplitudes.insert(p.amplitude);
  }
  for (int a : amplitudes) {
    if (a < 0 || a >= static_cast<int>(model.amplitudes.size())) continue;
    const Amplitude& amp = model.amplitudes[static_cast<std::size_t>(a)];
    history.add_int(a);
    history.add_int(amp.total_time ? 1 : 0);
    history.add(amp.times.size());
    for (std::size_t i = 0; i < amp.times.size(); ++i)
      history.add_double(amp.times[i]), history.add_double(amp.values[i]);
  }
  f.history_hash = history.value();
  f.history_steps = n_steps;
  return f;
}

std::string fingerprint_differences(const RestartFingerprint& deck, const RestartFingerprint& file) {
  std::string out;
  const auto add = [&](const std::string& text) { out += (out.empty() ? "" : "; ") + text; };
  const auto count = [&](const char* what, std::int64_t d, std::int64_t f) {
    if (d != f) add("the deck has " + std::to_string(d) + " " + what + ", the file " + std::to_string(f));
  };
  count("nodes", deck.nodes, file.nodes);
  count("elements", deck.elements, file.elements);
  count("unknowns (dofs)", deck.dofs, file.dofs);
  count("multipliers", deck.multipliers, file.multipliers);
  count("elements, constraints and contact pairs", deck.contributions, file.contributions);
  if (deck.nodes == file.nodes && deck.nodes_hash != file.nodes_hash)
    add("node labels or coordinates differ");
  if (deck.elements == file.elements && deck.elements_hash != file.elements_hash)
    add("element labels, types or connectivity differ");
  if (deck.history_steps != file.history_steps)
    add("the file's state is from step " + std::to_string(file.history_steps) + " but the deck has only " +
        std::to_string(deck.history_steps) + " step(s)");
  else if (deck.history_hash != file.history_hash)
    add("the load history of steps 1.." + std::to_string(deck.history_steps) +
        " differs (NLGEOM, step period, boundary conditions (FIXED and TYPE=VELOCITY included), loads, body "
        "loads, temperatures or their amplitudes)");
  return out;
}

}  // namespace tether
