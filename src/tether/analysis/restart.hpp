#pragma once
/// \file What identifies the model a restart state belongs to (RestartFingerprint).

#include <string>

#include "tether/analysis/discretization.hpp"
#include "tether/model/restart_state.hpp"

namespace tether {

/// The fingerprint of `model` as discretized, with the load history of its
/// first `history_steps` steps (NLGEOM, period, AMPLITUDE=RAMP/STEP, boundary
/// conditions with their kind (`FIXED`, `TYPE=VELOCITY`), loads, body loads,
/// initial and step temperatures and the amplitudes they use; not the
/// increment controls or output requests, which a restarted run may change). `contributions` is the number of
/// contributions restart records index (see StaticAnalysis).
RestartFingerprint restart_fingerprint(const Model& model, const Discretization& discretization, int contributions,
                                       int history_steps);

/// What differs between the fingerprint of the deck and that of a file, as
/// "the deck has 12 nodes, the file 16; node coordinates differ" ("" when equal).
std::string fingerprint_differences(const RestartFingerprint& deck, const RestartFingerprint& file);

}  // namespace tether
