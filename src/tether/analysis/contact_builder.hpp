#pragma once
/// \file Turns a `*CONTACT PAIR` of the model into a ContactPair over node
/// indices: master segments from element faces, slave nodes with their
/// tributary areas, the interaction's law and friction, search radius and
/// complementarity stiffness.

#include <memory>

#include "tether/contact/contact_pair.hpp"
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

}  // namespace tether
