// Face pressure: direction and magnitude of the total force, reference versus
// follower load, and the follower load stiffness against finite differences.
#include <gtest/gtest.h>

#include <numbers>
#include <numeric>

#include "element_fixtures.hpp"
#include "tether/elements/face_pressure.hpp"

using namespace tether;
using namespace tether::test;

namespace {

const LinearElastic kSteel(210.0, 0.3);

/// Sum of the residual over the face nodes (x and y components).
Eigen::Vector2d total(const LocalSystem& sys) {
  Eigen::Vector2d f = Eigen::Vector2d::Zero();
  for (Eigen::Index i = 0; i < sys.residual.size(); i += 2) f += sys.residual.segment<2>(i);
  return f;
}

/// Element whose face S1 runs along y = 0 from r = 1 to r = 3 (outward normal -y).
std::vector<Eigen::Vector2d> rectangle(Shape shape) {
  std::vector<Eigen::Vector2d> x;
  for (int a = 0; a < n_nodes(shape); ++a) {
    const Eigen::Vector2d xi = reference_node(shape, a);
    if (shape == Shape::Tri3 || shape == Shape::Tri6)
      x.emplace_back(1 + 2 * xi.x(), 1.5 * xi.y());
    else
      x.emplace_back(2 + xi.x(), 0.75 * (1 + xi.y()));
  }
  return x;
}

}  // namespace

TEST(FacePressure, TotalForceOnStraightFaceIsPressureTimesArea) {
  const double p = 2.5, thickness = 0.4;
  for (const ElementType& type : supported_types()) {
    const auto X = rectangle(type.shape);
    DofMap dofs(std::vector<int>(X.size(), 0));
    std::vector<int> nodes(X.size());
    std::iota(nodes.begin(), nodes.end(), 0);
    FacePressure load(5, type, nodes, X, 0, thickness, kSteel, dofs);
    load.set_pressure(p);
    EXPECT_EQ(load.describe(), "pressure on element 5 (" + std::string(type.name) + ") face S1");
    // Plane stress: the thickness under NLGEOM depends on every node of the element.
    EXPECT_EQ(load.dofs().size(),
              2u * (type.family == Family::PlaneStress ? n_nodes(type.shape) : n_face_nodes(type.shape)));
    const Eigen::VectorXd u = Eigen::VectorXd::Zero(dofs.n_dofs());
    for (bool nlgeom : {false, true}) {
      const Eigen::Vector2d f = total(evaluate_at(load, u, nlgeom));
      // Pressure pushes into the face: f_ext = +p A in y, residual = -f_ext.
      const double area = type.family == Family::Axisymmetric ? std::numbers::pi * (9.0 - 1.0) : 2.0 * thickness;
      EXPECT_NEAR(f.x(), 0.0, 1e-12);
      EXPECT_NEAR(f.y(), -p * area, 1e-12 * p * area) << type.name;
    }
  }
}

TEST(FacePressure, ReferenceLoadIgnoresDisplacementFollowerLoadRotatesWithTheFace) {
  const ElementType cpe4 = *find_element_type("CPE4");
  const std::vector<Eigen::Vector2d> X = {{0, 0}, {2, 0}, {2, 1}, {0, 1}};
  DofMap dofs(std::vector<int>(4, 0));
  FacePressure load(1, cpe4, {0, 1, 2, 3}, X, 0, 1.0, kSteel, dofs);
  load.set_pressure(3.0);
  // Rotate the whole element by 90 degrees: face S1 then points along +y, outward normal +x.
  Eigen::VectorXd u(8);
  for (int a = 0; a < 4; ++a) u.segment<2>(2 * a) = Eigen::Vector2d(-X[a].y(), X[a].x()) - X[a];
  const LocalSystem small = evaluate_at(load, u, false);
  EXPECT_NEAR(total(small).y(), -6.0, 1e-12);
  EXPECT_EQ(small.tangent.norm(), 0.0);
  const LocalSystem follower = evaluate_at(load, u, true);
  EXPECT_NEAR(total(follower).x(), 6.0, 1e-12);  // residual = -f_ext = p A n_out
  EXPECT_NEAR(total(follower).y(), 0.0, 1e-12);
}

