#pragma once
/// \file The bolt force and tightening of each `*PRE-TENSION SECTION`, and
/// their .dat blocks.

#include <string>
#include <string_view>

#include "tether/model/model.hpp"
#include "tether/model/results.hpp"

namespace tether {

/// Title of the .dat blocks (one per section, after the multiplier blocks):
/// `pretension section (node,tightening,bolt force) for set PRETENSION-<SURFACE> and time ...`,
/// then one row: pretension node label, u_p [length], bolt force [force].
inline constexpr std::string_view kPretensionTitle = "pretension section (node,tightening,bolt force)";

/// A section's state in one increment.
struct BoltState {
  double tightening = 0;  ///< u_p, dof 1 of the pretension node [length]; positive shortens the bolt
  /// The force the cut carries across [force], positive in tension: the
  /// force the section's equations put on the pretension node's dof 1, with
  /// its sign turned (equal to the *CLOAD there while one acts alone).
  double force = 0;
};

/// The state of `section` in `results`, from its constraint's nodal forces.
/// Throws std::invalid_argument when the results hold no values of the
/// section's constraint (results of another model).
BoltState bolt_state(const PretensionSection& section, const IncrementResults& results);

/// Appends one block per section of `model` (nothing when it has none).
void write_pretension_blocks(std::string& text, const Model& model, const IncrementResults& results);

}  // namespace tether
