#include "tether/contact/mortar_node.hpp"

#include <algorithm>
#include <cmath>

#include "tether/contact/mortar_pair.hpp"
#include "tether/contact/mortar_segmentation.hpp"
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

/// The real nodes one term (slave face e, master face f) of g̃_j depends on:
/// the nodes of e, of the slave faces around them (their normals), and of f.
std::vector<int> term_nodes(const MortarPair& pair, int e, int f) {
  std::vector<int> nodes;
  const auto add = [&nodes](int node) {
    if (std::find(nodes.begin(), nodes.end(), node) == nodes.end()) nodes.push_back(node);
  };
  for (int q : pair.setup().slave_faces[static_cast<std::size_t>(e)])
    for (const auto& [e2, k2] : pair.faces_of_node()[static_cast<std::size_t>(q)])
      for (int r : pair.setup().slave_faces[static_cast<std::size_t>(e2)]) add(r);
  for (int q : pair.setup().master_faces[static_cast<std::size_t>(f)]) add(q);
  return nodes;
}

/// One term of the weighted gap of slave node j (position k on slave face
/// e) against master face f: n_j · (Σ_a M^e_kfa y_fa - D^e_kf x_j) and its
/// weight D^e_kf (the part of D^e_k over the overlap with f). `x`: the
/// positions of `nodes` (term_nodes()). `nlgeom`: dA from the current
/// positions; otherwise from the reference ones.
template <class T>
struct Term {
  T gap{}, D{};
  bool overlaps = false;
};

template <class T>
Term<T> gap_term(const MortarPair& pair, int j, int e, int k, int f, const std::vector<int>& nodes,
                 std::span<const Vec2T<T>> x, bool nlgeom) {
  Term<T> out{T(0.0), T(0.0), false};
  const std::vector<int>& face = pair.setup().slave_faces[static_cast<std::size_t>(e)];
  const std::vector<Vec2T<T>> xe = gather(nodes, x, face);
  std::vector<Vec2T<T>> ne;
  for (int q : face) ne.push_back(normal_at(pair, nodes, x, q));
  const std::vector<std::vector<Vec2T<T>>> master{gather(nodes, x, pair.setup().master_faces[static_cast<std::size_t>(f)])};
  std::vector<Vec2T<double>> reference;
  if (!nlgeom)
    for (int q : face) {
      const Eigen::Vector2d& X = pair.reference()[static_cast<std::size_t>(q)];
      reference.push_back({X.x(), X.y()});
    }
  const SegmentMortar<T> m = integrate_segment<T>(
      xe, ne, master, pair.setup().slave_thickness[static_cast<std::size_t>(e)], kMortarGaussPoints, reference);
  if (!(m.overlap[0][0] < m.overlap[0][1])) return out;
  out.overlaps = true;
  Vec2T<T> weighted{T(0.0), T(0.0)};
  for (std::size_t a = 0; a < master[0].size(); ++a)
    weighted = weighted + m.M[0][static_cast<std::size_t>(k)][a] * master[0][a];
  const T& D = m.D[static_cast<std::size_t>(k)];
  const Vec2T<T>& n_j = ne[static_cast<std::size_t>(k)];
  out.gap = dot(n_j, weighted - D * x[static_cast<std::size_t>(index_of(nodes, j))]);
  out.D = D;
  return out;
}

Vec2T<double> position(const MortarPair& pair, const Eigen::VectorXd& u, int n) {
  const Eigen::Vector2d& X = pair.reference()[static_cast<std::size_t>(n)];
  return {X.x() + u[DofMap::displacement(n, 0)], X.y() + u[DofMap::displacement(n, 1)]};
}

/// g̃_j with its derivatives over the displacements of s.nodes (order 0:
/// value only, 1: gradient, 2: gradient and Hessian), summed term by term;
/// each term is differentiated over its own few nodes only and scattered.
struct WeightedGap {
  double gap = 0, D = 0;
  bool covered = false;
  Eigen::VectorXd gradient;
  Eigen::MatrixXd hessian;
};

