// *NSET, *ELSET, *SURFACE.
#include <map>
#include <set>

#include "tether/io/deck_state.hpp"
#include "tether/io/keyword_handlers.hpp"
#include "tether/io/numbers.hpp"

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
  std::vector<int> members;
  for (const DataLine& line : block.data) {
    const SourceLocation at = line.where();
    if (generate) {
      for (int label : generate_labels(line, state.model.n_elements(), "element"))
        members.push_back(state.element(label, at));
      continue;
    }
    for (const std::string& f : data_fields(line, 1, 0, "element labels or element set names")) {
      if (f.empty()) continue;
      const auto elements = state.elements_of(f, at);
      members.insert(members.end(), elements.begin(), elements.end());
    }
  }
  auto& set = state.model.element_sets[params.name("ELSET")];
  set.insert(set.end(), members.begin(), members.end());
  sort_unique(set);
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
          throw InputError(at, "node " + std::to_string(state.model.node_ids[static_cast<std::size_t>(n)]) +
                                   " is given the area " + format_number(a) + " here (1 when omitted) and " +
                                   format_number(it->second.first) + " at " + it->second.second.str());
      }
    }
    for (const auto& [n, a] : area) s.nodes.push_back(n), s.node_areas.push_back(a.first);
  } else {
    s.kind = Surface::Kind::ElementFaces;
    std::set<long long> seen;  // element * 4 + face
    for (const DataLine& line : block.data) {
      const SourceLocation at = line.where();
      const auto f = data_fields(line, 2, 2, "`element_or_elset, S1..S4`");
      for (int e : state.elements_of(f[0], at)) {
        const ElementFace face{e, parse_face_id(f[1], state.model.elements[static_cast<std::size_t>(e)], at, 'S')};
        if (seen.insert(4LL * face.element + face.face).second) s.faces.push_back(face);
      }
    }
  }
  state.model.surfaces.emplace(s.name, std::move(s));
}

}  // namespace tether::deck
