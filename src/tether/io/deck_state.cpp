#include "tether/io/deck_state.hpp"

#include <algorithm>
#include <charconv>

#include "tether/io/numbers.hpp"

namespace tether::deck {

void DeckState::warn(const SourceLocation& where, std::string message) const {
  if (warnings) warnings->push_back({where, std::move(message)});
}

int DeckState::node(int label, const SourceLocation& where) const {
  const auto it = model.node_index.find(label);
  if (it == model.node_index.end())
    throw InputError(where, "undefined node " + label_text(model.instances, label) + ": expected a node defined by *NODE");
  return it->second;
}

int DeckState::element(int label, const SourceLocation& where) const {
  const auto it = model.element_index.find(label);
  if (it == model.element_index.end())
    throw InputError(where, "undefined element " + label_text(model.instances, label) +
                                ": expected an element defined by *ELEMENT");
  return it->second;
}

const std::vector<int>& DeckState::node_set(std::string_view name, const SourceLocation& where) const {
  const auto it = model.node_sets.find(to_upper(name));
  if (it == model.node_sets.end())
    throw InputError(where, "undefined node set '" + std::string(name) +
                                "': expected a node label or a set defined by *NSET or NSET= (a set named inside "
                                "another set comes first)");
  return it->second;
}

const std::vector<int>& DeckState::element_set(std::string_view name, const SourceLocation& where) const {
  const auto it = model.element_sets.find(to_upper(name));
  if (it == model.element_sets.end() && line_sets.count(to_upper(name)))
    throw InputError(where, "element set '" + std::string(name) + "' holds only line elements (" +
                                lines[static_cast<std::size_t>(line_sets.at(to_upper(name)).front())].type +
                                "), which carry no stiffness in tether: expected a set of solid elements here (a "
                                "set of line elements names faces in *SURFACE, TYPE=ELEMENT, without a face id)");
  if (it == model.element_sets.end())
    throw InputError(where, "undefined element set '" + std::string(name) +
                                "': expected an element label or a set defined by *ELSET or ELSET= (a set named "
                                "inside another set comes first)");
  return it->second;
}

std::vector<int> DeckState::nodes_of(std::string_view token, const SourceLocation& where) const {
  if (is_integer_token(token)) return {node(parse_label(token, where, "node label"), where)};
  return node_set(token, where);
}

std::vector<int> DeckState::elements_of(std::string_view token, const SourceLocation& where) const {
  if (is_integer_token(token)) {
    const int label = parse_label(token, where, "element label");
    if (line_index.count(label) && !model.element_index.count(label))
      throw InputError(where, "element " + label_text(model.instances, label) + " is a line element (" +
                                  lines[static_cast<std::size_t>(line_index.at(label))].type +
                                  "), which carries no stiffness in tether: expected a solid element here (a line "
                                  "element names a face in *SURFACE, TYPE=ELEMENT, without a face id)");
    return {element(label, where)};
  }
  return element_set(token, where);
}

namespace {

/// The line-element index of an integer token, -1 when it is not a line element's label.
int line_label_index(const DeckState& state, std::string_view token) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  int label = 0;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), label);
  if (ec != std::errc() || end != token.data() + token.size()) return -1;
  const auto it = state.line_index.find(label);
  return it == state.line_index.end() ? -1 : it->second;
}

}  // namespace

bool DeckState::names_lines(std::string_view token) const {
  if (is_integer_token(token)) return line_label_index(*this, token) >= 0;
  return line_sets.count(to_upper(token)) > 0;
}

std::vector<int> DeckState::lines_of(std::string_view token) const {
  if (!names_lines(token)) return {};
  if (is_integer_token(token)) return {line_label_index(*this, token)};
  return line_sets.at(to_upper(token));
}

int DeckState::amplitude(std::string_view name, const SourceLocation& where) const {
  if (name.empty()) return -1;
  const std::string key = to_upper(name);
  for (std::size_t i = 0; i < model.amplitudes.size(); ++i)
    if (model.amplitudes[i].name == key) return static_cast<int>(i);
  throw InputError(where, "undefined amplitude '" + std::string(name) +
                              "': expected the name of an *AMPLITUDE in the model data");
}

std::vector<std::string> data_fields(const DataLine& line, std::size_t min_fields, std::size_t max_fields,
                                     std::string_view what) {
  std::vector<std::string> f = split_data_line(line.text).fields;
  while (f.size() > min_fields && f.back().empty()) f.pop_back();
  if (f.size() < min_fields || (min_fields > 0 && f[0].empty()) ||
      (max_fields > 0 && f.size() > max_fields))
    throw InputError(line.where(), "expected " + std::string(what) + " but found '" + line.text + "'");
  return f;
}

void require_data(const KeywordBlock& block, std::string_view what) {
  if (block.data.empty())
    throw InputError(block.where, "*" + block.keyword + " needs a data line: expected " + std::string(what));
}

/// Face id "S1".."S4" (0-based result), checked against the element's shape.
int parse_face_id(const std::string& token, const Model& model, const Element& e, const SourceLocation& at,
                  char prefix) {
  const std::string t = to_upper(token);
  const int n = n_faces(e.type.shape);
  if (t.size() == 2 && t[0] == prefix && t[1] >= '1' && t[1] <= '0' + n) return t[1] - '1';
  throw InputError(at, "bad face '" + token + "' for element " + label_text(model.instances, e.id) + " (" +
                           std::string(e.type.name) + "): expected " + prefix + "1.." + prefix +
                           std::to_string(n));
}

void sort_unique(std::vector<int>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

}  // namespace tether::deck
