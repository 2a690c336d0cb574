// *STEP, *STATIC, *DYNAMIC, *CONTROLS, *END STEP, *RESTART.
#include <algorithm>
#include <optional>

#include "tether/io/deck_state.hpp"
#include "tether/io/keyword_handlers.hpp"
#include "tether/io/numbers.hpp"
#include "tether/output/output_schedule.hpp"

namespace tether::deck {

namespace {

/// Field i of a data line as a number, or nullopt when absent/blank.
std::optional<double> real_field(const std::vector<std::string>& f, std::size_t i, const SourceLocation& at,
                                 std::string_view what) {
  if (i >= f.size() || f[i].empty()) return std::nullopt;
  return parse_real(f[i], at, what);
}

std::optional<int> int_field(const std::vector<std::string>& f, std::size_t i, const SourceLocation& at,
                             std::string_view what) {
  if (i >= f.size() || f[i].empty()) return std::nullopt;
  const int v = parse_int(f[i], at, what);
  if (v <= 0) throw InputError(at, std::string(what) + " = " + f[i] + ": expected a positive integer");
  return v;
}

/// Warns about non-blank fields tether reads but does not use.
void warn_unused(DeckState& state, const std::vector<std::string>& f, const std::vector<std::size_t>& used,
                 const std::vector<std::string_view>& names, const SourceLocation& at) {
  std::string ignored;
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (f[i].empty() || std::find(used.begin(), used.end(), i) != used.end()) continue;
    ignored += (ignored.empty() ? "" : ", ") + (i < names.size() ? std::string(names[i]) : "field " + std::to_string(i + 1));
  }
  if (!ignored.empty()) state.warn(at, "*CONTROLS values not used by tether ignored: " + ignored);
}

void read_field_controls(DeckState& state, const KeywordBlock& block, Controls& c) {
  require_data(block, "`R_n, C_n, q0, qu, R_P, eps, C_eps, R_l`");
  const DataLine& line = block.data[0];
  const SourceLocation at = line.where();
  const auto f = data_fields(line, 0, 8, "`R_n, C_n, q0, qu, R_P, eps, C_eps, R_l`");
  const auto positive = [&](std::size_t i, std::string_view what, double& target) {
    if (const auto v = real_field(f, i, at, what)) {
      if (!(*v > 0)) throw InputError(at, std::string(what) + " = " + f[i] + ": expected a value > 0");
      target = *v;
    }
  };
  positive(0, "R_n", c.residual_tolerance);
  positive(1, "C_n", c.correction_tolerance);
  positive(5, "eps", c.zero_force_tolerance);
  warn_unused(state, f, {0, 1, 5}, {"R_n", "C_n", "q0", "qu", "R_P", "eps", "C_eps", "R_l"}, at);
  for (std::size_t i = 1; i < block.data.size(); ++i)
    state.warn(block.data[i].where(), "further *CONTROLS, PARAMETERS=FIELD lines are not used by tether: ignored");
}

void read_time_controls(DeckState& state, const KeywordBlock& block, Controls& c) {
  require_data(block, "`I0, IR, IP, IC, IL, IG, IS, IA, IJ, IT`");
  if (block.data.size() > 2)
    throw InputError(block.data[2].where(), "*CONTROLS, PARAMETERS=TIME INCREMENTATION has at most two data "
                                            "lines: expected `I0, ..., IT` and `Df, DC, ..., WG`");
  const DataLine& line1 = block.data[0];
  const auto f1 = data_fields(line1, 0, 10, "`I0, IR, IP, IC, IL, IG, IS, IA, IJ, IT`");
  if (const auto v = int_field(f1, 3, line1.where(), "IC")) c.max_iterations = *v;
  if (const auto v = int_field(f1, 5, line1.where(), "IG")) c.easy_iterations = *v;
  if (const auto v = int_field(f1, 7, line1.where(), "IA")) c.max_cutbacks = *v;
  warn_unused(state, f1, {3, 5, 7}, {"I0", "IR", "IP", "IC", "IL", "IG", "IS", "IA", "IJ", "IT"}, line1.where());
  if (block.data.size() < 2) return;
  const DataLine& line2 = block.data[1];
  const SourceLocation at = line2.where();
  const auto f2 = data_fields(line2, 0, 8, "`Df, DC, DB, DA, DS, DH, DD, WG`");
  if (const auto v = real_field(f2, 0, at, "Df")) {
    if (!(*v > 0 && *v < 1)) throw InputError(at, "Df = " + f2[0] + ": expected a cut-back factor 0 < Df < 1");
    c.cutback_factor = *v;
  }
  if (const auto v = real_field(f2, 6, at, "DD")) {
    if (!(*v > 1)) throw InputError(at, "DD = " + f2[6] + ": expected a growth factor DD > 1");
    c.growth_factor = *v;
  }
  warn_unused(state, f2, {0, 6}, {"Df", "DC", "DB", "DA", "DS", "DH", "DD", "WG"}, at);
}

/// NLGEOM of a new step. As in ABAQUS and CalculiX, a step without the
/// parameter keeps the previous step's setting. ABAQUS does not turn it off
/// again, so in that dialect NLGEOM=NO after a step with NLGEOM keeps it on
/// with a warning; the calculix dialect turns it off, as CalculiX does.
bool step_nlgeom(const DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  const bool before = !state.model.steps.empty() && state.model.steps.back().nlgeom;
  if (!params.given("NLGEOM")) return before;
  const bool asked = params.name("NLGEOM") == "YES";
  if (state.model.dialect == Dialect::Calculix) return asked;
  if (before && !asked)
    state.warn(block.where, "NLGEOM=NO after a step with NLGEOM: geometric nonlinearity stays on, as in ABAQUS, "
                            "which never turns it off again (CalculiX would turn it off here: --dialect calculix)");
  return before || asked;
}

}  // namespace