WeightedGap weighted_gap(const MortarPair& pair, const MortarSlave& s, const Eigen::VectorXd& u, bool nlgeom,
                         int order) {
  WeightedGap out;
  const auto n_u = static_cast<Eigen::Index>(2 * s.nodes.size());
  if (order >= 1) out.gradient = Eigen::VectorXd::Zero(n_u);
  if (order >= 2) out.hessian = Eigen::MatrixXd::Zero(n_u, n_u);
  for (const auto& [e, k] : s.faces)
    for (int f : pair.overlapped(e)) {
      const std::vector<int> nodes = term_nodes(pair, e, f);
      std::vector<Vec2T<double>> x;
      for (int n : nodes) x.push_back(position(pair, u, n));
      if (order == 0) {
        const Term<double> t = gap_term<double>(pair, s.node, e, k, f, nodes, x, nlgeom);
        out.covered = out.covered || t.overlaps;
        out.gap += t.gap, out.D += t.D;
        continue;
      }
      const int n = 2 * static_cast<int>(nodes.size());
      std::vector<Vec2T<Dual2>> d;
      for (std::size_t a = 0; a < x.size(); ++a) {
        const int i = 2 * static_cast<int>(a);
        d.push_back({Dual2::variable(x[a].x, i, n, order >= 2), Dual2::variable(x[a].y, i + 1, n, order >= 2)});
      }
      const Term<Dual2> t = gap_term<Dual2>(pair, s.node, e, k, f, nodes, d, nlgeom);
      if (!t.overlaps) continue;
      out.covered = true;
      out.gap += t.gap.value(), out.D += t.D.value();
      if (t.gap.constant()) continue;
      std::vector<Eigen::Index> to;  // term unknown -> node unknown
      for (int node : nodes)
        for (int c = 0; c < 2; ++c) to.push_back(2 * index_of(s.nodes, node) + c);
      for (int a = 0; a < n; ++a) {
        out.gradient[to[static_cast<std::size_t>(a)]] += t.gap.gradient()[a];
        if (order >= 2)
          for (int b = 0; b < n; ++b)
            out.hessian(to[static_cast<std::size_t>(a)], to[static_cast<std::size_t>(b)]) += t.gap.hessian()(a, b);
      }
    }
  if (!(out.D > 0)) out.covered = false;
  return out;
}

}  // namespace

std::span<const int> MortarNode::dofs() const { return pair_.slave(slave_).dofs; }

std::string MortarNode::describe() const {
  return pair_.describe() + ", slave node " + std::to_string(pair_.slave(slave_).node);
}

double MortarNode::row_stiffness() const {
  const double area = pair_.slave(slave_).area;
  return pair_.setup().complementarity_stiffness / (area * area);
}

MortarNode::Gap MortarNode::gap(const Eigen::VectorXd& u, bool nlgeom) const {
  const WeightedGap g = weighted_gap(pair_, pair_.slave(slave_), u, nlgeom, 0);
  return {g.gap, g.D, g.covered};
}

bool MortarNode::closed(const EvaluationState& state) const {
  const MortarSlave& s = pair_.slave(slave_);
  const Gap g = gap(state.u, state.nlgeom);
  if (!g.covered) return false;
  // A gap within round-off of zero is a touch: surfaces that coincide in
  // the mesh start closed rather than a few ulps open.
  double largest = 0;
  for (int n : s.nodes) {
    const Vec2T<double> p = position(pair_, state.u, n);
    largest = std::max({largest, std::abs(p.x), std::abs(p.y)});
  }
  const double decisive = std::abs(g.gap) <= 1e-12 * largest * g.D ? 0.0 : g.gap;
  return state.u[s.multiplier] - row_stiffness() * decisive >= 0;
}

void MortarNode::evaluate(const EvaluationState& state, LocalSystem& out, bool need_tangent) const {
  const MortarSlave& s = pair_.slave(slave_);
  const auto n_u = static_cast<Eigen::Index>(2 * s.nodes.size());
  const Eigen::Index in = n_u;
  const double lambda = state.u[s.multiplier];
  const auto open_row = [&] {
    const double c = row_stiffness();
    out.residual[in] = -lambda / c;
    if (need_tangent) out.tangent(in, in) = -1 / c;
  };
  if (!closed(state)) return open_row();
  const WeightedGap g = weighted_gap(pair_, s, state.u, state.nlgeom, need_tangent ? 2 : 1);
  if (!g.covered) return open_row();
  out.residual.head(n_u) -= lambda * g.gradient;
  out.residual[in] = -g.gap;
  if (!need_tangent) return;
  out.tangent.topLeftCorner(n_u, n_u) -= lambda * g.hessian;
  out.tangent.col(in).head(n_u) -= g.gradient;
  out.tangent.row(in).head(n_u) -= g.gradient.transpose();
}

Eigen::VectorXd MortarNode::forces(const EvaluationState& state) const {
  const MortarSlave& s = pair_.slave(slave_);
  const auto n_u = static_cast<Eigen::Index>(2 * s.nodes.size());
  if (!closed(state)) return Eigen::VectorXd::Zero(n_u);
  const WeightedGap g = weighted_gap(pair_, s, state.u, state.nlgeom, 1);
  return state.u[s.multiplier] * g.gradient;
}

}  // namespace tether
