#pragma once
/// Shared helpers of the element tests: every supported type, distorted single
/// elements, random states and central finite differences over a Contribution.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "tether/assembly/contribution.hpp"
#include "tether/dofs/dof_map.hpp"
#include "tether/fem/shape_functions.hpp"
#include "tether/materials/linear_elastic.hpp"
#include "tether/materials/neo_hooke.hpp"
#include "tether/model/element_type.hpp"

namespace tether::test {

/// All element types tether supports (reduced 4-node types are refused; the
/// hybrid ones are CPE4H and CAX4H): 17.
inline std::vector<ElementType> supported_types() {
  std::vector<ElementType> out;
  for (const char* family : {"CPE", "CPS", "CAX"})
    for (const char* shape : {"3", "4", "4H", "6", "8", "8R"}) {
      const auto t = find_element_type(std::string(family) + shape);
      if (t && unsupported_reason(*t).empty()) out.push_back(*t);
    }
  return out;
}

/// One linear elastic (SVK under NLGEOM) and one neo-Hookean model.
inline std::vector<std::unique_ptr<ElasticModel>> test_materials() {
  std::vector<std::unique_ptr<ElasticModel>> m;
  m.push_back(std::make_unique<LinearElastic>(210.0, 0.3));
  m.push_back(std::make_unique<NeoHooke>(40.0, 0.02));
  return m;
}

/// Reference coordinates of a distorted single element of `shape`: the
/// reference element mapped by an affine map, nodes jittered, shifted to
/// r in about [1, 2.5] so it also serves axisymmetry.
inline std::vector<Eigen::Vector2d> distorted_element(Shape shape, unsigned seed = 3) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> jitter(-0.06, 0.06);
  const bool tri = shape == Shape::Tri3 || shape == Shape::Tri6;
  Eigen::Matrix2d A;
  A << 0.9, 0.25, -0.1, 1.1;
  if (!tri) A *= 0.5;
  const Eigen::Vector2d shift = tri ? Eigen::Vector2d(1.1, -0.3) : Eigen::Vector2d(1.7, 0.2);
  std::vector<Eigen::Vector2d> x;
  for (int a = 0; a < n_nodes(shape); ++a)
    x.push_back(A * reference_node(shape, a) + shift + Eigen::Vector2d(jitter(gen), jitter(gen)));
  return x;
}

/// The mesh's coordinate table a ContinuumElement reads its reference
/// coordinates from: node nodes[a] at X[a], the other nodes (up to the
/// largest index) at NaN, so that reading one of them shows in the results.
inline std::vector<Eigen::Vector2d> coordinate_table(const std::vector<int>& nodes,
                                                     const std::vector<Eigen::Vector2d>& X) {
  int n = 0;
  for (const int i : nodes) n = std::max(n, i + 1);
  std::vector<Eigen::Vector2d> table(static_cast<std::size_t>(n), Eigen::Vector2d::Constant(std::nan("")));
  for (std::size_t a = 0; a < nodes.size(); ++a) table[static_cast<std::size_t>(nodes[a])] = X[a];
  return table;
}

/// Random global displacement vector of size n with entries in [-amp, amp].
inline Eigen::VectorXd random_vector(int n, double amp, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> dist(-amp, amp);
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i) v(i) = dist(gen);
  return v;
}

/// Evaluates c at global state u.
inline LocalSystem evaluate_at(const Contribution& c, const Eigen::VectorXd& u, bool nlgeom) {
  const EvaluationState s{u, u, 1, 1, 1, nlgeom};
  LocalSystem out;
  out.reset(static_cast<Eigen::Index>(c.dofs().size()));
  c.evaluate(s, out, true);
  return out;
}

/// Central finite-difference Jacobian of the residual over the local dofs.
inline Eigen::MatrixXd fd_tangent(const Contribution& c, const Eigen::VectorXd& u, bool nlgeom, double h) {
  const auto dofs = c.dofs();
  const int n = static_cast<int>(dofs.size());
  Eigen::MatrixXd K(n, n);
  for (int j = 0; j < n; ++j) {
    Eigen::VectorXd up = u, um = u;
    up(dofs[j]) += h;
    um(dofs[j]) -= h;
    K.col(j) = (evaluate_at(c, up, nlgeom).residual - evaluate_at(c, um, nlgeom).residual) / (2 * h);
  }
  return K;
}

/// Largest absolute entry.
inline double max_abs(const Eigen::MatrixXd& m) { return m.cwiseAbs().maxCoeff(); }

}  // namespace tether::test
