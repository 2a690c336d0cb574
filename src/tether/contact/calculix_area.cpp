#include "tether/contact/calculix_area.hpp"

#include <cmath>
#include <numbers>

#include "tether/fem/shape_functions.hpp"
#include "tether/model/dialect.hpp"

namespace tether {

FaceArea calculix_face_area(const MasterFaceArea& rule, std::span<const Eigen::Vector2d> y, double xi) {
  const int m = static_cast<int>(y.size());
  Eigen::Vector3d N, dN;
  face_shape_functions(m, xi, N, dN);
  const Eigen::Vector3d ddN = m == 3 ? Eigen::Vector3d(1, 1, -2) : Eigen::Vector3d::Zero();
  Eigen::Vector2d p(0, 0), dp(0, 0), ddp(0, 0);
  for (int a = 0; a < m; ++a) {
    const Eigen::Vector2d& ya = y[static_cast<std::size_t>(a)];
    p += N[a] * ya, dp += dN[a] * ya, ddp += ddN[a] * ya;
  }
  FaceArea out;
  out.d_nodes.assign(static_cast<std::size_t>(m), Eigen::Vector2d::Zero());
  // A = F(p, dp, chord): its partials, then the chain rule through p, dp, chord.
  Eigen::Vector2d dF_dp(0, 0), dF_ddp(0, 0);
  double dF_dchord = 0;
  if (rule.kind == MasterFaceArea::Kind::plane) {
    const double length = dp.norm();
    out.area = 2 * rule.thickness * length;
    if (length > 0) dF_ddp = 2 * rule.thickness * dp / length;
  } else {
    // φ: half the angle of CalculiX's wedge. ccx expands a CAX element into
    // 2π/180 = 2° about the y axis (gen3dfrom2d.f: a node at radius r becomes
    // r cos φ, y, ∓r sin φ on the side faces and, for quadratic elements,
    // r, y, 0 in the mid-layer, hence r̃' on quadratic faces).
    const double phi = std::numbers::pi / kCalculixAxisymmetricSegments;
    const double c = std::cos(phi), k = kCalculixAxisymmetricSegments * 4 * std::sin(phi);
    const double chord = (y[1].x() - y[0].x()) / 2;
    const double shift = m == 3 ? 1 - c : 0.0;  // r̃' = c r' + shift · r'_chord
    const Eigen::Vector2d q(c * dp.x() + shift * chord, dp.y());
    const double qn = q.norm();
    out.area = k * p.x() * qn;
    if (qn > 0) {
      dF_dp = Eigen::Vector2d(k * qn, 0);
      dF_ddp = k * p.x() * Eigen::Vector2d(c * q.x(), q.y()) / qn;
      dF_dchord = k * p.x() * shift * q.x() / qn;
    }
  }
  for (int a = 0; a < m; ++a) out.d_nodes[static_cast<std::size_t>(a)] = N[a] * dF_dp + dN[a] * dF_ddp;
  out.d_nodes[0].x() -= dF_dchord / 2;
  out.d_nodes[1].x() += dF_dchord / 2;
  out.d_xi = dF_dp.dot(dp) + dF_ddp.dot(ddp);
  return out;
}

}  // namespace tether
