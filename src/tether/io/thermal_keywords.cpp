// *EXPANSION, *INITIAL CONDITIONS TYPE=TEMPERATURE, *TEMPERATURE, and the
// temperature table of *ELASTIC.
#include <algorithm>
#include <unordered_map>

#include "tether/io/deck_state.hpp"
#include "tether/io/keyword_handlers.hpp"
#include "tether/io/numbers.hpp"

namespace tether::deck {

namespace {

/// Checks that row `k`'s temperature lies above the previous row's.
void check_increasing(const std::vector<double>& temperatures, const DataLine& line, std::string_view keyword) {
  const std::size_t k = temperatures.size() - 1;
  if (k > 0 && !(temperatures[k] > temperatures[k - 1]))
    throw InputError(line.where(), "*" + std::string(keyword) + " temperature " + std::to_string(temperatures[k]) +
                                       " after " + std::to_string(temperatures[k - 1]) +
                                       ": expected strictly increasing temperatures, one row per temperature");
}

/// `node_or_nset, value` lines as (node, value) entries, the last given for a node winning.
std::vector<NodeTemperature> node_values(DeckState& state, const KeywordBlock& block, int amplitude) {
  require_data(block, "`node or node set, temperature`");
  std::vector<NodeTemperature> values;
  std::unordered_map<int, std::size_t> index;
  for (const DataLine& line : block.data) {
    const SourceLocation at = line.where();
    const auto f = data_fields(line, 2, 2, "`node or node set, temperature`");
    const double value = parse_real(f[1], at, "temperature");
    for (int node : state.nodes_of(f[0], at)) {
      const auto [it, inserted] = index.emplace(node, values.size());
      if (inserted) values.push_back({node, value, amplitude, at});
      else values[it->second] = {node, value, amplitude, at};
    }
  }
  return values;
}

/// Adds `added` to `list`, replacing entries of the same node.
void merge_by_node(std::vector<NodeTemperature>& list, std::vector<NodeTemperature> added) {
  std::unordered_map<int, std::size_t> index;
  for (std::size_t i = 0; i < list.size(); ++i) index[list[i].node] = i;
  for (NodeTemperature& t : added) {
    const auto [it, inserted] = index.emplace(t.node, list.size());
    if (inserted) list.push_back(t);
    else list[it->second] = t;
  }
}

}  // namespace

void handle_expansion(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  MaterialData& m = state.model.materials[static_cast<std::size_t>(state.material)];
  if (m.expansion)
    throw InputError(block.where, "material " + m.name + " already has *EXPANSION (" + m.expansion->where.str() +
                                      "): expected one per material");
  require_data(block, "`alpha[, temperature]`");
  MaterialData::Expansion e;
  e.zero = params.real("ZERO");
  e.where = block.where;
  const bool table = block.data.size() > 1;
  for (const DataLine& line : block.data) {
    const auto f = data_fields(line, 1, 2, table ? "`alpha, temperature`" : "`alpha[, temperature]`");
    e.alpha.push_back(parse_real(f[0], line.where(), "expansion coefficient alpha"));
    if (!table) {
      if (f.size() == 2 && !f[1].empty()) (void)parse_real(f[1], line.where(), "temperature");
      continue;
    }
    if (f.size() < 2 || f[1].empty())
      throw InputError(line.where(), "*EXPANSION with several rows needs a temperature on each: expected "
                                     "`alpha, temperature`");
    e.temperature.push_back(parse_real(f[1], line.where(), "temperature"));
    check_increasing(e.temperature, line, "EXPANSION");
  }
  m.expansion = std::move(e);
}

void handle_initial_temperatures(DeckState& state, const KeywordBlock& block) {
  merge_by_node(state.model.initial_temperatures, node_values(state, block, -1));
}

void handle_temperature(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  if (params.given("FILE"))
    throw InputError(block.where, "*TEMPERATURE, FILE= reads temperatures from a results file, which tether does "
                                  "not do: give them on data lines `node or node set, temperature`");
  const bool expansion = std::any_of(state.model.materials.begin(), state.model.materials.end(),
                                     [](const MaterialData& m) { return m.expansion.has_value(); });
  const bool table = std::any_of(state.model.materials.begin(), state.model.materials.end(), [](const MaterialData& m) {
    return (m.elastic && !m.elastic->table_young.empty()) || m.user;  // a UMAT reads TEMP and DTEMP
  });
  if (!expansion && !table)
    state.warn(block.where, "*TEMPERATURE, but no material has *EXPANSION, a temperature-dependent *ELASTIC or "
                            "*USER MATERIAL: the temperatures cause no strain or stress");
  const int amplitude = state.amplitude(params.name("AMPLITUDE"), block.where);
  StepTemperatureData& data = state.step().temperatures;
  if (params.name("OP") == "NEW" &&
      std::find(state.cleared_this_step.begin(), state.cleared_this_step.end(), "TEMPERATURE") ==
          state.cleared_this_step.end()) {
    data.values.clear();
    data.reset = true;
    state.cleared_this_step.emplace_back("TEMPERATURE");
  }
  merge_by_node(data.values, node_values(state, block, amplitude));
}

void read_elastic_table(const KeywordBlock& block, MaterialData::Elastic& elastic) {
  for (const DataLine& line : block.data) {
    const SourceLocation at = line.where();
    const auto f = data_fields(line, 3, 3, "`E, nu, temperature` (one row per temperature)");
    const double young = parse_real(f[0], at, "Young's modulus E");
    const double poisson = parse_real(f[1], at, "Poisson's ratio nu");
    if (!(young > 0)) throw InputError(at, "Young's modulus E = " + f[0] + ": expected E > 0");
    if (!(poisson > -1 && poisson < 0.5))
      throw InputError(at, "Poisson's ratio nu = " + f[1] + ": expected -1 < nu < 0.5");
    elastic.table_young.push_back(young);
    elastic.table_poisson.push_back(poisson);
    elastic.table_temperature.push_back(parse_real(f[2], at, "temperature"));
    check_increasing(elastic.table_temperature, line, "ELASTIC");
  }
  elastic.young = elastic.table_young.front();
  elastic.poisson = elastic.table_poisson.front();
}

void apply_temperature_table_dialect(DeckState& state) {
  Model& m = state.model;
  if (m.has_temperatures()) return;
  for (MaterialData& material : m.materials) {
    if (!material.elastic || material.elastic->table_young.empty()) continue;
    MaterialData::Elastic& e = *material.elastic;
    if (e.table_temperature.front() >= 0) continue;  // at 0 both read the first row (constant below it)
    if (m.dialect == Dialect::Calculix) {
      state.warn(material.where, "material " + material.name + ": the deck gives no temperatures, so its *ELASTIC "
                                 "table is read at its first row, as CalculiX does (dialect calculix; ABAQUS "
                                 "interpolates at temperature 0)");
      e.table_young.clear(), e.table_poisson.clear(), e.table_temperature.clear();
    } else {
      state.warn(material.where, "material " + material.name + ": the deck gives no temperatures, so its *ELASTIC "
                                 "table is interpolated at temperature 0, as ABAQUS does (CalculiX would use the "
                                 "first row: --dialect calculix)");
    }
  }
}

}  // namespace tether::deck
