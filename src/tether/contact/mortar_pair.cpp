#include "tether/contact/mortar_pair.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "tether/assembly/saved_state.hpp"
#include "tether/contact/mortar_node.hpp"
#include "tether/core/error.hpp"
#include "tether/contact/mortar_segmentation.hpp"
#include "tether/dofs/dof_map.hpp"
#include "tether/fem/quadrature.hpp"
#include "tether/fem/shape_functions.hpp"

namespace tether {

namespace {

/// Changes of a node's friction branch (stick, slip +, slip -) within one
/// increment attempt after which it is held in stick until Newton converges:
/// the semi-smooth Newton method can cycle between stick and slip, or
/// between slip directions, where sliding starts.
constexpr int kMaxFrictionSwitches = 2;
/// Releases of held nodes (found outside the friction cone at convergence)
/// within one attempt before the pair gives up.
constexpr int kMaxReleases = 10;
constexpr double kStateTag = 2101;  ///< first value of a saved MortarPair state

Vec2T<double> current(const std::vector<Eigen::Vector2d>& reference, const Eigen::VectorXd& u, int node) {
  const Eigen::Vector2d& X = reference[static_cast<std::size_t>(node)];
  return {X.x() + u[DofMap::displacement(node, 0)], X.y() + u[DofMap::displacement(node, 1)]};
}

/// Axis-aligned bounding box of some points: {min x, min y, max x, max y}.
std::array<double, 4> box_of(const std::vector<Vec2T<double>>& p) {
  std::array<double, 4> b{p[0].x, p[0].y, p[0].x, p[0].y};
  for (const auto& q : p) b = {std::min(b[0], q.x), std::min(b[1], q.y), std::max(b[2], q.x), std::max(b[3], q.y)};
  return b;
}

/// Whether boxes a and b are within distance r of each other: hypot(dx, dy)
/// <= r for their gaps dx, dy along the axes, tested only where neither gap
/// alone exceeds r (hypot is never below either), so most pairs of a long
/// surface are rejected without it.
bool boxes_within(const std::array<double, 4>& a, const std::array<double, 4>& b, double r) {
  const double dx = std::max({0.0, a[0] - b[2], b[0] - a[2]});
  const double dy = std::max({0.0, a[1] - b[3], b[1] - a[3]});
  if (dx > r || dy > r) return false;
  return std::hypot(dx, dy) <= r;
}

}  // namespace

std::vector<int> MortarPair::slave_nodes_of(const std::vector<std::vector<int>>& faces) {
  std::vector<int> nodes;
  for (const auto& f : faces) nodes.insert(nodes.end(), f.begin(), f.end());
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

MortarPair::MortarPair(MortarPairSetup setup, const std::vector<Eigen::Vector2d>& reference, int first_multiplier)
    : setup_(std::move(setup)), reference_(reference) {
  faces_of_node_.assign(reference_.size(), {});
  for (std::size_t e = 0; e < setup_.slave_faces.size(); ++e)
    for (std::size_t k = 0; k < setup_.slave_faces[e].size(); ++k)
      faces_of_node_[static_cast<std::size_t>(setup_.slave_faces[e][k])].emplace_back(static_cast<int>(e),
                                                                                     static_cast<int>(k));
  const std::vector<int> nodes = slave_nodes_of(setup_.slave_faces);
  slaves_.resize(nodes.size());
  const int per = multipliers_per_slave(setup_.mu);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    MortarSlave& s = slaves_[i];
    s.node = nodes[i];
    s.multiplier = first_multiplier + per * static_cast<int>(i);
    if (per == 2) s.tangent_multiplier = s.multiplier + 1;
    s.faces = faces_of_node_[static_cast<std::size_t>(s.node)];
  }
  // Reference areas A_j = ∫ N_j dA over the slave faces.
  std::vector<double> area(reference_.size(), 0.0);
  for (std::size_t e = 0; e < setup_.slave_faces.size(); ++e) {
    const std::vector<int>& face = setup_.slave_faces[e];
    const int m = static_cast<int>(face.size());
    for (const LinePoint& q : line_points(3)) {
      Eigen::Vector3d N, dN;
      face_shape_functions(m, q.s, N, dN);
      Eigen::Vector2d dx(0, 0);
      for (int a = 0; a < m; ++a) dx += dN[a] * reference_[static_cast<std::size_t>(face[static_cast<std::size_t>(a)])];
      for (int a = 0; a < m; ++a)
        area[static_cast<std::size_t>(face[static_cast<std::size_t>(a)])] +=
            N[a] * q.weight * dx.norm() * setup_.slave_thickness[e];
    }
  }
  for (MortarSlave& s : slaves_) s.area = area[static_cast<std::size_t>(s.node)];
  overlapped_.assign(setup_.slave_faces.size(), {});
  committed_.assign(setup_.slave_faces.size(), {});
  term_faces_.assign(setup_.slave_faces.size(), {});
  for (std::size_t i = 0; i < slaves_.size(); ++i) {
    rebuild_dofs(slaves_[i]);
    nodes_.push_back(std::make_unique<MortarNode>(*this, static_cast<int>(i)));
  }
}

MortarPair::~MortarPair() = default;

std::vector<Contribution*> MortarPair::nodes() const {
  std::vector<Contribution*> out;
  out.reserve(nodes_.size());
  for (const auto& n : nodes_) out.push_back(n.get());
  return out;
}

bool MortarPair::find_overlaps(const Eigen::VectorXd& u) {
  const auto positions_of = [&](const std::vector<int>& nodes) {
    std::vector<Vec2T<double>> x;
    for (int n : nodes) x.push_back(current(reference_, u, n));
    return x;
  };
  std::vector<std::vector<Vec2T<double>>> master_x;
  std::vector<std::array<double, 4>> master_box;
  for (const auto& f : setup_.master_faces) {
    master_x.push_back(positions_of(f));
    master_box.push_back(box_of(master_x.back()));
  }
  // The nodal normal of each slave node, computed once (a node is on two faces).
  std::unordered_map<int, Vec2T<double>> normal_of;
  normal_of.reserve(2 * setup_.slave_faces.size() + 1);
  const auto normal_at = [&](int q) {
    const auto [it, fresh] = normal_of.try_emplace(q);
    if (!fresh) return it->second;
    std::vector<std::vector<Vec2T<double>>> around;
    std::vector<int> at;
    for (const auto& [e2, k2] : faces_of_node_[static_cast<std::size_t>(q)]) {
      around.push_back(positions_of(setup_.slave_faces[static_cast<std::size_t>(e2)]));
      at.push_back(k2);
    }
    return it->second = nodal_normal<double>(around, at);
  };
  bool changed = false;
  for (std::size_t e = 0; e < setup_.slave_faces.size(); ++e) {
    const std::vector<int>& face = setup_.slave_faces[e];
    const std::vector<Vec2T<double>> x = positions_of(face);
    std::vector<Vec2T<double>> normals;
    for (int q : face) normals.push_back(normal_at(q));
    const std::array<double, 4> box = box_of(x);
    std::vector<int> candidates;
    std::vector<std::vector<Vec2T<double>>> candidate_x;
    for (std::size_t f = 0; f < master_x.size(); ++f)
      if (boxes_within(box, master_box[f], setup_.search_radius)) {
        candidates.push_back(static_cast<int>(f));
        candidate_x.push_back(master_x[f]);
      }
    const SegmentMortar<double> m = integrate_segment<double>(x, normals, candidate_x, 1.0, 1);
    std::vector<int> overlapped;
    for (std::size_t c = 0; c < candidates.size(); ++c)
      if (m.overlap[c][0] < m.overlap[c][1]) overlapped.push_back(candidates[c]);
    if (overlapped != overlapped_[e]) {
      changed = true;
      ++statistics_.repaired;
      overlapped_[e] = std::move(overlapped);
    }
  }
  if (changed) update_term_faces();
  return changed;
}

void MortarPair::update_term_faces() {
  ++overlap_version_;
  for (std::size_t e = 0; e < overlapped_.size(); ++e) {
    std::vector<int>& t = term_faces_[e];
    t = overlapped_[e];
    for (int f : committed_[e])
      if (std::find(t.begin(), t.end(), f) == t.end()) t.push_back(f);
  }
}

void MortarPair::rebuild_dofs(MortarSlave& s) {
  s.nodes.clear();
  const auto add = [&s](int node) {
    if (std::find(s.nodes.begin(), s.nodes.end(), node) == s.nodes.end()) s.nodes.push_back(node);
  };
  add(s.node);
  for (const auto& [e, k] : s.faces)
    for (int q : setup_.slave_faces[static_cast<std::size_t>(e)]) {
      add(q);
      for (const auto& [e2, k2] : faces_of_node_[static_cast<std::size_t>(q)])
        for (int r : setup_.slave_faces[static_cast<std::size_t>(e2)]) add(r);
    }
  s.n_slave_nodes = static_cast<int>(s.nodes.size());
  for (const auto& [e, k] : s.faces)
    for (int f : term_faces_[static_cast<std::size_t>(e)])
      for (int q : setup_.master_faces[static_cast<std::size_t>(f)]) add(q);
  s.dofs.clear();
  for (int n : s.nodes)
    for (int c = 0; c < kDofsPerNode; ++c) s.dofs.push_back(DofMap::displacement(n, c));
  s.dofs.push_back(s.multiplier);
  if (s.tangent_multiplier >= 0) s.dofs.push_back(s.tangent_multiplier);
}

bool MortarPair::update_connectivity(const EvaluationState& state) {
  statistics_ = {};
  const bool new_attempt = state.total_time != attempt_time_ || state.dt != attempt_dt_ || !searched_once_;
  if (new_attempt) {
    attempt_time_ = state.total_time, attempt_dt_ = state.dt, releases_ = 0;
    for (MortarSlave& s : slaves_) s.switches = 0, s.held_stick = false, s.direction = 0;
  }
  bool changed = find_overlaps(state.u);
  if (changed || !searched_once_ || dofs_stale_) {
    dofs_stale_ = false;
    for (MortarSlave& s : slaves_) {
      const std::vector<int> previous = s.dofs;
      rebuild_dofs(s);
      if (s.dofs != previous) changed = true;
    }
  }
  for (std::size_t i = 0; i < slaves_.size(); ++i) {
    MortarSlave& s = slaves_[i];
    const bool closed = nodes_[i]->closed(state);
    const MortarNode::Friction f = mu() > 0 ? nodes_[i]->friction(state) : MortarNode::Friction{};
    const bool friction_changed = closed && s.closed && (f.stick != s.stick || f.direction != s.direction);
    if (searched_once_ && (closed != s.closed || friction_changed)) ++statistics_.status_changes;
    if (!new_attempt && friction_changed && ++s.switches >= kMaxFrictionSwitches) s.held_stick = true;
    s.closed = closed;
    s.stick = f.stick;
    s.direction = f.direction;
    if (closed) ++statistics_.closed;
    if (s.held_stick) ++statistics_.held;
  }
  searched_once_ = true;
  return changed;
}

Acceptance MortarPair::on_converged(const EvaluationState& state) {
  bool released = false;
  for (MortarSlave& s : slaves_) {
    if (!s.held_stick) continue;
    const double lambda_n = state.u[s.multiplier], lambda_t = state.u[s.tangent_multiplier];
    if (std::abs(lambda_t) > mu() * std::max(lambda_n, 0.0) * (1 + 1e-9) + 1e-12 * std::abs(lambda_n)) {
      s.held_stick = false;
      s.switches = 0;
      released = true;
    }
  }
  if (!released) {
    for (MortarSlave& s : slaves_) s.held_stick = false;
    return Acceptance::Accept;
  }
  if (++releases_ > kMaxReleases)
    throw ModelError(setup_.name + ": the friction active set keeps cycling (nodes held in stick by the guard leave "
                     "the friction cone after " + std::to_string(kMaxReleases) + " releases)");
  return Acceptance::Iterate;
}

void MortarPair::commit(const EvaluationState& state) {
  if (!(mu() > 0)) return;
  for (std::size_t i = 0; i < slaves_.size(); ++i) {
    MortarSlave& s = slaves_[i];
    const MortarNode::Friction f = nodes_[i]->friction(state);
    if (!f.closed || f.stick) continue;
    const MortarNode::Gap g = nodes_[i]->gap(state.u, state.nlgeom);
    s.total_slip += std::abs(f.slip / g.D);
    s.dissipation += std::abs(state.u[s.tangent_multiplier] * f.slip);
  }
  // The next increment's slip is measured from the integrals at this state,
  // over the faces overlapped now.
  committed_ = overlapped_;
  update_term_faces();
  dofs_stale_ = true;
}

void MortarPair::save_state(std::vector<double>& out) const {
  out.push_back(kStateTag);
  out.push_back(static_cast<double>(slaves_.size()));
  out.push_back(static_cast<double>(committed_.size()));
  out.push_back(searched_once_ ? 1 : 0);
  for (const MortarSlave& s : slaves_) out.insert(out.end(), {static_cast<double>(s.node), s.total_slip, s.dissipation});
  for (const std::vector<int>& faces : committed_) {
    out.push_back(static_cast<double>(faces.size()));
    for (int f : faces) out.push_back(static_cast<double>(f));
  }
}

void MortarPair::load_state(std::span<const double>& in) {
  using namespace saved_state;
  expect_tag(in, kStateTag, "mortar contact pair");
  const int n = static_cast<int>(slaves_.size()), n_faces = static_cast<int>(committed_.size());
  take_int(in, n, n, "number of slave nodes");
  take_int(in, n_faces, n_faces, "number of slave faces");
  const bool searched = take_int(in, 0, 1, "search flag") == 1;
  std::vector<MortarSlave> slaves = slaves_;
  for (MortarSlave& s : slaves) {
    take_int(in, s.node, s.node, "slave node");
    s.total_slip = take(in);
    s.dissipation = take(in);
  }
  std::vector<std::vector<int>> committed(committed_.size());
  const int last_face = static_cast<int>(setup_.master_faces.size()) - 1;
  for (std::vector<int>& faces : committed) {
    const int count = take_int(in, 0, last_face + 1, "number of committed master faces");
    for (int k = 0; k < count; ++k) faces.push_back(take_int(in, 0, last_face, "committed master face"));
  }
  slaves_ = std::move(slaves);
  committed_ = std::move(committed);
  searched_once_ = searched;
  update_term_faces();
  for (MortarSlave& s : slaves_) rebuild_dofs(s);
}

ContactPairValues MortarPair::values(const EvaluationState& state) const {
  ContactPairValues out;
  out.name = setup_.name;
  std::vector<Eigen::Vector2d> force(reference_.size(), Eigen::Vector2d::Zero());
  for (std::size_t i = 0; i < slaves_.size(); ++i) {
    const Eigen::VectorXd f = nodes_[i]->forces(state);
    for (std::size_t a = 0; a < slaves_[i].nodes.size(); ++a)
      force[static_cast<std::size_t>(slaves_[i].nodes[a])] += f.segment<2>(static_cast<Eigen::Index>(2 * a));
  }
  for (std::size_t i = 0; i < slaves_.size(); ++i) {
    const MortarSlave& s = slaves_[i];
    const MortarNode::Gap g = nodes_[i]->gap(state.u, state.nlgeom);
    ContactNodeValues v;
    v.node = s.node;
    v.status = nodes_[i]->closed(state) ? ContactNodeValues::Status::Slip : ContactNodeValues::Status::Open;
    v.total_slip = s.total_slip;
    v.dissipation = s.dissipation;
    if (mu() > 0 && v.status != ContactNodeValues::Status::Open && g.covered) {
      const MortarNode::Friction f = nodes_[i]->friction(state);
      const double lambda_t = state.u[s.tangent_multiplier];
      v.status = f.stick ? ContactNodeValues::Status::Stick : ContactNodeValues::Status::Slip;
      v.shear = lambda_t;
      v.tangential_force = lambda_t * g.D;
      v.slip = f.slip / g.D;
      if (!f.stick) v.total_slip += std::abs(v.slip), v.dissipation += std::abs(lambda_t * f.slip);
    }
    v.gap = g.covered ? g.gap / g.D : 0.0;
    v.pressure = state.u[s.multiplier];
    v.normal_force = g.covered ? v.pressure * g.D : 0.0;
    v.force = force[static_cast<std::size_t>(s.node)];
    for (const auto& [e, k] : s.faces)
      if (!overlapped_[static_cast<std::size_t>(e)].empty() && v.master_element == 0) {
        const auto& label = setup_.master_face_labels[static_cast<std::size_t>(overlapped_[static_cast<std::size_t>(e)].front())];
        v.master_element = label.first;
        v.master_face = label.second;
      }
    out.total_force += v.force;
    out.dissipation += v.dissipation;
    out.nodes.push_back(v);
  }
  return out;
}

}  // namespace tether
