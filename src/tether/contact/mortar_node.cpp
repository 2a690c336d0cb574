#include "tether/contact/mortar_node.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "tether/contact/mortar_pair.hpp"
#include "tether/contact/mortar_segmentation.hpp"
#include "tether/contact/pressure_overclosure.hpp"
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

/// One term of the mortar kinematics of slave node j (position k on slave
/// face e) against master face f: D = D^e_kf (the part of D^e_k over the
/// overlap with f), M_a = M^e_kfa, the nodal normal n_j, and the weighted gap
/// vector v = Σ_a M_a y_a - D x_j, whose normal part n_j·v is the term's
/// share of g̃_j. `x`: the positions of `nodes` (term_nodes()). `nlgeom`: dA
/// from the current positions; otherwise from the reference ones.
template <class T>
struct Term {
  bool overlaps = false;
  T D{};
  std::array<T, 3> M{};
  Vec2T<T> normal{}, v{};
  std::vector<Vec2T<T>> y;  ///< master face positions
  Vec2T<T> x_j{};
};

template <class T>
Term<T> term_of(const MortarPair& pair, int j, int e, int k, int f, const std::vector<int>& nodes,
                std::span<const Vec2T<T>> x, bool nlgeom) {
  Term<T> out;
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
  out.y = master[0];
  out.x_j = x[static_cast<std::size_t>(index_of(nodes, j))];
  out.normal = ne[static_cast<std::size_t>(k)];
  if (!(m.overlap[0][0] < m.overlap[0][1])) return out;
  out.overlaps = true;
  out.D = m.D[static_cast<std::size_t>(k)];
  Vec2T<T> weighted{T(0.0), T(0.0)};
  for (std::size_t a = 0; a < out.y.size(); ++a) {
    out.M[a] = m.M[0][static_cast<std::size_t>(k)][a];
    weighted = weighted + out.M[a] * out.y[a];
  }
  out.v = weighted - out.D * out.x_j;
  return out;
}

Vec2T<double> position(const MortarPair& pair, const Eigen::VectorXd& u, int n) {
  const Eigen::Vector2d& X = pair.reference()[static_cast<std::size_t>(n)];
  return {X.x() + u[DofMap::displacement(n, 0)], X.y() + u[DofMap::displacement(n, 1)]};
}

/// The tangent τ = n rotated by +90°.
template <class T>
Vec2T<T> tangent_of(const Vec2T<T>& n) {
  return {-n.y, n.x};
}

/// Kinematics of slave node j over the displacements of s.nodes (order 0:
/// values only, 1: gradients, 2: gradients and the gap's Hessian), summed
/// term by term; each term is differentiated over its own few nodes only
/// and scattered. With `friction`: the weighted slip increment
///   ũ_j = τ_j·[Σ_l (M_jl - M⁰_jl) y_l - (D_j - D⁰_j) x_j]
/// (⁰: the integrals at the start of the increment, u_start; objective: a
/// rigid motion changes neither D nor M) and the frictional direction
/// G_j = τ_j·(D_j δx_j - Σ_l M_jl δy_l) (coefficients frozen) with its
/// derivative, so that λt_j G_j is the virtual work of the tangential
/// traction λt_j (force on the slave -D_j λt_j τ_j).
struct Kinematics {
  double gap = 0, D = 0;
  bool covered = false;
  Eigen::VectorXd gradient;
  Eigen::VectorXd D_gradient;  ///< ∂D_j/∂u (order >= 1): the soft laws' mean overclosure -g̃_j / D_j
  Eigen::MatrixXd D_hessian;   ///< ∂²D_j/∂u² (order 2, soft laws only)
  Eigen::MatrixXd hessian;
  double slip = 0;
  Eigen::VectorXd slip_gradient, G;
  Eigen::MatrixXd G_jacobian;
};

