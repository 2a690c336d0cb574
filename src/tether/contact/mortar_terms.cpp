#include "tether/contact/mortar_terms.hpp"

#include <algorithm>

#include "tether/contact/mortar_pair.hpp"
#include "tether/dofs/dof_map.hpp"

namespace tether {

namespace {

/// Gauss points per overlap of a slave and a master segment: exact for the
/// polynomial integrands of straight and quadratic faces with constant normals.
constexpr int kMortarGaussPoints = 6;

/// Index of real node `node` in `nodes`.
int index_of(const std::vector<int>& nodes, int node) {
  return static_cast<int>(std::find(nodes.begin(), nodes.end(), node) - nodes.begin());
}

/// Positions of `wanted` from the positions `x` of `nodes`.
template <class T>
std::vector<Vec2T<T>> gather(const std::vector<int>& nodes, std::span<const Vec2T<T>> x, const std::vector<int>& wanted) {
  std::vector<Vec2T<T>> out;
  out.reserve(wanted.size());
  for (int n : wanted) out.push_back(x[static_cast<std::size_t>(index_of(nodes, n))]);
  return out;
}

/// Averaged unit normal at slave node `node` from the positions `x` of `nodes`.
template <class T>
Vec2T<T> normal_at(const MortarPair& pair, const std::vector<int>& nodes, std::span<const Vec2T<T>> x, int node) {
  std::vector<std::vector<Vec2T<T>>> faces;
  std::vector<int> at;
  for (const auto& [e, k] : pair.faces_of_node()[static_cast<std::size_t>(node)]) {
    faces.push_back(gather(nodes, x, pair.setup().slave_faces[static_cast<std::size_t>(e)]));
    at.push_back(k);
  }
  return nodal_normal<T>(faces, at);
}

/// The terms of every node k of slave face e against master face f, from one
/// segment integration. `x`: the positions of `nodes` (mortar_term_nodes()).
/// `nlgeom`: dA from the current positions; otherwise from the reference ones.
/// `normals`: the nodal normals of e's nodes at x, over the same unknowns
/// (MortarTermCache::face_normals); null: computed here.
template <class T>
std::vector<MortarTerm<T>> terms_of(const MortarPair& pair, int e, int f, const std::vector<int>& nodes,
                                    std::span<const Vec2T<T>> x, bool nlgeom,
                                    const std::vector<Vec2T<T>>* normals = nullptr) {
  const std::vector<int>& face = pair.setup().slave_faces[static_cast<std::size_t>(e)];
  const std::vector<Vec2T<T>> xe = gather(nodes, x, face);
  std::vector<Vec2T<T>> computed;
  if (!normals)
    for (int q : face) computed.push_back(normal_at(pair, nodes, x, q));
  const std::vector<Vec2T<T>>& ne = normals ? *normals : computed;
  const std::vector<std::vector<Vec2T<T>>> master{gather(nodes, x, pair.setup().master_faces[static_cast<std::size_t>(f)])};
  std::vector<Vec2T<double>> reference;
  if (!nlgeom)
    for (int q : face) {
      const Eigen::Vector2d& X = pair.reference()[static_cast<std::size_t>(q)];
      reference.push_back({X.x(), X.y()});
    }
  const SegmentMortar<T> m = integrate_segment<T>(
      xe, ne, master, pair.setup().slave_thickness[static_cast<std::size_t>(e)], kMortarGaussPoints, reference);
  std::vector<MortarTerm<T>> out(face.size());
  for (std::size_t k = 0; k < face.size(); ++k) {
    MortarTerm<T>& t = out[k];
    t.y = master[0];
    t.x_j = xe[k];
    t.normal = ne[k];
    if (!(m.overlap[0][0] < m.overlap[0][1])) continue;
    t.overlaps = true;
    t.D = m.D[k];
    Vec2T<T> weighted{T(0.0), T(0.0)};
    for (std::size_t a = 0; a < t.y.size(); ++a) {
      t.M[a] = m.M[0][k][a];
      weighted = weighted + t.M[a] * t.y[a];
    }
    t.v = weighted - t.D * t.x_j;
  }
  return out;
}

/// The tangent τ = n rotated by +90°.
template <class T>
Vec2T<T> tangent_of(const Vec2T<T>& n) {
  return {-n.y, n.x};
}

/// Node k's share of a term with derivatives; `start`: the term at the start
/// of the increment (friction), else null.
MortarTermShare share_of(const MortarTerm<Dual2>& t, const MortarTerm<double>* start, bool friction) {
  MortarTermShare s;
  s.overlaps = t.overlaps;
  if (t.overlaps) s.gap = MortarTermScalar(dot(t.normal, t.v)), s.D = MortarTermScalar(t.D);
  if (!friction) return s;
  const Vec2T<Dual2> tau = tangent_of(t.normal);
  Dual2 slip(0.0);
  if (t.overlaps) slip += dot(tau, t.v);
  if (start && start->overlaps) {
    Vec2T<Dual2> w{Dual2(-start->D) * t.x_j.x, Dual2(-start->D) * t.x_j.y};
    for (std::size_t a = 0; a < t.y.size(); ++a) w = w + Dual2(start->M[a]) * t.y[a];
    slip -= dot(tau, w);
  }
  s.slip = MortarTermScalar(slip);
  if (!t.overlaps) return s;
  s.G.emplace_back(t.D * tau.x);
  s.G.emplace_back(t.D * tau.y);
  for (std::size_t a = 0; a < t.y.size(); ++a) {
    s.G.emplace_back(-(t.M[a] * tau.x));
    s.G.emplace_back(-(t.M[a] * tau.y));
  }
  return s;
}

/// Computes the terms of slave face e against master face f at positions x
/// (x0 at the start of the increment, with friction); `normals` (order >= 1):
/// the nodal normals of e's nodes at x over the term's unknowns.
MortarFaceTerms compute(const MortarPair& pair, int e, int f, std::vector<int> nodes,
                        const std::vector<Vec2T<double>>& x, const std::vector<Vec2T<double>>& x0, int order,
                        bool nlgeom, bool friction, const std::vector<Vec2T<Dual2>>* normals) {
  MortarFaceTerms out;
  if (friction) out.start = terms_of<double>(pair, e, f, nodes, x0, nlgeom);
  if (order == 0) {
    out.values = terms_of<double>(pair, e, f, nodes, x, nlgeom);
  } else {
    const int n = 2 * static_cast<int>(nodes.size());
    std::vector<Vec2T<Dual2>> d;
    for (std::size_t a = 0; a < x.size(); ++a) {
      const int i = 2 * static_cast<int>(a);
      d.push_back({Dual2::variable(x[a].x, i, n, order >= 2), Dual2::variable(x[a].y, i + 1, n, order >= 2)});
    }
    const std::vector<MortarTerm<Dual2>> terms = terms_of<Dual2>(pair, e, f, nodes, d, nlgeom, normals);
    for (std::size_t k = 0; k < terms.size(); ++k)
      out.shares.push_back(share_of(terms[k], friction ? &out.start[k] : nullptr, friction));
  }
  out.nodes = std::move(nodes);
  return out;
}

}  // namespace

MortarTermScalar::MortarTermScalar(const Dual2& d) : value(d.value()), gradient(d.gradient()), hessian(d.hessian()) {}

std::vector<int> mortar_term_nodes(const MortarPair& pair, int e, int f, int* n_slave) {
  std::vector<int> nodes;
  const auto add = [&nodes](int node) {
    if (std::find(nodes.begin(), nodes.end(), node) == nodes.end()) nodes.push_back(node);
  };
  for (int q : pair.setup().slave_faces[static_cast<std::size_t>(e)])
    for (const auto& [e2, k2] : pair.faces_of_node()[static_cast<std::size_t>(q)])
      for (int r : pair.setup().slave_faces[static_cast<std::size_t>(e2)]) add(r);
  if (n_slave) *n_slave = static_cast<int>(nodes.size());
  for (int q : pair.setup().master_faces[static_cast<std::size_t>(f)]) add(q);
  return nodes;
}

Vec2T<double> mortar_position(const MortarPair& pair, const Eigen::VectorXd& u, int n) {
  const Eigen::Vector2d& X = pair.reference()[static_cast<std::size_t>(n)];
  return {X.x() + u[DofMap::displacement(n, 0)], X.y() + u[DofMap::displacement(n, 1)]};
}

void MortarTermCache::with_terms(const MortarPair& pair, int e, int f, const EvaluationState& state, int order,
                                 bool friction, const std::function<void(const MortarFaceTerms&)>& use) {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (entries_.size() != pair.setup().slave_faces.size()) entries_.assign(pair.setup().slave_faces.size(), {});
  std::vector<Entry>& of_face = entries_[static_cast<std::size_t>(e)];
  // Forget the master faces e no longer sums (a long slide passes many):
  // the memo holds at most the current terms of each slave face.
  if (const std::vector<int>& current = pair.term_faces(e); of_face.size() >= current.size())
    std::erase_if(of_face, [&](const Entry& en) { return std::find(current.begin(), current.end(), en.f) == current.end(); });
  auto entry = std::find_if(of_face.begin(), of_face.end(), [f](const Entry& en) { return en.f == f; });
  if (entry == of_face.end()) {
    of_face.push_back({});
    entry = of_face.end() - 1;
    entry->f = f;
    entry->nodes = mortar_term_nodes(pair, e, f, &entry->n_slave);  // fixed by the faces' topology
  }
  const std::vector<int>& nodes = entry->nodes;
  // The positions are compared in place with those a slot was computed at
  // (no copy on a hit: most look-ups are).
  const auto at = [&](const std::vector<Vec2T<double>>& held, const Eigen::VectorXd& u) {
    if (held.size() != nodes.size()) return false;
    for (std::size_t a = 0; a < nodes.size(); ++a) {
      const Vec2T<double> p = mortar_position(pair, u, nodes[a]);
      if (!(p.x == held[a].x && p.y == held[a].y)) return false;
    }
    return true;
  };
  const auto holds = [&](const Slot& s) {
    return s.valid && s.nlgeom == state.nlgeom && s.friction == friction && at(s.x, state.u) &&
           (!friction || at(s.x0, state.u_start));
  };
  // Gradients are wanted (forces, residual-only assemblies) mostly at a state
  // whose Hessians the tangent's assembly has just computed: the second-order
  // terms serve, their values and gradients being bit for bit those of a
  // first-order evaluation (Dual2 computes them by the same operations).
  if (order == 1 && holds(entry->slots[2])) return use(entry->slots[2].terms);
  Slot& slot = entry->slots[static_cast<std::size_t>(std::clamp(order, 0, 2))];
  if (!holds(slot)) {
    std::vector<Vec2T<double>> x, x0;
    x.reserve(nodes.size());
    if (friction) x0.reserve(nodes.size());
    for (int n : nodes) {
      x.push_back(mortar_position(pair, state.u, n));
      if (friction) x0.push_back(mortar_position(pair, state.u_start, n));
    }
    slot.valid = false;
    slot.terms = compute(pair, e, f, nodes, x, x0, order, state.nlgeom, friction,
                         order >= 1 ? &face_normals(pair, e, *entry, x, order) : nullptr);
    slot.x = std::move(x), slot.x0 = std::move(x0);
    slot.nlgeom = state.nlgeom, slot.friction = friction, slot.valid = true;
  }
  use(slot.terms);
}

const std::vector<Vec2T<Dual2>>& MortarTermCache::face_normals(const MortarPair& pair, int e, const Entry& entry,
                                                               const std::vector<Vec2T<double>>& x, int order) {
  const int n = 2 * static_cast<int>(entry.nodes.size());
  const bool second = order >= 2;
  const auto m = static_cast<std::size_t>(entry.n_slave);
  const auto holds = [&](const NormalSlot& s) {
    if (s.e != e || s.n != n || s.second != second || s.x.size() != m) return false;
    for (std::size_t a = 0; a < m; ++a)
      if (!(s.x[a].x == x[a].x && s.x[a].y == x[a].y)) return false;
    return true;
  };
  for (const NormalSlot& s : normal_slots_)
    if (holds(s)) return s.normals;
  NormalSlot& s = normal_slots_[next_normal_slot_];
  next_normal_slot_ = (next_normal_slot_ + 1) % normal_slots_.size();
  // The same variables as compute() makes for the term (index 2a, 2a + 1 of
  // n for node a of entry.nodes). The normal of node q depends only on the
  // nodes of the slave faces around it: it is computed over their variables
  // (6 for linear faces, where the term has 12) and embedded into the n,
  // the same entries at about a quarter of the Hessian work.
  const std::vector<int> slave_nodes(entry.nodes.begin(), entry.nodes.begin() + entry.n_slave);
  s.e = -1;
  s.normals.clear();
  for (int q : pair.setup().slave_faces[static_cast<std::size_t>(e)]) {
    std::vector<int> around;  // the nodes q's normal depends on, their variables in the term
    for (const auto& [e2, k2] : pair.faces_of_node()[static_cast<std::size_t>(q)])
      for (int r : pair.setup().slave_faces[static_cast<std::size_t>(e2)])
        if (std::find(around.begin(), around.end(), r) == around.end()) around.push_back(r);
    // In the term's order, so that the embedding keeps the variables' order:
    // the same bits as computing over all n.
    std::sort(around.begin(), around.end(),
              [&](int r1, int r2) { return index_of(slave_nodes, r1) < index_of(slave_nodes, r2); });
    const int n_local = 2 * static_cast<int>(around.size());
    std::vector<Vec2T<Dual2>> d;
    std::vector<int> to;
    for (std::size_t b = 0; b < around.size(); ++b) {
      const int a = index_of(slave_nodes, around[b]), i = 2 * static_cast<int>(b);
      const Vec2T<double>& p = x[static_cast<std::size_t>(a)];
      d.push_back({Dual2::variable(p.x, i, n_local, second), Dual2::variable(p.y, i + 1, n_local, second)});
      to.push_back(2 * a), to.push_back(2 * a + 1);
    }
    const Vec2T<Dual2> local = normal_at<Dual2>(pair, around, d, q);
    s.normals.push_back({local.x.embedded(to, n), local.y.embedded(to, n)});
  }
  s.x.assign(x.begin(), x.begin() + entry.n_slave);
  s.e = e, s.n = n, s.second = second;
  return s.normals;
}

std::size_t MortarTermCache::size() {
  const std::lock_guard<std::mutex> lock(mutex_);
  std::size_t n = 0;
  for (const std::vector<Entry>& of_face : entries_) n += of_face.size();
  return n;
}

}  // namespace tether
