#pragma once
/// \file Parameters shared by the constraint keywords (*EQUATION, *MPC,
/// *CONSTRAINT, *TIE, *PERIODIC): enforcement and single-node references.

#include <string>
#include <string_view>

#include "tether/io/deck_state.hpp"
#include "tether/io/keyword_table.hpp"

namespace tether::deck {

/// ENFORCEMENT=, EPSILON=, PENALTY=, TOLERANCE= validated: EPSILON and
/// TOLERANCE >= 0, PENALTY > 0 for PENALTY/AUGMENTED, EPSILON only with
/// LAGRANGE, ELIMINATION only where `linear` is true. InputError at `at`.
Enforcement read_enforcement(const ParameterValues& params, const SourceLocation& at, bool linear);

/// The one node of `token` (a node label or a one-node set). `what` names the
/// parameter in the message ("REFERENCE1"); empty for a data field.
int single_node(const DeckState& state, const std::string& token, const SourceLocation& at,
                std::string_view what = {});

}  // namespace tether::deck
