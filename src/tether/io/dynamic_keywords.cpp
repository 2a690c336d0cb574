// *INITIAL CONDITIONS (TYPE=VELOCITY) and *DAMPING: the data of dynamic steps.
#include "tether/io/deck_state.hpp"
#include "tether/io/keyword_handlers.hpp"
#include "tether/io/numbers.hpp"

namespace tether::deck {

void handle_initial_conditions(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  const std::string type = params.name("TYPE");
  if (type == "TEMPERATURE") return handle_initial_temperatures(state, block);
  if (type != "VELOCITY")
    throw InputError(block.where, "*INITIAL CONDITIONS, TYPE=" + type +
                                      ": tether reads TYPE=VELOCITY and TYPE=TEMPERATURE only (initial stresses and "
                                      "other fields are planned for a later version)");
  require_data(block, "`node or node set, dof, velocity`");
  for (const DataLine& line : block.data) {
    const SourceLocation at = line.where();
    const auto f = data_fields(line, 3, 3, "`node or node set, dof, velocity`");
    const int dof = parse_int(f[1], at, "dof");
    const double value = parse_real(f[2], at, "velocity");
    if (dof < 1 || dof > 6)
      throw InputError(at, "dof " + f[1] + ": expected 1 or 2 (a 2D model's translations; 3 with velocity 0)");
    if (dof > 2) {
      if (value != 0)
        throw InputError(at, "dof " + f[1] + " with velocity " + f[2] +
                                 ": a 2D model moves in its plane only (dofs 1 and 2)");
      state.warn(at, "initial velocity 0 on dof " + f[1] + " of a 2D model: ignored");
      continue;
    }
    for (const int node : state.nodes_of(f[0], at))
      state.model.initial_velocities.push_back({node, dof - 1, value, at});
  }
}

void handle_damping(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  if (!block.data.empty())
    throw InputError(block.data[0].where(), "*DAMPING takes no data lines: expected ALPHA= and BETA= on its line");
  if (params.given("STRUCTURAL"))
    throw InputError(block.where, "*DAMPING, STRUCTURAL= is structural (hysteretic) damping of frequency-domain "
                                  "procedures, which tether does not have: give Rayleigh ALPHA= and BETA=");
  if (!params.given("ALPHA") && !params.given("BETA"))
    throw InputError(block.where, "*DAMPING needs ALPHA= (mass-proportional) and/or BETA= (stiffness-proportional)");
  MaterialData::Damping d;
  d.alpha = params.real("ALPHA");
  d.beta = params.real("BETA");
  d.where = block.where;
  if (d.alpha < 0 || d.beta < 0)
    throw InputError(block.where, "*DAMPING ALPHA=" + params.text("ALPHA") + ", BETA=" + params.text("BETA") +
                                      ": expected factors >= 0");
  if (state.material < 0) throw InputError(block.where, "*DAMPING outside a *MATERIAL definition");
  state.model.materials[static_cast<std::size_t>(state.material)].damping = d;
}

}  // namespace tether::deck
