#include "tether/analysis/contact_builder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <set>
#include <span>

#include "tether/contact/calculix_area.hpp"
#include "tether/contact/segment_geometry.hpp"
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

/// The rule of CalculiX's area (calculix_area.hpp) on the faces of element
/// `e`: the thickness of its section for plane elements, CalculiX's 2° wedge
/// for axisymmetric ones.
MasterFaceArea calculix_area_rule(const Model& model, const Element& e) {
  if (e.type.family == Family::Axisymmetric) return {MasterFaceArea::Kind::axisymmetric, 0};
  return {MasterFaceArea::Kind::plane, measure(model, e, {0, 0})};
}

/// The master face nearest to a point and where on it.
struct NearestFace {
  std::size_t face = 0;  ///< index into the master surface's faces
  double xi = 0;         ///< closest point on the face, clamped to [-1, 1]
  double distance = std::numeric_limits<double>::infinity();
};

/// The face of `faces` (node indices) closest to x in the reference
/// configuration `reference`; the first of equally near ones (a point above
/// the node two faces share).
NearestFace nearest_face(const std::vector<std::vector<int>>& faces, const std::vector<Eigen::Vector2d>& reference,
                         const Eigen::Vector2d& x) {
  NearestFace best;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    std::vector<Eigen::Vector2d> y;
    for (int n : faces[f]) y.push_back(reference[static_cast<std::size_t>(n)]);
    const SegmentProjection pr = project(x, y);
    if (pr.status == ProjectionStatus::degenerate || !(pr.clamped_distance < best.distance)) continue;
    best = {f, pr.clamped_xi, pr.clamped_distance};
  }
  return best;
}

/// For each node of `nodes`: 1 when the elements through it are
/// axisymmetric, 0 when they are plane, -1 when it belongs to no element.
/// Throws ModelError for a node that joins both kinds.
std::map<int, int> axisymmetric_nodes(const Model& model, const std::vector<int>& nodes, const std::string& where) {
  std::map<int, int> kind;
  for (int n : nodes) kind[n] = -1;
  for (const Element& e : model.elements)
    for (int n : e.nodes) {
      const auto it = kind.find(n);
      if (it == kind.end()) continue;
      const int k = e.type.family == Family::Axisymmetric ? 1 : 0;
      if (it->second >= 0 && it->second != k)
        throw ModelError("node " + label_text(model.instances, model.node_ids[static_cast<std::size_t>(n)]) +
                         " of a node-based slave surface joins axisymmetric and plane elements" + where);
      it->second = k;
    }
  return kind;
}

/// Throws ModelError when the element faces of `slave` and `master` mix
/// axisymmetric and plane elements (dialect calculix): ccx's contact spring
/// then acts on one 2° segment of the axisymmetric side and on the whole
/// thickness of the plane one, forces 180-fold apart that no 2D model
/// reproduces.
void refuse_mixed_faces(const Model& model, const Surface& slave, const Surface& master, const std::string& where) {
  const auto axisymmetric = [&](const ElementFace& f) {
    return model.elements[static_cast<std::size_t>(f.element)].type.family == Family::Axisymmetric;
  };
  const bool slave_axi = std::any_of(slave.faces.begin(), slave.faces.end(), axisymmetric);
  const bool slave_plane = !std::all_of(slave.faces.begin(), slave.faces.end(), axisymmetric);
  const bool master_axi = std::any_of(master.faces.begin(), master.faces.end(), axisymmetric);
  const bool master_plane = !std::all_of(master.faces.begin(), master.faces.end(), axisymmetric);
  if ((slave_axi || master_axi) && (slave_plane || master_plane))
    throw ModelError("contact surfaces " + slave.name + " and " + master.name + " mix axisymmetric and plane "
                     "elements: CalculiX's contact spring acts on one 2-degree segment of the axisymmetric side and on "
                     "the whole thickness of the plane one, forces 180-fold apart that no 2D model reproduces" + where);
}