void handle_step(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  Step s;
  s.name = params.given("NAME") ? params.text("NAME") : "Step-" + std::to_string(state.model.steps.size() + 1);
  s.nlgeom = step_nlgeom(state, block, params);
  s.max_increments = params.integer("INC");
  if (s.max_increments <= 0)
    throw InputError(block.where, "INC=" + params.text("INC") + ": expected a positive number of increments");
  s.where = block.where;
  if (params.name("EXTRAPOLATION") == "PARABOLIC")
    throw InputError(block.where, "EXTRAPOLATION=PARABOLIC (quadratic extrapolation of the last two increments) "
                                  "is not implemented: expected LINEAR (the default) or NO");
  s.extrapolate = params.name("EXTRAPOLATION") != "NO";
  state.step_amplitude_given = params.given("AMPLITUDE");
  s.ramp_loads = params.name("AMPLITUDE") != "STEP";
  if (!block.data.empty())
    state.warn(block.data[0].where(), "*STEP data lines (a step title) are ignored");
  state.model.steps.push_back(std::move(s));
  state.in_step = true;
  state.seen_step = true;
  state.step_has_procedure = false;
  state.cleared_this_step.clear();
  state.output_active = false;
}

namespace {

/// The data line `initial, period, min, max` of *STATIC and *DYNAMIC.
void read_increments(const KeywordBlock& block, Step& s, std::string_view keyword) {
  if (block.data.size() > 1)
    throw InputError(block.data[1].where(), std::string(keyword) + " has one data line: expected `initial, period, min, max`");
  if (block.data.empty()) return;
  const DataLine& line = block.data[0];
  const SourceLocation at = line.where();
  const auto f = data_fields(line, 0, 4, "`initial, period, min, max`");
  const auto initial = real_field(f, 0, at, "initial increment");
  if (const auto v = real_field(f, 1, at, "step period")) s.period = *v;
  if (!(s.period > 0)) throw InputError(at, "step period " + f[1] + ": expected a period > 0");
  s.initial_increment = initial.value_or(s.period);
  if (!(s.initial_increment > 0 && s.initial_increment <= s.period))
    throw InputError(at, "initial increment " + f[0] + ": expected 0 < initial <= period (" +
                             std::to_string(s.period) + ")");
  if (const auto v = real_field(f, 2, at, "minimum increment")) s.min_increment = *v;
  if (const auto v = real_field(f, 3, at, "maximum increment")) s.max_increment = *v;
  if (s.min_increment < 0 || s.min_increment > s.initial_increment)
    throw InputError(at, "minimum increment " + f[2] + ": expected 0 <= min <= initial increment");
  if (s.max_increment != 0 && s.max_increment < s.initial_increment)
    throw InputError(at, "maximum increment " + f[3] + ": expected max >= initial increment");
}

void require_one_procedure(const DeckState& state, const KeywordBlock& block) {
  if (state.step_has_procedure)
    throw InputError(block.where, "second procedure in step " + state.model.steps.back().name +
                                      ": expected one *STATIC or *DYNAMIC per step");
}

/// Loads without an amplitude in a dynamic step: held from the step's start
/// unless *STEP said AMPLITUDE=RAMP (ABAQUS's and CalculiX's default for
/// dynamic steps).
void dynamic_load_default(DeckState& state, Step& s) {
  if (!state.step_amplitude_given) s.ramp_loads = false;
}

}  // namespace

