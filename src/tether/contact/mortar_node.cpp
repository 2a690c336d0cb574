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

template <class T>
struct NodeGap {
  T gap{};
  T D{};
  bool covered = false;
};

/// Local index of real node `node` in s.nodes.
int local_of(const MortarSlave& s, int node) {
  const auto it = std::find(s.nodes.begin(), s.nodes.end(), node);
  return static_cast<int>(it - s.nodes.begin());
}

template <class T>
std::vector<Vec2T<T>> gather(const MortarSlave& s, std::span<const Vec2T<T>> x, const std::vector<int>& nodes) {
  std::vector<Vec2T<T>> out;
  out.reserve(nodes.size());
  for (int n : nodes) out.push_back(x[static_cast<std::size_t>(local_of(s, n))]);
  return out;
}

/// Averaged unit normal at slave node `node` from the local positions.
template <class T>
Vec2T<T> normal_at(const MortarPair& pair, const MortarSlave& s, std::span<const Vec2T<T>> x, int node) {
  std::vector<std::vector<Vec2T<T>>> faces;
  std::vector<int> at;
  for (const auto& [e, k] : pair.faces_of_node()[static_cast<std::size_t>(node)]) {
    faces.push_back(gather(s, x, pair.setup().slave_faces[static_cast<std::size_t>(e)]));
    at.push_back(k);
  }
  return nodal_normal<T>(faces, at);
}

/// g̃_j and D_j from the positions of s.nodes (local order).
/// `nlgeom`: dA from the current positions; otherwise from the reference ones.
template <class T>
NodeGap<T> weighted_gap(const MortarPair& pair, const MortarSlave& s, std::span<const Vec2T<T>> x, bool nlgeom) {
  NodeGap<T> out{T(0.0), T(0.0), false};
  const Vec2T<T> n_j = normal_at(pair, s, x, s.node);
  const Vec2T<T>& x_j = x[0];
  for (const auto& [e, k] : s.faces) {
    const std::vector<int>& face = pair.setup().slave_faces[static_cast<std::size_t>(e)];
    const std::vector<Vec2T<T>> xe = gather(s, x, face);
    std::vector<Vec2T<T>> ne;
    for (int q : face) ne.push_back(normal_at(pair, s, x, q));
    std::vector<std::vector<Vec2T<T>>> masters;
    for (int f : pair.overlapped(e)) masters.push_back(gather(s, x, pair.setup().master_faces[static_cast<std::size_t>(f)]));
    if (masters.empty()) continue;
    std::vector<Vec2T<double>> reference;
    if (!nlgeom)
      for (int q : face) {
        const Eigen::Vector2d& X = pair.reference()[static_cast<std::size_t>(q)];
        reference.push_back({X.x(), X.y()});
      }
    const SegmentMortar<T> m = integrate_segment<T>(
        xe, ne, masters, pair.setup().slave_thickness[static_cast<std::size_t>(e)], kMortarGaussPoints, reference);
    Vec2T<T> weighted{T(0.0), T(0.0)};
    for (std::size_t f = 0; f < masters.size(); ++f) {
      if (!(m.overlap[f][0] < m.overlap[f][1])) continue;
      out.covered = true;
      for (std::size_t a = 0; a < masters[f].size(); ++a)
        weighted = weighted + m.M[f][static_cast<std::size_t>(k)][a] * masters[f][a];
    }
    const T& D = m.D[static_cast<std::size_t>(k)];
    out.gap += dot(n_j, weighted - D * x_j);
    out.D += D;
  }
  if (!(value_of(out.D) > 0)) out.covered = false;
  return out;
}

std::vector<Vec2T<double>> positions(const MortarPair& pair, const MortarSlave& s, const Eigen::VectorXd& u) {
  std::vector<Vec2T<double>> x;
  x.reserve(s.nodes.size());
  for (int n : s.nodes) {
    const Eigen::Vector2d& X = pair.reference()[static_cast<std::size_t>(n)];
    x.push_back({X.x() + u[DofMap::displacement(n, 0)], X.y() + u[DofMap::displacement(n, 1)]});
  }
  return x;
}

std::vector<Vec2T<Dual2>> variables(const std::vector<Vec2T<double>>& x) {
  const int n = 2 * static_cast<int>(x.size());
  std::vector<Vec2T<Dual2>> d;
  d.reserve(x.size());
  for (std::size_t a = 0; a < x.size(); ++a) {
    const int i = 2 * static_cast<int>(a);
    d.push_back({Dual2::variable(x[a].x, i, n), Dual2::variable(x[a].y, i + 1, n)});
  }
  return d;
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
  const MortarSlave& s = pair_.slave(slave_);
  const std::vector<Vec2T<double>> x = positions(pair_, s, u);
  const NodeGap<double> g = weighted_gap<double>(pair_, s, x, nlgeom);
  return {g.gap, g.D, g.covered};
}

bool MortarNode::closed(const EvaluationState& state) const {
  const MortarSlave& s = pair_.slave(slave_);
  const Gap g = gap(state.u, state.nlgeom);
  if (!g.covered) return false;
  // A gap within round-off of zero is a touch: surfaces that coincide in
  // the mesh start closed rather than a few ulps open.
  double largest = 0;
  for (const Vec2T<double>& p : positions(pair_, s, state.u)) largest = std::max({largest, std::abs(p.x), std::abs(p.y)});
  const double decisive = std::abs(g.gap) <= 1e-12 * largest * g.D ? 0.0 : g.gap;
  return state.u[s.multiplier] - row_stiffness() * decisive >= 0;
}

void MortarNode::evaluate(const EvaluationState& state, LocalSystem& out, bool need_tangent) const {
  const MortarSlave& s = pair_.slave(slave_);
  const auto n_u = static_cast<Eigen::Index>(2 * s.nodes.size());
  const Eigen::Index in = n_u;
  const double lambda = state.u[s.multiplier];
  if (!closed(state)) {
    const double c = row_stiffness();
    out.residual[in] = -lambda / c;
    if (need_tangent) out.tangent(in, in) = -1 / c;
    return;
  }
  const std::vector<Vec2T<Dual2>> x = variables(positions(pair_, s, state.u));
  const NodeGap<Dual2> g = weighted_gap<Dual2>(pair_, s, x, state.nlgeom);
  if (g.gap.constant()) {  // a gap that depends on no position: nothing to constrain, λ_j = 0
    const double c = row_stiffness();
    out.residual[in] = -lambda / c;
    if (need_tangent) out.tangent(in, in) = -1 / c;
    return;
  }
  const Eigen::VectorXd& grad = g.gap.gradient();
  out.residual.head(n_u) -= lambda * grad;
  out.residual[in] = -g.gap.value();
  if (!need_tangent) return;
  out.tangent.topLeftCorner(n_u, n_u) -= lambda * g.gap.hessian();
  out.tangent.col(in).head(n_u) -= grad;
  out.tangent.row(in).head(n_u) -= grad.transpose();
}

Eigen::VectorXd MortarNode::forces(const EvaluationState& state) const {
  const MortarSlave& s = pair_.slave(slave_);
  const auto n_u = static_cast<Eigen::Index>(2 * s.nodes.size());
  if (!closed(state)) return Eigen::VectorXd::Zero(n_u);
  const std::vector<Vec2T<Dual2>> x = variables(positions(pair_, s, state.u));
  const Dual2 g = weighted_gap<Dual2>(pair_, s, x, state.nlgeom).gap;
  if (g.constant()) return Eigen::VectorXd::Zero(n_u);
  return state.u[s.multiplier] * g.gradient();
}

}  // namespace tether
