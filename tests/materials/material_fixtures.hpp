#pragma once
/// Shared helpers of the material tests: the models under test and random
/// deformations.

#include <Eigen/LU>
#include <memory>
#include <random>
#include <vector>

#include "tether/materials/linear_elastic.hpp"
#include "tether/materials/neo_hooke.hpp"

namespace tether::test {

/// One linear elastic and one neo-Hookean model with comparable stiffness.
inline std::vector<std::unique_ptr<ElasticModel>> all_models() {
  std::vector<std::unique_ptr<ElasticModel>> m;
  m.push_back(std::make_unique<LinearElastic>(210.0, 0.3));
  m.push_back(std::make_unique<NeoHooke>(40.0, 0.02));
  return m;
}

/// Random deformation gradients (3x3, det > 0, plane: F13 = F23 = F31 = F32 = 0
/// when `plane`), amplitude `amp` around the identity.
inline std::vector<Eigen::Matrix3d> random_deformations(int count, double amp, bool plane, unsigned seed = 7) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> dist(-amp, amp);
  std::vector<Eigen::Matrix3d> out;
  while (static_cast<int>(out.size()) < count) {
    Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        if (!plane || (i < 2 && j < 2) || (i == 2 && j == 2)) F(i, j) += dist(gen);
    if (F.determinant() > 0.3) out.push_back(F);
  }
  return out;
}

/// Right Cauchy-Green tensor of a Voigt Green-Lagrange strain (engineering shear).
inline Eigen::Matrix3d cauchy_green_of(const Vec6& E) {
  Eigen::Matrix3d C;
  C << 1 + 2 * E(0), E(3), E(5),  //
      E(3), 1 + 2 * E(1), E(4),   //
      E(5), E(4), 1 + 2 * E(2);
  return C;
}

/// Voigt Green-Lagrange strain of C.
inline Vec6 green_lagrange_of(const Eigen::Matrix3d& C) {
  return to_voigt_strain(0.5 * (C - Eigen::Matrix3d::Identity()));
}

}  // namespace tether::test
