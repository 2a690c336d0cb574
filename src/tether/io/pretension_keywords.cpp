// *PRE-TENSION SECTION: a bolt's cut with its pretension node. The handler
// cuts the mesh along the surface (constraints/pretension_section.hpp) and
// writes the cut's equations as one Linear constraint enforced by multipliers.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "tether/constraints/pretension_section.hpp"
#include "tether/io/deck_state.hpp"
#include "tether/io/keyword_handlers.hpp"
#include "tether/io/numbers.hpp"

namespace tether::deck {

namespace {

std::string node_text(const Model& model, int node) {
  return label_text(model.instances, model.node_ids[static_cast<std::size_t>(node)]);
}

/// The element-face surface SURFACE= names; InputError otherwise.
const Surface& section_surface(const DeckState& state, const std::string& name, const SourceLocation& at) {
  const auto it = state.model.surfaces.find(name);
  if (it == state.model.surfaces.end())
    throw InputError(at, "undefined surface '" + name + "' in SURFACE=: expected a surface defined by *SURFACE");
  if (it->second.kind != Surface::Kind::ElementFaces || it->second.faces.empty())
    throw InputError(at, "surface '" + name + "' is made of nodes: a pre-tension section is cut along element "
                         "faces (*SURFACE, TYPE=ELEMENT)");
  for (const PretensionSection& p : state.model.pretension_sections)
    if (p.surface == name)
      throw InputError(at, "surface '" + name + "' already cuts the pre-tension section at " + p.where.str() +
                           ": expected one section per surface");
  return it->second;
}

/// The pretension node NODE= names (a label or a one-node set): a node no
/// element and no other section uses.
int pretension_node(const DeckState& state, const std::string& token, const SourceLocation& at) {
  const std::vector<int> nodes = state.nodes_of(token, at);
  if (nodes.size() != 1)
    throw InputError(at, "NODE=" + token + " names " + std::to_string(nodes.size()) +
                         " nodes: expected one pretension node (a label or a set of one node)");
  const int node = nodes.front();
  const Model& model = state.model;
  for (const Element& e : model.elements)
    if (std::find(e.nodes.begin(), e.nodes.end(), node) != e.nodes.end())
      throw InputError(at, "pretension node " + node_text(model, node) + " belongs to element " +
                           label_text(model.instances, e.id) +
                           ": expected a separate node that no element uses (its dof 1 is the bolt's tightening)");
  for (const PretensionSection& p : model.pretension_sections)
    if (p.node == node)
      throw InputError(at, "node " + node_text(model, node) + " is already the pretension node of the section at " +
                           p.where.str() + ": expected one pretension node per section");
  return node;
}

/// The section's normal: the data line's `nx, ny[, nz]` (normalised), else
/// the mean outward normal of the faces.
Eigen::Vector2d section_normal(const DeckState& state, const KeywordBlock& block, const Surface& surface) {
  if (block.data.size() > 1)
    throw InputError(block.data[1].where(), "a second data line under *PRE-TENSION SECTION: expected at most one "
                                            "line, the section's normal `nx, ny[, nz]`");
  if (block.data.empty()) {
    const Eigen::Vector2d n = mean_outward_normal(state.model, surface.faces);
    if (n.isZero())
      throw InputError(block.where, "the faces of surface '" + surface.name + "' have no mean normal (they cancel "
                                    "out): give the section's normal on a data line `nx, ny, 0`");
    return n;
  }
  const DataLine& line = block.data.front();
  const SourceLocation at = line.where();
  const auto f = data_fields(line, 2, 3, "the section's normal `nx, ny[, nz]`");
  const Eigen::Vector2d n(parse_real(f[0], at, "normal x"), parse_real(f[1], at, "normal y"));
  if (f.size() == 3 && !f[2].empty() && parse_real(f[2], at, "normal z") != 0)
    throw InputError(at, "the section's normal has a z component: tether is 2D; expected `nx, ny, 0`");
  if (!(n.norm() > 0)) throw InputError(at, "the section's normal is zero: expected a direction `nx, ny, 0`");
  return n.normalized();
}

}  // namespace

void handle_pre_tension_section(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  if (params.given("ELEMENT"))
    throw InputError(block.where, "ELEMENT= pre-tensions a truss or beam bolt, and tether has only 2D continuum "
                                  "elements: cut a continuum bolt with SURFACE= instead");
  if (!params.given("SURFACE"))
    throw InputError(block.where, "*PRE-TENSION SECTION needs SURFACE= (the element faces that cut the bolt)");
  const Surface& surface = section_surface(state, params.name("SURFACE"), block.where);
  const int node = pretension_node(state, params.text("NODE"), block.where);
  PretensionSection section;
  section.surface = surface.name;
  section.node = node;
  section.normal = section_normal(state, block, surface);
  section.where = block.where;
  section.constraint = "PRETENSION-" + surface.name;
  const std::vector<ElementFace> faces = surface.faces;  // the cut adds nodes, not faces
  try {
    section.pairs = cut_mesh_along(state.model, faces, section.normal);
  } catch (const std::invalid_argument& e) {
    throw InputError(block.where, std::string(e.what()));
  }
  ConstraintData c;
  c.kind = ConstraintData::Kind::Linear;
  c.name = section.constraint;
  c.rows = pretension_equations(section.pairs, section.normal, node);
  for (const auto& [a, b] : section.pairs) c.nodes.push_back(a), c.nodes.push_back(b);
  c.nodes.push_back(node);
  c.where = block.where;
  state.model.constraints.push_back(std::move(c));
  state.model.pretension_sections.push_back(std::move(section));
}

void check_pretension_loads(const DeckState& state) {
  const Model& model = state.model;
  for (const PretensionSection& p : model.pretension_sections)
    for (const Step& step : model.steps) {
      for (const Prescribed& b : step.boundary)
        if (b.node == p.node && b.dof != 0)
          throw InputError(b.where, "dof " + std::to_string(b.dof + 1) + " of pretension node " +
                                        node_text(model, p.node) + " (section at " + p.where.str() +
                                        "): a pretension node has dof 1 only, the tightening");
      for (const ConcentratedLoad& l : step.cloads)
        if (l.node == p.node && l.dof != 0)
          throw InputError(l.where, "load on dof " + std::to_string(l.dof + 1) + " of pretension node " +
                                        node_text(model, p.node) + " (section at " + p.where.str() +
                                        "): a pretension node has dof 1 only; its load is the bolt force");
    }
}

}  // namespace tether::deck
