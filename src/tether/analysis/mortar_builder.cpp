#include "tether/analysis/mortar_builder.hpp"

#include <algorithm>
#include <map>
#include <set>

#include "tether/core/error.hpp"
#include "tether/model/part_instance.hpp"

namespace tether {

namespace {

std::vector<int> face_node_indices(const Model& model, const ElementFace& f) {
  const Element& e = model.elements[static_cast<std::size_t>(f.element)];
  std::vector<int> nodes;
  for (int local : face_nodes(e.type.shape, f.face))
    if (local >= 0) nodes.push_back(e.nodes[static_cast<std::size_t>(local)]);
  return nodes;
}

/// What mortar contact does not model in the pair's interaction: empty when all is supported.
std::string unsupported_law(const SurfaceInteraction& interaction) {
  const PressureOverclosure& law = interaction.behavior;
  if (law.law == PressureOverclosure::Law::Hard &&
      (law.enforcement.method != Enforcement::Method::Lagrange || law.enforcement.epsilon > 0))
    return "a penalty, augmented or regularised HARD law (mortar contact enforces HARD exactly by "
           "multipliers; TYPE=NODE TO SURFACE models those)";
  if (interaction.friction && interaction.friction->mu > 0 &&
      (interaction.friction->stick_slope > 0 || interaction.friction->elastic_slip > 0))
    return "a stick slope or ELASTIC SLIP on *FRICTION (mortar friction enforces stick exactly by a multiplier; "
           "TYPE=NODE TO SURFACE models the stick penalty)";
  return "";
}

}  // namespace

std::unique_ptr<MortarPair> make_mortar_pair(const Model& model, const ContactPairData& data,
                                             const std::vector<Eigen::Vector2d>& reference, DofMap& dofs) {
  const std::string where = " (*CONTACT PAIR, TYPE=SURFACE TO SURFACE at " + data.where.str() + ")";
  const Surface& slave = model.surfaces.at(data.slave);
  const Surface& master = model.surfaces.at(data.master);
  const auto interaction = std::find_if(model.interactions.begin(), model.interactions.end(),
                                        [&](const SurfaceInteraction& s) { return s.name == data.interaction; });
  if (interaction == model.interactions.end()) throw ModelError("undefined interaction " + data.interaction + where);
  if (const std::string why = unsupported_law(*interaction); !why.empty())
    throw ModelError("*SURFACE INTERACTION " + interaction->name + " (" + interaction->where.str() + ") has " + why +
                     where);
  if (slave.kind != Surface::Kind::ElementFaces)
    throw ModelError("slave surface " + data.slave + " is node-based: mortar contact integrates over the slave "
                     "faces, so it needs a surface of element faces (TYPE=ELEMENT)" + where);
  if (data.smoothing > 0)
    throw ModelError("SMOOTH applies to node-to-surface contact only: mortar contact integrates the master faces "
                     "as they are" + where);

  MortarPairSetup setup;
  setup.name = "CONTACT PAIR " + data.slave + "-" + data.master;
  double longest = 0, stiffness = 0;
  const auto add_face = [&](const ElementFace& f, const std::string& role) {
    const Element& e = model.elements[static_cast<std::size_t>(f.element)];
    if (e.type.family == Family::Axisymmetric)
      throw ModelError(role + " surface face of element " + std::to_string(e.id) + " (" + std::string(e.type.name) +
                       "): mortar contact does not model axisymmetric faces yet" + where);
    std::vector<int> nodes = face_node_indices(model, f);
    longest = std::max(longest, (reference[static_cast<std::size_t>(nodes[1])] -
                                 reference[static_cast<std::size_t>(nodes[0])]).norm());
    const double thickness = e.section >= 0 ? model.sections[static_cast<std::size_t>(e.section)].thickness : 1.0;
    if (e.section >= 0)
      stiffness = std::max(stiffness, thickness * model.materials[static_cast<std::size_t>(
                                                      model.sections[static_cast<std::size_t>(e.section)].material)]
                                                      .modulus());
    return std::pair{nodes, thickness};
  };
  for (const ElementFace& f : slave.faces) {
    auto [nodes, thickness] = add_face(f, "slave");
    setup.slave_faces.push_back(std::move(nodes));
    setup.slave_thickness.push_back(thickness);
  }
  for (const ElementFace& f : master.faces) {
    setup.master_faces.push_back(add_face(f, "master").first);
    setup.master_face_labels.emplace_back(model.elements[static_cast<std::size_t>(f.element)].id, f.face + 1);
  }
  if (setup.slave_faces.empty()) throw ModelError("slave surface " + data.slave + " has no faces" + where);
  if (setup.master_faces.empty()) throw ModelError("master surface " + data.master + " has no faces" + where);
  // The averaged normals and the kinematics of a term (contact/dual2.hpp's
  // fixed number of variables) assume a chain of slave faces.
  std::map<int, int> faces_at;
  for (const auto& face : setup.slave_faces)
    for (int node : face) ++faces_at[node];
  for (const auto& [node, count] : faces_at)
    if (count > 2)
      throw ModelError("node " + label_text(model.instances, model.node_ids[static_cast<std::size_t>(node)]) + " is on " +
                       std::to_string(count) + " faces of the slave surface " + data.slave + where +
                       ": mortar contact needs a slave surface that is a chain of faces (each node on at most two)");
  std::set<int> master_nodes;
  for (const auto& f : setup.master_faces) master_nodes.insert(f.begin(), f.end());
  const std::vector<int> slave_nodes = MortarPair::slave_nodes_of(setup.slave_faces);
  for (int node : slave_nodes)
    if (master_nodes.count(node))
      throw ModelError("node " + label_text(model.instances, model.node_ids[static_cast<std::size_t>(node)]) +
                       " belongs to both the slave surface " + data.slave + " and the master surface " + data.master +
                       where + ": contact is between distinct surfaces; split the node or the surfaces");
  for (int node : slave_nodes)
    setup.slave_names.push_back(label_text(model.instances, model.node_ids[static_cast<std::size_t>(node)]));
  setup.search_radius = 2 * longest + data.adjust;
  setup.complementarity_stiffness = stiffness > 0 ? stiffness : 1.0;
  setup.mu = interaction->friction ? interaction->friction->mu : 0.0;
  setup.law = interaction->behavior;
  const int first = dofs.add_multipliers(MortarPair::multipliers_per_slave(setup.mu) * static_cast<int>(slave_nodes.size()),
                                         "mortar contact pair " + data.slave + "-" + data.master);
  return std::make_unique<MortarPair>(std::move(setup), reference, first);
}

std::vector<int> mortar_equations(const std::vector<std::unique_ptr<MortarPair>>& pairs, const DofMap& dofs,
                                  const EquationMap& equations) {
  std::vector<int> out;
  const auto add = [&](int dof) {
    for (const EquationWeight& w : equations.weights(dof)) out.push_back(w.equation);
  };
  const auto add_faces = [&](const std::vector<std::vector<int>>& faces) {
    for (const auto& face : faces)
      for (int node : face)
        for (int c = 0; c < kDofsPerNode; ++c) add(dofs.displacement(node, c));
  };
  for (const auto& pair : pairs) {
    add_faces(pair->setup().slave_faces);
    add_faces(pair->setup().master_faces);
    for (int i = 0; i < pair->n_slaves(); ++i) {
      add(pair->slave(i).multiplier);
      if (pair->slave(i).tangent_multiplier >= 0) add(pair->slave(i).tangent_multiplier);
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<DualNodeEquations> mortar_dual_equations(const std::vector<std::unique_ptr<MortarPair>>& pairs,
                                                     const DofMap& dofs, const EquationMap& equations) {
  const auto single = [&](int dof) {
    const auto w = equations.weights(dof);
    return w.size() == 1 && w[0].weight == 1 ? w[0].equation : -1;
  };
  std::vector<DualNodeEquations> out;
  for (const auto& pair : pairs)
    for (int i = 0; i < pair->n_slaves(); ++i) {
      const MortarSlave& s = pair->slave(i);
      out.push_back({single(s.multiplier), {single(dofs.displacement(s.node, 0)), single(dofs.displacement(s.node, 1))}});
    }
  return out;
}

}  // namespace tether