/// Adds one term's contributions (T = double: values only).
void add_term(Kinematics& out, const Term<double>& t, const Term<double>* old, bool friction,
              const std::vector<Eigen::Index>&) {
  if (t.overlaps) out.covered = true, out.gap += dot(t.normal, t.v), out.D += t.D;
  if (!friction) return;
  const Vec2T<double> tau = tangent_of(t.normal);
  out.slip += dot(tau, t.v);
  if (old && old->overlaps) {
    Vec2T<double> w = -old->D * t.x_j;
    for (std::size_t a = 0; a < t.y.size(); ++a) w = w + old->M[a] * t.y[a];
    out.slip -= dot(tau, w);
  }
}

void scatter(Eigen::VectorXd& g, const Dual2& value, const std::vector<Eigen::Index>& to) {
  if (value.constant()) return;
  for (Eigen::Index a = 0; a < value.gradient().size(); ++a) g[to[static_cast<std::size_t>(a)]] += value.gradient()[a];
}

void add_term(Kinematics& out, const Term<Dual2>& t, const Term<double>* old, bool friction,
              const std::vector<Eigen::Index>& to) {
  if (t.overlaps) {
    out.covered = true;
    const Dual2 gap = dot(t.normal, t.v);
    out.gap += gap.value(), out.D += t.D.value();
    scatter(out.gradient, gap, to);
    scatter(out.D_gradient, t.D, to);
    const auto add_hessian = [&to](Eigen::MatrixXd& h, const Dual2& value) {
      if (h.size() == 0 || !value.second()) return;
      for (std::size_t a = 0; a < to.size(); ++a)
        for (std::size_t b = 0; b < to.size(); ++b)
          h(to[a], to[b]) += value.hessian()(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b));
    };
    add_hessian(out.hessian, gap);
    add_hessian(out.D_hessian, t.D);
  }
  if (!friction) return;
  const Vec2T<Dual2> tau = tangent_of(t.normal);
  Dual2 slip(0.0);
  if (t.overlaps) slip += dot(tau, t.v);
  if (old && old->overlaps) {
    Vec2T<Dual2> w{Dual2(-old->D) * t.x_j.x, Dual2(-old->D) * t.x_j.y};
    for (std::size_t a = 0; a < t.y.size(); ++a) w = w + Dual2(old->M[a]) * t.y[a];
    slip -= dot(tau, w);
  }
  out.slip += slip.value();
  scatter(out.slip_gradient, slip, to);
}

/// Where the unknowns of `nodes` sit among those of s.nodes.
std::vector<Eigen::Index> unknown_map(const MortarSlave& s, const std::vector<int>& nodes) {
  std::vector<Eigen::Index> to;
  for (int node : nodes)
    for (int c = 0; c < 2; ++c) to.push_back(2 * index_of(s.nodes, node) + c);
  return to;
}

