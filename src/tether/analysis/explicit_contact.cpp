#include "tether/analysis/explicit_contact.hpp"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>

#include "tether/contact/contact_pair.hpp"
#include "tether/contact/segment_geometry.hpp"
#include "tether/core/error.hpp"

namespace tether {

ExplicitContact::ExplicitContact(const Discretization& discretization) : discretization_(discretization) {
  for (const auto& pair : discretization.contact_pairs()) {
    const ContactPairSetup& s = pair->setup();
    const std::string refuse = "*DYNAMIC, EXPLICIT: " + s.name + ": the explicit contact corrector (hard, frictionless) ";
    if (s.law.law != PressureOverclosure::Law::Hard)
      throw ModelError(refuse + "does not support a soft pressure-overclosure law yet; use HARD");
    if (s.friction && s.friction->mu > 0) throw ModelError(refuse + "does not support friction yet");
    if (s.smoothing > 0) throw ModelError(refuse + "does not support SMOOTH yet");
    Pair& p = pairs_.emplace_back(s);
    p.pairing.assign(s.slave_nodes.size(), ContactPairing{});
    p.multiplier.assign(s.slave_nodes.size(), 0.0);
    p.normal.assign(s.slave_nodes.size(), Eigen::Vector2d::Zero());
  }
  positions_.assign(discretization.model().coords.size(), Eigen::Vector2d::Zero());
}

std::vector<ExplicitContact::Constraint> ExplicitContact::penetrations(const Eigen::VectorXd& u) {
  const std::vector<Eigen::Vector2d>& coords = discretization_.model().coords;
  for (std::size_t i = 0; i < coords.size(); ++i) {
    const int node = static_cast<int>(i);
    positions_[i] = coords[i] + Eigen::Vector2d(u[DofMap::displacement(node, 0)], u[DofMap::displacement(node, 1)]);
  }
  std::vector<Constraint> out;
  std::vector<Eigen::Vector2d> slaves, segment;
  for (std::size_t p = 0; p < pairs_.size(); ++p) {
    Pair& pair = pairs_[p];
    const ContactPairSetup& s = *pair.setup;
    slaves.clear();
    for (int node : s.slave_nodes) slaves.push_back(positions_[static_cast<std::size_t>(node)]);
    SearchOptions options;
    options.search_radius = s.search_radius;
    pair.pairing = find_closest(pair.surface, positions_, slaves, options);
    std::fill(pair.multiplier.begin(), pair.multiplier.end(), 0.0);
    for (std::size_t k = 0; k < slaves.size(); ++k) {
      const ContactPairing& pairing = pair.pairing[k];
      if (!pairing.found() || pairing.at_corner || pairing.gap >= 0) continue;
      const auto nodes = pair.surface.segment_nodes(pairing.segment);
      segment.clear();
      for (int node : nodes) segment.push_back(positions_[static_cast<std::size_t>(node)]);
      const SegmentGeometry g = segment_geometry(slaves[k], segment, ContactDerivatives::gradient);
      if (g.projection.status == ProjectionStatus::degenerate || !g.projection.inside || g.gap >= 0) continue;
      Constraint c;
      c.pair = static_cast<int>(p), c.slave = static_cast<int>(k), c.gap = g.gap;
      c.dofs.push_back(DofMap::displacement(s.slave_nodes[k], 0));
      c.dofs.push_back(DofMap::displacement(s.slave_nodes[k], 1));
      for (int node : nodes) c.dofs.push_back(DofMap::displacement(node, 0)), c.dofs.push_back(DofMap::displacement(node, 1));
      c.gradient.assign(g.gap_gradient.data(), g.gap_gradient.data() + g.n_dofs);
      pair.normal[k] = g.normal;
      out.push_back(std::move(c));
    }
  }
  return out;
}

Eigen::VectorXd ExplicitContact::multipliers(const std::vector<Constraint>& constraints, const std::vector<int>& active,
                                             const Eigen::VectorXd& inverse_mass, double c) const {
  // A = c G M^-1 G^T from the rows of G scaled by sqrt(c / m) per dof.
  const auto m = static_cast<Eigen::Index>(active.size());
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd rhs(m);
  for (Eigen::Index r = 0; r < m; ++r) {
    const Constraint& k = constraints[static_cast<std::size_t>(active[static_cast<std::size_t>(r)])];
    for (std::size_t i = 0; i < k.dofs.size(); ++i)
      entries.emplace_back(r, k.dofs[i], k.gradient[i] * std::sqrt(c * inverse_mass[k.dofs[i]]));
    rhs[r] = -k.gap;
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

void ExplicitContact::correct(const Eigen::VectorXd& u, const Eigen::VectorXd& inverse_mass, double c,
                              Eigen::VectorXd& force) {
  force.setZero(u.size());
  const std::vector<Constraint> constraints = penetrations(u);
  std::vector<int> active;
  for (std::size_t k = 0; k < constraints.size(); ++k) {
    double mobility = 0;  // diagonal of G M^-1 G^T: 0 when no node of the constraint can move
    for (std::size_t i = 0; i < constraints[k].dofs.size(); ++i)
      mobility += constraints[k].gradient[i] * constraints[k].gradient[i] * inverse_mass[constraints[k].dofs[i]];
    if (mobility > 0) active.push_back(static_cast<int>(k));
  }
  Eigen::VectorXd lambda;
  while (!active.empty()) {  // release the slaves the correction would pull back
    lambda = multipliers(constraints, active, inverse_mass, c);
    std::vector<int> kept;
    for (std::size_t r = 0; r < active.size(); ++r)
      if (lambda[static_cast<Eigen::Index>(r)] >= 0) kept.push_back(active[r]);
    if (kept.size() == active.size()) break;
    active = std::move(kept);
  }
  for (std::size_t r = 0; r < active.size(); ++r) {
    const Constraint& k = constraints[static_cast<std::size_t>(active[r])];
    const double l = lambda[static_cast<Eigen::Index>(r)];
    for (std::size_t i = 0; i < k.dofs.size(); ++i) force[k.dofs[i]] += k.gradient[i] * l;
    pairs_[static_cast<std::size_t>(k.pair)].multiplier[static_cast<std::size_t>(k.slave)] = l;
  }
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
      n.status = lambda > 0 ? ContactNodeValues::Status::Slip : ContactNodeValues::Status::Open;
      if (pairing.found()) {
        const auto& label = s.master_face_labels[static_cast<std::size_t>(pairing.segment)];
        n.master_element = label.first, n.master_face = label.second, n.xi = pairing.xi;
      }
      n.gap = lambda > 0 ? 0.0 : pairing.gap;  // closed slaves are corrected onto the master
      n.normal_force = lambda;
      n.pressure = lambda / s.slave_area[k];
      n.force = lambda * pair.normal[k];
      v.total_force += n.force;
    }
  }
  return out;
}

}  // namespace tether
