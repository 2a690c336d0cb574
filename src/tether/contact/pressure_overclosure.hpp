#pragma once
/// \file Soft pressure-overclosure laws of contact (`*SURFACE BEHAVIOR`,
/// PRESSURE-OVERCLOSURE=LINEAR, EXPONENTIAL, TABULAR) as pure functions.
///
/// Overclosure h = -g_n [length] (> 0 when the surfaces interpenetrate);
/// contact pressure p(h) [force/area] >= 0. HARD contact has no function: it
/// is enforced exactly by a multiplier (contact_node.hpp).
///
/// - LINEAR (ABAQUS `K`): p = K h for h >= 0, else 0 (c0 = 0: the reader
///   refuses CalculiX's σ∞ and c0, whose law is not modelled).
/// - EXPONENTIAL (ABAQUS `c0, p0`): p = p0/(e - 1) (h/c0 + 1)(exp(h/c0 + 1) - 1)
///   for h > -c0, else 0; p(0) = p0, and p = p' = 0 at h = -c0 (C¹).
///   With CalculiX's meaning (dialect calculix): p = p0 exp(ln(100) h / c0),
///   positive at every clearance (1 % of p0 at h = -c0).
/// - TABULAR: piecewise linear through (p_i, h_i); p = 0 left of h_1 when
///   p_1 = 0, otherwise extended with the first slope; extended with the last
///   slope right of the table.
/// At the point where the pressure starts (h = -c0, or h_1) the slope is the
/// one on the closed side, so bodies that start exactly touching are held.

#include "tether/model/contact_data.hpp"

namespace tether {

/// Pressure and its derivative at overclosure h.
struct ContactPressure {
  double p = 0;      ///< [force/area]
  double dp_dh = 0;  ///< [force/area/length]
};

/// Evaluates a soft law. Throws std::invalid_argument for Law::Hard.
ContactPressure contact_pressure(const PressureOverclosure& law, double overclosure);

}  // namespace tether
