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

/// Reads the data lines of *ELEMENT into `(label, node labels, line)` rows,
/// joining continuation lines; `n_nodes` nodes per element.
struct ElementRow {
  std::vector<std::string> fields;  ///< label, then the node labels
  SourceLocation where;
};
std::vector<ElementRow> element_rows(const KeywordBlock& block, int n_nodes, const std::string& type_name) {
  const std::string expected = "`label, n1, ..., n" + std::to_string(n_nodes) + "` for " + type_name;
  const auto wanted = static_cast<std::size_t>(n_nodes) + 1;
  std::vector<ElementRow> rows;
  ElementRow row;
  for (const DataLine& line : block.data) {
    DataFields split = split_data_line(line.text);
    if (row.fields.empty()) row.where = line.where();
    row.fields.insert(row.fields.end(), split.fields.begin(), split.fields.end());
    if (split.trailing_comma && row.fields.size() < wanted) continue;  // continues on the next line
    if (row.fields.size() != wanted)
      throw InputError(row.where, "wrong number of nodes for " + type_name + " element: expected " +
                                      std::to_string(n_nodes) + " nodes but found " +
                                      std::to_string(static_cast<int>(row.fields.size()) - 1) + " (" + expected + ")");
    for (std::size_t i = 1; i < row.fields.size(); ++i)
      if (row.fields[i].empty())
        throw InputError(row.where, "empty node field in element " + row.fields[0] + ": expected " + expected);
    rows.push_back(std::move(row));
    row = ElementRow{};
  }
  if (!row.fields.empty())
    throw InputError(row.where, "element line ends with ',' but no continuation follows: expected " + expected);
  return rows;
}

/// Node index of `field` in element `label`; InputError if the node is undefined.
int element_node(const Model& m, const std::string& field, const std::string& label, const SourceLocation& at) {
  const int node = parse_label(field, at, "node label");
  const auto it = m.node_index.find(node);
  if (it == m.node_index.end())
    throw InputError(at, "element " + label + " references undefined node " + std::to_string(node) +
                             ": expected nodes defined by *NODE");
  return it->second;
}

/// InputError when `label` is already used by a solid or a line element.
void check_new_element_label(const DeckState& state, int label, const SourceLocation& at) {
  const Model& m = state.model;
  std::string before;
  if (m.element_index.count(label))
    before = m.location(m.elements[static_cast<std::size_t>(m.element_index.at(label))].where).str();
  if (state.line_index.count(label)) before = state.lines[static_cast<std::size_t>(state.line_index.at(label))].where.str();
  if (!before.empty())
    throw InputError(at, "duplicate element " + std::to_string(label) +
                             ": element labels must be unique (it is already defined at " + before + ")");
}

/// *ELEMENT of line elements (ABAQUS node order: end, middle, end): kept beside the model, without stiffness, to name faces.
void read_line_elements(DeckState& state, const KeywordBlock& block, const ParameterValues& params, int n_nodes) {
  const std::string type_name = params.name("TYPE");
  std::vector<int> added;
  for (const ElementRow& row : element_rows(block, n_nodes, type_name)) {
    DeckState::LineElement l;
    l.id = parse_label(row.fields[0], row.where, "element label");
    l.type = type_name;
    l.where = row.where;
    for (std::size_t i = 1; i < row.fields.size(); ++i)
      l.nodes.push_back(element_node(state.model, row.fields[i], row.fields[0], row.where));
    if (l.nodes.size() == 3) std::swap(l.nodes[1], l.nodes[2]);  // ABAQUS's end, middle, end -> corners first
    check_new_element_label(state, l.id, row.where);
    state.line_index.emplace(l.id, static_cast<int>(state.lines.size()));
    added.push_back(static_cast<int>(state.lines.size()));
    state.lines.push_back(std::move(l));
  }
  add_to_set(state.line_sets, params.name("ELSET"), added);
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
  bool warned_z = false, warned_normal = false;
  for (const DataLine& line : block.data) {
    const SourceLocation at = line.where();
    // Empty or missing coordinates are 0, as CalculiX reads them. Fields 5-7
    // are ABAQUS's normal direction (shells and beams only; CalculiX ignores them).
    const auto f = data_fields(line, 1, 7, "`label, x, y[, z[, nx, ny, nz]]`");
    const int label = parse_label(f[0], at, "node label");
    const double x = f.size() < 2 || f[1].empty() ? 0.0 : parse_real(f[1], at, "x coordinate");
    const double y = f.size() < 3 || f[2].empty() ? 0.0 : parse_real(f[2], at, "y coordinate");
    if (f.size() >= 4 && !f[3].empty() && parse_real(f[3], at, "z coordinate") != 0.0 && !warned_z) {
      state.warn(at, "non-zero z coordinate ignored: tether models are 2D (x, y)");
      warned_z = true;
    }
    for (std::size_t k = 4; k < f.size(); ++k)
      if (!f[k].empty()) (void)parse_real(f[k], at, "normal direction component");
    if (f.size() > 4 && !warned_normal) {
      state.warn(at, "fields 5-7 of *NODE (a normal direction in ABAQUS, for shells and beams; CalculiX ignores "
                     "them) are ignored: tether's continuum elements use no nodal normals");
      warned_normal = true;
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
  if (const int n = line_element_nodes(type_name); n > 0) return read_line_elements(state, block, params, n);
  const auto type = find_element_type(type_name);
  if (!type)
    throw InputError(block.where, "unsupported element type " + type_name + ": " + unknown_element_reason(type_name));
  if (const std::string reason = unsupported_reason(*type); !reason.empty())
    throw InputError(block.where, "unsupported element type " + type_name + ": " + reason);

  std::vector<int> added;
  for (const ElementRow& row : element_rows(block, type->n_nodes, type_name)) {
    Element e;
    e.id = parse_label(row.fields[0], row.where, "element label");
    e.type = *type;
    e.where = m.deck_line(row.where);
    for (std::size_t i = 1; i < row.fields.size(); ++i)
      e.nodes.push_back(element_node(m, row.fields[i], row.fields[0], row.where));
    check_new_element_label(state, e.id, row.where);
    m.element_index.emplace(e.id, m.n_elements());
    added.push_back(m.n_elements());
    m.elements.push_back(std::move(e));
  }
  add_to_set(m.element_sets, params.name("ELSET"), added);
}

}  // namespace tether::deck
