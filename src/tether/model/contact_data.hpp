#pragma once
/// \file Contact as read from a deck (`*SURFACE INTERACTION`, `*SURFACE
/// BEHAVIOR`, `*FRICTION`, `*CONTACT PAIR`): plain data.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "tether/core/error.hpp"
#include "tether/model/constraint_data.hpp"
#include "tether/model/dialect.hpp"

namespace tether {

/// Pressure-overclosure law (`*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=`).
/// Overclosure h = -gap (> 0 when the surfaces interpenetrate).
struct PressureOverclosure {
  enum class Law {
    Hard,         ///< gap >= 0, p >= 0, p * gap = 0 (tether: exact, by multipliers)
    Linear,       ///< p = K h for h > 0; CalculiX's meaning (dialect calculix): K, sigma_inf, c0 (pressure_overclosure.hpp)
    Exponential,  ///< ABAQUS: p = p0 / (exp(1) - 1) (h/c0 + 1) (exp(h/c0 + 1) - 1) for h > -c0
    Tabular,      ///< piecewise linear p(h) through (pressure, overclosure) pairs
  };
  Law law = Law::Hard;
  /// Linear: K [pressure/length]; with CalculiX's meaning 0 = CalculiX's
  /// default 50 E (E of the deck's first material), set by the analysis.
  double stiffness = 0;
  /// Linear (CalculiX's meaning): the tension approached at open gaps
  /// [pressure], > 0; 0 = CalculiX's default E/70000, set by the analysis.
  double sigma_inf = 0;
  /// Linear (CalculiX's meaning): c0 [-], an open slave node carries (a small
  /// tension) only while its clearance is within c0 sqrt(its area); 1e-3 when
  /// not given (or <= 0), as in CalculiX.
  double reach_factor = 0;
  double c0 = 0;         ///< Exponential: clearance at which pressure starts [length] (Linear: an offset, tests only)
  double p0 = 0;         ///< Exponential: pressure at zero clearance [pressure]
  /// Exponential: whose function `c0, p0` define: ABAQUS's (above), or
  /// CalculiX's p = p0 exp(ln(100) h / c0) (1 % of p0 at the clearance c0).
  /// Linear: ABAQUS's p = K h, or CalculiX's smooth law with tension
  /// (pressure_overclosure.hpp).
  Dialect meaning = Dialect::Abaqus;
  std::vector<std::pair<double, double>> table;  ///< Tabular: (pressure, overclosure), overclosure increasing
  /// Hard: how the normal constraint g >= 0 is enforced (tether extension):
  /// Lagrange (exact; regularised g + epsilon*N >= 0 when epsilon > 0, epsilon
  /// [length/force]), Penalty (N = rho <-g>, rho [force/length]) or Augmented
  /// (N = <lambda_bar - rho g> with Uzawa updates until the largest
  /// penetration is below tolerance [length]). Elimination is not available.
  Enforcement enforcement;
};

/// Coulomb friction (`*FRICTION`).
struct FrictionData {
  double mu = 0;           ///< friction coefficient, >= 0
  double stick_slope = 0;  ///< CalculiX's 2nd field: tangential stiffness in stick [pressure/length]; 0 = exact stick
  double elastic_slip = 0; ///< ABAQUS ELASTIC SLIP=: slip at which full friction is reached [length]; 0 = none given
};

/// `*SURFACE INTERACTION` with its options.
struct SurfaceInteraction {
  std::string name;
  PressureOverclosure behavior;          ///< HARD unless *SURFACE BEHAVIOR says otherwise
  std::optional<FrictionData> friction;  ///< none = frictionless
  SourceLocation where;
};

/// `*CONTACT PAIR`: one slave surface against one master surface.
struct ContactPairData {
  std::string interaction;  ///< name of a SurfaceInteraction (upper case)
  std::string slave;        ///< surface name (element faces or nodes)
  std::string master;       ///< surface name (element faces)
  bool node_to_surface = true;  ///< TYPE=NODE TO SURFACE; false: SURFACE TO SURFACE or MORTAR (mortar contact)
  bool small_sliding = false;   ///< SMALL SLIDING: keep the first pairing
  double adjust = 0;            ///< ADJUST=value: move slave nodes within this clearance onto the master [length]
  /// SMOOTH=s: round each corner of a linear master surface over the fraction
  /// s of both adjacent faces, 0 < s <= 0.5 (C¹ surface); 0 = not smoothed
  /// (tether's default when SMOOTH is absent; ABAQUS's default is 0.2).
  double smoothing = 0;
  SourceLocation where;
};

}  // namespace tether
