// *TIE (surface ties for non-matching meshes) and *PERIODIC (periodic cells
// driven by reference nodes, a tether extension). Both are resolved here into
// ConstraintData of kind Linear: one constraint per slave node / node pair,
// two equations (x and y) each, with general coefficients.
#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "tether/constraints/periodic_pairs.hpp"
#include "tether/constraints/tie_mortar.hpp"
#include "tether/constraints/tie_projection.hpp"
#include "tether/io/constraint_params.hpp"
#include "tether/io/deck_state.hpp"
#include "tether/io/keyword_handlers.hpp"
#include "tether/io/numbers.hpp"

namespace tether::deck {

namespace {

std::string point(const Eigen::Vector2d& x) { return "(" + format_number(x.x()) + ", " + format_number(x.y()) + ")"; }

/// POSITION TOLERANCE=, >= 0 (0 or absent: the keyword's default).
double position_tolerance(const ParameterValues& params, const SourceLocation& at) {
  const double tolerance = params.real("POSITION TOLERANCE");
  if (tolerance < 0) throw InputError(at, "POSITION TOLERANCE=" + format_number(tolerance) + ": expected a length >= 0");
  return tolerance;
}

/// The surface named `token`; InputError otherwise.
const Surface& surface(const DeckState& state, const std::string& token, const SourceLocation& at,
                       std::string_view role) {
  const auto it = state.model.surfaces.find(to_upper(token));
  if (it == state.model.surfaces.end())
    throw InputError(at, "undefined " + std::string(role) + " surface '" + token +
                             "': expected a surface defined by *SURFACE");
  return it->second;
}

/// The faces of an element-face surface with their nodes and reference coordinates.
std::vector<TieFace> tie_faces(const Model& model, const Surface& surface) {
  std::vector<TieFace> faces;
  for (const ElementFace& f : surface.faces) {
    const Element& e = model.elements[static_cast<std::size_t>(f.element)];
    TieFace face;
    for (int local : face_nodes(e.type.shape, f.face)) {
      if (local < 0) continue;
      const int n = e.nodes[static_cast<std::size_t>(local)];
      face.nodes.push_back(n);
      face.x.push_back(model.coords[static_cast<std::size_t>(n)]);
    }
    faces.push_back(std::move(face));
  }
  return faces;
}

std::vector<int> surface_nodes(const Model& model, const Surface& s) {
  if (s.kind == Surface::Kind::Nodes) return s.nodes;
  std::vector<int> nodes;
  for (const TieFace& face : tie_faces(model, s)) nodes.insert(nodes.end(), face.nodes.begin(), face.nodes.end());
  sort_unique(nodes);
  return nodes;
}

/// Labels of up to `limit` nodes as the user knows them (label_text()), for messages.
std::string labels(const Model& model, const std::vector<int>& nodes, std::size_t limit = 10) {
  std::string out;
  for (std::size_t i = 0; i < nodes.size() && i < limit; ++i)
    out += (i ? ", " : "") + label_text(model.instances, model.node_ids[static_cast<std::size_t>(nodes[i])]);
  if (nodes.size() > limit) out += ", ... (" + std::to_string(nodes.size()) + " in all)";
  return out;
}

/// A tied slave node: its constraint equations u_s - sum_i w_i u_i = 0 (x and y).
ConstraintData tie_constraint(const Model& model, int slave, const std::map<int, double>& weights,
                              const std::string& name, const SourceLocation& at, const Enforcement& enforcement) {
  ConstraintData c;
  c.kind = ConstraintData::Kind::Linear;
  c.name = name + " node " + label_text(model.instances, model.node_ids[static_cast<std::size_t>(slave)]);
  c.where = at;
  c.enforcement = enforcement;
  c.nodes.push_back(slave);
  for (const auto& [node, w] : weights)
    if (node != slave) c.nodes.push_back(node);
  for (int dof = 0; dof < 2; ++dof) {
    std::vector<EquationTerm> row{{slave, dof, 1.0}};
    for (const auto& [node, w] : weights)
      if (node != slave) row.push_back({node, dof, -w});
    c.rows.push_back(std::move(row));
  }
  return c;
}

/// Ties the slave nodes of one data line `slave, master` (InputError when none is tied).
void tie_surfaces(DeckState& state, const DataLine& line, const Enforcement& enforcement, const std::string& name,
                  double tolerance, bool adjust, bool mortar) {
  const SourceLocation at = line.where();
  const auto f = data_fields(line, 2, 2, "`slave_surface, master_surface`");
  Model& model = state.model;
  const Surface& slave = surface(state, f[0], at, "slave");
  const Surface& master = surface(state, f[1], at, "master");
  if (master.kind != Surface::Kind::ElementFaces)
    throw InputError(at, "master surface " + master.name +
                             " is a node surface: expected an element-face surface (TYPE=ELEMENT)");
  if (slave.name == master.name) throw InputError(at, "slave and master are the same surface " + slave.name);
  const std::vector<TieFace> faces = tie_faces(model, master);
  double typical = 0;
  for (const TieFace& face : faces) typical += (face.x[1] - face.x[0]).norm();
  typical /= static_cast<double>(faces.size());
  if (tolerance == 0) tolerance = 0.05 * typical;  // ABAQUS: 5 % of the typical master face size

  std::vector<int> master_nodes;
  for (const TieFace& face : faces) master_nodes.insert(master_nodes.end(), face.nodes.begin(), face.nodes.end());
  sort_unique(master_nodes);

  // Closest point of every slave node; node-to-surface weights; ADJUST.
  std::vector<int> too_far;
  std::map<int, std::map<int, double>> node_to_surface;  // slave node -> master node -> N_i(xi*)
  int n_moved = 0;
  double largest_move = 0, closest_untied = -1;
  for (int s : surface_nodes(model, slave)) {
    if (std::binary_search(master_nodes.begin(), master_nodes.end(), s)) continue;  // shared node: tied already
    const Eigen::Vector2d xs = model.coords[static_cast<std::size_t>(s)];
    FaceProjection best;
    const TieFace* best_face = nullptr;
    for (const TieFace& face : faces) {
      const FaceProjection p = project_onto_face(xs, face.x);
      if (!best_face || p.distance < best.distance) best = p, best_face = &face;
    }
    if (best.distance > tolerance) {
      too_far.push_back(s);
      if (closest_untied < 0 || best.distance < closest_untied) closest_untied = best.distance;
      continue;
    }
    // Weights below round-off dropped, partition of unity kept exact.
    auto& weights = node_to_surface[s];
    double sum = 0;
    for (std::size_t i = 0; i < best_face->nodes.size(); ++i) {
      const double w = best.weights[static_cast<int>(i)];
      if (std::abs(w) > 1e-13) weights[best_face->nodes[i]] += w, sum += w;
    }
    for (auto& [node, w] : weights) w /= sum;
    if (adjust && best.distance > 0) {
      model.coords[static_cast<std::size_t>(s)] = best.point;
      if (best.distance > 1e-12 * typical) ++n_moved;
      largest_move = std::max(largest_move, best.distance);
    }
  }

  int n_tied = 0;
  if (mortar && slave.kind == Surface::Kind::ElementFaces) {
    const std::vector<TieFace> slave_faces = tie_faces(model, slave);  // after ADJUST
    for (const auto& [s, row] : mortar_tie_rows(slave_faces, faces, tolerance)) {
      if (!node_to_surface.count(s)) continue;  // shared with the master, or too far
      const double diagonal = row.at(s);
      std::map<int, double> weights;
      for (const auto& [node, coefficient] : row)
        if (node != s && coefficient != 0) weights[node] = -coefficient / diagonal;
      model.constraints.push_back(tie_constraint(model, s, weights, name, at, enforcement));
      ++n_tied;
    }
  } else {
    for (const auto& [s, weights] : node_to_surface) {
      model.constraints.push_back(tie_constraint(model, s, weights, name, at, enforcement));
      ++n_tied;
    }
  }
  if (n_tied == 0) {
    std::string why = too_far.empty()
                          ? "every node of slave surface " + slave.name + " is also a node of the master surface"
                          : "no node of slave surface " + slave.name + " lies within POSITION TOLERANCE=" +
                                format_number(tolerance) + " of master surface " + master.name + " (the closest is " +
                                format_number(closest_untied) + " away)";
    throw InputError(at, "*TIE " + name + " ties nothing: " + why +
                             "; expected slave nodes on (or near) the master surface");
  }
  if (!too_far.empty())
    state.warn(at, "*TIE " + name + ": " + std::to_string(too_far.size()) + " slave node(s) farther than POSITION " +
                       "TOLERANCE=" + format_number(tolerance) + " from master surface " + master.name +
                       " are not tied: " + labels(model, too_far));
  if (n_moved > 0)
    state.warn(at, "*TIE " + name + ": ADJUST=YES moved " + std::to_string(n_moved) +
                       " slave node(s) onto master surface " + master.name + " in the reference configuration " +
                       "(largest move " + format_number(largest_move) + "); ADJUST=NO keeps them where they are");
}

}  // namespace

void handle_tie(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  const Enforcement enforcement = read_enforcement(params, block.where, true);
  const double tolerance = position_tolerance(params, block.where);
  const bool adjust = params.name("ADJUST") == "YES";
  const bool mortar = params.name("TYPE") == "SURFACE TO SURFACE";
  require_data(block, "`slave_surface, master_surface`");
  const std::string name =
      params.given("NAME") ? params.name("NAME") : "TIE-" + std::to_string(state.model.constraints.size() + 1);
  for (const DataLine& line : block.data) tie_surfaces(state, line, enforcement, name, tolerance, adjust, mortar);
}

void handle_periodic(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  const Enforcement enforcement = read_enforcement(params, block.where, true);
  const double given_tolerance = position_tolerance(params, block.where);
  Model& model = state.model;
  const int r1 = single_node(state, params.text("REFERENCE1"), block.where, "REFERENCE1");
  const int r2 = single_node(state, params.text("REFERENCE2"), block.where, "REFERENCE2");
  if (r1 == r2) throw InputError(block.where, "REFERENCE1 and REFERENCE2 name the same node: expected two nodes");
  require_data(block, "`nset_a, nset_b[, dx, dy]`");
  const std::string name =
      params.given("NAME") ? params.name("NAME") : "PERIODIC-" + std::to_string(model.constraints.size() + 1);
  IndependentPairs independent;
  for (const DataLine& line : block.data) {
    const SourceLocation at = line.where();
    const auto f = data_fields(line, 2, 4, "`nset_a, nset_b[, dx, dy]`");
    if (f.size() == 3) throw InputError(at, "expected `nset_a, nset_b` or `nset_a, nset_b, dx, dy`, got 3 fields");
    const std::vector<int> a = state.nodes_of(f[0], at), b = state.nodes_of(f[1], at);
    for (const std::vector<int>* side : {&a, &b})
      for (int n : *side)
        if (n == r1 || n == r2)
          throw InputError(at, "reference node " + label_text(model.instances, model.node_ids[static_cast<std::size_t>(n)]) +
                                   " is in a paired set: expected the reference nodes apart from the cell "
                                   "(they carry the macroscopic displacement gradient)");
    for (int n : a)
      if (std::find(b.begin(), b.end(), n) != b.end())
        throw InputError(at, "node " + label_text(model.instances, model.node_ids[static_cast<std::size_t>(n)]) + " is in both " +
                                 f[0] + " and " + f[1] + ": expected two disjoint sets of opposite nodes");
    std::vector<Eigen::Vector2d> xa, xb;
    for (int n : a) xa.push_back(model.coords[static_cast<std::size_t>(n)]);
    for (int n : b) xb.push_back(model.coords[static_cast<std::size_t>(n)]);
    Eigen::Vector2d translation;
    if (f.size() == 4) {
      translation = {parse_real(f[2], at, "dx"), parse_real(f[3], at, "dy")};
    } else {
      Eigen::Vector2d ca = Eigen::Vector2d::Zero(), cb = Eigen::Vector2d::Zero();
      for (const auto& x : xa) ca += x;
      for (const auto& x : xb) cb += x;
      translation = cb / static_cast<double>(xb.size()) - ca / static_cast<double>(xa.size());
    }
    if (!(translation.norm() > 0))
      throw InputError(at, "the translation from " + f[0] + " to " + f[1] +
                               " is zero: expected two opposite sides of the cell");
    const double tolerance = given_tolerance > 0 ? given_tolerance : 1e-6 * translation.norm();
    const PeriodicPairing pairing = pair_by_translation(xa, xb, translation, tolerance);
    if (pairing.unpaired_a >= 0) {
      const int n = a[static_cast<std::size_t>(pairing.unpaired_a)];
      throw InputError(at, "node " + label_text(model.instances, model.node_ids[static_cast<std::size_t>(n)]) + " of " + f[0] +
                               " at " + point(xa[static_cast<std::size_t>(pairing.unpaired_a)]) +
                               " has no partner in " + f[1] + ": expected a node at " +
                               point(xa[static_cast<std::size_t>(pairing.unpaired_a)] + translation) +
                               " within POSITION TOLERANCE=" + format_number(tolerance) + " (translation " +
                               point(translation) + ")");
    }
    if (pairing.unpaired_b >= 0) {
      const int n = b[static_cast<std::size_t>(pairing.unpaired_b)];
      throw InputError(at, "node " + label_text(model.instances, model.node_ids[static_cast<std::size_t>(n)]) + " of " + f[1] +
                               " at " + point(xb[static_cast<std::size_t>(pairing.unpaired_b)]) +
                               " has no partner in " + f[0] + ": expected a node at " +
                               point(xb[static_cast<std::size_t>(pairing.unpaired_b)] - translation) +
                               " (the sets must have the same number of nodes, " + std::to_string(a.size()) +
                               " and " + std::to_string(b.size()) + ")");
    }
    int written = 0;
    for (const auto& [i, j] : pairing.pairs) {
      const int na = a[static_cast<std::size_t>(i)], nb = b[static_cast<std::size_t>(j)];
      if (!independent.add(na, nb)) continue;  // implied by earlier pairs (cell corners)
      const Eigen::Vector2d d = xb[static_cast<std::size_t>(j)] - xa[static_cast<std::size_t>(i)];
      ConstraintData c;
      c.kind = ConstraintData::Kind::Linear;
      c.name = name + " " + label_text(model.instances, model.node_ids[static_cast<std::size_t>(na)]) + "-" +
               label_text(model.instances, model.node_ids[static_cast<std::size_t>(nb)]);
      c.where = at;
      c.enforcement = enforcement;
      c.nodes = {na, nb, r1, r2};
      // u_b - u_a - H (X_b - X_a) = 0 with H = [u(R1) u(R2)] (columns).
      for (int dof = 0; dof < 2; ++dof) {
        std::vector<EquationTerm> row{{nb, dof, 1.0}, {na, dof, -1.0}};
        if (d.x() != 0) row.push_back({r1, dof, -d.x()});
        if (d.y() != 0) row.push_back({r2, dof, -d.y()});
        c.rows.push_back(std::move(row));
      }
      model.constraints.push_back(std::move(c));
      ++written;
    }
    if (written == 0)
      throw InputError(at, "every pair of " + f[0] + " and " + f[1] +
                               " repeats pairs of earlier lines: expected new opposite nodes");
  }
}

}  // namespace tether::deck
