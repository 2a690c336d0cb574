#include "tether/analysis/explicit_contact.hpp"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>

#include "tether/contact/contact_pair.hpp"
#include "tether/contact/segment_geometry.hpp"
#include "tether/core/error.hpp"

namespace tether {

ExplicitContact::ExplicitContact(const Discretization& discretization) : discretization_(discretization) {
  for (const auto& pair : discretization.contact_pairs()) {
    const ContactPairSetup& s = pair->setup();
    const std::string refuse = "*DYNAMIC, EXPLICIT: " + s.name + ": the explicit contact corrector (hard, with Coulomb friction) ";
    if (s.law.law != PressureOverclosure::Law::Hard)
      throw ModelError(refuse + "does not support a soft pressure-overclosure law yet; use HARD");
    if (s.friction && (s.friction->stick_slope > 0 || s.friction->elastic_slip > 0))
      throw ModelError(refuse + "sticks exactly: a stick slope or ELASTIC SLIP is not supported yet");
    if (s.smoothing > 0) throw ModelError(refuse + "does not support SMOOTH yet");
    Pair& p = pairs_.emplace_back(s);
    p.pairing.assign(s.slave_nodes.size(), ContactPairing{});
    p.multiplier.assign(s.slave_nodes.size(), 0.0);
    p.normal.assign(s.slave_nodes.size(), Eigen::Vector2d::Zero());
    p.tangent = p.normal;
    p.tangential = p.slip = p.total_slip = p.dissipation = p.multiplier;
    p.slipping.assign(s.slave_nodes.size(), false);
  }
  positions_.assign(discretization.model().coords.size(), Eigen::Vector2d::Zero());
  tolerance_ = 1e-12 * discretization.length_scale();
}

namespace {

/// Position of `node` at the displacements `u` [length].
Eigen::Vector2d position(const std::vector<Eigen::Vector2d>& coords, const Eigen::VectorXd& u, int node) {
  return coords[static_cast<std::size_t>(node)] +
         Eigen::Vector2d(u[DofMap::displacement(node, 0)], u[DofMap::displacement(node, 1)]);
}

}  // namespace

std::vector<ExplicitContact::Constraint> ExplicitContact::penetrations(const Eigen::VectorXd& u_now,
                                                                       const Eigen::VectorXd& u) {
  const std::vector<Eigen::Vector2d>& coords = discretization_.model().coords;
  for (std::size_t i = 0; i < coords.size(); ++i) positions_[i] = position(coords, u, static_cast<int>(i));
  std::vector<Constraint> out;
  std::vector<Eigen::Vector2d> slaves, segment, segment_now;
  for (std::size_t p = 0; p < pairs_.size(); ++p) {
    Pair& pair = pairs_[p];
    const ContactPairSetup& s = *pair.setup;
    slaves.clear();
    for (int node : s.slave_nodes) slaves.push_back(positions_[static_cast<std::size_t>(node)]);
    SearchOptions options;
    options.search_radius = s.search_radius;
    pair.pairing = find_closest(pair.surface, positions_, slaves, options);
    for (auto* v : {&pair.multiplier, &pair.tangential, &pair.slip}) std::fill(v->begin(), v->end(), 0.0);
    std::fill(pair.slipping.begin(), pair.slipping.end(), false);
    for (std::size_t k = 0; k < slaves.size(); ++k) {
      const ContactPairing& pairing = pair.pairing[k];
      if (!pairing.found() || pairing.at_corner || pairing.gap >= 0) continue;
      const auto nodes = pair.surface.segment_nodes(pairing.segment);
      segment.clear(), segment_now.clear();
      for (int node : nodes) {
        segment.push_back(positions_[static_cast<std::size_t>(node)]);
        segment_now.push_back(position(coords, u_now, node));
      }
      const SegmentGeometry g = segment_geometry(slaves[k], segment, ContactDerivatives::gradient);
      if (g.projection.status == ProjectionStatus::degenerate || !g.projection.inside || g.gap >= 0) continue;
      // The force's direction: the same pairing at t_n (the extended segment; a degenerate one keeps g's).
      const SegmentGeometry now =
          segment_geometry(position(coords, u_now, s.slave_nodes[k]), segment_now, ContactDerivatives::gradient);
      const SegmentGeometry& acting = now.projection.status == ProjectionStatus::degenerate ? g : now;
      Constraint c;
      c.pair = static_cast<int>(p), c.slave = static_cast<int>(k), c.gap = g.gap;
      c.nodes.push_back(s.slave_nodes[k]);
      c.nodes.insert(c.nodes.end(), nodes.begin(), nodes.end());
      for (int node : c.nodes) c.dofs.push_back(DofMap::displacement(node, 0)), c.dofs.push_back(DofMap::displacement(node, 1));
      c.gradient.assign(g.gap_gradient.data(), g.gap_gradient.data() + g.n_dofs);
      c.direction.assign(acting.gap_gradient.data(), acting.gap_gradient.data() + acting.n_dofs);
      c.normal_now = acting.normal;
      c.tangent_gradient.resize(c.gradient.size());
      for (std::size_t a = 0; 2 * a < c.gradient.size(); ++a) {  // node a's block is -N_a n (slave: +n)
        const double weight = c.gradient[2 * a] * g.normal.x() + c.gradient[2 * a + 1] * g.normal.y();
        c.tangent_gradient[2 * a] = weight * g.tangent.x(), c.tangent_gradient[2 * a + 1] = weight * g.tangent.y();
      }
      pair.normal[k] = acting.normal;
      pair.tangent[k] = g.tangent;
      out.push_back(std::move(c));
    }
  }
  return out;
}

void ExplicitContact::corrected_gaps(std::vector<Constraint>& constraints, const std::vector<int>& active,
                                     const Eigen::VectorXd& u, const Eigen::VectorXd& inverse_mass, double c,
                                     const Eigen::VectorXd& f, Eigen::VectorXd& gaps) const {
  const std::vector<Eigen::Vector2d>& coords = discretization_.model().coords;
  gaps.resize(static_cast<Eigen::Index>(active.size()));
  std::vector<Eigen::Vector2d> points;
  for (std::size_t r = 0; r < active.size(); ++r) {
    Constraint& k = constraints[static_cast<std::size_t>(active[r])];
    points.clear();
    for (std::size_t a = 0; a < k.nodes.size(); ++a) {
      const int dx = k.dofs[2 * a], dy = k.dofs[2 * a + 1];
      points.push_back(position(coords, u, k.nodes[a]) +
                       c * Eigen::Vector2d(inverse_mass[dx] * f[dx], inverse_mass[dy] * f[dy]));
    }
    const SegmentGeometry g =
        segment_geometry(points.front(), std::span(points).subspan(1), ContactDerivatives::gradient);
    gaps[static_cast<Eigen::Index>(r)] = g.gap;
    if (g.projection.status != ProjectionStatus::degenerate)
      k.gradient.assign(g.gap_gradient.data(), g.gap_gradient.data() + g.n_dofs);
  }
}

Eigen::VectorXd ExplicitContact::multipliers(const std::vector<Constraint>& constraints, const std::vector<int>& active,
                                             const Eigen::VectorXd& inverse_mass, double c, bool tangential,
                                             const Eigen::VectorXd& rhs) const {
  // A = c G M^-1 G^T from the rows of G scaled by sqrt(c / m) per dof.
  const auto m = static_cast<Eigen::Index>(active.size());
  std::vector<Eigen::Triplet<double>> entries;
  for (Eigen::Index r = 0; r < m; ++r) {
    const Constraint& k = constraints[static_cast<std::size_t>(active[static_cast<std::size_t>(r)])];
    const std::vector<double>& row = tangential ? k.tangent_gradient : k.gradient;
    for (std::size_t i = 0; i < k.dofs.size(); ++i)
      entries.emplace_back(r, k.dofs[i], row[i] * std::sqrt(c * inverse_mass[k.dofs[i]]));
  }
  Eigen::SparseMatrix<double> scaled(m, inverse_mass.size());
  scaled.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SparseMatrix<double> system = scaled * scaled.transpose();
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(system);
  if (ldlt.info() != Eigen::Success || !(ldlt.vectorD().array() > 0).all())
    throw ModelError("*DYNAMIC, EXPLICIT: the contact corrector's system is singular: two penetrating slave nodes "
                     "constrain the same motion (coincident slave nodes, or a slave node on two master surfaces)");
  return ldlt.solve(rhs);
}

namespace {

/// Diagonal of G M^-1 G^T for one row: 0 when no node of the row can move along it.
double mobility(const std::vector<int>& dofs, const std::vector<double>& row, const Eigen::VectorXd& inverse_mass) {
  double m = 0;
  for (std::size_t i = 0; i < dofs.size(); ++i) m += row[i] * row[i] * inverse_mass[dofs[i]];
  return m;
}

/// row . (c M^-1 f) over the row's dofs.
double moved(const std::vector<int>& dofs, const std::vector<double>& row, const Eigen::VectorXd& inverse_mass,
             double c, const Eigen::VectorXd& f) {
  double m = 0;
  for (std::size_t i = 0; i < dofs.size(); ++i) m += row[i] * c * inverse_mass[dofs[i]] * f[dofs[i]];
  return m;
}

}  // namespace

Eigen::VectorXd ExplicitContact::solve_normal(std::vector<Constraint>& constraints, const std::vector<int>& active,
                                              const Eigen::VectorXd& u, const Eigen::VectorXd& inverse_mass,
                                              double c) {
  constexpr int kMaxPasses = 25;
  const auto m = static_cast<Eigen::Index>(active.size());
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(m), gaps(m);
  for (int pass = 0;; ++pass) {
    for (int k : active)  // the forces D^T lambda of this pass (0 elsewhere)
      for (int dof : constraints[static_cast<std::size_t>(k)].dofs) normal_force_[dof] = 0;
    for (Eigen::Index r = 0; r < m; ++r) {
      const Constraint& k = constraints[static_cast<std::size_t>(active[static_cast<std::size_t>(r)])];
      for (std::size_t i = 0; i < k.dofs.size(); ++i) normal_force_[k.dofs[i]] += k.direction[i] * lambda[r];
    }
    corrected_gaps(constraints, active, u, inverse_mass, c, normal_force_, gaps);
    if (pass > 0 && gaps.cwiseAbs().maxCoeff() <= tolerance_) break;
    if (pass == kMaxPasses)
      throw ModelError("*DYNAMIC, EXPLICIT: the contact correction did not converge in " + std::to_string(kMaxPasses) +
                       " passes (largest remaining penetration " + std::to_string(gaps.cwiseAbs().maxCoeff()) + ")");
    // Jacobian c G M^-1 D^T (G at the corrected positions): rows scaled by c / m, times D^T.
    std::vector<Eigen::Triplet<double>> g_entries, d_entries;
    for (Eigen::Index r = 0; r < m; ++r) {
      const Constraint& k = constraints[static_cast<std::size_t>(active[static_cast<std::size_t>(r)])];
      for (std::size_t i = 0; i < k.dofs.size(); ++i) {
        g_entries.emplace_back(r, k.dofs[i], c * inverse_mass[k.dofs[i]] * k.gradient[i]);
        d_entries.emplace_back(r, k.dofs[i], k.direction[i]);
      }
    }
    Eigen::SparseMatrix<double> g_rows(m, u.size()), d_rows(m, u.size());
    g_rows.setFromTriplets(g_entries.begin(), g_entries.end());
    d_rows.setFromTriplets(d_entries.begin(), d_entries.end());
    Eigen::SparseMatrix<double> jacobian = g_rows * d_rows.transpose();
    jacobian.makeCompressed();
    Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(jacobian);
    if (lu.info() != Eigen::Success)
      throw ModelError("*DYNAMIC, EXPLICIT: the contact corrector's system is singular: two penetrating slave nodes "
                       "constrain the same motion (coincident slave nodes, or a slave node on two master surfaces)");
    lambda -= lu.solve(gaps);
  }
  return lambda;
}

Eigen::VectorXd ExplicitContact::normal_multipliers(std::vector<Constraint>& constraints, const Eigen::VectorXd& u,
                                                    const Eigen::VectorXd& inverse_mass, double c) {
  Eigen::VectorXd out = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(constraints.size()));
  if (normal_force_.size() != u.size()) normal_force_ = Eigen::VectorXd::Zero(u.size());
  std::vector<int> active;
  for (std::size_t k = 0; k < constraints.size(); ++k)
    if (mobility(constraints[k].dofs, constraints[k].direction, inverse_mass) > 0) active.push_back(static_cast<int>(k));
  while (!active.empty()) {  // release the slaves the correction would pull back
    const Eigen::VectorXd lambda = solve_normal(constraints, active, u, inverse_mass, c);
    std::vector<int> kept;
    for (std::size_t r = 0; r < active.size(); ++r)
      if (lambda[static_cast<Eigen::Index>(r)] >= 0) kept.push_back(active[r]);
    if (kept.size() == active.size()) {
      for (std::size_t r = 0; r < active.size(); ++r) out[active[r]] = lambda[static_cast<Eigen::Index>(r)];
      break;
    }
    active = std::move(kept);
  }
  for (std::size_t k = 0; k < constraints.size(); ++k)  // normal_force_ back to 0
    for (int dof : constraints[k].dofs) normal_force_[dof] = 0;
  return out;
}

