#pragma once
/// \file Turns a `*CONTACT PAIR` of the model into a ContactPair over node
/// indices: master segments from element faces, slave nodes with their
/// tributary areas, the interaction's law and friction, search radius and
/// complementarity stiffness.

#include <memory>

#include "tether/contact/contact_pair.hpp"
#include "tether/assembly/equation_map.hpp"
#include "tether/dofs/dof_map.hpp"
#include "tether/model/model.hpp"
#include "tether/solvers/dual_condensation.hpp"

namespace tether {

/// Builds the pair and reserves its multipliers in `dofs`. `reference` holds
/// the reference coordinates of all nodes and must outlive the pair.
/// Throws ModelError (naming the pair's deck line) when the surfaces cannot
/// form a pair: an empty surface, slave and master sharing a node, a law
/// option tether does not model.
std::unique_ptr<ContactPair> make_contact_pair(const Model& model, const ContactPairData& data,
                                               const std::vector<Eigen::Vector2d>& reference, DofMap& dofs);

/// Every free equation a contact contribution of `pairs` can ever touch,
/// whatever the pairing: the displacements of the slave nodes and of all
/// master-surface nodes (through `equations`, so a dof eliminated by an MPC
/// counts as the equations it expands to) and the contact multipliers.
/// Sorted, unique. The interface of CondensedSolver.
std::vector<int> contact_equations(const std::vector<std::unique_ptr<ContactPair>>& pairs, const DofMap& dofs,
                                   const EquationMap& equations);

/// The node-to-segment slave nodes whose normal multiplier CondensedSolver
/// eliminates from its dense interface system with a displacement of the
/// node itself (CondensedSolver::eliminate_dual_multipliers; a closed row of
/// slave node s is ∂g/∂u_s = n there, a unit vector): per such node of a
/// HARD pair enforced by Lagrange multipliers, its normal multiplier and its
/// two displacement equations (-1 where the dof is not a free equation of
/// weight 1: prescribed, or eliminated by *EQUATION/MPC with a weight; never
/// a pivot). Tangential (friction) multipliers are not listed: they stay.
/// Left out, so that a pivot is coupled to no other closed multiplier's row
/// and the eliminated block stays as well conditioned as a single node's: a
/// node whose displacement equations (through `equations`, so an
/// MPC-dependent dof counts as the equations it expands to) are also those
/// of another slave row (a slave of two pairs; two slaves tied together), of
/// a node of any pair's master surface, or of a node in `other_contact_nodes`
/// (node indices, e.g. those of mortar pairs). Pairs without multipliers
/// (soft laws, penalty) add nothing.
std::vector<DualNodeEquations> contact_dual_equations(const std::vector<std::unique_ptr<ContactPair>>& pairs,
                                                      const DofMap& dofs, const EquationMap& equations,
                                                      const std::vector<int>& other_contact_nodes);

}  // namespace tether