Kinematics kinematics(const MortarPair& pair, const MortarSlave& s, const EvaluationState& state, int order,
                      bool friction) {
  Kinematics out;
  const auto n_u = static_cast<Eigen::Index>(2 * s.nodes.size());
  if (order >= 1) {
    out.gradient = Eigen::VectorXd::Zero(n_u);
    out.D_gradient = Eigen::VectorXd::Zero(n_u);
    if (friction) {
      out.slip_gradient = Eigen::VectorXd::Zero(n_u);
      out.G = Eigen::VectorXd::Zero(n_u);
      out.G_jacobian = Eigen::MatrixXd::Zero(n_u, n_u);
    }
  }
  if (order >= 2) out.hessian = Eigen::MatrixXd::Zero(n_u, n_u);
  if (order >= 2 && pair.soft()) out.D_hessian = Eigen::MatrixXd::Zero(n_u, n_u);
  for (const auto& [e, k] : s.faces)
    for (int f : pair.term_faces(e)) {
      const std::vector<int> nodes = term_nodes(pair, e, f);
      std::vector<Vec2T<double>> x, x0;
      for (int n : nodes) x.push_back(position(pair, state.u, n)), x0.push_back(position(pair, state.u_start, n));
      const std::vector<Eigen::Index> to = unknown_map(s, nodes);
      std::optional<Term<double>> old;
      if (friction) old = term_of<double>(pair, s.node, e, k, f, nodes, x0, state.nlgeom);
      if (order == 0) {
        add_term(out, term_of<double>(pair, s.node, e, k, f, nodes, x, state.nlgeom), old ? &*old : nullptr, friction,
                 to);
        continue;
      }
      const int n = 2 * static_cast<int>(nodes.size());
      std::vector<Vec2T<Dual2>> d;
      for (std::size_t a = 0; a < x.size(); ++a) {
        const int i = 2 * static_cast<int>(a);
        d.push_back({Dual2::variable(x[a].x, i, n, order >= 2), Dual2::variable(x[a].y, i + 1, n, order >= 2)});
      }
      const Term<Dual2> t = term_of<Dual2>(pair, s.node, e, k, f, nodes, d, state.nlgeom);
      add_term(out, t, old ? &*old : nullptr, friction, to);
      if (friction && t.overlaps) {
        const Vec2T<Dual2> tau = tangent_of(t.normal);
        const auto add_G = [&](Eigen::Index row, const Dual2& value) {
          out.G[row] += value.value();
          if (value.constant()) return;
          for (Eigen::Index b = 0; b < value.gradient().size(); ++b)
            out.G_jacobian(row, to[static_cast<std::size_t>(b)]) += value.gradient()[b];
        };
        const Eigen::Index xj = 2 * index_of(s.nodes, s.node);
        add_G(xj, t.D * tau.x);
        add_G(xj + 1, t.D * tau.y);
        const std::vector<int>& master = pair.setup().master_faces[static_cast<std::size_t>(f)];
        for (std::size_t a = 0; a < master.size(); ++a) {
          const Eigen::Index ya = 2 * index_of(s.nodes, master[a]);
          add_G(ya, -(t.M[a] * tau.x));
          add_G(ya + 1, -(t.M[a] * tau.y));
        }
      }
    }
  if (!(out.D > 0)) out.covered = false;
  return out;
}

}  // namespace

std::span<const int> MortarNode::dofs() const { return pair_.slave(slave_).dofs; }

bool MortarNode::symmetric_tangent(bool /*nlgeom*/) const { return !(pair_.mu() > 0) && !pair_.soft(); }

std::string MortarNode::describe() const {
  return pair_.describe() + ", slave node " + std::to_string(pair_.slave(slave_).node);
}

double MortarNode::row_stiffness() const {
  const double area = pair_.slave(slave_).area;
  return pair_.setup().complementarity_stiffness / (area * area);
}

MortarNode::Gap MortarNode::gap(const Eigen::VectorXd& u, bool nlgeom) const {
  const Kinematics k = kinematics(pair_, pair_.slave(slave_), EvaluationState{u, u, 0, 0, 0, nlgeom}, 0, false);
  return {k.gap, k.D, k.covered};
}

namespace {

/// 1e-12 of the largest coordinate of the node's nodes times D_j [length × area]:
/// a weighted gap or slip within it is round-off.
double round_off(const MortarPair& pair, const MortarSlave& s, const Eigen::VectorXd& u, double D) {
  double largest = 0;
  for (int n : s.nodes) {
    const Vec2T<double> p = position(pair, u, n);
    largest = std::max({largest, std::abs(p.x), std::abs(p.y)});
  }
  return 1e-12 * largest * std::abs(D);
}

/// A weighted gap within round-off of zero is a touch: surfaces that coincide
/// in the mesh start closed rather than a few ulps open (or overclosed).
double decisive_gap(const MortarPair& pair, const MortarSlave& s, const Eigen::VectorXd& u, double gap, double D) {
  return std::abs(gap) <= round_off(pair, s, u, D) ? 0.0 : gap;
}

/// The soft law at the mean overclosure h_j = -g̃_j / D_j of a (decisive) weighted gap.
ContactPressure soft_pressure(const MortarPair& pair, double decisive, double D) {
  return contact_pressure(pair.setup().law, -decisive / D);
}

}  // namespace

