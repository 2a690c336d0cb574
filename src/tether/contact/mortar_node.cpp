#include "tether/contact/mortar_node.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "tether/contact/mortar_pair.hpp"
#include "tether/contact/mortar_segmentation.hpp"
#include "tether/contact/mortar_terms.hpp"
#include "tether/contact/pressure_overclosure.hpp"
#include "tether/dofs/dof_map.hpp"

namespace tether {

namespace {

/// Index of real node `node` in `nodes`.
int index_of(const std::vector<int>& nodes, int node) {
  return static_cast<int>(std::find(nodes.begin(), nodes.end(), node) - nodes.begin());
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

/// Adds the share of one term without derivatives (order 0).
void add_term(Kinematics& out, const MortarTerm<double>& t, const MortarTerm<double>* old, bool friction) {
  if (t.overlaps) out.covered = true, out.gap += dot(t.normal, t.v), out.D += t.D;
  if (!friction) return;
  const Vec2T<double> tau = {-t.normal.y, t.normal.x};
  out.slip += dot(tau, t.v);
  if (old && old->overlaps) {
    Vec2T<double> w = -old->D * t.x_j;
    for (std::size_t a = 0; a < t.y.size(); ++a) w = w + old->M[a] * t.y[a];
    out.slip -= dot(tau, w);
  }
}

void scatter(Eigen::VectorXd& g, const MortarTermScalar& value, const std::vector<Eigen::Index>& to) {
  if (value.constant()) return;
  for (Eigen::Index a = 0; a < value.gradient.size(); ++a) g[to[static_cast<std::size_t>(a)]] += value.gradient[a];
}

void scatter_hessian(Eigen::MatrixXd& h, const MortarTermScalar& value, const std::vector<Eigen::Index>& to) {
  if (h.size() == 0 || !value.second()) return;
  for (std::size_t a = 0; a < to.size(); ++a)
    for (std::size_t b = 0; b < to.size(); ++b)
      h(to[a], to[b]) += value.hessian(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b));
}

/// Adds the share of one term with derivatives (order >= 1); `to`: where the
/// term's unknowns sit among the node's, `xj` the row of x_j there and
/// `master` those of the master face's nodes (frictional direction).
void add_share(Kinematics& out, const MortarTermShare& t, bool friction, const std::vector<Eigen::Index>& to,
               Eigen::Index xj, const std::vector<Eigen::Index>& master) {
  if (t.overlaps) {
    out.covered = true;
    out.gap += t.gap.value, out.D += t.D.value;
    scatter(out.gradient, t.gap, to);
    scatter(out.D_gradient, t.D, to);
    scatter_hessian(out.hessian, t.gap, to);
    scatter_hessian(out.D_hessian, t.D, to);
  }
  if (!friction) return;
  out.slip += t.slip.value;
  scatter(out.slip_gradient, t.slip, to);
  if (!t.overlaps) return;
  const auto add_G = [&](Eigen::Index row, const MortarTermScalar& value) {
    out.G[row] += value.value;
    if (value.constant()) return;
    for (Eigen::Index b = 0; b < value.gradient.size(); ++b)
      out.G_jacobian(row, to[static_cast<std::size_t>(b)]) += value.gradient[b];
  };
  add_G(xj, t.G[0]);
  add_G(xj + 1, t.G[1]);
  for (std::size_t a = 0; a < master.size(); ++a) {
    add_G(master[a], t.G[2 + 2 * a]);
    add_G(master[a] + 1, t.G[3 + 2 * a]);
  }
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
  const Eigen::Index xj = 2 * index_of(s.nodes, s.node);
  for (const auto& [e, k] : s.faces)
    for (int f : pair.term_faces(e)) {
      const auto kk = static_cast<std::size_t>(k);
      pair.term_cache().with_terms(pair, e, f, state, order, friction, [&](const MortarFaceTerms& terms) {
        if (order == 0) return add_term(out, terms.values[kk], friction ? &terms.start[kk] : nullptr, friction);
        std::vector<Eigen::Index> master;
        if (friction)
          for (int q : pair.setup().master_faces[static_cast<std::size_t>(f)]) master.push_back(2 * index_of(s.nodes, q));
        add_share(out, terms.shares[kk], friction, unknown_map(s, terms.nodes), xj, master);
      });
    }
  if (!(out.D > 0)) out.covered = false;
  return out;
}

}  // namespace

std::span<const int> MortarNode::dofs() const { return pair_.slave(slave_).dofs; }

bool MortarNode::symmetric_tangent(bool /*nlgeom*/) const { return !(pair_.mu() > 0) && !pair_.soft(); }

std::string MortarNode::describe() const {
  const auto& names = pair_.setup().slave_names;
  const auto k = static_cast<std::size_t>(slave_);
  return pair_.describe() + ", slave node " +
         (k < names.size() ? names[k] : "index " + std::to_string(pair_.slave(slave_).node));
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
    const Vec2T<double> p = mortar_position(pair, u, n);
    largest = std::max({largest, std::abs(p.x), std::abs(p.y)});
  }
  return 1e-12 * largest * std::abs(D);
}

