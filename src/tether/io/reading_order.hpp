#pragma once
/// \file The order in which the reader hands keyword blocks to their handlers.
///
/// CalculiX reads a deck in groups, each in deck order: nodes, elements, node
/// sets, element sets, surfaces, materials (with their options), ties,
/// surface interactions (with their options), initial conditions, amplitudes,
/// contact pairs, then everything else (sections, constraints, model-data
/// loads, steps). A name may therefore be used before the line that defines
/// it whenever its group comes earlier: a *CONTACT PAIR before the *SURFACE
/// INTERACTION it names, a *SOLID SECTION before its *ELSET, a *BOUNDARY
/// before its *AMPLITUDE, an *ELEMENT before its *NODE lines. ABAQUS reads
/// the whole model before resolving names too, so tether uses this order in
/// every dialect. Within a group the deck order is kept, so a set still has
/// to be defined before another set names it, exactly as in CalculiX.

#include <cstddef>
#include <vector>

#include "tether/io/line_reader.hpp"

namespace tether::deck {

/// Indices into `blocks` in reading order (a stable reordering by group).
/// Unknown keywords go with "everything else".
std::vector<std::size_t> reading_order(const std::vector<KeywordBlock>& blocks);

}  // namespace tether::deck