TEST(FacePressure, FollowerTangentMatchesFiniteDifferences) {
  for (const ElementType& type : supported_types()) {
    const auto X = distorted_element(type.shape);
    DofMap dofs(std::vector<int>(X.size(), 0));
    std::vector<int> nodes(X.size());
    std::iota(nodes.begin(), nodes.end(), 0);
    for (const auto& material : test_materials())  // plane stress: its thickness stretch
      for (int face = 0; face < n_faces(type.shape); ++face) {
        FacePressure load(9, type, nodes, X, face, 0.7, *material, dofs);
        load.set_pressure(-1.7);
        for (unsigned seed : {4u, 5u}) {
          // Plane stress: St.Venant-Kirchhoff has no S_33 = 0 solution under
          // strong compression, which 0.15 reaches at the corners of quadratic faces.
          const double amplitude = type.family == Family::PlaneStress ? 0.06 : 0.15;
          const Eigen::VectorXd u = random_vector(dofs.n_dofs(), amplitude, seed);
          SCOPED_TRACE(load.describe() + " " + material->describe() + " seed " + std::to_string(seed));
          const LocalSystem sys = evaluate_at(load, u, true);
          const Eigen::MatrixXd fd = fd_tangent(load, u, true, 1e-6);
          EXPECT_LT(max_abs(fd - sys.tangent), 1e-7 * max_abs(sys.tangent)) << load.describe();
        }
      }
  }
}

TEST(FacePressure, RefusesMissingFaces) {
  const ElementType cpe3 = *find_element_type("CPE3");
  DofMap dofs(std::vector<int>(3, 0));
  EXPECT_THROW(FacePressure(1, cpe3, {0, 1, 2}, {{0, 0}, {1, 0}, {0, 1}}, 3, 1.0, kSteel, dofs), ModelError);
  EXPECT_THROW(FacePressure(1, cpe3, {0, 1, 2}, {{0, 0}, {0, 0}, {0, 1}}, 0, 1.0, kSteel, dofs), ModelError);
}

// Plane stress under NLGEOM: the load acts on the current thickness h0 F33.
// A homogeneous uniaxial stretch of a CPS4 along x: F33 from S_33 = 0 in
// closed form for St.Venant-Kirchhoff, E33 = -nu/(1-nu) (E11 + E22) with
// E22 from S_22 = 0, so the force on face S2 is p * L * h0 * F33.
TEST(FacePressure, PlaneStressLoadActsOnTheCurrentThickness) {
  const ElementType cps4 = *find_element_type("CPS4");
  const std::vector<Eigen::Vector2d> X = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  DofMap dofs(std::vector<int>(4, 0));
  const double E = 100, nu = 0.3, h0 = 0.1, p = -10;
  const LinearElastic material(E, nu);
  FacePressure load(1, cps4, {0, 1, 2, 3}, X, 1, h0, material, dofs);
  load.set_pressure(p);
  const double stretch = 1.09;
  const double E11 = 0.5 * (stretch * stretch - 1);
  // SVK: S = lambda tr(E) I + 2 mu E; S22 = S33 = 0 gives E22 = E33 = -nu E11.
  const double F22 = std::sqrt(1 - 2 * nu * E11), F33 = F22;
  Eigen::VectorXd u(8);
  for (int a = 0; a < 4; ++a) u.segment<2>(2 * a) << (stretch - 1) * X[a].x(), (F22 - 1) * X[a].y();
  const Eigen::Vector2d f = total(evaluate_at(load, u, true));
  // residual = -f_ext; the outward normal of S2 is +x, traction -p n.
  EXPECT_NEAR(f.x(), p * F22 * h0 * F33, 1e-12);
  EXPECT_NEAR(f.y(), 0.0, 1e-12);
  EXPECT_NEAR(total(evaluate_at(load, u, false)).x(), p * h0, 1e-12);  // small strain: the reference area
}
