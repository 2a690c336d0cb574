#pragma once
/// \file `*DLOAD` body loads (GRAV, CENTRIF) as read from a deck: plain data.

#include <Eigen/Core>

#include "tether/core/error.hpp"

namespace tether {

/// A body force per unit mass on one element, from `*DLOAD` GRAV or CENTRIF;
/// the element's material supplies the density (its `*DENSITY`).
/// - Gravity: b = magnitude * direction [length/time^2]; constant.
/// - Centrifugal: b = magnitude * (x - p)_perp with magnitude = omega^2
///   [1/time^2] and (x - p)_perp the part of x - point normal to the axis,
///   x the reference position (the current one under NLGEOM).
/// In a plane model the axis is z (rotation in the plane); in an axisymmetric
/// one it is the symmetry axis (y through r = 0). The reader checks both.
struct BodyLoad {
  enum class Kind { Gravity, Centrifugal };
  Kind kind = Kind::Gravity;
  int element = -1;                                  ///< element index
  double magnitude = 0;                              ///< g, or omega^2
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();  ///< unit gravity direction, or unit rotation axis
  Eigen::Vector3d point = Eigen::Vector3d::Zero();      ///< a point on the rotation axis (CENTRIF)
  int amplitude = -1;
  SourceLocation where;
};

}  // namespace tether
