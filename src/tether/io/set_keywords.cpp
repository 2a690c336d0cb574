// *NSET, *ELSET, *SURFACE.
#include <map>
#include <optional>
#include <set>

#include "tether/io/deck_state.hpp"
#include "tether/io/keyword_handlers.hpp"
#include "tether/io/numbers.hpp"
#include "tether/io/surface_faces.hpp"

namespace tether::deck {

namespace {

constexpr long long kMaxGenerated = 100'000'000;  ///< GENERATE ranges larger than this are refused

/// Labels of a GENERATE line `first, last[, increment]`, checked before anything is allocated.
std::vector<int> generate_labels(const DataLine& line, int n_defined, std::string_view what) {
  const SourceLocation at = line.where();
  const auto f = data_fields(line, 2, 3, "`first, last[, increment]` (GENERATE)");
  const int first = parse_label(f[0], at, std::string(what) + " label");
  const int last = parse_label(f[1], at, std::string(what) + " label");
  const int step = (f.size() == 3 && !f[2].empty()) ? parse_int(f[2], at, "increment") : 1;
  if (step <= 0) throw InputError(at, "bad GENERATE increment " + f[2] + ": expected a positive integer");
  if (last < first)
    throw InputError(at, "bad GENERATE range " + f[0] + ".." + f[1] + ": expected first <= last");
  const long long count = (static_cast<long long>(last) - first) / step + 1;
  if (count > kMaxGenerated)
    throw InputError(at, "GENERATE range " + f[0] + ".." + f[1] + " has " + std::to_string(count) +
                             " members: expected at most " + std::to_string(kMaxGenerated));
  if (count > n_defined)
    throw InputError(at, "GENERATE range " + f[0] + ".." + f[1] + " has " + std::to_string(count) + " " +
                             std::string(what) + "s but only " + std::to_string(n_defined) +
                             " are defined: expected labels of existing " + std::string(what) + "s");
  std::vector<int> labels;
  labels.reserve(static_cast<std::size_t>(count));
  for (long long l = first; l <= last; l += step) labels.push_back(static_cast<int>(l));
  return labels;
}

}  // namespace

namespace {

/// INSTANCE= is resolved when the assembly is flattened; anywhere else it has no meaning.
void refuse_instance_outside_assembly(const KeywordBlock& block, const ParameterValues& params) {
  if (params.given("INSTANCE"))
    throw InputError(block.where, "INSTANCE= on *" + block.keyword + " outside *ASSEMBLY: it names an instance of a "
                                  "*PART, and belongs to sets defined between *ASSEMBLY and *END ASSEMBLY");
}

/// Faces of a TYPE=ELEMENT surface: `element_or_elset, Sn` lines; an element or
/// set given without a face id means its exposed faces, and line elements (or
/// their sets) the faces of the solids they lie on.
std::vector<ElementFace> element_surface_faces(const DeckState& state, const KeywordBlock& block) {
  std::vector<ElementFace> faces;
  std::set<long long> seen;  // element * 4 + face
  const auto add = [&](const std::vector<ElementFace>& more) {
    for (const ElementFace& face : more)
      if (seen.insert(4LL * face.element + face.face).second) faces.push_back(face);
  };
  std::optional<FaceIndex> index;  // built on first use
  for (const DataLine& line : block.data) {
    const SourceLocation at = line.where();
    const auto f = data_fields(line, 1, 2, "`element_or_elset[, S1..S4]`");
    const bool lines = state.names_lines(f[0]);
    const bool solids = !lines || (!is_integer_token(f[0]) && state.model.element_sets.count(to_upper(f[0])));
    if (f.size() == 2 && !f[1].empty()) {
      if (!solids)
        throw InputError(at, "'" + f[0] + "' names line elements, which have no faces " + f[1] +
                                 ": expected it without a face id (the faces of the solid elements the lines lie on)");
      for (int e : state.elements_of(f[0], at))
        add({ElementFace{e, parse_face_id(f[1], state.model, state.model.elements[static_cast<std::size_t>(e)], at, 'S')}});
      continue;
    }
    if (!index) index.emplace(state.model);
    if (lines) add(faces_under_lines(state, *index, state.lines_of(f[0]), at));
    if (solids) add(exposed_faces(state.model, *index, state.elements_of(f[0], at)));
  }
  return faces;
}

}  // namespace

void handle_nset(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  refuse_instance_outside_assembly(block, params);
  const bool generate = params.given("GENERATE");
  std::vector<int> members;
  for (const DataLine& line : block.data) {
    const SourceLocation at = line.where();
    if (generate) {
      for (int label : generate_labels(line, state.model.n_nodes(), "node")) members.push_back(state.node(label, at));
      continue;
    }
    for (const std::string& f : data_fields(line, 1, 0, "node labels or node set names")) {
      if (f.empty()) continue;
      const auto nodes = state.nodes_of(f, at);
      members.insert(members.end(), nodes.begin(), nodes.end());
    }
  }
  auto& set = state.model.node_sets[params.name("NSET")];
  set.insert(set.end(), members.begin(), members.end());
  sort_unique(set);
}

void handle_elset(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  refuse_instance_outside_assembly(block, params);
  const bool generate = params.given("GENERATE");
  std::vector<int> members, lines;  // solid elements; line elements (kept apart, see DeckState::lines)
  const auto add = [&](std::string_view token, const SourceLocation& at) {
    const std::vector<int> l = state.lines_of(token);
    lines.insert(lines.end(), l.begin(), l.end());
    const bool solid_set = !is_integer_token(token) && state.model.element_sets.count(to_upper(token));
    if (!l.empty() && !solid_set && !is_integer_token(token)) return;  // a set of line elements only
    if (!l.empty() && is_integer_token(token)) return;                   // a line element's label
    const auto e = state.elements_of(token, at);
    members.insert(members.end(), e.begin(), e.end());
  };
  const int n_defined = state.model.n_elements() + static_cast<int>(state.lines.size());
  for (const DataLine& line : block.data) {
    const SourceLocation at = line.where();
    if (generate) {
      for (int label : generate_labels(line, n_defined, "element")) add(std::to_string(label), at);
      continue;
    }
    for (const std::string& f : data_fields(line, 1, 0, "element labels or element set names"))
      if (!f.empty()) add(f, at);
  }
  const std::string name = params.name("ELSET");
  if (!lines.empty()) {
    auto& set = state.line_sets[name];
    set.insert(set.end(), lines.begin(), lines.end());
    sort_unique(set);
  }
  if (!members.empty() || lines.empty() || state.model.element_sets.count(name)) {
    auto& set = state.model.element_sets[name];
    set.insert(set.end(), members.begin(), members.end());
    sort_unique(set);
  }
}

void handle_surface(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  Surface s;
  s.name = params.name("NAME");
  s.where = block.where;
  if (state.model.surfaces.count(s.name))
    throw InputError(block.where, "duplicate surface " + s.name + ": already defined at " +
                                      state.model.surfaces.at(s.name).where.str());
  require_data(block, params.name("TYPE") == "NODE" ? "`node_or_nset`" : "`element_or_elset, S1..S4`");
  if (params.name("TYPE") == "NODE") {
    s.kind = Surface::Kind::Nodes;
    std::map<int, std::pair<double, SourceLocation>> area;  // node -> area, the line giving it
    for (const DataLine& line : block.data) {
      const SourceLocation at = line.where();
      const auto f = data_fields(line, 1, 2, "`node_or_nset[, area]`");
      const double a = f.size() > 1 && !f[1].empty() ? parse_real(f[1], at, "node area") : 1.0;
      if (!(a > 0)) throw InputError(at, "node area " + f.at(1) + ": expected an area > 0 (default 1)");
      for (int n : state.nodes_of(f[0], at)) {
        const auto [it, added] = area.try_emplace(n, a, at);
        if (!added && it->second.first != a)
          throw InputError(at, "node " + label_text(state.model.instances, state.model.node_ids[static_cast<std::size_t>(n)]) +
                                   " is given the area " + format_number(a) + " here (1 when omitted) and " +
                                   format_number(it->second.first) + " at " + it->second.second.str());
      }
    }
    for (const auto& [n, a] : area) s.nodes.push_back(n), s.node_areas.push_back(a.first);
  } else {
    s.kind = Surface::Kind::ElementFaces;
    s.faces = element_surface_faces(state, block);
  }
  state.model.surfaces.emplace(s.name, std::move(s));
}

}  // namespace tether::deck
