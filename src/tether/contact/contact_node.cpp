#include "tether/contact/contact_node.hpp"

#include <cmath>

#include "tether/contact/contact_pair.hpp"
#include "tether/contact/pressure_overclosure.hpp"
#include "tether/contact/segment_geometry.hpp"
#include "tether/dofs/dof_map.hpp"
#include "tether/fem/shape_functions.hpp"
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
    const int dx = s.dofs[static_cast<std::size_t>(2 * a)];
    y[static_cast<std::size_t>(a)] = pair.reference()[static_cast<std::size_t>(dx / kDofsPerNode)] +
                                     Eigen::Vector2d(u[dx], u[dx + 1]);
  }
  if (s.pairing.found() && !pair.segments().segment(s.pairing.segment).identity) {
    const std::vector<Eigen::Vector2d> real(y.begin() + 1, y.end());
    pair.segments().virtual_positions(s.pairing.segment, real, std::span(y).subspan(1));
  }
  return y;
}

/// ξ on the current segment of the master point the slave was paired with at
/// the last converged increment (the reference of the slip increment).
double committed_xi_on(const ContactPair& pair, const ContactSlave& s, std::span<const Eigen::Vector2d> segment,
                       const Eigen::VectorXd& u) {
  if (s.committed_segment == s.pairing.segment || s.committed_segment < 0) return s.committed_xi;
  // The slave moved to another segment: the old master point, at current
  // positions, projected onto the new segment (exact on a straight surface).
  const std::vector<Eigen::Vector2d> old_segment = pair.segment_points(s.committed_segment, u);
  Eigen::Vector3d N, dN;
  face_shape_functions(static_cast<int>(old_segment.size()), s.committed_xi, N, dN);
  Eigen::Vector2d y_old(0, 0);
  for (std::size_t a = 0; a < old_segment.size(); ++a) y_old += N[static_cast<Eigen::Index>(a)] * old_segment[a];
  return project(y_old, segment).xi;
}

/// Normal gap with derivatives: of the segment at ξ*, or of the end node for
/// a slave in the shadow of a convex corner (node-to-node contact).
struct Gap {
  SegmentGeometry geometry;
  double g = 0;
  ContactVector gradient;
  ContactMatrix hessian;
};

Gap gap_of(const ContactSlave& s, std::span<const Eigen::Vector2d> y, bool need_hessian) {
  Gap gap;
  const auto seg = y.subspan(1);
  gap.geometry = segment_geometry(y[0], seg, need_hessian ? ContactDerivatives::hessian : ContactDerivatives::gradient);
  const int nu = 2 * static_cast<int>(y.size());
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

/// Hessian of the slip increment by central differences of its exact
/// gradient (the curvature term T ∂²Δs only; see the theory page).
ContactMatrix slip_hessian(std::vector<Eigen::Vector2d> y, double xi_ref) {
  const int nu = 2 * static_cast<int>(y.size());
  const double h = 1e-6 * std::max((y[2] - y[1]).norm(), 1e-300);
  ContactMatrix H(nu, nu);
  for (int j = 0; j < nu; ++j) {
    auto& c = y[static_cast<std::size_t>(j / 2)][j % 2];
    const double keep = c;
    c = keep + h;
    const ContactVector plus =
        slip_increment_gradient(segment_geometry(y[0], std::span(y).subspan(1), ContactDerivatives::gradient), xi_ref);
    c = keep - h;
    const ContactVector minus =
        slip_increment_gradient(segment_geometry(y[0], std::span(y).subspan(1), ContactDerivatives::gradient), xi_ref);
    c = keep;
    H.col(j) = (plus - minus) / (2 * h);
  }
  return 0.5 * (H + H.transpose());
}

}  // namespace

