#include "tether/analysis/contact_builder.hpp"

#include <algorithm>
#include <map>
#include <numbers>
#include <set>

#include "tether/core/error.hpp"
#include "tether/fem/quadrature.hpp"
#include "tether/fem/shape_functions.hpp"

namespace tether {

namespace {

/// Out-of-plane measure of the element at reference point x: thickness, or 2πr (CAX).
double measure(const Model& model, const Element& e, const Eigen::Vector2d& x) {
  if (e.type.family == Family::Axisymmetric) return 2 * std::numbers::pi * x.x();
  return e.section >= 0 ? model.sections[static_cast<std::size_t>(e.section)].thickness : 1.0;
}

/// A stiffness of the element's material [stress] (MaterialData::modulus), 0 without a section.
double modulus(const Model& model, const Element& e) {
  if (e.section < 0) return 0;
  return model.materials[static_cast<std::size_t>(model.sections[static_cast<std::size_t>(e.section)].material)]
      .modulus();
}

std::vector<int> face_node_indices(const Model& model, const ElementFace& f) {
  const Element& e = model.elements[static_cast<std::size_t>(f.element)];
  std::vector<int> nodes;
  for (int local : face_nodes(e.type.shape, f.face))
    if (local >= 0) nodes.push_back(e.nodes[static_cast<std::size_t>(local)]);
  return nodes;
}

/// CalculiX's defaults of its LINEAR law: K = 50 E, sigma_inf = E/70000, E
/// of the deck's first material (CalculiX's elcon(1,1,1)).
void resolve_calculix_linear(const Model& model, const SurfaceInteraction& interaction, PressureOverclosure& law) {
  if (law.stiffness > 0 && law.sigma_inf > 0) return;
  if (model.materials.empty() || !model.materials.front().elastic)
    throw ModelError("PRESSURE-OVERCLOSURE=LINEAR (*SURFACE BEHAVIOR at " + interaction.where.str() +
                     ") leaves K or sigma_inf to CalculiX's defaults (50 E, E/70000), which take E from the first "
                     "material; the first material has no *ELASTIC: give 'K, sigma_inf'");
  const double young = model.materials.front().elastic->young;
  if (!(law.stiffness > 0)) law.stiffness = 50 * young;
  if (!(law.sigma_inf > 0)) law.sigma_inf = young / 70000;
}

/// The area CalculiX gives each node of a node-based slave surface (dialect
/// calculix): CalculiX expands the 2D mesh to one layer of 3D elements and
/// shares every free face of that layer among its nodes (1/4 per node of a
/// 4-node face, 1/3 of a 3-node one). A 2D node stands for its two 3D nodes,
/// so its area is L t / 2 for each free edge of length L (t: thickness)
/// through it plus, from the front and back faces, A_e / 2 (quadrilateral) or
/// 2 A_e / 3 (triangle) for each element of area A_e it belongs to. Linear
/// plane elements only (ModelError otherwise: CalculiX's shares on quadratic
/// and axisymmetric faces are not modelled). Measured against ccx 2.20 on two
/// CPE4 blocks: the same displacements as with these areas given by hand.
std::map<int, double> calculix_node_areas(const Model& model, const Surface& slave, const std::string& where) {
  std::map<std::pair<int, int>, std::pair<int, double>> edges;  // corner pair -> (count, L t / 2)
  std::map<int, double> area;
  for (int n : slave.nodes) area[n] = 0;
  for (const Element& e : model.elements) {
    const int corners = n_corners(e.type.shape);
    const bool uses_slave = std::any_of(e.nodes.begin(), e.nodes.end(), [&](int n) { return area.count(n) > 0; });
    if (uses_slave && (e.type.family == Family::Axisymmetric || e.type.shape == Shape::Tri6 || e.type.shape == Shape::Quad8))
      throw ModelError("node-based slave surface " + slave.name + " touches element " + label_text(model.instances, e.id) + " (" +
                       std::string(e.type.name) + "): in the calculix dialect its nodes take CalculiX's areas, which "
                       "tether models for linear plane elements only (CPE3/CPE4/CPS3/CPS4); use an element-face "
                       "surface, or --dialect abaqus (area 1 or as given)" + where);
    double twice_area = 0;  // shoelace over the corners
    for (int a = 0; a < corners; ++a) {
      const Eigen::Vector2d& p = model.coords[static_cast<std::size_t>(e.nodes[static_cast<std::size_t>(a)])];
      const Eigen::Vector2d& q = model.coords[static_cast<std::size_t>(e.nodes[static_cast<std::size_t>((a + 1) % corners)])];
      twice_area += p.x() * q.y() - q.x() * p.y();
      const int i = e.nodes[static_cast<std::size_t>(a)], j = e.nodes[static_cast<std::size_t>((a + 1) % corners)];
      auto& edge = edges[{std::min(i, j), std::max(i, j)}];
      edge.first += 1;
      edge.second = (q - p).norm() * measure(model, e, p) / 2;
    }
    for (int a = 0; a < corners; ++a)
      if (auto it = area.find(e.nodes[static_cast<std::size_t>(a)]); it != area.end())
        it->second += std::abs(twice_area) / corners;  // 2 faces x A_e / corners
  }
  for (const auto& [key, edge] : edges)
    if (edge.first == 1)
      for (int n : {key.first, key.second})
        if (auto it = area.find(n); it != area.end()) it->second += edge.second;
  for (const auto& [n, a] : area)
    if (!(a > 0))
      throw ModelError("node " + label_text(model.instances, model.node_ids[static_cast<std::size_t>(n)]) + " of node-based slave "
                       "surface " + slave.name + " belongs to no element, so it has no area in the calculix dialect" +
                       where);
  return area;
}

}  // namespace

std::unique_ptr<ContactPair> make_contact_pair(const Model& model, const ContactPairData& data,
                                               const std::vector<Eigen::Vector2d>& reference, DofMap& dofs) {
  const std::string where = " (*CONTACT PAIR at " + data.where.str() + ")";
  const Surface& slave = model.surfaces.at(data.slave);
  const Surface& master = model.surfaces.at(data.master);
  const auto interaction = std::find_if(model.interactions.begin(), model.interactions.end(),
                                        [&](const SurfaceInteraction& s) { return s.name == data.interaction; });
  if (interaction == model.interactions.end())
    throw ModelError("undefined interaction " + data.interaction + where);

  ContactPairSetup setup;
  setup.name = "CONTACT PAIR " + data.slave + "-" + data.master;
  setup.law = interaction->behavior;
  setup.friction = interaction->friction;
  setup.small_sliding = data.small_sliding;
  setup.smoothing = data.smoothing;
  if (setup.law.law == PressureOverclosure::Law::Linear && setup.law.meaning == Dialect::Calculix)
    resolve_calculix_linear(model, *interaction, setup.law);
  if (setup.friction && setup.friction->mu > 0 && setup.friction->stick_slope > 0 && setup.friction->elastic_slip > 0)
    throw ModelError("*FRICTION of " + interaction->name + " gives both a stick slope and ELASTIC SLIP; give one");

  double longest = 0, stiffness = 0;
  for (const ElementFace& f : master.faces) {
    const std::vector<int> nodes = face_node_indices(model, f);
    longest = std::max(longest, (reference[static_cast<std::size_t>(nodes[1])] - reference[static_cast<std::size_t>(nodes[0])]).norm());
    setup.master_faces.push_back(nodes);
    setup.master_face_labels.emplace_back(model.elements[static_cast<std::size_t>(f.element)].id, f.face + 1);
  }
  if (setup.master_faces.empty()) throw ModelError("master surface " + data.master + " has no faces" + where);

  // Slave nodes and tributary areas ∫ N_a ds × thickness (2πr for CAX) in the reference configuration.
  std::map<int, double> area;
  setup.node_based_slave = slave.kind == Surface::Kind::Nodes;
  if (slave.kind == Surface::Kind::Nodes) {
    if (model.dialect == Dialect::Calculix) {
      if (std::any_of(slave.node_areas.begin(), slave.node_areas.end(), [](double a) { return a != 1.0; }))
        throw ModelError("node-based slave surface " + slave.name + " gives node areas (" + slave.where.str() +
                         "): CalculiX's *SURFACE, TYPE=NODE has no area field, and in the calculix dialect each "
                         "node's area is CalculiX's (from the free faces at the node)" + where);
      area = calculix_node_areas(model, slave, where);
    } else {
      for (std::size_t i = 0; i < slave.nodes.size(); ++i) area[slave.nodes[i]] = slave.node_areas.at(i);
    }
    for (const Element& e : model.elements) stiffness = std::max(stiffness, modulus(model, e) * measure(model, e, {1, 0}));
  } else {
    for (const ElementFace& f : slave.faces) {
      const Element& e = model.elements[static_cast<std::size_t>(f.element)];
      const std::vector<int> nodes = face_node_indices(model, f);
      const int m = static_cast<int>(nodes.size());
      longest = std::max(longest, (reference[static_cast<std::size_t>(nodes[1])] - reference[static_cast<std::size_t>(nodes[0])]).norm());
      for (const LinePoint& q : line_points(3)) {
        Eigen::Vector3d N, dN;
        face_shape_functions(m, q.s, N, dN);
        Eigen::Vector2d x(0, 0), dx(0, 0);
        for (int a = 0; a < m; ++a)
          x += N[a] * reference[static_cast<std::size_t>(nodes[static_cast<std::size_t>(a)])],
              dx += dN[a] * reference[static_cast<std::size_t>(nodes[static_cast<std::size_t>(a)])];
        const double w = q.weight * dx.norm() * measure(model, e, x);
        for (int a = 0; a < m; ++a) area[nodes[static_cast<std::size_t>(a)]] += N[a] * w;
      }
      const Eigen::Vector2d mid = 0.5 * (reference[static_cast<std::size_t>(nodes[0])] + reference[static_cast<std::size_t>(nodes[1])]);
      stiffness = std::max(stiffness, modulus(model, e) * measure(model, e, mid));
    }
  }
  if (area.empty()) throw ModelError("slave surface " + data.slave + " has no nodes" + where);
  std::set<int> master_nodes;
  for (const auto& f : setup.master_faces) master_nodes.insert(f.begin(), f.end());
  for (const auto& [node, a] : area) {
    if (master_nodes.count(node))
      throw ModelError("node " + label_text(model.instances, model.node_ids[static_cast<std::size_t>(node)]) +
                       " belongs to both the slave surface " + data.slave + " and the master surface " + data.master +
                       where + ": contact is between distinct surfaces; split the node or the surfaces");
    setup.slave_nodes.push_back(node);
    setup.slave_names.push_back(label_text(model.instances, model.node_ids[static_cast<std::size_t>(node)]));
    setup.slave_area.push_back(a);
  }
  setup.search_radius = 2 * longest + data.adjust;
  if (setup.law.enforcement.method == Enforcement::Method::Augmented && setup.law.enforcement.tolerance == 0)
    setup.law.enforcement.tolerance = 1e-8 * longest;
  setup.complementarity_stiffness = stiffness > 0 ? stiffness : 1.0;

  const int per_slave = ContactPair::multipliers_per_slave(setup.law, setup.friction);
  const int first = per_slave > 0 ? dofs.add_multipliers(per_slave * static_cast<int>(setup.slave_nodes.size()),
                                                          "contact pair " + data.slave + "-" + data.master)
                                  : -1;
  return std::make_unique<ContactPair>(std::move(setup), reference, first);
}

std::vector<int> contact_equations(const std::vector<std::unique_ptr<ContactPair>>& pairs, const DofMap& dofs,
                                   const EquationMap& equations) {
  std::vector<int> out;
  const auto add = [&](int dof) {
    if (dof < 0) return;
    for (const EquationWeight& w : equations.weights(dof)) out.push_back(w.equation);
  };
  const auto add_node = [&](int node) {
    for (int c = 0; c < kDofsPerNode; ++c) add(dofs.displacement(node, c));
  };
  for (const auto& pair : pairs) {
    for (int node : pair->setup().slave_nodes) add_node(node);
    for (const auto& face : pair->setup().master_faces)
      for (int node : face) add_node(node);
    for (int i = 0; i < pair->n_slaves(); ++i) add(pair->slave(i).normal_multiplier), add(pair->slave(i).tangent_multiplier);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace tether