void ExplicitContact::add_friction(const std::vector<Constraint>& constraints, const Eigen::VectorXd& normal,
                                   const Eigen::VectorXd& u_now, const Eigen::VectorXd& u,
                                   const Eigen::VectorXd& inverse_mass, double c, Eigen::VectorXd& force) {
  const auto mu_of = [&](const Constraint& k) {
    const ContactPairSetup& s = *pairs_[static_cast<std::size_t>(k.pair)].setup;
    return s.friction ? s.friction->mu : 0.0;
  };
  // Slip of each closed slave over the increment after the normal correction.
  std::vector<int> closed;
  std::vector<double> slip(constraints.size(), 0.0);
  for (std::size_t k = 0; k < constraints.size(); ++k) {
    const Constraint& ck = constraints[k];
    if (normal[static_cast<Eigen::Index>(k)] <= 0 || mu_of(ck) <= 0 ||
        mobility(ck.dofs, ck.tangent_gradient, inverse_mass) <= 0)
      continue;
    closed.push_back(static_cast<int>(k));
    for (std::size_t i = 0; i < ck.dofs.size(); ++i)
      slip[k] += ck.tangent_gradient[i] * (u[ck.dofs[i]] - u_now[ck.dofs[i]]);
    slip[k] += moved(ck.dofs, ck.tangent_gradient, inverse_mass, c, force);
  }
  if (closed.empty()) return;
  // Stick where |lambda_t| <= mu lambda_n; the others slip at mu lambda_n, fixed, and the rest is solved again.
  std::vector<double> lambda(constraints.size(), 0.0);
  std::vector<bool> slipping(constraints.size(), false);
  friction_force_.setZero(u.size());
  for (std::size_t round = 0; round <= closed.size(); ++round) {
    std::vector<int> stick;
    for (int k : closed)
      if (!slipping[static_cast<std::size_t>(k)]) stick.push_back(k);
    if (stick.empty()) break;
    Eigen::VectorXd rhs(static_cast<Eigen::Index>(stick.size()));
    for (std::size_t r = 0; r < stick.size(); ++r) {
      const Constraint& ck = constraints[static_cast<std::size_t>(stick[r])];
      rhs[static_cast<Eigen::Index>(r)] = -slip[static_cast<std::size_t>(stick[r])] -
                                          moved(ck.dofs, ck.tangent_gradient, inverse_mass, c, friction_force_);
    }
    const Eigen::VectorXd stuck = multipliers(constraints, stick, inverse_mass, c, true, rhs);
    bool changed = false;
    for (std::size_t r = 0; r < stick.size(); ++r) {
      const auto k = static_cast<std::size_t>(stick[r]);
      const double bound = mu_of(constraints[k]) * normal[static_cast<Eigen::Index>(k)];
      lambda[k] = stuck[static_cast<Eigen::Index>(r)];
      if (std::abs(lambda[k]) <= bound) continue;
      lambda[k] = std::copysign(bound, lambda[k]), slipping[k] = changed = true;
      for (std::size_t i = 0; i < constraints[k].dofs.size(); ++i)
        friction_force_[constraints[k].dofs[i]] += constraints[k].tangent_gradient[i] * lambda[k];
    }
    if (!changed) break;
  }
  for (int k : closed) {
    const Constraint& ck = constraints[static_cast<std::size_t>(k)];
    if (!slipping[static_cast<std::size_t>(k)])
      for (std::size_t i = 0; i < ck.dofs.size(); ++i)
        friction_force_[ck.dofs[i]] += ck.tangent_gradient[i] * lambda[static_cast<std::size_t>(k)];
  }
  for (int k : closed) {
    const Constraint& ck = constraints[static_cast<std::size_t>(k)];
    Pair& pair = pairs_[static_cast<std::size_t>(ck.pair)];
    const auto slave = static_cast<std::size_t>(ck.slave);
    pair.tangential[slave] = lambda[static_cast<std::size_t>(k)];
    pair.slip[slave] =
        slip[static_cast<std::size_t>(k)] + moved(ck.dofs, ck.tangent_gradient, inverse_mass, c, friction_force_);
    pair.slipping[slave] = slipping[static_cast<std::size_t>(k)];
  }
  force += friction_force_;
}