struct ContactNode::Point {
  ContactStatus status = ContactStatus::Open;
  double gap = 0, xi = 0;
  double normal_force = 0, tangential_force = 0, slip = 0;
  int slip_sign = 0;  ///< slip: the sign the friction force is driven to (of λt + cΔs, or of the trial force)
  Eigen::Vector2d normal{0, 0}, tangent{0, 0};
};

std::span<const int> ContactNode::dofs() const { return pair_.slave(slave_).dofs; }

std::string ContactNode::describe() const {
  return pair_.describe() + ", slave node " + std::to_string(pair_.slave(slave_).node);
}

ContactNode::Point ContactNode::compute(const EvaluationState& state, LocalSystem* out, bool need_tangent) const {
  const ContactSlave& s = pair_.slave(slave_);
  const ContactPairSetup& setup = pair_.setup();
  const double c = setup.complementarity_stiffness;
  const bool hard = setup.law.law == PressureOverclosure::Law::Hard;
  const bool hard_multiplier = hard && setup.law.enforcement.method == Enforcement::Method::Lagrange;
  const double mu = pair_.mu();
  const bool friction = mu > 0;
  const bool exact_stick = friction && pair_.exact_stick();
  const int n_local = static_cast<int>(s.dofs.size());
  const int n_mult = (hard_multiplier ? 1 : 0) + (exact_stick ? 1 : 0);
  const int nu = n_local - n_mult;  // displacement dofs
  const int in = hard_multiplier ? nu : -1;  // local index of λn
  const int it = exact_stick ? nu + (hard_multiplier ? 1 : 0) : -1;  // local index of λt
  const double lambda_n = hard_multiplier ? state.u[s.dofs[static_cast<std::size_t>(in)]] : 0.0;
  const double lambda_t = exact_stick ? state.u[s.dofs[static_cast<std::size_t>(it)]] : 0.0;
  need_tangent = need_tangent && out;

  Point point;
  if (!s.pairing.found()) {  // free slave: multipliers vanish
    if (out)
      for (int k = nu; k < n_local; ++k) {
        out->residual[k] = -state.u[s.dofs[static_cast<std::size_t>(k)]] / c;
        if (need_tangent) out->tangent(k, k) = -1 / c;
      }
    return point;
  }

  const std::vector<Eigen::Vector2d> y = local_positions(pair_, s, state.u, nu / 2);
  const Gap gap = gap_of(s, y, need_tangent);
  point.gap = gap.g;
  point.xi = gap.geometry.projection.xi;
  point.normal = gap.geometry.normal;
  point.tangent = gap.geometry.tangent;

  // ---- normal contact: N and dN (over the local unknowns)
  Vec dN = Vec::Zero(n_local);
  double N = 0;
  bool closed = false;
  const Enforcement& enforcement = setup.law.enforcement;
  if (hard && enforcement.method == Enforcement::Method::Lagrange) {
    // min(λn/c, g + ε λn) = 0: exact for ε = 0, regularised otherwise.
    const double eps = enforcement.epsilon;
    const double g_reg = gap.g + eps * lambda_n;
    closed = lambda_n - c * g_reg >= 0 || s.held_closed;
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
      const ContactPressure p = contact_pressure(setup.law, -gap.g);
      N = s.area * p.p;
      dN.head(nu) = -s.area * p.dp_dh * gap.gradient;
    } else {
      const double rho = enforcement.penalty;
      const double base = enforcement.method == Enforcement::Method::Augmented ? s.lambda_bar : 0.0;
      const double trial = base - rho * gap.g;
      if (trial >= 0 && (trial > 0 || gap.g <= 0)) {
        N = trial;
        dN.head(nu) = -rho * gap.gradient;
      }
    }
    closed = N > 0 || dN.head(nu).squaredNorm() > 0;
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
  const double xi_ref = committed_xi_on(pair_, s, std::span(y).subspan(1), state.u);
  const double ds = slip_increment(gap.geometry, xi_ref);
  const ContactVector grad_ds = slip_increment_gradient(gap.geometry, xi_ref);
  point.slip = ds;
  double T = 0;
  if (exact_stick) {
    T = lambda_t;
    const double tau = lambda_t + c * ds;
    const double bound = mu * N;
    if (out) {
      out->residual.head(nu) += lambda_t * grad_ds;
      if (need_tangent) {
        out->tangent.topLeftCorner(nu, nu) += lambda_t * slip_hessian(y, xi_ref);
        out->tangent.col(it).head(nu) += grad_ds;
      }
    }
    if (!(N > 0)) {
      if (out) {
        out->residual[it] = -lambda_t / c;
        if (need_tangent) out->tangent(it, it) = -1 / c;
      }
    } else if (std::abs(tau) < bound || s.held_stick) {
      point.status = ContactStatus::Stick;
      if (out) {
        out->residual[it] = ds;
        if (need_tangent) out->tangent.row(it).head(nu) += grad_ds.transpose();
      }
    } else {
      const double sign = tau >= 0 ? 1.0 : -1.0;
      point.slip_sign = tau >= 0 ? 1 : -1;
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
      k = f.stick_slope * s.area;
    } else {
      k = mu * N / f.elastic_slip;
      dk = (mu / f.elastic_slip) * dN;
    }
    const double trial = s.committed_tangential_force + k * ds;
    Vec dT = Vec::Zero(n_local);
    if (N > 0 && (std::abs(trial) <= mu * N || s.held_stick)) {
      T = trial;
      point.status = ContactStatus::Stick;
      dT.head(nu) += k * grad_ds;
      dT += ds * dk;
    } else if (N > 0) {
      const double sign = trial >= 0 ? 1.0 : -1.0;
      point.slip_sign = trial >= 0 ? 1 : -1;
      T = mu * N * sign;
      dT = mu * sign * dN;
    }
    if (out) {
      out->residual.head(nu) += T * grad_ds;
      if (need_tangent && T != 0) {
        out->tangent.topRows(nu) += grad_ds * dT.transpose();
        out->tangent.topLeftCorner(nu, nu) += T * slip_hessian(y, xi_ref);
      }
    }
  }
  point.tangential_force = T;
  return point;
}

