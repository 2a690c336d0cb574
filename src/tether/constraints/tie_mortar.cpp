#include "tether/constraints/tie_mortar.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "tether/constraints/tie_projection.hpp"
#include "tether/fem/shape_functions.hpp"

namespace tether {

std::map<int, MortarRow> mortar_tie_rows(std::span<const TieFace> slave, std::span<const TieFace> master,
                                         double tolerance) {
  // 4-point Gauss-Legendre on [-1, 1].
  const double a = std::sqrt(3.0 / 7 - 2.0 / 7 * std::sqrt(6.0 / 5)), b = std::sqrt(3.0 / 7 + 2.0 / 7 * std::sqrt(6.0 / 5));
  const double wa = (18 + std::sqrt(30.0)) / 36, wb = (18 - std::sqrt(30.0)) / 36;
  const std::array<double, 4> gauss_x{-b, -a, a, b}, gauss_w{wb, wa, wa, wb};

  std::map<int, MortarRow> rows;
  for (const TieFace& face : slave) {
    const int n = static_cast<int>(face.nodes.size());
    // Break points: where the ends of the master faces project onto this slave face.
    std::vector<double> cuts{-1.0, 1.0};
    for (const TieFace& m : master)
      for (std::size_t end = 0; end < 2; ++end) {
        const FaceProjection p = project_onto_face(m.x[end], face.x);
        if (p.s > -1 + 1e-12 && p.s < 1 - 1e-12) cuts.push_back(p.s);
      }
    std::sort(cuts.begin(), cuts.end());
    for (std::size_t piece = 0; piece + 1 < cuts.size(); ++piece) {
      const double s0 = cuts[piece], s1 = cuts[piece + 1];
      if (s1 - s0 < 1e-12) continue;
      for (std::size_t g = 0; g < gauss_x.size(); ++g) {
        const double s = 0.5 * (s0 + s1) + 0.5 * (s1 - s0) * gauss_x[g];
        Eigen::Vector3d phi, dphi;
        face_shape_functions(n, s, phi, dphi);
        Eigen::Vector2d x = Eigen::Vector2d::Zero(), dx = Eigen::Vector2d::Zero();
        for (int l = 0; l < n; ++l) x += phi[l] * face.x[static_cast<std::size_t>(l)], dx += dphi[l] * face.x[static_cast<std::size_t>(l)];
        const double weight = gauss_w[g] * 0.5 * (s1 - s0) * dx.norm();  // dGamma
        FaceProjection best;
        const TieFace* best_face = nullptr;
        for (const TieFace& m : master) {
          const FaceProjection p = project_onto_face(x, m.x);
          if (!best_face || p.distance < best.distance) best = p, best_face = &m;
        }
        if (!best_face || best.distance > tolerance) continue;
        for (int k = 0; k < n; ++k) {
          MortarRow& row = rows[face.nodes[static_cast<std::size_t>(k)]];
          const double psi = phi[k] * weight;
          for (int l = 0; l < n; ++l) row[face.nodes[static_cast<std::size_t>(l)]] += psi * phi[l];
          for (std::size_t i = 0; i < best_face->nodes.size(); ++i)
            row[best_face->nodes[i]] -= psi * best.weights[static_cast<int>(i)];
        }
      }
    }
  }
  return rows;
}

}  // namespace tether
