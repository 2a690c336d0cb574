#pragma once
/// \file Soft pressure-overclosure laws of contact (`*SURFACE BEHAVIOR`,
/// PRESSURE-OVERCLOSURE=LINEAR, EXPONENTIAL, TABULAR) as pure functions.
///
/// Overclosure h = -g_n [length] (> 0 when the surfaces interpenetrate);
/// contact pressure p(h) [force/area] >= 0. HARD contact has no function: it
/// is enforced exactly by a multiplier (contact_node.hpp).
///
/// - LINEAR (ABAQUS `K`): p = K h for h >= 0, else 0 (c0 = 0 from decks).
///   With CalculiX's meaning (dialect calculix, `K, σ∞, c0`), node-to-surface
///   contact (CalculiX's springforc_n2f): p = K h (1/2 + atan(h/ε)/π),
///   ε = π σ∞ / K, smooth at every overclosure: p(0) = 0, p → K h for
///   h >> ε, p → -σ∞ (a tension) for h << -ε. An open node whose clearance
///   exceeds the reach c0 sqrt(area) carries nothing (CalculiX generates no
///   contact element for it): p jumps there from about -σ∞ to 0.
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

/// Evaluates a soft law. Throws std::invalid_argument for Law::Hard and for
/// CalculiX's LINEAR law, which needs the reach (the overload below).
ContactPressure contact_pressure(const PressureOverclosure& law, double overclosure);

/// Evaluates a soft law at a node-to-surface slave node whose open clearance
/// `reach` [length] is the farthest at which CalculiX's LINEAR law still acts
/// (c0 sqrt(area), calculix_linear_reach); other laws ignore it.
ContactPressure contact_pressure(const PressureOverclosure& law, double overclosure, double reach);

/// CalculiX's LINEAR law p = K h (1/2 + atan(h/ε)/π), ε = π σ∞/K, and its
/// derivative, at overclosure h [length], without the reach cut-off.
ContactPressure calculix_linear_pressure(double stiffness, double sigma_inf, double overclosure);

/// The reach c0 sqrt(A) of CalculiX's LINEAR law [length] for a slave node of
/// area A [area] as CalculiX counts it: CalculiX expands a 2D model to one
/// layer of 3D elements, so each 2D node of a linear face becomes two 3D
/// nodes that share its area: A = tether's node area / 2.
double calculix_linear_reach(const PressureOverclosure& law, double tether_node_area);

/// The reach of CalculiX's LINEAR law at a node of a node-based slave surface
/// of a 2D model [length]: ccx finds no face of its expanded mesh through such
/// a node, so it gives it the area 0 when it generates contact elements and
/// then the clearance limit 1e-10 instead of c0 sqrt(area) (gencontelem_n2f.f);
/// the force uses the master face's area (contact_builder.cpp).
inline constexpr double kCalculixNodeSlaveReach = 1e-10;

}  // namespace tether
