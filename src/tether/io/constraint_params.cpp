#include "tether/io/constraint_params.hpp"

namespace tether::deck {

Enforcement read_enforcement(const ParameterValues& params, const SourceLocation& at, bool linear) {
  Enforcement e;
  const std::string method = params.name("ENFORCEMENT");
  if (method == "PENALTY")
    e.method = Enforcement::Method::Penalty;
  else if (method == "AUGMENTED")
    e.method = Enforcement::Method::Augmented;
  else if (method == "ELIMINATION")
    e.method = Enforcement::Method::Elimination;
  e.epsilon = params.real("EPSILON");
  e.penalty = params.real("PENALTY");
  e.tolerance = params.real("TOLERANCE");
  if (e.epsilon < 0) throw InputError(at, "EPSILON must be >= 0");
  if (e.tolerance < 0) throw InputError(at, "TOLERANCE must be >= 0");
  if ((e.method == Enforcement::Method::Penalty || e.method == Enforcement::Method::Augmented) && !(e.penalty > 0))
    throw InputError(at, "ENFORCEMENT=" + method + " needs PENALTY=rho > 0 (the penalty stiffness)");
  if (e.method == Enforcement::Method::Elimination && !linear)
    throw InputError(at, "ENFORCEMENT=ELIMINATION needs a linear constraint (*EQUATION, *MPC TIE or PIN, *TIE, "
                         "*PERIODIC)");
  if (params.given("EPSILON") && e.method != Enforcement::Method::Lagrange)
    throw InputError(at, "EPSILON applies to ENFORCEMENT=LAGRANGE only");
  return e;
}

int single_node(const DeckState& state, const std::string& token, const SourceLocation& at, std::string_view what) {
  const std::vector<int> nodes = state.nodes_of(token, at);
  if (nodes.size() != 1) {
    const std::string name = what.empty() ? "'" + token + "'" : std::string(what) + "='" + token + "'";
    throw InputError(at, name + " names " + std::to_string(nodes.size()) +
                             " nodes; expected a node label or a set with one node");
  }
  return nodes[0];
}

}  // namespace tether::deck
