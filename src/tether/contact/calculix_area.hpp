#pragma once
/// \file CalculiX's area of a node of a node-based slave surface (dialect
/// calculix): the master face's "representative area" at the point the node
/// projects onto, on the current (deformed) face, with its derivatives.
///
/// ccx keeps such a node as the 2D node itself, on no face of its expanded
/// 3D mesh, so its own area is 0 and springforc_n2f.f takes the master face's
/// 4 |x_ξ × x_η| (η = 0, the mid-plane of the one-layer expansion) at the
/// projection, computed from the current coordinates (co + vold, in every
/// static step, with or without NLGEOM). On the expanded faces:
/// - plane (CPE, CPS; thickness t of the master's section): A = 2 t |y'(ξ)|;
/// - axisymmetric (2° wedge, φ = 1°): A_segment = 4 sin φ r(ξ) |(r̃', y')|,
///   r̃' = cos φ r' on linear faces, r̃' = r'_chord + cos φ (r' - r'_chord) on
///   quadratic ones (r'_chord = (r_2 - r_1)/2); tether's full circle is 180 ×
///   A_segment. Theory: docs/theory/contact.md.

#include <Eigen/Core>
#include <span>
#include <vector>

namespace tether {

/// Which of CalculiX's area formulas a master face follows.
struct MasterFaceArea {
  enum class Kind { plane, axisymmetric };
  Kind kind = Kind::plane;
  double thickness = 1;  ///< plane: the master element's section thickness [length]
};

/// The area at ξ and its partial derivatives.
struct FaceArea {
  double area = 0;                        ///< [length²] (full circle for axisymmetric faces)
  std::vector<Eigen::Vector2d> d_nodes;   ///< ∂A/∂y_a at fixed ξ, one per face node
  double d_xi = 0;                        ///< ∂A/∂ξ at fixed nodes
};

/// CalculiX's area of the face with (current) node positions `y` (2 or 3,
/// face_nodes() order: corners first, then the mid-side node) at ξ. 0 at the
/// axis (r = 0) of an axisymmetric face, and for a face of zero length
/// (derivatives 0 there).
FaceArea calculix_face_area(const MasterFaceArea& rule, std::span<const Eigen::Vector2d> y, double xi);

}  // namespace tether
