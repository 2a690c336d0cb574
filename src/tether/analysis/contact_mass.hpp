#pragma once
/// \file Mass redistribution at contact surfaces for implicit dynamics: the
/// stabilisation of impact with exact multipliers (Khenous, Laborde & Renard
/// 2008). Nodes of the slave and master surfaces of every contact pair carry
/// no mass: their motion is then quasi-static, so the multipliers cannot
/// excite the velocity jumps that make the contact force chatter and the
/// energy grow under Newmark/HHT. The mass goes to the other nodes of the
/// same element (ElementInertia::redistribute). See docs/theory/dynamics.md,
/// "Impact".

#include <memory>
#include <string>
#include <vector>

#include "tether/analysis/discretization.hpp"
#include "tether/elements/element_inertia.hpp"

namespace tether {

/// What redistribute_contact_mass() did, for the .msg.
struct ContactMassSummary {
  int nodes = 0;     ///< contact-surface nodes (slave and master)
  int elements = 0;  ///< elements whose mass moved
  /// Elements whose every node lies on a contact surface: their mass stays
  /// (nowhere to move it), so their nodes keep some mass.
  int kept = 0;

  /// One line for the .msg ("" when there is no contact surface).
  [[nodiscard]] std::string describe() const;
};

/// Redistributes the mass of `inertia` (one per element of `disc`, same
/// order) away from the nodes of every contact pair's slave and master
/// surfaces (node-to-surface and mortar).
ContactMassSummary redistribute_contact_mass(const Discretization& disc,
                                             const std::vector<std::unique_ptr<ElementInertia>>& inertia);

}  // namespace tether