bool MortarNode::closed(const EvaluationState& state) const {
  const MortarSlave& s = pair_.slave(slave_);
  const Gap g = gap(state.u, state.nlgeom);
  if (!g.covered) return false;
  const double decisive = decisive_gap(pair_, s, state.u, g.gap, g.D);
  if (pair_.soft()) {  // the law acts wherever it gives a pressure or a slope, and while λ_j is not yet zero
    const ContactPressure p = soft_pressure(pair_, decisive, g.D);
    return p.p > 0 || p.dp_dh > 0 || state.u[s.multiplier] != 0;
  }
  return state.u[s.multiplier] - row_stiffness() * decisive >= 0;
}

namespace {

/// Whether a closed node sticks: |λt + c ũ| < μ λn, or touches at rest
/// (no normal force and no trial force: the limit from the stick side, so
/// that a node touching with no friction history does not slide freely in
/// the first iteration). `tolerance` [length × area]: a slip within it is
/// no slip for this decision (the slip of a node at rest is a few ulps).
bool sticks(double lambda_t, double lambda_n, double slip, double mu, double c, double tolerance) {
  const double decisive = std::abs(slip) <= tolerance ? 0.0 : slip;
  const double trial = lambda_t + c * decisive, bound = mu * std::max(lambda_n, 0.0);
  return std::abs(trial) < bound || (bound == 0 && trial == 0);
}

}  // namespace

MortarNode::Friction MortarNode::friction(const EvaluationState& state) const {
  const MortarSlave& s = pair_.slave(slave_);
  Friction f;
  if (!(pair_.mu() > 0) || !closed(state)) return f;
  const Kinematics k = kinematics(pair_, s, state, 0, true);
  if (!k.covered) return f;
  f.closed = true;
  f.slip = k.slip;
  const double lambda_t = state.u[s.tangent_multiplier];
  f.stick = sticks(lambda_t, state.u[s.multiplier], k.slip, pair_.mu(), row_stiffness(),
                   round_off(pair_, s, state.u, k.D));
  if (!f.stick) f.direction = lambda_t + row_stiffness() * k.slip > 0 ? 1 : -1;
  return f;
}

namespace {

/// The rows of a node under a soft law (closed, covered; c = c_j).
void soft_rows(const MortarPair& pair, const MortarSlave& s, double c, const EvaluationState& state,
               const Kinematics& k, LocalSystem& out, bool need_tangent) {
  // The law λ_j = p(h_j) of the mean overclosure h_j = -g̃_j / D_j, and the
  // virtual work of the nodal force λ_j D_j on the mean gap:
  //   r_u += λ_j D_j ∇h_j = -λ_j (∇g̃_j + h_j ∇D_j),  r_λ = (p(h_j) - λ_j) / c_j,
  // so that a uniform overclosure does no work through the change of the
  // measure (NLGEOM) or of the overlap.
  const auto n_u = static_cast<Eigen::Index>(2 * s.nodes.size());
  const Eigen::Index in = n_u;
  const double lambda = state.u[s.multiplier];
  const double decisive = decisive_gap(pair, s, state.u, k.gap, k.D);
  const double h = -decisive / k.D;
  const ContactPressure p = soft_pressure(pair, decisive, k.D);
  const Eigen::VectorXd direction = k.gradient + h * k.D_gradient;  // = -D_j ∇h_j
  out.residual.head(n_u) -= lambda * direction;
  out.residual[in] = (p.p - lambda) / c;
  if (!need_tangent) return;
  const Eigen::VectorXd grad_h = -direction / k.D;
  out.tangent.topLeftCorner(n_u, n_u) -= lambda * (k.hessian + h * k.D_hessian + k.D_gradient * grad_h.transpose());
  out.tangent.col(in).head(n_u) -= direction;
  out.tangent.row(in).head(n_u) += (p.dp_dh / c) * grad_h.transpose();
  out.tangent(in, in) = -1 / c;
}

}  // namespace

