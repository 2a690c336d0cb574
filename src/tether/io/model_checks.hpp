#pragma once
/// \file Checks of the whole model after the last keyword: section and
/// material resolution, element orientation. Each failure is an InputError
/// at the deck line of the offending definition.

#include "tether/io/deck_state.hpp"

namespace tether::deck {

/// Resolves section materials, assigns a section to every element and
/// validates the model (every element in exactly one section, every material
/// with elastic data, a density wherever a body load acts, no inverted or
/// degenerate element, r >= 0 for axisymmetric elements).
void check_model(DeckState& state);

/// ADJUST= of *CONTACT PAIR: moves the slave nodes whose gap is at most the
/// clearance (overclosed ones included) onto the master surface in the
/// reference configuration, before any element is built (stress-free, as
/// ABAQUS does), and notes how many moved. In contact_keywords.cpp.
void apply_contact_adjustments(DeckState& state);

/// Slave surfaces of a body at least kStiffSlaveRatio times stiffer than
/// their master (MaterialData::modulus of the faces' elements): a warning at
/// the *CONTACT PAIR line that names both and the swap. In contact_keywords.cpp.
void warn_about_stiff_slaves(DeckState& state);
inline constexpr double kStiffSlaveRatio = 10;

/// Determinant of the isoparametric Jacobian at each corner of `e` (in
/// corner order), from the reference coordinates of the model.
std::vector<double> corner_jacobians(const Model& model, const Element& e);

}  // namespace tether::deck
