#include "tether/constraints/tie_projection.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "tether/fem/shape_functions.hpp"

namespace tether {

namespace {

FaceProjection at(const Eigen::Vector2d& x, std::span<const Eigen::Vector2d> face, double s) {
  FaceProjection p;
  Eigen::Vector3d dN;
  face_shape_functions(static_cast<int>(face.size()), s, p.weights, dN);
  p.s = s;
  for (std::size_t i = 0; i < face.size(); ++i) p.point += p.weights[static_cast<int>(i)] * face[i];
  p.distance = (x - p.point).norm();
  return p;
}

}  // namespace

FaceProjection project_onto_face(const Eigen::Vector2d& x, std::span<const Eigen::Vector2d> face) {
  assert(face.size() == 2 || face.size() == 3);
  const Eigen::Vector2d chord = face[1] - face[0];
  if (face.size() == 2) {
    // x(s) = (x1 + x2)/2 + s (x2 - x1)/2: (x(s) - x)·(x2 - x1) = 0 is linear in s.
    const double s = 2 * (x - 0.5 * (face[0] + face[1])).dot(chord) / chord.squaredNorm();
    return at(x, face, std::clamp(s, -1.0, 1.0));
  }
  // Quadratic face: start from the best of nine samples, then Newton on
  // g(s) = (x(s) - x)·x'(s), g'(s) = |x'|^2 + (x(s) - x)·x''.
  FaceProjection best = at(x, face, -1.0);
  for (int k = 1; k <= 8; ++k) {
    const FaceProjection sample = at(x, face, -1 + k * 0.25);
    if (sample.distance < best.distance) best = sample;
  }
  double s = best.s;
  const Eigen::Vector2d second_derivative = face[0] + face[1] - 2 * face[2];  // x'' (constant)
  for (int iteration = 0; iteration < 50; ++iteration) {
    Eigen::Vector3d N, dN;
    face_shape_functions(3, s, N, dN);
    Eigen::Vector2d xs = Eigen::Vector2d::Zero(), dxs = Eigen::Vector2d::Zero();
    for (int i = 0; i < 3; ++i) xs += N[i] * face[static_cast<std::size_t>(i)], dxs += dN[i] * face[static_cast<std::size_t>(i)];
    const double g = (xs - x).dot(dxs);
    const double dg = dxs.squaredNorm() + (xs - x).dot(second_derivative);
    if (!(dg > 0)) break;  // not a minimum nearby: keep the best sample
    const double next = std::clamp(s - g / dg, -1.0, 1.0);
    const double step = std::abs(next - s);
    s = next;
    if (step < 1e-15) break;
  }
  const FaceProjection p = at(x, face, s);
  return p.distance <= best.distance ? p : best;  // the samples include both ends
}

}  // namespace tether
