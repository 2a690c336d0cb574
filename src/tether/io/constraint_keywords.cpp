// *EQUATION, *MPC and *CONSTRAINT: constraints as model data, with tether's
// ENFORCEMENT= extension parameters.
#include <filesystem>

#include "tether/io/constraint_params.hpp"
#include "tether/io/deck_state.hpp"
#include "tether/io/keyword_handlers.hpp"
#include "tether/io/numbers.hpp"

namespace tether::deck {

namespace {

std::string default_name(const DeckState& state, const std::string& what) {
  return what + "-" + std::to_string(state.model.constraints.size() + 1);
}

/// The LIBRARY= path, relative to the directory of the deck line's file. A
/// deck named without a directory ("deck.inp") gives "./libx.so", not
/// "libx.so": dlopen() searches the system library path for a name without
/// '/', so it would miss the library next to the deck and could load another
/// of the same name.
std::string library_path(const std::string& library, const std::string& deck_file) {
  std::filesystem::path path(library);
  if (path.is_relative()) {
    std::filesystem::path dir = std::filesystem::path(deck_file).parent_path();
    if (dir.empty()) dir = ".";
    path = dir / path;
  }
  return path.string();
}

}  // namespace

void handle_equation(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  const Enforcement enforcement = read_enforcement(params, block.where, true);
  std::size_t k = 0;
  const std::size_t n_lines = block.data.size();
  if (n_lines == 0) throw InputError(block.where, "*EQUATION needs data lines: the number of terms, then the terms");
  while (k < n_lines) {
    const DataLine& count_line = block.data[k++];
    const auto count_fields = split_data_line(count_line.text).fields;
    const int n_terms = parse_int(count_fields.at(0), count_line.where(), "number of terms");
    if (n_terms < 1 || n_terms > 10000)
      throw InputError(count_line.where(), "number of terms " + std::to_string(n_terms) + ": expected 1..10000");
    if (count_fields.size() > 1 && !count_fields[1].empty())
      throw InputError(count_line.where(), "expected only the number of terms on this line, got '" +
                                               count_line.text + "'");
    // Terms: node (label or set), dof, coefficient; up to four per line.
    struct RawTerm {
      std::vector<int> nodes;
      int dof;
      double coefficient;
      SourceLocation at;
    };
    std::vector<RawTerm> raw;
    while (static_cast<int>(raw.size()) < n_terms) {
      if (k >= n_lines)
        throw InputError(count_line.where(), "*EQUATION announces " + std::to_string(n_terms) + " terms but " +
                                                 std::to_string(raw.size()) + " follow");
      const DataLine& line = block.data[k++];
      const auto f = split_data_line(line.text).fields;
      if (f.size() % 3 != 0 || f.size() > 12)
        throw InputError(line.where(), "expected up to four terms 'node, dof, coefficient' on a line, got " +
                                           std::to_string(f.size()) + " fields");
      for (std::size_t i = 0; i < f.size(); i += 3) {
        RawTerm t;
        t.at = line.where();
        t.nodes = state.nodes_of(f[i], t.at);
        const int dof = parse_int(f[i + 1], t.at, "dof");
        if (dof < 1 || dof > 2)
          throw InputError(t.at, "dof " + std::to_string(dof) + " in *EQUATION: expected 1 or 2 (2D models)");
        t.dof = dof - 1;
        t.coefficient = parse_real(f[i + 2], t.at, "coefficient");
        if (t.coefficient == 0) throw InputError(t.at, "coefficient of term " + std::to_string(raw.size() + 1) + " is zero");
        raw.push_back(std::move(t));
      }
      if (static_cast<int>(raw.size()) > n_terms)
        throw InputError(line.where(), "*EQUATION announces " + std::to_string(n_terms) + " terms but " +
                                           std::to_string(raw.size()) + " are given");
    }
    // Node sets apply the equation member by member (all sets equally long).
    std::size_t members = 1;
    for (const auto& t : raw) {
      if (t.nodes.size() == 1) continue;
      if (members != 1 && t.nodes.size() != members)
        throw InputError(t.at, "node sets in one *EQUATION must have the same number of nodes (" +
                                   std::to_string(members) + " and " + std::to_string(t.nodes.size()) + ")");
      members = t.nodes.size();
    }
    for (std::size_t m = 0; m < members; ++m) {
      ConstraintData c;
      c.kind = ConstraintData::Kind::Equation;
      c.where = count_line.where();
      c.enforcement = enforcement;
      if (params.given("NAME")) {
        c.name = params.name("NAME");
        if (members > 1) c.name.append("-").append(std::to_string(m + 1));  // not "-" + ...: GCC 12 -Wrestrict
      } else {
        c.name = default_name(state, "EQUATION");
      }
      for (const auto& t : raw) c.terms.push_back({t.nodes.size() == 1 ? t.nodes[0] : t.nodes[m], t.dof, t.coefficient});
      state.model.constraints.push_back(std::move(c));
    }
  }
}

namespace {

/// *MPC, USER: ABAQUS-style routine; data lines `JTYPE, node1, node2, ...`
/// (a trailing comma continues the node list on the next line).
void read_user_mpc(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  const std::string library = params.text("LIBRARY");
  if (library.empty()) throw InputError(block.where, "*MPC, USER needs LIBRARY=path of the shared library");
  const std::string path = library_path(library, block.where.file);
  const Enforcement enforcement = read_enforcement(params, block.where, false);
  for (std::size_t k = 0; k < block.data.size();) {
    ConstraintData c;
    c.kind = ConstraintData::Kind::UserMpc;
    c.where = block.data[k].where();
    c.library = path;
    c.symbol = params.given("SYMBOL") ? params.text("SYMBOL") : "tether_user_mpc";
    c.node_mode = params.name("MODE") == "NODE";
    c.enforcement = enforcement;
    bool first = true;
    for (bool more = true; more;) {
      if (k >= block.data.size()) throw InputError(c.where, "the node list of *MPC, USER ends with ','");
      const DataLine& line = block.data[k++];
      const DataFields fields = split_data_line(line.text);
      for (const std::string& token : fields.fields) {
        if (token.empty()) continue;
        if (first) {
          c.flag = parse_int(token, line.where(), "JTYPE (the user MPC type)");
          first = false;
        } else {
          c.nodes.push_back(single_node(state, token, line.where()));
        }
      }
      more = fields.trailing_comma;
    }
    if (c.nodes.empty()) throw InputError(c.where, "*MPC, USER line needs 'JTYPE, node1, node2, ...'");
    c.name = params.given("NAME") ? params.name("NAME") : default_name(state, "MPC") + " USER " + std::to_string(c.flag);
    if (params.given("NAME") && block.data.size() > 1)
      c.name.append("-").append(std::to_string(state.model.constraints.size() + 1));
    state.model.constraints.push_back(std::move(c));
  }
}

}  // namespace

void handle_mpc(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  if (block.data.empty()) throw InputError(block.where, "*MPC needs data lines 'TYPE, node, node, ...'");
  if (params.given("USER")) return read_user_mpc(state, block, params);
  for (const DataLine& line : block.data) {
    const auto f = split_data_line(line.text).fields;
    const std::string type = normalize_name(f.at(0));
    ConstraintData c;
    c.where = line.where();
    std::size_t n_nodes = 2;
    if (type == "TIE" || type == "PIN") {
      c.kind = ConstraintData::Kind::Tie;
    } else if (type == "LINK") {
      c.kind = ConstraintData::Kind::Link;
    } else if (type == "SLIDER") {
      c.kind = ConstraintData::Kind::Slider;
      n_nodes = 3;
    } else if (type == "BEAM") {
      c.kind = ConstraintData::Kind::Beam;
    } else {
      throw InputError(c.where, "unknown *MPC type '" + f.at(0) + "': expected TIE, PIN, LINK, SLIDER or BEAM");
    }
    if (f.size() != n_nodes + 1)
      throw InputError(c.where, "*MPC " + type + " takes " + std::to_string(n_nodes) + " nodes, got " +
                                    std::to_string(f.size() - 1));
    for (std::size_t i = 1; i < f.size(); ++i) c.nodes.push_back(single_node(state, f[i], c.where));
    for (std::size_t i = 0; i < c.nodes.size(); ++i)
      for (std::size_t j = i + 1; j < c.nodes.size(); ++j)
        if (c.nodes[i] == c.nodes[j]) throw InputError(c.where, "*MPC " + type + " names node " + f[i + 1] + " twice");
    c.enforcement = read_enforcement(params, block.where, c.kind == ConstraintData::Kind::Tie);
    c.name = params.given("NAME") && block.data.size() == 1 ? params.name("NAME")
                                                             : default_name(state, "MPC") + " " + type;
    state.model.constraints.push_back(std::move(c));
  }
}

void handle_constraint(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  ConstraintData c;
  c.where = block.where;
  const std::string type = params.name("TYPE");
  c.kind = type == "USER" ? ConstraintData::Kind::User : ConstraintData::Kind::Expression;
  c.name = params.given("NAME") ? params.name("NAME") : default_name(state, type);
  if (block.data.empty())
    throw InputError(block.where, "*CONSTRAINT needs a data line with its node labels");
  // First data line(s): the nodes; a trailing comma continues the list.
  std::size_t k = 0;
  for (bool more = true; more;) {
    if (k >= block.data.size()) throw InputError(block.where, "the node list of *CONSTRAINT ends with ','");
    const DataLine& line = block.data[k++];
    const DataFields fields = split_data_line(line.text);
    for (const std::string& token : fields.fields)
      if (!token.empty()) c.nodes.push_back(single_node(state, token, line.where()));
    more = fields.trailing_comma;
  }
  if (params.given("NODES") && params.integer("NODES") != static_cast<int>(c.nodes.size()))
    throw InputError(block.data.front().where(), "NODES=" + std::to_string(params.integer("NODES")) + " but " +
                                                     std::to_string(c.nodes.size()) + " node labels are given");
  if (c.kind == ConstraintData::Kind::User) {
    c.enforcement = read_enforcement(params, block.where, false);
    if (c.enforcement.method != Enforcement::Method::Lagrange)
      throw InputError(block.where, "TYPE=USER constraints return their own residual and stiffness: only "
                                    "ENFORCEMENT=LAGRANGE applies");
    std::string library = params.text("LIBRARY");
    if (library.empty()) throw InputError(block.where, "TYPE=USER needs LIBRARY=path of the shared library");
    c.library = library_path(library, block.where.file);
    c.symbol = params.given("SYMBOL") ? params.text("SYMBOL") : "tether_user_constraint";
    c.n_multipliers = params.integer("MULTIPLIERS");
    c.flag = params.integer("FLAG");
    if (c.n_multipliers < 1 || c.n_multipliers > 64)
      throw InputError(block.where, "MULTIPLIERS=" + std::to_string(c.n_multipliers) + ": expected 1..64");
    for (; k < block.data.size(); ++k) {
      const DataLine& line = block.data[k];
      for (const std::string& token : split_data_line(line.text).fields)
        if (!token.empty()) c.properties.push_back(parse_real(token, line.where(), "property"));
    }
  } else {
    c.enforcement = read_enforcement(params, block.where, false);
    for (; k < block.data.size(); ++k) {
      c.formulas.push_back(block.data[k].text);
      c.formula_where.push_back(block.data[k].where());
    }
    if (c.formulas.empty())
      throw InputError(block.where, "TYPE=EXPRESSION needs one formula line per equation after the node list");
  }
  state.model.constraints.push_back(std::move(c));
}

}  // namespace tether::deck
