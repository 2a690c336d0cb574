// *NODE PRINT, *EL PRINT, *NODE FILE, *EL FILE, *OUTPUT, *NODE OUTPUT, *ELEMENT OUTPUT.
// Output requests belong to the step they are written in.
#include <algorithm>

#include "tether/io/deck_state.hpp"
#include "tether/io/keyword_handlers.hpp"
#include "tether/io/numbers.hpp"

namespace tether::deck {

namespace {

const std::vector<std::string_view> kNodeVariables = {"U", "RF", "V", "A", "NT"};
const std::vector<std::string_view> kElementVariables = {"S", "E", "THE", "PEEQ", "PE", "AC YIELD", "SDV"};
constexpr std::string_view kElementList = "S, E, THE, PEEQ, PE, AC YIELD, SDV";

/// The variable name of a data field: upper case, blanks collapsed, and
/// ABAQUS's two-word AC YIELD also when written without the blank (ACYIELD).
std::string variable_name(const std::string& field) {
  std::string v = normalize_name(field);
  return v == "ACYIELD" ? "AC YIELD" : v;
}

/// AC YIELD is 0 at every point of a user material (UMAT): says so once per
/// such material that a section uses. Sections name their material (resolved
/// at the end of the deck); materials and sections are model data, so all of
/// them are known when a step asks for output.
void warn_user_material_yield_flag(const DeckState& state, const SourceLocation& where) {
  std::vector<std::string> warned;
  for (const std::string& name : state.section_material) {
    const auto& materials = state.model.materials;
    const auto m = std::find_if(materials.begin(), materials.end(), [&](const MaterialData& d) { return d.name == name; });
    if (m == materials.end() || !m->user || std::find(warned.begin(), warned.end(), name) != warned.end()) continue;
    warned.push_back(name);
    state.warn(where, "AC YIELD is written as 0 at the points of user material " + name +
                          " (*USER MATERIAL): tether cannot tell whether a UMAT yields");
  }
}

/// SDV means a user material's state variables (ABAQUS); CalculiX also
/// prints its built-in materials' internal variables under that name. Says
/// so when no section uses a user material with *DEPVAR (nothing to write).
void warn_without_state_variables(const DeckState& state, const SourceLocation& where) {
  for (const std::string& name : state.section_material) {
    const auto& materials = state.model.materials;
    const auto m = std::find_if(materials.begin(), materials.end(), [&](const MaterialData& d) { return d.name == name; });
    if (m != materials.end() && m->user && m->depvar.value_or(0) > 0) return;
  }
  state.warn(where, "SDV: no section uses a user material with *DEPVAR, so there are no state variables to write "
                    "(SDV is a UMAT's STATEV, as in ABAQUS; CalculiX also writes its built-in materials' internal "
                    "variables as SDV, which tether writes as PEEQ, PE and AC YIELD)");
}

bool is_nodal(OutputRequest::Kind k) {
  return k == OutputRequest::Kind::NodePrint || k == OutputRequest::Kind::NodeFile;
}

/// Reads the variable names of the data lines; unknown ones are ignored with a warning.
std::vector<std::string> read_variables(DeckState& state, const KeywordBlock& block, OutputRequest::Kind kind) {
  const auto& allowed = is_nodal(kind) ? kNodeVariables : kElementVariables;
  const std::string expected = is_nodal(kind) ? "U, RF, V, A, NT" : std::string(kElementList);
  require_data(block, "the variables to write (" + expected + ")");
  std::vector<std::string> vars;
  for (const DataLine& line : block.data)
    for (const std::string& f : data_fields(line, 1, 0, "variable names (" + expected + ")")) {
      const std::string v = variable_name(f);
      if (v.empty()) continue;
      if (std::find(allowed.begin(), allowed.end(), v) == allowed.end()) {
        state.warn(line.where(), "output variable " + v + " is not available in tether and is ignored (available: " +
                                     expected + ")");
        continue;
      }
      if (v == "AC YIELD" && std::find(vars.begin(), vars.end(), v) == vars.end())
        warn_user_material_yield_flag(state, line.where());
      if (v == "SDV" && std::find(vars.begin(), vars.end(), v) == vars.end())
        warn_without_state_variables(state, line.where());
      if (std::find(vars.begin(), vars.end(), v) == vars.end()) vars.push_back(v);
    }
  return vars;
}

/// The request's FREQUENCY of a keyword with only that parameter (*NODE PRINT, *EL FILE, ...).
OutputRequest frequency_schedule(const KeywordBlock& block, const ParameterValues& params) {
  OutputRequest r;
  r.frequency = params.integer("FREQUENCY");
  r.schedule_given = params.given("FREQUENCY");
  if (r.frequency < 0)
    throw InputError(block.where, "FREQUENCY=" + params.text("FREQUENCY") + ": expected a value >= 0");
  return r;
}

/// Adds one request to the current step (`set_param` is NSET or ELSET) with
/// the schedule (FREQUENCY, intervals, TIME MARKS) of `schedule`; returns it,
/// or nullptr when no usable variable was requested.
OutputRequest* add_request(DeckState& state, const KeywordBlock& block, const ParameterValues& params,
                           OutputRequest::Kind kind, std::string_view set_param, const OutputRequest& schedule) {
  OutputRequest r = schedule;
  r.kind = kind;
  r.where = block.where;
  r.set = params.name(set_param);
  if (!r.set.empty()) {
    if (is_nodal(kind))
      (void)state.node_set(r.set, block.where);
    else
      (void)state.element_set(r.set, block.where);
  }
  r.variables = read_variables(state, block, kind);
  if (r.variables.empty()) {
    state.warn(block.where, "output request without any available variable ignored");
    return nullptr;
  }
  state.step().outputs.push_back(std::move(r));
  return &state.step().outputs.back();
}

OutputRequest* print_or_file(DeckState& state, const KeywordBlock& block, const ParameterValues& params,
                             OutputRequest::Kind kind, std::string_view set_param) {
  const bool print = kind == OutputRequest::Kind::NodePrint || kind == OutputRequest::Kind::ElementPrint;
  if (print && params.given("FREQUENCY")) note_print_frequency(state, params.integer("FREQUENCY"));
  OutputRequest* r = add_request(state, block, params, kind, set_param, frequency_schedule(block, params));
  if (print && r) state.print_requests.push_back(state.step().outputs.size() - 1);
  return r;
}

/// FREQUENCY, NUMBER INTERVAL, TIME INTERVAL (at most one: ABAQUS's rule)
/// and TIME MARKS of an *OUTPUT block.
OutputRequest output_block_schedule(const KeywordBlock& block, const ParameterValues& params) {
  OutputRequest r = frequency_schedule(block, params);
  const int given = int{params.given("FREQUENCY")} + int{params.given("NUMBER INTERVAL")} + int{params.given("TIME INTERVAL")};
  if (given > 1)
    throw InputError(block.where, "*OUTPUT takes at most one of FREQUENCY, NUMBER INTERVAL and TIME INTERVAL");
  if (params.given("NUMBER INTERVAL")) {
    r.number_interval = params.integer("NUMBER INTERVAL");
    if (r.number_interval < 1)
      throw InputError(block.where, "NUMBER INTERVAL=" + params.text("NUMBER INTERVAL") +
                                        ": expected a number of intervals >= 1");
  }
  if (params.given("TIME INTERVAL")) {
    r.time_interval = params.real("TIME INTERVAL");
    if (!(r.time_interval > 0))
      throw InputError(block.where, "TIME INTERVAL=" + params.text("TIME INTERVAL") + ": expected a time > 0");
  }
  r.schedule_given = given > 0;
  r.time_marks = params.name("TIME MARKS") == "YES";
  if (params.given("TIME MARKS") && given == int{params.given("FREQUENCY")})
    throw InputError(block.where, "TIME MARKS applies to NUMBER INTERVAL or TIME INTERVAL: give one of them");
  return r;
}

}  // namespace

void handle_node_print(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  OutputRequest* r = print_or_file(state, block, params, OutputRequest::Kind::NodePrint, "NSET");
  if (!r) return;
  const std::string totals = params.name("TOTALS");
  r->totals = totals != "NO";
  r->totals_only = totals == "ONLY";
}

void handle_el_print(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  print_or_file(state, block, params, OutputRequest::Kind::ElementPrint, "ELSET");
}

void handle_node_file(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  print_or_file(state, block, params, OutputRequest::Kind::NodeFile, "NSET");
}

void handle_el_file(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  print_or_file(state, block, params, OutputRequest::Kind::ElementFile, "ELSET");
}

void handle_output(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  const bool field = params.given("FIELD");
  if (field == params.given("HISTORY"))
    throw InputError(block.where, "*OUTPUT needs exactly one of FIELD or HISTORY");
  if (!block.data.empty()) throw InputError(block.data[0].where(), "*OUTPUT takes no data lines: expected "
                                                                   "*NODE OUTPUT or *ELEMENT OUTPUT");
  state.output_active = true;
  state.output_field = field;
  state.output_schedule = output_block_schedule(block, params);
  // VARIABLE=PRESELECT / ALL, as ABAQUS means them: FIELD, the default field variables (tether's: U, RF, S, E,
  // and the contact stress and opening when the model has contact); HISTORY, the whole-model energies, which
  // tether writes to the .dat of every dynamic step anyway, so it adds no request.
  if (params.given("VARIABLE") && field) {
    using K = OutputRequest::Kind;
    const auto preselect = [&](K kind, std::vector<std::string> variables) {
      OutputRequest r = state.output_schedule;
      r.kind = kind, r.variables = std::move(variables), r.where = block.where;
      state.step().outputs.push_back(std::move(r));
    };
    preselect(K::NodeFile, {"U", "RF"});
    preselect(K::ElementFile, {"S", "E"});
    if (!state.model.contact_pairs.empty()) preselect(K::ContactFile, {"CSTR", "CDIS"});
  }
}

void handle_node_output(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  if (!state.output_active)
    throw InputError(block.where, "*NODE OUTPUT must follow *OUTPUT, FIELD or *OUTPUT, HISTORY in the same step");
  add_request(state, block, params,
              state.output_field ? OutputRequest::Kind::NodeFile : OutputRequest::Kind::NodePrint, "NSET",
              state.output_schedule);
}

void handle_element_output(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  if (!state.output_active)
    throw InputError(block.where, "*ELEMENT OUTPUT must follow *OUTPUT, FIELD or *OUTPUT, HISTORY in the same step");
  add_request(state, block, params,
              state.output_field ? OutputRequest::Kind::ElementFile : OutputRequest::Kind::ElementPrint, "ELSET",
              state.output_schedule);
}

}  // namespace tether::deck