/// The area CalculiX gives each node of the node-based slave surface `slave`
/// against the master surface `master` (dialect calculix) in the reference
/// configuration: the area of the master face the node projects onto, at that
/// point (calculix_face_area). The contact element re-evaluates it on the
/// current face (ContactPairSetup::calculix_face_areas); this one serves the
/// reach and the checks below. Measured against ccx 2.20 on two
/// blocks under CalculiX's LINEAR law (tests/verification/dialect_ccx_test.cpp):
/// CPE4, CPE8, CAX4, CAX8. ModelError for a slave node in no element (ccx
/// would keep it a free 3D node) and for a pair that joins plane slave nodes
/// to axisymmetric master faces or the reverse: ccx's contact spring then acts
/// on the full thickness on one side and on one 2° segment on the other,
/// forces that differ 180-fold and no 2D model reproduces.
std::map<int, double> calculix_node_areas(const Model& model, const Surface& slave, const Surface& master,
                                          const std::vector<Eigen::Vector2d>& reference, const std::string& where) {
  std::vector<std::vector<int>> faces;
  for (const ElementFace& f : master.faces) faces.push_back(face_node_indices(model, f));
  const std::map<int, int> kinds = axisymmetric_nodes(model, slave.nodes, where);
  std::map<int, double> area;
  for (int n : slave.nodes) {
    const std::string node = label_text(model.instances, model.node_ids[static_cast<std::size_t>(n)]);
    const int kind = kinds.at(n);
    if (kind < 0)
      throw ModelError("node " + node + " of node-based slave surface " + slave.name + " belongs to no element: in the "
                       "calculix dialect tether models only nodes of 2D elements, whose area is CalculiX's (from the "
                       "master face)" + where);
    const NearestFace near = nearest_face(faces, reference, reference[static_cast<std::size_t>(n)]);
    if (!std::isfinite(near.distance))
      throw ModelError("master surface " + master.name + " has only faces of zero length, so node " + node +
                       " of node-based slave surface " + slave.name + " has no area in the calculix dialect" + where);
    const Element& e = model.elements[static_cast<std::size_t>(master.faces.at(near.face).element)];
    if (kind != (e.type.family == Family::Axisymmetric ? 1 : 0))
      throw ModelError("node " + node + " of node-based slave surface " + slave.name + " (" +
                       (kind ? "axisymmetric" : "plane") + " elements) faces master element " +
                       label_text(model.instances, e.id) + " (" + std::string(e.type.name) + "): CalculiX's contact "
                       "spring acts on one 2-degree segment of its axisymmetric side and on the whole thickness of the "
                       "plane one, forces 180-fold apart that no 2D model reproduces" + where);
    std::vector<Eigen::Vector2d> y;
    for (int m : faces[near.face]) y.push_back(reference[static_cast<std::size_t>(m)]);
    area[n] = calculix_face_area(calculix_area_rule(model, e), y, near.xi).area;
  }
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
      if (data.smoothing > 0)
        throw ModelError("SMOOTH on a pair whose slave surface " + slave.name + " is node-based: in the calculix "
                         "dialect each node's area is CalculiX's, that of the master face under it, which SMOOTH would "
                         "replace by other segments (CalculiX has no SMOOTH)" + where);
      area = calculix_node_areas(model, slave, master, reference, where);
      for (const ElementFace& f : master.faces)
        setup.calculix_face_areas.push_back(
            calculix_area_rule(model, model.elements[static_cast<std::size_t>(f.element)]));
    } else {
      for (std::size_t i = 0; i < slave.nodes.size(); ++i) area[slave.nodes[i]] = slave.node_areas.at(i);
    }
    for (const Element& e : model.elements) stiffness = std::max(stiffness, modulus(model, e) * measure(model, e, {1, 0}));
  } else {
    if (model.dialect == Dialect::Calculix) refuse_mixed_faces(model, slave, master, where);
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

std::vector<DualNodeEquations> contact_dual_equations(const std::vector<std::unique_ptr<ContactPair>>& pairs,
                                                      const DofMap& dofs, const EquationMap& equations,
                                                      const std::vector<int>& other_contact_nodes) {
  // Equations of a node's displacements (each dof through `equations`: an
  // MPC-dependent dof counts as the equations it expands to).
  const auto node_equations = [&](int node) {
    std::vector<int> out;
    for (int c = 0; c < kDofsPerNode; ++c)
      for (const EquationWeight& w : equations.weights(dofs.displacement(node, c))) out.push_back(w.equation);
    return out;
  };
  // Displacement equations carried by a master node or another pair's node,
  // and how many slave rows touch each one.
  std::set<int> shared;
  std::map<int, int> slave_rows;
  for (int node : other_contact_nodes)
    for (int e : node_equations(node)) shared.insert(e);
  for (const auto& pair : pairs) {
    for (const auto& face : pair->setup().master_faces)
      for (int node : face)
        for (int e : node_equations(node)) shared.insert(e);
    for (int i = 0; i < pair->n_slaves(); ++i) {
      std::vector<int> own = node_equations(pair->slave(i).node);
      std::sort(own.begin(), own.end());
      own.erase(std::unique(own.begin(), own.end()), own.end());
      for (int e : own) ++slave_rows[e];
    }
  }
  const auto single = [&](int dof) {
    const auto w = equations.weights(dof);
    return w.size() == 1 && w[0].weight == 1 ? w[0].equation : -1;
  };
  std::vector<DualNodeEquations> out;
  for (const auto& pair : pairs)
    for (int i = 0; i < pair->n_slaves(); ++i) {
      const ContactSlave& s = pair->slave(i);
      if (s.normal_multiplier < 0) continue;
      const std::vector<int> own = node_equations(s.node);
      if (std::any_of(own.begin(), own.end(), [&](int e) { return slave_rows[e] > 1 || shared.count(e) > 0; }))
        continue;
      out.push_back({single(s.normal_multiplier),
                     {single(dofs.displacement(s.node, 0)), single(dofs.displacement(s.node, 1))}});
    }
  return out;
}

}  // namespace tether