void handle_static(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  require_one_procedure(state, block);
  if (params.given("SOLVER")) state.warn(block.where, "SOLVER=" + params.text("SOLVER") + " ignored");
  Step& s = state.step();
  s.direct = params.given("DIRECT");
  read_increments(block, s, "*STATIC");
  state.step_has_procedure = true;
}

void handle_dynamic(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  require_one_procedure(state, block);
  if (params.given("SOLVER")) state.warn(block.where, "SOLVER=" + params.text("SOLVER") + " ignored");
  Step& s = state.step();
  const bool explicit_scheme = params.given("EXPLICIT");
  s.procedure = explicit_scheme ? StepProcedure::ExplicitDynamic : StepProcedure::ImplicitDynamic;
  s.direct = params.given("DIRECT");
  DynamicData& d = s.dynamic;
  if (explicit_scheme) {
    for (std::string_view p : {"ALPHA", "HAFTOL", "CONTACT MASS"})
      if (params.given(p))
        throw InputError(block.where, std::string(p) + "= belongs to the implicit *DYNAMIC; *DYNAMIC, EXPLICIT "
                                                       "integrates by central differences");
    d.lumped_mass = true;
    d.alpha = 0;
  } else {
    d.alpha = params.real("ALPHA");
    if (!(d.alpha >= -1.0 / 3.0 && d.alpha <= 0))
      throw InputError(block.where, "ALPHA=" + params.text("ALPHA") + ": expected -1/3 <= alpha <= 0 (HHT)");
    d.lumped_mass = params.name("MASS") == "LUMPED";
    d.redistribute_contact_mass = params.name("CONTACT MASS") != "KEPT";
    if (params.given("HAFTOL")) {
      d.half_increment_tolerance = params.real("HAFTOL");
      if (!(d.half_increment_tolerance > 0))
        throw InputError(block.where, "HAFTOL=" + params.text("HAFTOL") + ": expected a force > 0");
      if (s.direct)
        state.warn(block.where, "HAFTOL=" + params.text("HAFTOL") +
                                    " ignored: DIRECT fixes the increments (ABAQUS ignores it likewise)");
      if (s.direct) d.half_increment_tolerance = 0;
    }
  }
  read_increments(block, s, "*DYNAMIC");
  if (explicit_scheme && block.data.empty())
    throw InputError(block.where, "*DYNAMIC, EXPLICIT needs a data line: expected `increment, period`");
  dynamic_load_default(state, s);
  state.step_has_procedure = true;
}