void MortarNode::evaluate(const EvaluationState& state, LocalSystem& out, bool need_tangent) const {
  const MortarSlave& s = pair_.slave(slave_);
  const bool with_friction = pair_.mu() > 0;
  const auto n_u = static_cast<Eigen::Index>(2 * s.nodes.size());
  const Eigen::Index in = n_u, it = n_u + 1;
  const double lambda_n = state.u[s.multiplier];
  const double lambda_t = with_friction ? state.u[s.tangent_multiplier] : 0.0;
  const double c = row_stiffness();
  const auto open_rows = [&] {
    out.residual[in] = -lambda_n / c;
    if (need_tangent) out.tangent(in, in) = -1 / c;
    if (!with_friction) return;
    out.residual[it] = -lambda_t / c;
    if (need_tangent) out.tangent(it, it) = -1 / c;
  };
  if (!closed(state)) return open_rows();
  const Kinematics k = kinematics(pair_, s, state, need_tangent ? 2 : 1, with_friction);
  if (!k.covered) return open_rows();
  if (pair_.soft()) {
    soft_rows(pair_, s, c, state, k, out, need_tangent);
  } else {
    out.residual.head(n_u) -= lambda_n * k.gradient;
    out.residual[in] = -k.gap;
    if (need_tangent) {
      out.tangent.topLeftCorner(n_u, n_u) -= lambda_n * k.hessian;
      out.tangent.col(in).head(n_u) -= k.gradient;
      out.tangent.row(in).head(n_u) -= k.gradient.transpose();
    }
  }
  if (!with_friction) return;
  // Coulomb: the tangential traction λt does the virtual work λt G; its row
  // is ũ = 0 in stick and λt = μ λn sgn(λt + c ũ) in slip.
  out.residual.head(n_u) += lambda_t * k.G;
  if (need_tangent) {
    out.tangent.topLeftCorner(n_u, n_u) += lambda_t * k.G_jacobian;
    out.tangent.col(it).head(n_u) += k.G;
  }
  const double mu = pair_.mu();
  // The pair's guard may hold a node in stick (MortarPair::update_connectivity).
  if (s.held_stick || sticks(lambda_t, lambda_n, k.slip, mu, c, round_off(pair_, s, state.u, k.D))) {
    out.residual[it] = k.slip;
    if (need_tangent) out.tangent.row(it).head(n_u) += k.slip_gradient.transpose();
    return;
  }
  const double sign = lambda_t + c * k.slip > 0 ? 1.0 : -1.0;
  out.residual[it] = -(lambda_t - mu * std::max(lambda_n, 0.0) * sign) / c;
  if (!need_tangent) return;
  out.tangent(it, it) = -1 / c;
  if (lambda_n > 0) out.tangent(it, in) = mu * sign / c;
}

Eigen::VectorXd MortarNode::forces(const EvaluationState& state) const {
  const MortarSlave& s = pair_.slave(slave_);
  const auto n_u = static_cast<Eigen::Index>(2 * s.nodes.size());
  if (!closed(state)) return Eigen::VectorXd::Zero(n_u);
  const bool with_friction = pair_.mu() > 0;
  const Kinematics k = kinematics(pair_, s, state, 1, with_friction);
  if (!k.covered) return Eigen::VectorXd::Zero(n_u);
  Eigen::VectorXd f = state.u[s.multiplier] * k.gradient;
  if (with_friction) f -= state.u[s.tangent_multiplier] * k.G;
  return f;
}

}  // namespace tether
