#pragma once
/// \file Closest point of a point on a 2- or 3-node element face: the geometry
/// of `*TIE` (slave node onto master surface). Pure functions, no model.

#include <Eigen/Core>
#include <span>

namespace tether {

/// The closest point of a face to a point.
struct FaceProjection {
  double s = 0;                  ///< face coordinate in [-1, 1] (first corner -1, second +1, mid-side node 0)
  Eigen::Vector2d point{0, 0};   ///< x(s), the closest point on the face
  double distance = 0;           ///< |x - x(s)| [length]
  Eigen::Vector3d weights{0, 0, 0};  ///< face shape functions N_i(s) (entry 2 zero for 2-node faces)
};

/// Closest point of `x` on the face through `face` (2 corners, or 2 corners and
/// the mid-side node, in face_nodes() order), with s clamped to [-1, 1].
/// Straight 2-node faces: closed form. 3-node faces: Newton on
/// (x(s) - x)·x'(s) = 0 from the best of a few samples, compared with the ends.
/// Precondition: face.size() is 2 or 3 and the face has non-zero length.
FaceProjection project_onto_face(const Eigen::Vector2d& x, std::span<const Eigen::Vector2d> face);

}  // namespace tether