void handle_controls(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  Controls& c = state.controls;
  if (params.given("RESET")) c = Controls{};
  const std::string kind = params.name("PARAMETERS");
  if (kind.empty()) {
    if (!params.given("RESET"))
      throw InputError(block.where, "*CONTROLS needs PARAMETERS=FIELD, TIME INCREMENTATION or LINE SEARCH, or RESET");
    if (!block.data.empty()) throw InputError(block.data[0].where(), "*CONTROLS, RESET takes no data lines");
    return;
  }
  if (kind == "FIELD") {
    read_field_controls(state, block, c);
  } else if (kind == "TIME INCREMENTATION") {
    read_time_controls(state, block, c);
  } else {  // LINE SEARCH
    c.line_search = true;
    if (!block.data.empty()) {
      const auto f = data_fields(block.data[0], 0, 5, "`N_ls, ...`");
      if (!f.empty() && !f[0].empty())
        c.line_search = parse_int(f[0], block.data[0].where(), "N_ls") > 0;
      warn_unused(state, f, {0}, {"N_ls", "s_max", "s_min", "f_s", "eta_ls"}, block.data[0].where());
    }
  }
}

/// Carries the previous step's output requests of every kind that step `s`
/// does not request itself (ABAQUS and CalculiX alike: requests stay in force
/// until a later step gives one of the same kind, which replaces them all).
/// V and A do not exist in a static step: they are dropped from carried
/// requests there, with a warning.
void carry_output_requests(DeckState& state, Step& s) {
  if (state.model.steps.size() < 2) return;
  const Step& previous = state.model.steps[state.model.steps.size() - 2];
  std::vector<OutputRequest> carried;
  for (const OutputRequest& r : previous.outputs) {
    const bool own = std::any_of(s.outputs.begin(), s.outputs.end(),
                                 [&r](const OutputRequest& o) { return o.kind == r.kind; });
    if (own) continue;
    OutputRequest c = r;
    if (s.procedure == StepProcedure::Static) {
      const auto dynamic_only = [](const std::string& v) { return v == "V" || v == "A"; };
      if (std::any_of(c.variables.begin(), c.variables.end(), dynamic_only))
        state.warn(r.where, "output variables V and A of this request are not carried into step " + s.name +
                                ", which is *STATIC (no velocities there)");
      std::erase_if(c.variables, dynamic_only);
      if (c.variables.empty()) continue;
    }
    carried.push_back(std::move(c));
  }
  s.outputs.insert(s.outputs.end(), carried.begin(), carried.end());
}

/// Explicit steps: requests written without FREQUENCY, NUMBER INTERVAL or
/// TIME INTERVAL (carried ones included) write, in the abaqus dialect, as
/// ABAQUS/Explicit's default output does: at 20 equal intervals to the result
/// files (field output) and at 200 to the .dat (history output); in the
/// calculix dialect at every explicit increment (CalculiX's FREQUENCY=1),
/// which is said.
void default_explicit_schedules(DeckState& state, Step& s) {
  const bool calculix = state.model.dialect == Dialect::Calculix;
  for (OutputRequest& r : s.outputs) {
    if (r.schedule_given || r.frequency == 0) continue;
    if (!calculix) {
      r.number_interval = is_file_request(r) ? kExplicitDefaultIntervals : kExplicitDefaultHistoryIntervals;
      continue;
    }
    state.warn(r.where, "this output request of explicit step " + s.name + " has no FREQUENCY: it writes at every "
                        "explicit increment, as CalculiX does (calculix dialect); give FREQUENCY=n to write every "
                        "n-th increment");
  }
}

