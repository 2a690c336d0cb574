// *MATERIAL, *ELASTIC, *HYPERELASTIC, *DENSITY, *SOLID SECTION.
#include "tether/io/deck_state.hpp"
#include "tether/io/keyword_handlers.hpp"
#include "tether/io/numbers.hpp"

namespace tether::deck {

namespace {

MaterialData& current_material(DeckState& state) {
  return state.model.materials[static_cast<std::size_t>(state.material)];
}

/// The single data line of a material option: `n_values` numbers (blank = 0),
/// optionally followed by a temperature. One line holds at every temperature
/// (as in ABAQUS and CalculiX), so its temperature is checked and not used; a
/// second line means temperature dependence, which tether does not have.
std::vector<double> material_values(const KeywordBlock& block, std::size_t n_values, std::string_view what) {
  require_data(block, what);
  if (block.data.size() > 1)
    throw InputError(block.data[1].where(), "*" + block.keyword + " has more than one data line: expected one "
                                            "line " + std::string(what) +
                                            " (temperature-dependent data is not supported)");
  const DataLine& line = block.data[0];
  const auto f = data_fields(line, 1, n_values + 1, std::string(what) + "[, temperature]");
  if (f.size() == n_values + 1 && !f[n_values].empty()) (void)parse_real(f[n_values], line.where(), "temperature");
  std::vector<double> values(n_values, 0.0);
  for (std::size_t i = 0; i < n_values && i < f.size(); ++i)
    if (!f[i].empty()) values[i] = parse_real(f[i], line.where(), "*" + block.keyword + " value " + std::to_string(i + 1));
  return values;
}

}  // namespace

void handle_material(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  MaterialData m;
  m.name = params.name("NAME");
  m.where = block.where;
  for (const MaterialData& other : state.model.materials)
    if (other.name == m.name)
      throw InputError(block.where, "duplicate material " + m.name + ": already defined at " + other.where.str());
  if (!block.data.empty())
    throw InputError(block.data[0].where(), "*MATERIAL takes no data lines: expected a material option such "
                                            "as *ELASTIC, *HYPERELASTIC or *DENSITY");
  state.model.materials.push_back(std::move(m));
  state.material = static_cast<int>(state.model.materials.size()) - 1;
}

void handle_elastic(DeckState& state, const KeywordBlock& block, const ParameterValues&) {
  if (block.data.size() > 1) {  // a temperature table
    MaterialData& m = current_material(state);
    if (m.elastic || m.neo_hooke)
      throw InputError(block.where, "material " + m.name + " already has elastic data: expected one *ELASTIC "
                                    "or *HYPERELASTIC per material");
    MaterialData::Elastic elastic;
    read_elastic_table(block, elastic);
    m.elastic = std::move(elastic);
    return;
  }
  const auto v = material_values(block, 2, "`E, nu`");
  const SourceLocation at = block.data[0].where();
  if (!(v[0] > 0)) throw InputError(at, "Young's modulus E = " + std::to_string(v[0]) + ": expected E > 0");
  if (!(v[1] > -1 && v[1] < 0.5))
    throw InputError(at, "Poisson's ratio nu = " + std::to_string(v[1]) + ": expected -1 < nu < 0.5");
  MaterialData& m = current_material(state);
  if (m.elastic || m.neo_hooke)
    throw InputError(block.where, "material " + m.name + " already has elastic data: expected one *ELASTIC "
                                  "or *HYPERELASTIC per material");
  m.elastic = MaterialData::Elastic{v[0], v[1], {}, {}, {}};
}

void handle_hyperelastic(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  if (!params.given("NEO HOOKE"))
    throw InputError(block.where, "*HYPERELASTIC without NEO HOOKE: expected *HYPERELASTIC, NEO HOOKE "
                                  "(the only hyperelastic model supported)");
  const auto v = material_values(block, 2, "`C10, D1`");
  const SourceLocation at = block.data[0].where();
  if (!(v[0] > 0)) throw InputError(at, "C10 = " + std::to_string(v[0]) + ": expected C10 > 0");
  if (v[1] == 0)
    throw InputError(at, "D1 = 0 (incompressible) is not supported: tether has no incompressible "
                         "formulation; expected D1 > 0 (D1 = 2/K)");
  if (!(v[1] > 0)) throw InputError(at, "D1 = " + std::to_string(v[1]) + ": expected D1 > 0");
  MaterialData& m = current_material(state);
  if (m.elastic || m.neo_hooke)
    throw InputError(block.where, "material " + m.name + " already has elastic data: expected one *ELASTIC "
                                  "or *HYPERELASTIC per material");
  m.neo_hooke = MaterialData::NeoHooke{v[0], v[1]};
}

void handle_density(DeckState& state, const KeywordBlock& block, const ParameterValues&) {
  const auto v = material_values(block, 1, "`rho`");
  if (!(v[0] > 0))
    throw InputError(block.data[0].where(), "density = " + std::to_string(v[0]) + ": expected rho > 0");
  current_material(state).density = v[0];
}

namespace {

/// FAMILY= of *SOLID SECTION: the set's elements become `family` ("PLANE STRAIN", ...) with the same shape and
/// integration, e.g. CPS8R -> CPE8R. A type the new family refuses (a
/// hybrid element made plane stress: ABAQUS has no CPS4H) is an error at `where`.
void change_family(Model& m, const std::string& elset, const std::string& family, const SourceLocation& where) {
  const std::string prefix = family == "PLANE STRAIN" ? "CPE" : family == "PLANE STRESS" ? "CPS" : "CAX";
  for (int e : m.element_sets.at(elset)) {
    Element& el = m.elements[static_cast<std::size_t>(e)];
    const std::string name = prefix + std::string(el.type.name.substr(3));
    const auto type = find_element_type(name);
    if (!type) throw InputError(where, "FAMILY=" + family + " makes element type " + name + ", which tether does not know");
    if (const std::string why = unsupported_reason(*type); !why.empty())
      throw InputError(where, "FAMILY=" + family + " makes element " + std::to_string(el.id) + " (" +
                                  std::string(el.type.name) + ") a " + name + ": " + why);
    el.type = *type;
  }
}

}  // namespace

void handle_solid_section(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  SolidSection s;
  s.elset = params.name("ELSET");
  s.where = block.where;
  (void)state.element_set(s.elset, block.where);  // must exist
  if (block.data.size() > 1)
    throw InputError(block.data[1].where(), "*SOLID SECTION has one optional data line: expected `thickness`");
  if (params.real("OFFSET") != 0)
    throw InputError(block.where, "OFFSET=" + params.text("OFFSET") + ": a solid section has no offset (it is a "
                                  "shell parameter); expected OFFSET=0 or none");
  if (!block.data.empty()) {
    const auto f = data_fields(block.data[0], 0, 1, "`thickness`");
    if (!f.empty() && !f[0].empty()) s.thickness = parse_real(f[0], block.data[0].where(), "thickness");
    if (!(s.thickness > 0))
      throw InputError(block.data[0].where(), "thickness " + f[0] + ": expected a thickness > 0");
  }
  if (params.given("FAMILY")) change_family(state.model, s.elset, params.name("FAMILY"), block.where);
  state.model.sections.push_back(std::move(s));
  state.section_material.push_back(params.name("MATERIAL"));
}

}  // namespace tether::deck
