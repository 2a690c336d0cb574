#include "tether/contact/contact_node.hpp"

#include <cmath>

#include "tether/contact/contact_pair.hpp"
#include "tether/contact/pressure_overclosure.hpp"
#include "tether/contact/segment_geometry.hpp"
#include "tether/dofs/dof_map.hpp"
#include "tether/model/constraint_data.hpp"

namespace tether {

namespace {

using Vec = Eigen::VectorXd;

/// Current positions of the slave node and the segment's (virtual) nodes, in
/// local order: for a smoothed segment, z = W y of its real nodes' positions y.
std::vector<Eigen::Vector2d> local_positions(const ContactPair& pair, const ContactSlave& s, const Eigen::VectorXd& u,
                                             int n_points) {
  std::vector<Eigen::Vector2d> y(static_cast<std::size_t>(n_points));
  for (int a = 0; a < n_points; ++a) {
    const int node = s.nodes[static_cast<std::size_t>(a)];
    y[static_cast<std::size_t>(a)] = pair.reference()[static_cast<std::size_t>(node)] +
                                     Eigen::Vector2d(u[DofMap::displacement(node, 0)], u[DofMap::displacement(node, 1)]);
  }
  if (s.pairing.found() && !pair.segments().segment(s.pairing.segment).identity) {
    const std::vector<Eigen::Vector2d> real(y.begin() + 1, y.end());
    pair.segments().virtual_positions(s.pairing.segment, real, std::span(y).subspan(1));
  }
  return y;
}

/// The points the slip increment depends on (current positions): the slave,
/// the current segment's (virtual) nodes and, after a hand-over, those of the
/// committed segment.
std::vector<Eigen::Vector2d> slip_points(const ContactPair& pair, const ContactSlave& s,
                                         std::span<const Eigen::Vector2d> y, const Eigen::VectorXd& u) {
  std::vector<Eigen::Vector2d> points(y.begin(), y.end());
  if (s.handed_over) {
    const std::vector<Eigen::Vector2d> committed = pair.segment_points(s.committed_segment, u);
    points.insert(points.end(), committed.begin(), committed.end());
  }
  return points;
}

/// Δs and its gradient over the points of slip_points() (`m` current segment
/// nodes). Without a hand-over the committed segment is the current one and
/// its part of the gradient is added to the current nodes'.
SlipIncrement slip_of(std::span<const Eigen::Vector2d> points, int m, double xi_c, const SegmentGeometry* geometry,
                      bool need_gradient) {
  const auto segment = points.subspan(1, static_cast<std::size_t>(m));
  const bool handed_over = points.size() > static_cast<std::size_t>(1 + m);
  const auto committed = handed_over ? points.subspan(static_cast<std::size_t>(1 + m)) : segment;
  const ContactDerivatives d = need_gradient ? ContactDerivatives::gradient : ContactDerivatives::none;
  SegmentGeometry own;
  if (!geometry) {
    own = segment_geometry(points[0], segment, d);
    geometry = &own;
  }
  SlipIncrement slip = slip_increment(points[0], segment, *geometry, committed, xi_c, d);
  if (need_gradient && !handed_over) {
    slip.gradient.segment(2, 2 * m) += slip.gradient.tail(2 * m);
    slip.gradient.conservativeResize(2 * (1 + m));
  }
  return slip;
}

/// Normal gap with derivatives: of the segment at ξ*, or of the end node for
/// a slave in the shadow of a convex corner (node-to-node contact).
struct Gap {
  SegmentGeometry geometry;
  double g = 0;
  ContactVector gradient;
  ContactMatrix hessian;
  /// Round-off of g [length]: 1e-12 of the largest coordinate involved.
  double round_off = 0;
  /// g for deciding contact: a positive gap within round-off is a touch
  /// (0). A node placed on the master surface by the mesh generator lands a
  /// few ulps either side of it; on the positive side it would otherwise be
  /// open in the first iteration, carry no friction and slide freely while
  /// its neighbours, at exactly 0, touch and stick.
  [[nodiscard]] double decisive() const { return g > 0 && g <= round_off ? 0.0 : g; }
};

Gap gap_of(const ContactSlave& s, std::span<const Eigen::Vector2d> y, bool need_hessian) {
  Gap gap;
  const auto seg = y.subspan(1);
  gap.geometry = segment_geometry(y[0], seg, need_hessian ? ContactDerivatives::hessian : ContactDerivatives::gradient);
  const int nu = 2 * static_cast<int>(y.size());
  double largest = 0;
  for (const Eigen::Vector2d& p : y) largest = std::max(largest, p.lpNorm<Eigen::Infinity>());
  gap.round_off = 1e-12 * largest;
  if (!s.pairing.at_corner) {
    gap.g = gap.geometry.gap;
    gap.gradient = gap.geometry.gap_gradient;
    gap.hessian = need_hessian ? gap.geometry.gap_hessian : ContactMatrix::Zero(nu, nu);
    return gap;
  }
  // Convex corner: g = ±|y_s - y_end|, the sign of the pairing.
  const int end = s.pairing.xi < 0 ? 1 : 2;  // local point index of the end node
  const Eigen::Vector2d d = y[0] - y[static_cast<std::size_t>(end)];
  const double len = d.norm();
  const double sign = s.pairing.gap < 0 ? -1.0 : 1.0;
  gap.g = sign * len;
  gap.gradient = ContactVector::Zero(nu);
  gap.hessian = ContactMatrix::Zero(nu, nu);
  if (len <= 0) return gap;
  const Eigen::Vector2d e = d / len;
  gap.gradient.segment<2>(0) = sign * e;
  gap.gradient.segment<2>(2 * end) = -sign * e;
  if (need_hessian) {
    const Eigen::Matrix2d h = sign * (Eigen::Matrix2d::Identity() - e * e.transpose()) / len;
    gap.hessian.block<2, 2>(0, 0) = h;
    gap.hessian.block<2, 2>(2 * end, 2 * end) = h;
    gap.hessian.block<2, 2>(0, 2 * end) = -h;
    gap.hessian.block<2, 2>(2 * end, 0) = -h;
  }
  return gap;
}

/// The area of a slave node at the state and its gradient over [slave,
/// segment]: CalculiX's (dialect calculix, node-based slave) is the master
/// face's at the projection on the current face, A(y, ξ*(y)), so ∇A =
/// ∂A/∂y + ∂A/∂ξ ∇ξ* (at a convex corner ξ is the end's, fixed); otherwise
/// the fixed tributary area (gradient 0, `varies` false).
struct Area {
  double value = 0;
  bool varies = false;
  ContactVector gradient;
};

Area area_of(const ContactPair& pair, const ContactSlave& s, std::span<const Eigen::Vector2d> y, const Gap& gap) {
  const ContactPairSetup& setup = pair.setup();
  Area area;
  area.value = s.area;
  if (setup.calculix_face_areas.empty() || !s.pairing.found()) return area;
  const MasterSegment& segment = pair.segments().segment(s.pairing.segment);
  const bool corner = s.pairing.at_corner;
  const double xi = corner ? (s.pairing.xi < 0 ? -1.0 : 1.0) : gap.geometry.projection.xi;
  const int face = segment.face_at(xi);
  const FaceArea a = calculix_face_area(setup.calculix_face_areas[static_cast<std::size_t>(face)], y.subspan(1), xi);
  const int nu = 2 * static_cast<int>(y.size());
  area.value = a.area;
  area.varies = true;
  area.gradient = ContactVector::Zero(nu);
  for (std::size_t k = 0; k < a.d_nodes.size(); ++k) area.gradient.segment<2>(2 + 2 * static_cast<int>(k)) = a.d_nodes[k];
  if (!corner) area.gradient += a.d_xi * gap.geometry.xi_gradient;
  return area;
}

/// T of r_real = Tᵀ r_v, K_real = Tᵀ K_v T: the local unknowns of compute()
/// [slave, current segment's virtual nodes, committed segment's virtual nodes
/// (after a hand-over), multipliers] as linear functions of the slave's dofs
/// (real nodes; MasterSegments' constant weights).
Eigen::MatrixXd virtual_to_real(const ContactPair& pair, const ContactSlave& s, int n_virtual) {
  const auto n_real = static_cast<Eigen::Index>(s.dofs.size());
  Eigen::MatrixXd T = Eigen::MatrixXd::Zero(n_virtual, n_real);
  T.topLeftCorner<2, 2>().setIdentity();
  auto slot_of = [&s](int node) {  // local node slot of a real node in s.dofs
    for (std::size_t a = 0; a < s.nodes.size(); ++a)
      if (s.nodes[a] == node) return static_cast<int>(a);
    return -1;
  };
  int row = 2;
  auto add_segment = [&](int k) {
    const MasterSegment& seg = pair.segments().segment(k);
    for (int p = 0; p < seg.n_nodes; ++p, row += 2)
      for (int a = 0; a < seg.n_nodes; ++a) {
        const int slot = slot_of(seg.nodes[static_cast<std::size_t>(a)]);
        T.block<2, 2>(row, 2 * slot) += seg.weights(p, a) * Eigen::Matrix2d::Identity();
      }
  };
  add_segment(s.pairing.segment);
  if (s.handed_over) add_segment(s.committed_segment);
  const Eigen::Index n_mult = n_virtual - row;
  T.bottomRightCorner(n_mult, n_mult).setIdentity();
  return T;
}

}  // namespace

struct ContactNode::Point {
  ContactStatus status = ContactStatus::Open;
  double gap = 0, xi = 0;
  double normal_force = 0, tangential_force = 0, slip = 0;
  double area = 0;  ///< the slave node's area at this state [length × thickness]
  int slip_sign = 0;  ///< slip: the sign the friction force is driven to (of λt + cΔs, or of the trial force)
  bool friction_active = false;  ///< with friction: the friction row is the stick or slip one (not the open one)
  Eigen::Vector2d normal{0, 0}, tangent{0, 0};
};

std::span<const int> ContactNode::dofs() const { return pair_.slave(slave_).dofs; }

std::string ContactNode::describe() const {
  const auto& names = pair_.setup().slave_names;
  const auto k = static_cast<std::size_t>(slave_);
  return pair_.describe() + ", slave node " +
         (k < names.size() ? names[k] : "index " + std::to_string(pair_.slave(slave_).node));
}

bool ContactNode::symmetric_tangent(bool /*nlgeom*/) const { return pair_.mu() <= 0; }

ContactNode::Point ContactNode::compute(const EvaluationState& state, LocalSystem* out, bool need_tangent) const {
  const ContactSlave& s = pair_.slave(slave_);
  const ContactPairSetup& setup = pair_.setup();
  const double c = setup.complementarity_stiffness;
  const bool hard = setup.law.law == PressureOverclosure::Law::Hard;
  const bool hard_multiplier = hard && setup.law.enforcement.method == Enforcement::Method::Lagrange;
  const double mu = pair_.mu();
  const bool friction = mu > 0;
  const bool exact_stick = friction && pair_.exact_stick();
  const int n_mult = (hard_multiplier ? 1 : 0) + (exact_stick ? 1 : 0);
  // Local unknowns here: [slave, the segment's m (virtual) nodes, after a
  // hand-over the committed segment's m_c (virtual) nodes, multipliers];
  // evaluate() maps them onto the dofs. nu: slave and segment, ns: all points.
  const int m = s.pairing.found() ? pair_.segments().segment(s.pairing.segment).n_nodes : 0;
  const int m_c = s.handed_over ? pair_.segments().segment(s.committed_segment).n_nodes : 0;
  const int nu = 2 * (1 + m);
  const int ns = nu + 2 * m_c;
  const int n_local = ns + n_mult;
  const int in = hard_multiplier ? ns : -1;  // local index of λn
  const int it = exact_stick ? ns + (hard_multiplier ? 1 : 0) : -1;  // local index of λt
  const auto mult = [&](int k) { return state.u[s.dofs[s.dofs.size() - static_cast<std::size_t>(n_local - k)]]; };
  const double lambda_n = hard_multiplier ? mult(in) : 0.0;
  const double lambda_t = exact_stick ? mult(it) : 0.0;
  need_tangent = need_tangent && out;

  Point point;
  point.area = s.area;
  if (!s.pairing.found()) {  // free slave: multipliers vanish
    if (out)
      for (int k = ns; k < n_local; ++k) {
        out->residual[k] = -mult(k) / c;
        if (need_tangent) out->tangent(k, k) = -1 / c;
      }
    return point;
  }

  const std::vector<Eigen::Vector2d> y = local_positions(pair_, s, state.u, 1 + m);
  const Gap gap = gap_of(s, y, need_tangent);
  point.gap = gap.g;
  point.xi = gap.geometry.projection.xi;
  point.normal = gap.geometry.normal;
  point.tangent = gap.geometry.tangent;
  const Area area = area_of(pair_, s, y, gap);
  point.area = area.value;

  // ---- normal contact: N and dN (over the local unknowns)
  Vec dN = Vec::Zero(n_local);
  double N = 0;
  bool closed = false;
  const Enforcement& enforcement = setup.law.enforcement;
  if (hard && enforcement.method == Enforcement::Method::Lagrange) {
    // min(λn/c, g + ε λn) = 0: exact for ε = 0, regularised otherwise.
    const double eps = enforcement.epsilon;
    const double g_reg = gap.g + eps * lambda_n;
    closed = lambda_n - c * (gap.decisive() + eps * lambda_n) >= 0 || s.held_closed;
    N = closed ? std::max(lambda_n, 0.0) : 0.0;
    if (closed && lambda_n > 0) dN[in] = 1;
    // An open node's multiplier is driven to zero by its own row; its force
    // term -λn ∇g is left out of r_u, so that the tangent stays symmetric (the
    // system is the same at every solution, where λn = 0 on open nodes).
    if (out) {
      if (closed) {
        out->residual.head(nu) -= lambda_n * gap.gradient;
        out->residual[in] = -g_reg;
      } else {
        out->residual[in] = -lambda_n / c;
      }
      if (need_tangent) {
        if (closed) {
          out->tangent.topLeftCorner(nu, nu) -= lambda_n * gap.hessian;
          out->tangent.col(in).head(nu) -= gap.gradient;
          out->tangent.row(in).head(nu) -= gap.gradient.transpose();
          out->tangent(in, in) = -eps;
        } else {
          out->tangent(in, in) = -1 / c;
        }
      }
    }
  } else {
    // A force law without multiplier: soft pressure-overclosure, or HARD by
    // penalty N = ρ<-g> / augmented Lagrangian N = <λ̄ - ρ g>.
    if (!hard) {
      const double reach = setup.node_based_slave ? kCalculixNodeSlaveReach : calculix_linear_reach(setup.law, s.area);
      const ContactPressure p = contact_pressure(setup.law, -gap.g, reach);
      // N = A p(-g): dN = -A p' ∇g + p ∇A (∇A = 0 for a fixed area).
      N = area.value * p.p;
      dN.head(nu) = -area.value * p.dp_dh * gap.gradient;
      if (area.varies) dN.head(nu) += p.p * area.gradient;
    } else {
      const double rho = enforcement.penalty;
      const double base = enforcement.method == Enforcement::Method::Augmented ? s.lambda_bar : 0.0;
      const double trial = base - rho * gap.g;
      if (trial >= 0 && (trial > 0 || gap.decisive() <= 0)) {
        N = trial;
        dN.head(nu) = -rho * gap.gradient;
      }
    }
    // A tension (CalculiX's LINEAR law at an open gap) is an open node: no friction.
    closed = N > 0 || (N == 0 && dN.head(nu).squaredNorm() > 0);
    if (out) {
      out->residual.head(nu) -= N * gap.gradient;
      if (need_tangent)
        out->tangent.topLeftCorner(nu, nu) -= gap.gradient * dN.head(nu).transpose() + N * gap.hessian;
    }
  }
  point.normal_force = N;
  point.status = closed ? ContactStatus::Slip : ContactStatus::Open;
  if (!friction) return point;

  // ---- friction: slip increment Δs since the last converged increment
  const std::vector<Eigen::Vector2d> points = slip_points(pair_, s, y, state.u);
  const SlipIncrement slip = slip_of(points, m, s.committed_xi, &gap.geometry, out != nullptr);
  const double ds = slip.value;
  const SlipVector& grad_ds = slip.gradient;
  point.slip = ds;
  // The friction force T acts at the contact point y(ξ*) along t: its
  // virtual work is T |y'| δξ* = T (δy_s - Σ N_a(ξ*) δy^a)·t (at g = 0), so
  // its direction over [slave, segment] is F = |y'| ∂ξ*/∂x, and ∂F/∂x =
  // ∂ξ*/∂x ⊗ ∂|y'|/∂x + |y'| ∂²ξ*/∂x². (Not T ∇Δs: that would put the
  // master's share at the committed point ξ_c, where the slave was at the
  // last converged increment, and move it to ξ* when the next increment
  // commits: a jump of the residual between increments, and answers that
  // depend on the increment size.)
  // At a convex corner (node-to-node contact with the end node, normal
  // e = ∇_s g) the contact point is the end node itself: T acts between the
  // slave and that node along t_e = e rotated by +90° (t_e = t where e = n),
  // at right angles to the normal force, and ∂t_e/∂y_s = R ∂e/∂y_s = R ∇²_ss g.
  const SegmentGeometry& geo = gap.geometry;
  const bool corner = s.pairing.at_corner;
  const Eigen::Matrix2d rot90{{0, -1}, {1, 0}};
  const int end = s.pairing.xi < 0 ? 1 : 2;  // local point of the end node at a corner
  ContactVector force_direction = geo.metric * geo.xi_gradient;
  if (corner) {
    const Eigen::Vector2d t_e = rot90 * gap.gradient.segment<2>(0);
    force_direction.setZero(nu);
    force_direction.segment<2>(0) = t_e;
    force_direction.segment<2>(2 * end) = -t_e;
  }
  const auto force_jacobian = [&] {
    if (!corner)
      return ContactMatrix(geo.xi_gradient * geo.metric_gradient.transpose() + geo.metric * geo.xi_hessian);
    ContactMatrix j = ContactMatrix::Zero(nu, nu);
    const Eigen::Matrix2d d = rot90 * gap.hessian.block<2, 2>(0, 0);  // ∂t_e/∂y_s; ∂t_e/∂y_end = -d
    j.block<2, 2>(0, 0) = d, j.block<2, 2>(0, 2 * end) = -d;
    j.block<2, 2>(2 * end, 0) = -d, j.block<2, 2>(2 * end, 2 * end) = d;
    return j;
  };
  double T = 0;
  if (exact_stick) {
    T = lambda_t;
    const double tau = lambda_t + c * ds;
    const double bound = mu * N;
    if (out) {
      out->residual.head(nu) += lambda_t * force_direction;
      if (need_tangent) {
        out->tangent.topLeftCorner(nu, nu) += lambda_t * force_jacobian();
        out->tangent.col(it).head(nu) += force_direction;
      }
    }
    // A closed node without force and with τ = 0 — touching at the start of
    // an increment with no friction history (λt = 0, Δs = 0) — sits where
    // the open row -λt/c and the stick row Δs meet, both zero. It takes the
    // stick row there (the limit from N > 0, |τ| < μN): otherwise the first
    // iteration gives it no friction and lets it slide freely.
    const bool touching_at_rest = closed && !(N > 0) && tau == 0;
    if (!(N > 0) && !touching_at_rest) {
      if (out) {
        out->residual[it] = -lambda_t / c;
        if (need_tangent) out->tangent(it, it) = -1 / c;
      }
    } else if (std::abs(tau) < bound || s.held_stick || touching_at_rest) {
      point.status = ContactStatus::Stick;
      point.friction_active = true;
      if (out) {
        out->residual[it] = ds;
        if (need_tangent) out->tangent.row(it).head(ns) += grad_ds.transpose();
      }
    } else {
      const double sign = tau >= 0 ? 1.0 : -1.0;
      point.slip_sign = tau >= 0 ? 1 : -1;
      point.friction_active = true;
      if (out) {
        out->residual[it] = -(lambda_t - bound * sign) / c;
        if (need_tangent) {
          out->tangent(it, it) += -1 / c;
          out->tangent.row(it) += (mu * sign / c) * dN.transpose();
        }
      }
    }
  } else {
    // Stick penalty: k from the stick slope (per area) or from the elastic slip.
    const FrictionData& f = *setup.friction;
    double k = 0;
    Vec dk = Vec::Zero(n_local);
    if (f.stick_slope > 0) {
      k = f.stick_slope * area.value;
      if (area.varies) dk.head(nu) = f.stick_slope * area.gradient;
    } else {
      k = mu * N / f.elastic_slip;
      dk = (mu / f.elastic_slip) * dN;
    }
    const double trial = s.committed_tangential_force + k * ds;
    Vec dT = Vec::Zero(n_local);
    if (N > 0 && (std::abs(trial) <= mu * N || s.held_stick)) {
      T = trial;
      point.status = ContactStatus::Stick;
      point.friction_active = true;
      if (out) dT.head(ns) += k * grad_ds;  // the gradient exists only when asked for
      dT += ds * dk;
    } else if (N > 0) {
      const double sign = trial >= 0 ? 1.0 : -1.0;
      point.slip_sign = trial >= 0 ? 1 : -1;
      point.friction_active = true;
      T = mu * N * sign;
      dT = mu * sign * dN;
    }
    if (out) {
      out->residual.head(nu) += T * force_direction;
      if (need_tangent) {
        // Also at T = 0: a node at rest in stick (T_c = 0, Δs = 0) has the
        // stiffness F ⊗ k ∇Δs, without which its first iteration slides freely.
        out->tangent.topRows(nu) += force_direction * dT.transpose();
        if (T != 0) out->tangent.topLeftCorner(nu, nu) += T * force_jacobian();
      }
    }
  }
  point.tangential_force = T;
  return point;
}

void ContactNode::evaluate(const EvaluationState& state, LocalSystem& out, bool need_tangent) const {
  const ContactSlave& s = pair_.slave(slave_);
  if (!s.pairing.found() || (pair_.segments().segment(s.pairing.segment).identity && !s.handed_over)) {
    compute(state, &out, need_tangent);  // the local unknowns are the dofs
    return;
  }
  // compute() works on the virtual nodes of smoothed segments and, after a
  // hand-over, on the committed segment's nodes as separate points; the
  // chain rule through the constant map onto the dofs gives their rows.
  const int n_mult = (s.normal_multiplier >= 0 ? 1 : 0) + (s.tangent_multiplier >= 0 ? 1 : 0);
  const int m = pair_.segments().segment(s.pairing.segment).n_nodes;
  const int m_c = s.handed_over ? pair_.segments().segment(s.committed_segment).n_nodes : 0;
  const int n_virtual = 2 * (1 + m + m_c) + n_mult;
  LocalSystem local;
  local.reset(n_virtual);
  compute(state, &local, need_tangent);
  const Eigen::MatrixXd T = virtual_to_real(pair_, s, n_virtual);
  out.residual.noalias() = T.transpose() * local.residual;
  if (need_tangent) out.tangent.noalias() = T.transpose() * local.tangent * T;
}

ContactNodeValues ContactNode::values(const EvaluationState& state) const {
  const ContactSlave& s = pair_.slave(slave_);
  const Point p = compute(state, nullptr, false);
  ContactNodeValues v;
  v.node = s.node;
  v.status = p.status == ContactStatus::Open    ? ContactNodeValues::Status::Open
             : p.status == ContactStatus::Stick ? ContactNodeValues::Status::Stick
                                                : ContactNodeValues::Status::Slip;
  if (s.pairing.found()) {
    const int face = pair_.segments().segment(s.pairing.segment).face_at(p.xi);
    const auto& label = pair_.setup().master_face_labels[static_cast<std::size_t>(face)];
    v.master_element = label.first;
    v.master_face = label.second;
  }
  v.xi = p.xi;
  v.gap = p.gap;
  v.normal_force = p.normal_force;
  // Per the area at this state (CalculiX's current one, or the fixed one); a CAX node on the axis has none.
  v.pressure = p.area > 0 ? p.normal_force / p.area : 0.0;
  v.tangential_force = p.tangential_force;
  v.shear = p.area > 0 ? p.tangential_force / p.area : 0.0;
  v.slip = p.slip;
  // History up to the last converged increment plus this increment's slip.
  const bool slipping = p.status == ContactStatus::Slip && pair_.mu() > 0;
  v.total_slip = s.total_slip + (slipping ? std::abs(p.slip) : 0.0);
  v.dissipation = s.dissipation + (slipping ? p.tangential_force * p.slip : 0.0);
  v.force = p.normal_force * p.normal - p.tangential_force * p.tangent;
  return v;
}

ContactBranch ContactNode::branch(const EvaluationState& state) const {
  const Point p = compute(state, nullptr, false);
  ContactBranch b;
  b.status = p.status;
  // The sign of the slip branch the residual takes at this state (for exact
  // stick that of λt + cΔs: λt itself still has the sign of the previous
  // iteration's branch).
  b.direction = p.status == ContactStatus::Slip ? p.slip_sign : 0;
  b.friction_active = p.friction_active;
  return b;
}

}  // namespace tether