void handle_end_step(DeckState& state, const KeywordBlock& block, const ParameterValues&) {
  if (!state.step_has_procedure)
    throw InputError(state.step().where, "step " + state.step().name +
                                             " has no procedure: expected *STATIC or *DYNAMIC between *STEP and *END STEP");
  if (!block.data.empty())
    throw InputError(block.data[0].where(), "*END STEP takes no data lines: expected a keyword line");
  Step& s = state.step();
  if (s.procedure == StepProcedure::Static)
    for (const OutputRequest& r : s.outputs)
      for (const std::string& v : r.variables)
        if (v == "V" || v == "A")
          throw InputError(r.where, "output variable " + v + " (velocity, acceleration) exists in *DYNAMIC steps "
                                    "only, and step " + s.name + " is *STATIC");
  carry_output_requests(state, s);
  // Prescribed displacements without an amplitude: ABAQUS/Standard always
  // ramps them (static and implicit dynamic steps, whatever *STEP AMPLITUDE=
  // says); ABAQUS/Explicit and CalculiX treat them as the loads.
  const bool abaqus_standard = state.model.dialect == Dialect::Abaqus && s.procedure != StepProcedure::ExplicitDynamic;
  s.ramp_prescribed = abaqus_standard || s.ramp_loads;
  s.controls = state.controls;
  s.boundary = state.boundary;
  s.cloads = state.cloads;
  s.pressures = state.dloads;
  s.pressures.insert(s.pressures.end(), state.dsloads.begin(), state.dsloads.end());
  s.body_loads = state.body_loads;
  s.restart_frequency = state.restart_frequency;
  if (state.model.dialect == Dialect::Calculix)  // CalculiX: one print frequency for the step
    for (std::size_t i : state.print_requests) {
      s.outputs.at(i).frequency = state.print_frequency;
      s.outputs.at(i).schedule_given = s.outputs.at(i).schedule_given || state.print_frequency_given;
    }
  if (s.procedure == StepProcedure::ExplicitDynamic) default_explicit_schedules(state, s);
  state.print_requests.clear();
  state.in_step = false;
  state.output_active = false;
}

void handle_restart(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  const bool read = params.given("READ"), write = params.given("WRITE");
  if (read == write)
    throw InputError(block.where, read ? "*RESTART takes READ or WRITE, not both: write two *RESTART lines"
                                       : "*RESTART needs READ (continue from a saved state) or WRITE (save it)");
  if (!block.data.empty()) throw InputError(block.data[0].where(), "*RESTART takes no data lines");
  const auto refuse = [&](std::string_view name, std::string_view with) {
    if (params.given(name))
      throw InputError(block.where, std::string(name) + "= belongs to *RESTART, " + std::string(with) + " only");
  };
  if (write) {
    refuse("STEP", "READ"), refuse("INC", "READ"), refuse("FILE", "READ");
    const int frequency = params.integer("FREQUENCY");
    if (frequency < 0)
      throw InputError(block.where, "FREQUENCY=" + params.text("FREQUENCY") + ": expected a number of increments >= 0");
    state.restart_frequency = frequency;
    return;
  }
  refuse("FREQUENCY", "WRITE"), refuse("OVERLAY", "WRITE");
  if (state.seen_step)
    throw InputError(block.where, "*RESTART, READ belongs in the model data (before the first *STEP)");
  if (state.model.restart_read)
    throw InputError(block.where, "second *RESTART, READ: the first is at " + state.model.restart_read->where.str());
  RestartRead r;
  r.where = block.where;
  r.file = params.text("FILE");
  if (params.given("FILE") && r.file.empty()) throw InputError(block.where, "FILE= needs a file name");
  if (params.given("STEP")) {
    r.step = params.integer("STEP");
    if (r.step <= 0) throw InputError(block.where, "STEP=" + params.text("STEP") + ": expected a step number >= 1");
  }
  if (params.given("INC")) {
    if (!params.given("STEP")) throw InputError(block.where, "INC= on *RESTART, READ needs STEP=");
    r.increment = params.integer("INC");
    if (r.increment <= 0)
      throw InputError(block.where, "INC=" + params.text("INC") + ": expected an increment number >= 1");
  }
  state.model.restart_read = std::move(r);
}

}  // namespace tether::deck