void ExplicitContact::correct(const Eigen::VectorXd& u_now, const Eigen::VectorXd& u,
                              const Eigen::VectorXd& inverse_mass, double c, Eigen::VectorXd& force) {
  force.setZero(u.size());
  std::vector<Constraint> constraints = penetrations(u_now, u);
  const Eigen::VectorXd lambda = normal_multipliers(constraints, u, inverse_mass, c);
  for (std::size_t k = 0; k < constraints.size(); ++k) {
    const Constraint& ck = constraints[k];
    const double l = lambda[static_cast<Eigen::Index>(k)];
    for (std::size_t i = 0; i < ck.dofs.size(); ++i) force[ck.dofs[i]] += ck.direction[i] * l;
    pairs_[static_cast<std::size_t>(ck.pair)].multiplier[static_cast<std::size_t>(ck.slave)] = l;
  }
  add_friction(constraints, lambda, u_now, u, inverse_mass, c, force);
}

void ExplicitContact::commit() {
  for (Pair& pair : pairs_)
    for (std::size_t k = 0; k < pair.slip.size(); ++k) {
      if (pair.tangential[k] == 0) continue;
      pair.dissipation[k] -= pair.tangential[k] * pair.slip[k];
      if (pair.slipping[k]) pair.total_slip[k] += std::abs(pair.slip[k]);
    }
}