/// Whether slave node j itself lies on the master surface: the ray from x_j
/// along its nodal normal n_j meets a master face that its faces overlap
/// (|η| <= 1) within round-off (1e-12 of the largest coordinate) of x_j.
bool touches_at_node(const MortarPair& pair, const MortarSlave& s, const Eigen::VectorXd& u) {
  const auto positions = [&](const std::vector<int>& nodes) {
    std::vector<Vec2T<double>> x;
    for (int n : nodes) x.push_back(mortar_position(pair, u, n));
    return x;
  };
  std::vector<std::vector<Vec2T<double>>> around;
  std::vector<int> at;
  for (const auto& [e, k] : pair.faces_of_node()[static_cast<std::size_t>(s.node)]) {
    around.push_back(positions(pair.setup().slave_faces[static_cast<std::size_t>(e)]));
    at.push_back(k);
  }
  const Vec2T<double> x = mortar_position(pair, u, s.node), n = nodal_normal<double>(around, at);
  const double tolerance = round_off(pair, s, u, 1.0);
  for (const auto& [e, k] : s.faces)
    for (int f : pair.overlapped(e)) {
      const std::vector<Vec2T<double>> y = positions(pair.setup().master_faces[static_cast<std::size_t>(f)]);
      const std::optional<double> eta = project_onto_master<double>(x, n, y);
      if (!eta || !(std::abs(*eta) <= 1 + 1e-12)) continue;
      std::array<double, 3> N{}, dN{};
      segment_shapes(static_cast<int>(y.size()), *eta, N, dN);
      Vec2T<double> p{0.0, 0.0};
      for (std::size_t a = 0; a < y.size(); ++a) p = p + N[a] * y[a];
      if (std::abs(dot(n, p - x)) <= tolerance) return true;
    }
  return false;
}

/// The weighted gap the active set is decided on: zero for a touch.
/// - A weighted gap within round-off of zero: surfaces that coincide in the
///   mesh start closed rather than a few ulps open (or overclosed).
/// - An open weighted gap of a node that itself lies on the master (a point
///   contact at the node, as between a cylinder and a flat): g̃_j is then the
///   dual-weighted gap of the faces around the point, which only the
///   discretisation makes non-zero (with quadratic faces about 1e-11 of the
///   face length at a cylinder of 8 faces per contact half-width, either
///   sign). Node-to-segment closes such a node (its gap is zero); so does
///   this, else a body held by contact alone has no closed node at the first
///   iteration and its matrix is singular. The NCP is unchanged: closed, the
///   row asks g̃_j = 0 and the node opens again when λ_j < 0.
double decisive_gap(const MortarPair& pair, const MortarSlave& s, const Eigen::VectorXd& u, double gap, double D) {
  if (std::abs(gap) <= round_off(pair, s, u, D)) return 0.0;
  return gap > 0 && touches_at_node(pair, s, u) ? 0.0 : gap;
}

/// The soft law at the mean overclosure h_j = -g̃_j / D_j of a (decisive) weighted gap.
ContactPressure soft_pressure(const MortarPair& pair, double decisive, double D) {
  return contact_pressure(pair.setup().law, -decisive / D);
}

}  // namespace

MortarNode::Decision MortarNode::decision(const EvaluationState& state) const {
  const MortarSlave& s = pair_.slave(slave_);
  const std::lock_guard<std::mutex> lock(memo_mutex_);
  const auto same_positions = [&] {
    for (std::size_t a = 0; a < s.nodes.size(); ++a) {
      const Vec2T<double> p = mortar_position(pair_, state.u, s.nodes[a]);
      if (!(p.x == memo_.x[2 * a] && p.y == memo_.x[2 * a + 1])) return false;
    }
    return true;
  };
  if (memo_.valid && memo_.nlgeom == state.nlgeom && memo_.version == pair_.overlap_version() &&
      memo_.nodes == s.nodes && same_positions())
    return memo_.decision;
  memo_.valid = false;
  Decision d;
  d.gap = gap(state.u, state.nlgeom);
  if (d.gap.covered) d.decisive = decisive_gap(pair_, s, state.u, d.gap.gap, d.gap.D);
  memo_.x.clear();
  for (int n : s.nodes) {
    const Vec2T<double> p = mortar_position(pair_, state.u, n);
    memo_.x.push_back(p.x), memo_.x.push_back(p.y);
  }
  memo_.nodes = s.nodes;
  memo_.nlgeom = state.nlgeom, memo_.version = pair_.overlap_version(), memo_.decision = d, memo_.valid = true;
  return d;
}

bool MortarNode::closed(const EvaluationState& state) const {
  const MortarSlave& s = pair_.slave(slave_);
  const Decision d = decision(state);
  const Gap& g = d.gap;
  if (!g.covered) return false;
  const double decisive = d.decisive;
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
