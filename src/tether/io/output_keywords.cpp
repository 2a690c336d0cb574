// *NODE PRINT, *EL PRINT, *NODE FILE, *EL FILE, *OUTPUT, *NODE OUTPUT, *ELEMENT OUTPUT.
// Output requests belong to the step they are written in.
#include <algorithm>

#include "tether/io/deck_state.hpp"
#include "tether/io/keyword_handlers.hpp"
#include "tether/io/numbers.hpp"

namespace tether::deck {

namespace {

const std::vector<std::string_view> kNodeVariables = {"U", "RF", "V", "A", "NT"};
const std::vector<std::string_view> kElementVariables = {"S", "E", "THE", "PEEQ", "PE"};

bool is_nodal(OutputRequest::Kind k) {
  return k == OutputRequest::Kind::NodePrint || k == OutputRequest::Kind::NodeFile;
}

/// Reads the variable names of the data lines; unknown ones are ignored with a warning.
std::vector<std::string> read_variables(DeckState& state, const KeywordBlock& block, OutputRequest::Kind kind) {
  const auto& allowed = is_nodal(kind) ? kNodeVariables : kElementVariables;
  const std::string expected = is_nodal(kind) ? "U, RF, V, A, NT" : "S, E, THE, PEEQ, PE";
  require_data(block, "the variables to write (" + expected + ")");
  std::vector<std::string> vars;
  for (const DataLine& line : block.data)
    for (const std::string& f : data_fields(line, 1, 0, "variable names (" + expected + ")")) {
      const std::string v = to_upper(f);
      if (v.empty()) continue;
      if (std::find(allowed.begin(), allowed.end(), v) == allowed.end()) {
        state.warn(line.where(), "output variable " + v + " is not available in tether and is ignored (available: " +
                                     expected + ")");
        continue;
      }
      if (std::find(vars.begin(), vars.end(), v) == vars.end()) vars.push_back(v);
    }
  return vars;
}

/// Adds one request to the current step (`set_param` is NSET or ELSET); returns
/// it, or nullptr when no usable variable was requested.
OutputRequest* add_request(DeckState& state, const KeywordBlock& block, const ParameterValues& params,
                 OutputRequest::Kind kind, std::string_view set_param, int frequency) {
  OutputRequest r;
  r.kind = kind;
  r.where = block.where;
  r.set = params.name(set_param);
  if (!r.set.empty()) {
    if (is_nodal(kind))
      (void)state.node_set(r.set, block.where);
    else
      (void)state.element_set(r.set, block.where);
  }
  if (frequency < 0)
    throw InputError(block.where, "FREQUENCY=" + std::to_string(frequency) + ": expected a value >= 0");
  r.frequency = frequency;
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
  OutputRequest* r = add_request(state, block, params, kind, set_param, params.integer("FREQUENCY"));
  if (print && r) state.print_requests.push_back(state.step().outputs.size() - 1);
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
  state.output_frequency = params.integer("FREQUENCY");
  if (state.output_frequency < 0)
    throw InputError(block.where, "FREQUENCY=" + params.text("FREQUENCY") + ": expected a value >= 0");
  // VARIABLE=PRESELECT / ALL, as ABAQUS means them: FIELD, the default field variables (tether's: U, RF, S, E,
  // and the contact stress and opening when the model has contact); HISTORY, the whole-model energies, which
  // tether writes to the .dat of every dynamic step anyway, so it adds no request.
  if (params.given("VARIABLE") && field) {
    using K = OutputRequest::Kind;
    state.step().outputs.push_back({K::NodeFile, "", {"U", "RF"}, state.output_frequency, false, false, block.where});
    state.step().outputs.push_back({K::ElementFile, "", {"S", "E"}, state.output_frequency, false, false,
                                    block.where});
    if (!state.model.contact_pairs.empty())
      state.step().outputs.push_back({K::ContactFile, "", {"CSTR", "CDIS"}, state.output_frequency, false, false,
                                      block.where});
  }
}

void handle_node_output(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  if (!state.output_active)
    throw InputError(block.where, "*NODE OUTPUT must follow *OUTPUT, FIELD or *OUTPUT, HISTORY in the same step");
  add_request(state, block, params,
              state.output_field ? OutputRequest::Kind::NodeFile : OutputRequest::Kind::NodePrint, "NSET",
              state.output_frequency);
}

void handle_element_output(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  if (!state.output_active)
    throw InputError(block.where, "*ELEMENT OUTPUT must follow *OUTPUT, FIELD or *OUTPUT, HISTORY in the same step");
  add_request(state, block, params,
              state.output_field ? OutputRequest::Kind::ElementFile : OutputRequest::Kind::ElementPrint, "ELSET",
              state.output_frequency);
}

}  // namespace tether::deck