double ExplicitContact::dissipation() const {
  double d = 0;
  for (const Pair& pair : pairs_)
    for (double v : pair.dissipation) d += v;
  return d;
}

std::vector<ContactPairValues> ExplicitContact::values() const {
  std::vector<ContactPairValues> out;
  for (const Pair& pair : pairs_) {
    const ContactPairSetup& s = *pair.setup;
    ContactPairValues& v = out.emplace_back();
    v.name = s.name;
    v.node_based = s.node_based_slave;
    for (std::size_t k = 0; k < s.slave_nodes.size(); ++k) {
      ContactNodeValues& n = v.nodes.emplace_back();
      const ContactPairing& pairing = pair.pairing[k];
      n.node = s.slave_nodes[k];
      const double lambda = pair.multiplier[k];
      const bool sticking = lambda > 0 && s.friction && s.friction->mu > 0 && !pair.slipping[k];
      n.status = lambda <= 0 ? ContactNodeValues::Status::Open
                             : (sticking ? ContactNodeValues::Status::Stick : ContactNodeValues::Status::Slip);
      if (pairing.found()) {
        const auto& label = s.master_face_labels[static_cast<std::size_t>(pairing.segment)];
        n.master_element = label.first, n.master_face = label.second, n.xi = pairing.xi;
      }
      n.gap = lambda > 0 ? 0.0 : pairing.gap;  // closed slaves are corrected onto the master
      n.normal_force = lambda;
      n.pressure = lambda / s.slave_area[k];
      // The master's force on the slave is N n - T t: T = -lambda_t.
      n.tangential_force = -pair.tangential[k];
      n.shear = n.tangential_force / s.slave_area[k];
      n.slip = pair.slip[k];
      n.total_slip = pair.total_slip[k];
      n.dissipation = pair.dissipation[k];
      n.force = lambda * pair.normal[k] + pair.tangential[k] * pair.tangent[k];
      v.dissipation += n.dissipation;
      v.total_force += n.force;
    }
  }
  return out;
}

}  // namespace tether