void ContactNode::evaluate(const EvaluationState& state, LocalSystem& out, bool need_tangent) const {
  compute(state, &out, need_tangent);
  // compute() works on the virtual nodes of a smoothed segment; the chain
  // rule through the constant map z = W y gives the real nodes' rows.
  const ContactSlave& s = pair_.slave(slave_);
  if (!s.pairing.found()) return;
  const MasterSegment& segment = pair_.segments().segment(s.pairing.segment);
  if (segment.identity) return;
  map_to_real_nodes(segment, out.residual);
  if (need_tangent) map_to_real_nodes(segment, out.tangent);
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
  v.pressure = s.area > 0 ? p.normal_force / s.area : 0.0;  // a CAX node on the axis has no area
  v.tangential_force = p.tangential_force;
  v.shear = s.area > 0 ? p.tangential_force / s.area : 0.0;
  v.slip = p.slip;
  // History up to the last converged increment plus this increment's slip.
  const bool slipping = p.status == ContactStatus::Slip && pair_.mu() > 0;
  v.total_slip = s.total_slip + (slipping ? std::abs(p.slip) : 0.0);
  v.dissipation = s.dissipation + (slipping ? p.tangential_force * p.slip : 0.0);
  v.force = p.normal_force * p.normal - p.tangential_force * p.tangent;
  return v;
}

std::pair<ContactStatus, int> ContactNode::status_and_direction(const EvaluationState& state) const {
  const Point p = compute(state, nullptr, false);
  // The sign of the slip branch the residual takes at this state (for exact
  // stick that of λt + cΔs: λt itself still has the sign of the previous
  // iteration's branch).
  const int direction = p.status == ContactStatus::Slip ? p.slip_sign : 0;
  return {p.status, direction};
}

}  // namespace tether
