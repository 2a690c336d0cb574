// *HEADING, *NODE, *ELEMENT.
#include "tether/io/deck_state.hpp"
#include "tether/io/keyword_handlers.hpp"
#include "tether/io/numbers.hpp"

namespace tether::deck {

namespace {

/// Adds `members` (indices) to a named set, keeping it sorted and unique.
void add_to_set(std::map<std::string, std::vector<int>>& sets, const std::string& name,
                const std::vector<int>& members) {
  if (name.empty()) return;
  auto& set = sets[name];
  set.insert(set.end(), members.begin(), members.end());
  sort_unique(set);
}

}  // namespace

void handle_heading(DeckState& state, const KeywordBlock& block, const ParameterValues&) {
  for (const DataLine& line : block.data) {
    if (!state.model.heading.empty()) state.model.heading += '\n';
    state.model.heading += line.text;
  }
}

void handle_preprint(DeckState&, const KeywordBlock& block, const ParameterValues&) {
  if (!block.data.empty())
    throw InputError(block.data[0].where(), "*PREPRINT takes no data lines (it only sets ABAQUS's input printing)");
}

void handle_node(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  Model& m = state.model;
  std::vector<int> added;
  added.reserve(block.data.size());
  bool warned_z = false;
  for (const DataLine& line : block.data) {
    const SourceLocation at = line.where();
    // Empty or missing coordinates are 0, as CalculiX reads them.
    const auto f = data_fields(line, 1, 4, "`label, x, y[, z]`");
    const int label = parse_label(f[0], at, "node label");
    const double x = f.size() < 2 || f[1].empty() ? 0.0 : parse_real(f[1], at, "x coordinate");
    const double y = f.size() < 3 || f[2].empty() ? 0.0 : parse_real(f[2], at, "y coordinate");
    if (f.size() == 4 && !f[3].empty() && parse_real(f[3], at, "z coordinate") != 0.0 && !warned_z) {
      state.warn(at, "non-zero z coordinate ignored: tether models are 2D (x, y)");
      warned_z = true;
    }
    if (m.node_index.count(label))
      throw InputError(at, "duplicate node " + std::to_string(label) +
                               ": node labels must be unique (it is already defined)");
    const int index = m.n_nodes();
    m.node_index.emplace(label, index);
    m.node_ids.push_back(label);
    m.coords.emplace_back(x, y);
    added.push_back(index);
  }
  add_to_set(m.node_sets, params.name("NSET"), added);
}

void handle_element(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  Model& m = state.model;
  const std::string type_name = params.name("TYPE");
  const auto type = find_element_type(type_name);
  if (!type)
    throw InputError(block.where, "unsupported element type " + type_name +
                                      ": tether has 2D continuum elements only; expected one of CPE3, CPE4, "
                                      "CPE6, CPE8, CPE8R, CPS3, CPS4, CPS6, CPS8, CPS8R, CAX3, CAX4, CAX6, "
                                      "CAX8, CAX8R");
  if (const std::string reason = unsupported_reason(*type); !reason.empty())
    throw InputError(block.where, "unsupported element type " + type_name + ": " + reason);

  const std::string expected = "`label, n1, ..., n" + std::to_string(type->n_nodes) + "` for " + type_name;
  std::vector<int> added;
  std::vector<std::string> fields;  // gathered over continuation lines
  SourceLocation first;
  for (const DataLine& line : block.data) {
    DataFields split = split_data_line(line.text);
    if (fields.empty()) first = line.where();
    fields.insert(fields.end(), split.fields.begin(), split.fields.end());
    const auto wanted = static_cast<std::size_t>(type->n_nodes) + 1;
    if (split.trailing_comma && fields.size() < wanted) continue;  // continues on the next line
    if (fields.size() != wanted)
      throw InputError(first, "wrong number of nodes for " + type_name + " element: expected " +
                                  std::to_string(type->n_nodes) + " nodes but found " +
                                  std::to_string(static_cast<int>(fields.size()) - 1) + " (" + expected + ")");
    Element e;
    e.id = parse_label(fields[0], first, "element label");
    e.type = *type;
    e.where = first;
    for (std::size_t i = 1; i < fields.size(); ++i) {
      if (fields[i].empty()) throw InputError(first, "empty node field in element " + fields[0] + ": expected " + expected);
      const int label = parse_label(fields[i], first, "node label");
      if (!m.node_index.count(label))
        throw InputError(first, "element " + std::to_string(e.id) + " references undefined node " +
                                    std::to_string(label) + ": expected nodes defined by *NODE");
      e.nodes.push_back(m.node_index.at(label));
    }
    if (m.element_index.count(e.id))
      throw InputError(first, "duplicate element " + std::to_string(e.id) +
                                  ": element labels must be unique (it is already defined at " +
                                  m.elements[static_cast<std::size_t>(m.element_index.at(e.id))].where.str() + ")");
    m.element_index.emplace(e.id, m.n_elements());
    added.push_back(m.n_elements());
    m.elements.push_back(std::move(e));
    fields.clear();
  }
  if (!fields.empty())
    throw InputError(first, "element line ends with ',' but no continuation follows: expected " + expected);
  add_to_set(m.element_sets, params.name("ELSET"), added);
}

}  // namespace tether::deck
