// *AMPLITUDE, *BOUNDARY, *CLOAD, *DLOAD, *DSLOAD and the OP=MOD/NEW bookkeeping.
#include <algorithm>
#include <unordered_map>

#include "tether/io/deck_state.hpp"
#include "tether/io/keyword_handlers.hpp"
#include "tether/io/numbers.hpp"

namespace tether::deck {

namespace {

/// Merges `added` into the list in force: OP=NEW (once per step) clears what
/// was inherited, then entries with the same key are replaced, others appended.
template <class T, class KeyFn>
void merge(DeckState& state, std::vector<T>& list, std::vector<T> added, const KeywordBlock& block,
           const ParameterValues& params, KeyFn key) {
  if (params.name("OP") == "NEW") {
    if (!state.in_step) {
      state.warn(block.where, "OP=NEW has no effect in model data");
    } else if (std::find(state.cleared_this_step.begin(), state.cleared_this_step.end(), block.keyword) ==
               state.cleared_this_step.end()) {
      list.clear();
      state.cleared_this_step.push_back(block.keyword);
    }
  }
  std::unordered_map<long long, std::size_t> index;
  for (std::size_t i = 0; i < list.size(); ++i) index[key(list[i])] = i;
  for (T& a : added) {
    const auto [it, inserted] = index.emplace(key(a), list.size());
    if (inserted)
      list.push_back(std::move(a));
    else
      list[it->second] = std::move(a);
  }
}

long long node_dof_key(int node, int dof) { return 8LL * node + dof; }
long long face_key(const ElementFace& f) { return 8LL * f.element + f.face; }

/// Dofs (0-based) of an ABAQUS boundary type name in 2D; nullopt if unknown.
std::optional<std::vector<int>> boundary_type_dofs(const std::string& type) {
  if (type == "ENCASTRE" || type == "PINNED" || type == "ZASYMM") return std::vector<int>{0, 1};
  if (type == "XSYMM" || type == "YASYMM") return std::vector<int>{0};
  if (type == "YSYMM" || type == "XASYMM") return std::vector<int>{1};
  if (type == "ZSYMM") return std::vector<int>{};
  return std::nullopt;
}

/// Dofs (0-based, 0..1) of a `first[, last]` range; warns once per block about
/// out-of-plane / rotational dofs that are ignored, errors for meaningless ones.
std::vector<int> boundary_range_dofs(DeckState& state, const std::vector<std::string>& f, double value,
                                     const SourceLocation& at, bool& warned) {
  const int first = parse_int(f[1], at, "first dof");
  const int last = (f.size() > 2 && !f[2].empty()) ? parse_int(f[2], at, "last dof") : first;
  if (first < 1 || last < first || last > 6)
    throw InputError(at, "bad dof range " + std::to_string(first) + ".." + std::to_string(last) +
                             ": expected 1 <= first <= last <= 6 (2D models use dofs 1 and 2)");
  if (first == 6 && last == 6) return {2};  // in-plane rotation: exists at *MPC BEAM reference nodes
  if (first >= 4)
    throw InputError(at, "dof " + std::to_string(first) + " is a rotation, which 2D continuum elements do not "
                         "have: expected dof 1 or 2 (or dof 6 alone, the in-plane rotation of an *MPC BEAM "
                         "reference node)");
  if (last >= 3 && value != 0)
    throw InputError(at, "non-zero prescribed value on out-of-plane dof 3: tether is 2D; expected dofs 1-2");
  if (last >= 3 && !warned) {
    state.warn(at, "dofs 3-6 ignored: a 2D model has only dofs 1 and 2");
    warned = true;
  }
  std::vector<int> dofs;
  for (int d = first; d <= std::min(last, 2); ++d) dofs.push_back(d - 1);
  return dofs;
}

}  // namespace

void handle_amplitude(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  Amplitude a;
  a.name = params.name("NAME");
  a.total_time = params.name("TIME") == "TOTAL TIME";
  a.where = block.where;
  for (const Amplitude& other : state.model.amplitudes)
    if (other.name == a.name)
      throw InputError(block.where, "duplicate amplitude " + a.name + ": already defined at " + other.where.str());
  require_data(block, "pairs `t, a`");
  for (const DataLine& line : block.data) {
    const SourceLocation at = line.where();
    const auto f = data_fields(line, 2, 0, "pairs `t, a`");
    if (f.size() % 2 != 0)
      throw InputError(at, "odd number of values (" + std::to_string(f.size()) + "): expected pairs `t, a`");
    for (std::size_t i = 0; i < f.size(); i += 2) {
      const double t = parse_real(f[i], at, "amplitude time");
      if (!a.times.empty() && !(t > a.times.back()))
        throw InputError(at, "amplitude time " + f[i] + " does not increase: expected times in strictly "
                             "increasing order");
      a.times.push_back(t);
      a.values.push_back(parse_real(f[i + 1], at, "amplitude value"));
    }
  }
  state.model.amplitudes.push_back(std::move(a));
}

void handle_boundary(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  const int amplitude = state.amplitude(params.name("AMPLITUDE"), block.where);
  std::vector<Prescribed> added;
  bool warned = false;
  for (const DataLine& line : block.data) {
    const SourceLocation at = line.where();
    const auto f = data_fields(line, 2, 4, "`node_or_nset, first_dof[, last_dof[, value]]` or `node_or_nset, TYPE`");
    std::vector<int> dofs;
    double value = 0;
    if (!is_integer_token(f[1])) {
      const auto typed = boundary_type_dofs(to_upper(f[1]));
      if (!typed || f.size() > 2)
        throw InputError(at, "bad boundary type '" + f[1] + "': expected a dof number or one of ENCASTRE, "
                                                            "PINNED, XSYMM, YSYMM, XASYMM, YASYMM, ZASYMM, ZSYMM");
      if (typed->empty()) state.warn(at, "ZSYMM ignored: it constrains only out-of-plane dofs");
      dofs = *typed;
    } else {
      if (f.size() > 3 && !f[3].empty()) value = parse_real(f[3], at, "prescribed value");
      dofs = boundary_range_dofs(state, f, value, at, warned);
    }
    for (int n : state.nodes_of(f[0], at))
      for (int d : dofs) added.push_back({n, d, value, amplitude, at});
  }
  merge(state, state.boundary, std::move(added), block, params,
        [](const Prescribed& p) { return node_dof_key(p.node, p.dof); });
}

void handle_cload(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  const int amplitude = state.amplitude(params.name("AMPLITUDE"), block.where);
  std::vector<ConcentratedLoad> added;
  for (const DataLine& line : block.data) {
    const SourceLocation at = line.where();
    const auto f = data_fields(line, 3, 3, "`node_or_nset, dof, magnitude`");
    const int dof = parse_int(f[1], at, "dof");
    const double magnitude = parse_real(f[2], at, "load magnitude");
    if (dof == 3 && magnitude == 0) {
      state.warn(at, "zero load on out-of-plane dof 3 ignored (2D model)");
      continue;
    }
    if (dof != 1 && dof != 2 && dof != 6)
      throw InputError(at, "bad load dof " + f[1] + ": expected dof 1 or 2 (2D model), or 6 (a moment on an "
                           "*MPC BEAM reference node)");
    const int index = dof == 6 ? 2 : dof - 1;
    for (int n : state.nodes_of(f[0], at)) added.push_back({n, index, magnitude, amplitude, at});
  }
  merge(state, state.cloads, std::move(added), block, params,
        [](const ConcentratedLoad& c) { return node_dof_key(c.node, c.dof); });
}

void handle_dload(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  const int amplitude = state.amplitude(params.name("AMPLITUDE"), block.where);
  std::vector<PressureLoad> added;
  for (const DataLine& line : block.data) {
    const SourceLocation at = line.where();
    const auto f = data_fields(line, 3, 3, "`element_or_elset, P1..P4, magnitude`");
    const double magnitude = parse_real(f[2], at, "pressure magnitude");
    for (int e : state.elements_of(f[0], at)) {
      const int face = parse_face_id(f[1], state.model.elements[static_cast<std::size_t>(e)], at, 'P');
      added.push_back({{e, face}, magnitude, amplitude, at});
    }
  }
  merge(state, state.dloads, std::move(added), block, params, [](const PressureLoad& p) { return face_key(p.face); });
}

void handle_dsload(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  const int amplitude = state.amplitude(params.name("AMPLITUDE"), block.where);
  std::vector<PressureLoad> added;
  for (const DataLine& line : block.data) {
    const SourceLocation at = line.where();
    const auto f = data_fields(line, 3, 3, "`surface, P, magnitude`");
    const auto it = state.model.surfaces.find(to_upper(f[0]));
    if (it == state.model.surfaces.end())
      throw InputError(at, "undefined surface '" + f[0] + "': expected a surface defined by *SURFACE");
    if (it->second.kind != Surface::Kind::ElementFaces)
      throw InputError(at, "surface " + it->second.name + " is a node surface: expected an element-face surface "
                           "(TYPE=ELEMENT) for a pressure");
    if (to_upper(f[1]) != "P") throw InputError(at, "bad load type '" + f[1] + "': expected P (pressure)");
    const double magnitude = parse_real(f[2], at, "pressure magnitude");
    for (const ElementFace& face : it->second.faces) added.push_back({face, magnitude, amplitude, at});
  }
  merge(state, state.dsloads, std::move(added), block, params, [](const PressureLoad& p) { return face_key(p.face); });
}

}  // namespace tether::deck
