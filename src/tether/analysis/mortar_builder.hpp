#pragma once
/// \file Turns a `*CONTACT PAIR, TYPE=SURFACE TO SURFACE` (or MORTAR) of the
/// model into a MortarPair over node indices: slave and master faces, the
/// slave faces' thickness, search radius and complementarity stiffness.

#include <memory>

#include "tether/assembly/equation_map.hpp"
#include "tether/contact/mortar_pair.hpp"
#include "tether/dofs/dof_map.hpp"
#include "tether/model/model.hpp"
#include "tether/solvers/dual_condensation.hpp"

namespace tether {

/// Builds the pair and reserves one multiplier per slave node in `dofs`.
/// `reference` holds the reference coordinates of all nodes and must outlive
/// the pair. Throws ModelError naming the pair's deck line for what mortar
/// contact does not model: a node-based slave surface, axisymmetric faces,
/// surfaces sharing a node, a soft law, a penalty or regularised HARD law,
/// friction, SMOOTH.
std::unique_ptr<MortarPair> make_mortar_pair(const Model& model, const ContactPairData& data,
                                             const std::vector<Eigen::Vector2d>& reference, DofMap& dofs);

/// Every free equation a mortar contribution of `pairs` can touch: the
/// displacements of all slave and master nodes (through `equations`) and the
/// multipliers. Sorted, unique.
std::vector<int> mortar_equations(const std::vector<std::unique_ptr<MortarPair>>& pairs, const DofMap& dofs,
                                  const EquationMap& equations);

/// Per slave node of `pairs`: the equation of its normal multiplier and of
/// its two displacement components (-1 where a dof is not one free equation
/// of weight 1), for DualCondensedSolver.
std::vector<DualNodeEquations> mortar_dual_equations(const std::vector<std::unique_ptr<MortarPair>>& pairs,
                                                     const DofMap& dofs, const EquationMap& equations);

}  // namespace tether
