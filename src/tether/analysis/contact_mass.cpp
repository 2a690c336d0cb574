#include "tether/analysis/contact_mass.hpp"

#include <fmt/format.h>

#include "tether/contact/contact_pair.hpp"
#include "tether/contact/mortar_pair.hpp"

namespace tether {

namespace {

/// Flags every node of the contact surfaces of `disc` (node indices).
std::vector<bool> contact_surface_nodes(const Discretization& disc) {
  std::vector<bool> on(static_cast<std::size_t>(disc.dofs().n_nodes()), false);
  const auto mark_faces = [&](const std::vector<std::vector<int>>& faces) {
    for (const auto& face : faces)
      for (const int node : face) on[static_cast<std::size_t>(node)] = true;
  };
  for (const auto& pair : disc.contact_pairs()) {
    for (const int node : pair->setup().slave_nodes) on[static_cast<std::size_t>(node)] = true;
    mark_faces(pair->setup().master_faces);
  }
  for (const auto& pair : disc.mortar_pairs()) {
    mark_faces(pair->setup().slave_faces);
    mark_faces(pair->setup().master_faces);
  }
  return on;
}

}  // namespace

std::string ContactMassSummary::describe() const {
  if (nodes == 0) return "";
  std::string line = fmt::format(
      "impact: the mass of {} contact-surface node(s) moved to the other nodes of their {} element(s) "
      "(mass redistribution; *DYNAMIC, CONTACT MASS=KEPT turns it off)",
      nodes, elements);
  if (kept > 0)
    line += fmt::format("; {} element(s) with every node on a contact surface keep their mass", kept);
  return line;
}

ContactMassSummary redistribute_contact_mass(const Discretization& disc,
                                             const std::vector<std::unique_ptr<ElementInertia>>& inertia) {
  const std::vector<bool> on = contact_surface_nodes(disc);
  ContactMassSummary summary;
  for (const bool b : on) summary.nodes += b ? 1 : 0;
  if (summary.nodes == 0) return summary;
  for (const auto& m : inertia) {
    const std::span<const int> nodes = m->element().nodes();
    std::vector<bool> massless(nodes.size());
    bool any = false;
    for (std::size_t a = 0; a < nodes.size(); ++a) any |= (massless[a] = on[static_cast<std::size_t>(nodes[a])]);
    if (!any) continue;
    if (m->redistribute(massless))
      ++summary.elements;
    else
      ++summary.kept;
  }
  return summary;
}

}  // namespace tether
