#include "tether/contact/contact_pair.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "tether/assembly/saved_state.hpp"
#include "tether/core/error.hpp"
#include "tether/dofs/dof_map.hpp"

namespace tether {

namespace {

/// Times the chattering guard may release held nodes in one increment attempt.
constexpr int kMaxReleases = 10;
/// Extension of an open end of the master surface, as a fraction of the end segment's length.
constexpr double kEndExtension = 0.05;
/// Hand-over band in ξ (segment length 2) within which a slave keeps its segment during Newton.
constexpr double kHandOverBand = 0.02;
/// Returns to the segment left one iteration before after which the re-pairing guard holds a node
/// (1 holds after A -> B -> A; 2, after A -> B -> A -> B, let a single Newton overshoot pass).
constexpr int kMinReturns = 2;
/// Band in ξ beyond which a node held by the re-pairing guard is released at convergence.
constexpr double kReleaseBand = 0.5;
/// Sine of the turn between two segments above which their join counts as a
/// kink for the re-pairing guard (a smooth join gives round-off only).
constexpr double kKinkSine = 1e-8;
/// First value of a saved ContactPair state (restart).
constexpr double kStateTag = 2001;

Eigen::Vector2d position(const std::vector<Eigen::Vector2d>& reference, const Eigen::VectorXd& u, int node) {
  return reference[static_cast<std::size_t>(node)] +
         Eigen::Vector2d(u[DofMap::displacement(node, 0)], u[DofMap::displacement(node, 1)]);
}

/// Geometry of a slave point on segment `segment` of `surface` (points by
/// the surface's indices), extended past the segment's ends.
SegmentGeometry extended_geometry(const MasterSurface& surface, const std::vector<Eigen::Vector2d>& points, int segment,
                                  const Eigen::Vector2d& slave) {
  std::vector<Eigen::Vector2d> y;
  for (int n : surface.segment_nodes(segment)) y.push_back(points[static_cast<std::size_t>(n)]);
  return segment_geometry(slave, y, ContactDerivatives::none);
}

/// Sine of the turn from segment `a` into segment `b` at their shared corner
/// node: > 0 where the surface is concave there (b leaves the corner into
/// a's outer side, e.g. a V under a pressed node), < 0 where convex, 0 on a
/// smooth join or when they share no corner.
double concave_turn(const MasterSurface& surface, const std::vector<Eigen::Vector2d>& points, int a, int b) {
  const auto nodes_a = surface.segment_nodes(a), nodes_b = surface.segment_nodes(b);
  for (int ca = 0; ca < 2; ++ca)
    for (int cb = 0; cb < 2; ++cb) {
      if (nodes_a[ca] != nodes_b[cb]) continue;
      const Eigen::Vector2d& corner = points[static_cast<std::size_t>(nodes_a[ca])];
      const SegmentGeometry ga = extended_geometry(surface, points, a, corner);
      const SegmentGeometry gb = extended_geometry(surface, points, b, corner);
      const Eigen::Vector2d into_b = cb == 0 ? gb.tangent : Eigen::Vector2d(-gb.tangent);
      return into_b.dot(ga.normal);
    }
  return 0;
}

}  // namespace

const std::vector<Eigen::Vector2d>& ContactPair::search_points(const Eigen::VectorXd& u) {
  for (const std::vector<int>& face : setup_.master_faces)
    for (int n : face) positions_[static_cast<std::size_t>(n)] = position(reference_, u, n);
  if (!segments_.smoothed()) return positions_;  // the search's points: the nodes, or
  segments_.point_positions(positions_, points_);  // the nodes and the smoothed surface's points
  return points_;
}

int ContactPair::multipliers_per_slave(const PressureOverclosure& law, const std::optional<FrictionData>& friction) {
  const bool exact_stick = friction && friction->mu > 0 && friction->stick_slope == 0 && friction->elastic_slip == 0;
  const bool hard_multiplier =
      law.law == PressureOverclosure::Law::Hard && law.enforcement.method == Enforcement::Method::Lagrange;
  return (hard_multiplier ? 1 : 0) + (exact_stick ? 1 : 0);
}

bool ContactPair::exact_stick() const {
  const auto& f = setup_.friction;
  return f && f->mu > 0 && f->stick_slope == 0 && f->elastic_slip == 0;
}

ContactPair::ContactPair(ContactPairSetup setup, const std::vector<Eigen::Vector2d>& reference, int first_multiplier)
    : setup_(std::move(setup)), reference_(reference), segments_(setup_.master_faces, setup_.smoothing) {
  if (setup_.slave_nodes.size() != setup_.slave_area.size())
    throw std::invalid_argument(setup_.name + ": one tributary area per slave node expected");
  if (setup_.master_face_labels.size() != setup_.master_faces.size())
    throw std::invalid_argument(setup_.name + ": one label per master face expected");
  if (!setup_.calculix_face_areas.empty() &&
      (setup_.calculix_face_areas.size() != setup_.master_faces.size() || setup_.smoothing != 0))
    throw std::invalid_argument(setup_.name + ": CalculiX's node areas need one rule per master face and no smoothing");
  if (!(setup_.search_radius > 0)) throw std::invalid_argument(setup_.name + ": search radius must be > 0");
  if (!(setup_.complementarity_stiffness > 0))
    throw std::invalid_argument(setup_.name + ": complementarity stiffness must be > 0");
  const int per_slave = multipliers_per_slave(setup_.law, setup_.friction);
  if (per_slave > 0 && first_multiplier < 0) throw std::invalid_argument(setup_.name + ": multipliers not reserved");
  const bool hard = setup_.law.law == PressureOverclosure::Law::Hard &&
                    setup_.law.enforcement.method == Enforcement::Method::Lagrange;

  slaves_.resize(setup_.slave_nodes.size());
  nodes_.reserve(slaves_.size());
  for (std::size_t i = 0; i < slaves_.size(); ++i) {
    ContactSlave& s = slaves_[i];
    s.node = setup_.slave_nodes[i];
    s.area = setup_.slave_area[i];
    int next = first_multiplier + per_slave * static_cast<int>(i);
    if (hard) s.normal_multiplier = next++;
    if (exact_stick()) s.tangent_multiplier = next++;
    set_pairing(s, ContactPairing{});
    nodes_.push_back(std::make_unique<ContactNode>(*this, static_cast<int>(i)));
  }
  positions_.assign(static_cast<std::size_t>(segments_.n_nodes_required()), Eigen::Vector2d::Zero());
}

ContactPair::~ContactPair() = default;

std::vector<Contribution*> ContactPair::nodes() const {
  std::vector<Contribution*> out;
  out.reserve(nodes_.size());
  for (const auto& n : nodes_) out.push_back(n.get());
  return out;
}

std::vector<Eigen::Vector2d> ContactPair::segment_points(int k, const Eigen::VectorXd& u) const {
  const MasterSegment& m = segments_.segment(k);
  std::vector<Eigen::Vector2d> y(static_cast<std::size_t>(m.n_nodes));
  for (int a = 0; a < m.n_nodes; ++a) y[static_cast<std::size_t>(a)] = position(reference_, u, m.nodes[static_cast<std::size_t>(a)]);
  if (!m.identity) {
    const std::vector<Eigen::Vector2d> real = y;
    segments_.virtual_positions(k, real, y);
  }
  return y;
}

void ContactPair::set_pairing(ContactSlave& s, const ContactPairing& p) {
  s.pairing = p;
  s.dofs.clear();
  s.nodes.clear();
  auto push_node = [&s](int node) {
    s.nodes.push_back(node);
    for (int c = 0; c < kDofsPerNode; ++c) s.dofs.push_back(DofMap::displacement(node, c));
  };
  auto add_node = [&s, &push_node](int node) {
    if (std::find(s.nodes.begin(), s.nodes.end(), node) == s.nodes.end()) push_node(node);
  };
  push_node(s.node);
  if (p.found()) {
    const MasterSegment& m = segments_.segment(p.segment);
    for (int a = 0; a < m.n_nodes; ++a) push_node(m.nodes[static_cast<std::size_t>(a)]);
  }
  // After a hand-over the slip is measured from a point of the committed
  // segment, whose nodes then enter the tangent too.
  s.handed_over = p.found() && mu() > 0 && s.committed_segment >= 0 && s.committed_segment != p.segment;
  if (s.handed_over) {
    const MasterSegment& c = segments_.segment(s.committed_segment);
    for (int a = 0; a < c.n_nodes; ++a) add_node(c.nodes[static_cast<std::size_t>(a)]);
  }
  if (s.normal_multiplier >= 0) s.dofs.push_back(s.normal_multiplier);
  if (s.tangent_multiplier >= 0) s.dofs.push_back(s.tangent_multiplier);
}

void ContactPair::start_attempt(const EvaluationState& state) {
  attempt_time_ = state.total_time;
  attempt_dt_ = state.dt;
  releases_ = 0;
  uzawa_updates_ = 0;
  for (ContactSlave& s : slaves_)
    s.status_changes = 0, s.held_closed = false, s.slip_direction = 0, s.friction_active = false,
    s.direction_flips = 0, s.stick_slip_switches = 0, s.held_stick = false,
    s.left_segment = -1, s.held_segment = false, s.returns = 0;
}

bool ContactPair::update_connectivity(const EvaluationState& state) {
  const bool new_attempt = state.total_time != attempt_time_ || state.dt != attempt_dt_ || !searched_once_;
  if (new_attempt) start_attempt(state);

  const MasterSurface& surface = segments_.surface();
  const std::vector<Eigen::Vector2d>* points = &search_points(state.u);
  std::vector<Eigen::Vector2d> slave_positions(slaves_.size());
  for (std::size_t i = 0; i < slaves_.size(); ++i) slave_positions[i] = position(reference_, state.u, slaves_[i].node);

  SearchOptions options;
  options.search_radius = setup_.search_radius;
  options.keep_pairing = setup_.small_sliding;
  std::vector<ContactPairing> previous;
  if (searched_once_ && (setup_.small_sliding || !new_attempt)) {
    previous.reserve(slaves_.size());
    for (const ContactSlave& s : slaves_) previous.push_back(s.pairing);
  }
  SearchStatistics work;
  std::vector<ContactPairing> pairings =
      find_closest(surface, *points, slave_positions, options, previous, &work);
  searched_once_ = true;

  statistics_ = {};
  bool changed = false;
  std::vector<char> repaired(slaves_.size(), 0);
  for (std::size_t i = 0; i < slaves_.size(); ++i) {
    ContactSlave& s = slaves_[i];
    ContactPairing p = pairings[i];
    // Beyond an open end of the master surface there is no contact, except
    // within a short extension of the end segment (kEndExtension of its
    // length), so that a slave node sitting on the end is not released by
    // round-off or a slight outward motion (ABAQUS extends its master
    // surfaces in the same spirit).
    if (p.found() && p.at_corner && surface.neighbours(p.segment, p.xi < 0 ? 0 : 1).empty()) {
      std::vector<Eigen::Vector2d> y;
      for (int n : surface.segment_nodes(p.segment)) y.push_back((*points)[static_cast<std::size_t>(n)]);
      const SegmentGeometry g = segment_geometry(slave_positions[i], y, ContactDerivatives::none);
      if (g.projection.status == ProjectionStatus::converged && std::abs(g.projection.xi) <= 1 + 2 * kEndExtension) {
        p.at_corner = false;
        p.xi = g.projection.xi;
        p.gap = g.gap;
      } else {
        p = ContactPairing{};
      }
    }
    // The current pairing continued on its segment extended past its ends
    // (no value when the projection fails).
    const auto kept = [&]() -> std::optional<ContactPairing> {
      const SegmentGeometry g = extended_geometry(surface, *points, s.pairing.segment, slave_positions[i]);
      if (g.projection.status != ProjectionStatus::converged) return std::nullopt;
      ContactPairing q = s.pairing;
      q.xi = g.projection.xi;
      q.gap = g.gap;
      q.at_corner = false;
      return q;
    };
    // Hysteresis during Newton: a slave that crosses a master node by less
    // than kHandOverBand keeps its segment (extended past its end) until the
    // next increment, so it cannot flip between two segments meeting at a
    // kink, one per iteration.
    if (!new_attempt && p.segment != s.pairing.segment && s.pairing.found() && !s.pairing.at_corner) {
      const std::optional<ContactPairing> q = kept();
      if (q && std::abs(q->xi) <= 1 + kHandOverBand) p = *q;
    }
    // Re-pairing guard: a slave returning across a concave kink to the
    // segment it left at the previous iteration (A -> B -> A; neither
    // extended segment alone has an equilibrium there, each one's extension
    // penetrates the other) for the kMinReturns-th time in the attempt is
    // held on its current segment, extended, until Newton converges;
    // on_converged releases it for another pass if it then lies clearly
    // outside. Smooth joins (SMOOTH) and convex kinks are left alone.
    if (!new_attempt && s.pairing.found() &&
        (s.held_segment || (p.found() && p.segment != s.pairing.segment && p.segment == s.left_segment &&
                            concave_turn(surface, *points, s.pairing.segment, p.segment) > kKinkSine &&
                            ++s.returns >= kMinReturns))) {
      if (const std::optional<ContactPairing> q = kept()) {
        p = *q;
        s.held_segment = true;
      }
    }
    s.left_segment = p.segment != s.pairing.segment ? s.pairing.segment : -1;
    if (p.segment != s.pairing.segment) {
      repaired[i] = 1;
      ++statistics_.repaired;
    }
    if (p.found() && s.committed_segment < 0) {
      // First pairing: the slip is measured from the projection at the start of the increment.
      const std::vector<Eigen::Vector2d> start = segment_points(p.segment, state.u_start);
      s.committed_segment = p.segment;
      s.committed_xi = project(position(reference_, state.u_start, s.node), start).xi;
    }
    // The dofs also change without a re-pairing when the committed segment
    // changed at the last commit (a hand-over's extra nodes are dropped).
    const std::vector<int> previous_dofs = std::move(s.dofs);
    set_pairing(s, p);
    if (s.dofs != previous_dofs) changed = true;
  }

  // Status of every node at this iterate; count changes, engage the chattering guard.
  const bool hard = setup_.law.law == PressureOverclosure::Law::Hard &&
                    setup_.law.enforcement.method == Enforcement::Method::Lagrange;
  for (std::size_t i = 0; i < slaves_.size(); ++i) {
    ContactSlave& s = slaves_[i];
    const ContactBranch branch = nodes_[i]->branch(state);
    const ContactStatus status = branch.status;
    const int direction = branch.direction;
    // Any change of the residual's branch is an active-set change; besides
    // the status this counts a reversed slip direction and a node that has
    // just closed starting to carry a normal force (its friction row turns
    // from the open one to stick or slip while its status stays Slip).
    if (!new_attempt && (direction != s.slip_direction || branch.friction_active != s.friction_active) &&
        status == s.status)
      ++statistics_.status_changes;
    s.friction_active = branch.friction_active;
    // Friction guard: a node whose slip keeps reversing on the same master
    // segment is really sticking (a reversal while it is handed over to the
    // next segment of a sliding surface is not counted).
    if (!new_attempt && !repaired[i] && direction != 0 && s.slip_direction != 0 && direction != s.slip_direction &&
        ++s.direction_flips >= setup_.max_direction_flips)
      s.held_stick = true;
    s.slip_direction = direction;
    if (!new_attempt && status != s.status) {
      ++statistics_.status_changes;
      const bool flipped = (status == ContactStatus::Open) != (s.status == ContactStatus::Open);
      if (flipped && hard && ++s.status_changes >= setup_.max_status_changes && !s.held_closed) {
        s.held_closed = true;
      }
      // Friction guard, second form: a closed node switching between stick
      // and slip on the same segment, again and again.
      if (!flipped && !repaired[i] && s.status != ContactStatus::Open &&
          ++s.stick_slip_switches >= setup_.max_stick_slip_switches)
        s.held_stick = true;
    }
    s.status = s.held_closed ? (status == ContactStatus::Open ? ContactStatus::Slip : status) : status;
    if (s.status != ContactStatus::Open) ++statistics_.closed;
    if (s.held_closed || s.held_stick || s.held_segment) ++statistics_.held_closed;
  }
  return changed;
}

Acceptance ContactPair::on_converged(const EvaluationState& state) {
  const Enforcement& enforcement = setup_.law.enforcement;
  if (setup_.law.law == PressureOverclosure::Law::Hard && enforcement.method == Enforcement::Method::Augmented) {
    // Uzawa: λ̄ ← N until the largest penetration is within the tolerance.
    double penetration = 0;
    std::vector<double> force(slaves_.size(), 0.0);
    for (std::size_t i = 0; i < slaves_.size(); ++i) {
      const ContactNodeValues v = nodes_[i]->values(state);
      force[i] = v.normal_force;
      if (v.status != ContactNodeValues::Status::Open) penetration = std::max(penetration, -v.gap);
    }
    if (penetration <= enforcement.tolerance) return Acceptance::Accept;
    if (++uzawa_updates_ > enforcement.max_updates)
      throw ModelError(setup_.name + ": augmented Lagrangian left a penetration of " + std::to_string(penetration) +
                       " after " + std::to_string(enforcement.max_updates) + " updates (tolerance " +
                       std::to_string(enforcement.tolerance) + "); raise PENALTY");
    for (std::size_t i = 0; i < slaves_.size(); ++i) slaves_[i].lambda_bar = force[i];
    return Acceptance::Iterate;
  }
  bool released = false;
  const std::vector<Eigen::Vector2d>& points = search_points(state.u);
  for (std::size_t i = 0; i < slaves_.size(); ++i) {
    ContactSlave& s = slaves_[i];
    // A node held closed must carry compression; in tension it should have opened.
    if (s.held_closed && state.u[s.normal_multiplier] < 0) {
      s.held_closed = false;
      s.status_changes = 0;
      released = true;
    }
    // A node held in stick must stay inside the friction cone.
    if (s.held_stick) {
      const ContactNodeValues v = nodes_[i]->values(state);
      if (std::abs(v.tangential_force) > mu() * v.normal_force * (1 + 1e-9) + 1e-12 * std::abs(v.normal_force)) {
        s.held_stick = false;
        s.direction_flips = 0;
        s.stick_slip_switches = 0;
        released = true;
      }
    }
    // A node held on its segment must still project onto it (within kReleaseBand).
    if (s.held_segment) {
      const SegmentGeometry g = extended_geometry(segments_.surface(), points, s.pairing.segment,
                                                 position(reference_, state.u, s.node));
      if (g.projection.status != ProjectionStatus::converged || std::abs(g.projection.xi) > 1 + kReleaseBand) {
        s.held_segment = false;
        s.left_segment = -1;
        released = true;
      }
    }
  }
  if (!released) {
    for (ContactSlave& s : slaves_) s.held_closed = false, s.held_stick = false, s.held_segment = false;
    return Acceptance::Accept;
  }
  if (++releases_ > kMaxReleases)
    throw ModelError(setup_.name + ": the contact active set keeps cycling (nodes held closed or in stick by the "
                     "chattering guard violate their condition after " + std::to_string(kMaxReleases) + " releases)");
  return Acceptance::Iterate;
}

void ContactPair::commit(const EvaluationState& state) {
  for (std::size_t i = 0; i < slaves_.size(); ++i) {
    ContactSlave& s = slaves_[i];
    const ContactNodeValues v = nodes_[i]->values(state);
    if (!s.pairing.found()) {
      s.committed_segment = -1;
      s.committed_tangential_force = 0;
      continue;
    }
    s.total_slip = v.total_slip;
    s.dissipation = v.dissipation;
    s.committed_tangential_force = v.tangential_force;
    s.committed_segment = s.pairing.segment;
    s.committed_xi = v.xi;
  }
}

void ContactPair::save_state(std::vector<double>& out) const {
  out.push_back(kStateTag);
  out.push_back(static_cast<double>(slaves_.size()));
  out.push_back(searched_once_ ? 1 : 0);
  for (const ContactSlave& s : slaves_) {
    out.insert(out.end(), {static_cast<double>(s.node), static_cast<double>(s.pairing.segment), s.pairing.xi,
                           s.pairing.gap, s.pairing.distance, s.pairing.at_corner ? 1.0 : 0.0,
                           static_cast<double>(static_cast<int>(s.status)), static_cast<double>(s.committed_segment),
                           s.committed_xi, s.committed_tangential_force, s.total_slip, s.dissipation, s.lambda_bar});
  }
}

void ContactPair::load_state(std::span<const double>& in) {
  using namespace saved_state;
  expect_tag(in, kStateTag, "contact pair");
  const int n = static_cast<int>(slaves_.size());
  take_int(in, n, n, "number of slave nodes");
  const bool searched = take_int(in, 0, 1, "search flag") == 1;
  std::vector<ContactSlave> loaded = slaves_;
  const int last_segment = segments_.n_segments() - 1;
  for (ContactSlave& s : loaded) {
    take_int(in, s.node, s.node, "slave node");
    ContactPairing p;
    p.segment = take_int(in, -1, last_segment, "paired segment");
    p.xi = take(in);
    p.gap = take(in);
    p.distance = take(in);
    p.at_corner = take_int(in, 0, 1, "corner flag") == 1;
    s.status = static_cast<ContactStatus>(take_int(in, 0, 2, "contact status"));
    s.committed_segment = take_int(in, -1, last_segment, "committed segment");
    s.committed_xi = take(in);
    s.committed_tangential_force = take(in);
    s.total_slip = take(in);
    s.dissipation = take(in);
    s.lambda_bar = take(in);
    set_pairing(s, p);
  }
  slaves_ = std::move(loaded);
  searched_once_ = searched;
}

ContactPairValues ContactPair::values(const EvaluationState& state) const {
  ContactPairValues out;
  out.name = setup_.name;
  out.node_based = setup_.node_based_slave;
  out.nodes.reserve(nodes_.size());
  for (const auto& n : nodes_) {
    ContactNodeValues v = n->values(state);
    out.total_force += v.force;
    out.dissipation += v.dissipation;
    out.nodes.push_back(v);
  }
  return out;
}

}  // namespace tether
