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

}  // namespace tether
