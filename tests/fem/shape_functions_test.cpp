#include <gtest/gtest.h>

#include "tether/fem/shape_functions.hpp"

using namespace tether;

namespace {

const Shape kShapes[] = {Shape::Tri3, Shape::Quad4, Shape::Tri6, Shape::Quad8};

bool is_triangle(Shape s) { return s == Shape::Tri3 || s == Shape::Tri6; }

/// Sample points inside the reference element.
std::vector<Eigen::Vector2d> samples(Shape s) {
  if (is_triangle(s)) return {{0.2, 0.3}, {0.6, 0.1}, {0.05, 0.9}, {1.0 / 3, 1.0 / 3}};
  return {{0.1, -0.7}, {-0.4, 0.35}, {0.9, 0.95}, {0, 0}};
}

}  // namespace

TEST(ShapeFunctions, PartitionOfUnityAndZeroDerivativeSum) {
  ShapeVector N;
  ShapeGradient dN;
  for (Shape s : kShapes)
    for (const auto& xi : samples(s)) {
      shape_functions(s, xi, N, dN);
      ASSERT_EQ(N.size(), n_nodes(s));
      EXPECT_NEAR(N.sum(), 1.0, 1e-14);
      EXPECT_NEAR(dN.col(0).sum(), 0.0, 1e-14);
      EXPECT_NEAR(dN.col(1).sum(), 0.0, 1e-14);
    }
}

TEST(ShapeFunctions, KroneckerPropertyAtNodes) {
  ShapeVector N;
  ShapeGradient dN;
  for (Shape s : kShapes)
    for (int b = 0; b < n_nodes(s); ++b) {
      shape_functions(s, reference_node(s, b), N, dN);
      for (int a = 0; a < n_nodes(s); ++a) EXPECT_NEAR(N(a), a == b ? 1.0 : 0.0, 1e-14) << a << " " << b;
    }
}

TEST(ShapeFunctions, ReproduceLinearFieldsOfTheCoordinates) {
  ShapeVector N;
  ShapeGradient dN;
  for (Shape s : kShapes)
    for (const auto& xi : samples(s)) {
      shape_functions(s, xi, N, dN);
      Eigen::Vector2d x = Eigen::Vector2d::Zero();
      Eigen::Matrix2d J = Eigen::Matrix2d::Zero();
      for (int a = 0; a < n_nodes(s); ++a) {
        x += N(a) * reference_node(s, a);
        J += reference_node(s, a) * dN.row(a);
      }
      EXPECT_NEAR((x - xi).norm(), 0.0, 1e-14);
      EXPECT_NEAR((J - Eigen::Matrix2d::Identity()).norm(), 0.0, 1e-14);
    }
}

TEST(ShapeFunctions, DerivativesMatchCentralDifferences) {
  ShapeVector N, Np, Nm;
  ShapeGradient dN, dummy;
  const double h = 1e-6;
  for (Shape s : kShapes)
    for (const auto& xi : samples(s)) {
      shape_functions(s, xi, N, dN);
      for (int j = 0; j < 2; ++j) {
        Eigen::Vector2d e = Eigen::Vector2d::Zero();
        e(j) = h;
        shape_functions(s, xi + e, Np, dummy);
        shape_functions(s, xi - e, Nm, dummy);
        const ShapeVector fd = (Np - Nm) / (2 * h);
        EXPECT_LT((fd - dN.col(j)).norm(), 1e-8) << "shape " << static_cast<int>(s) << " dir " << j;
      }
    }
}

TEST(ShapeFunctions, QuadraticShapesReproduceQuadraticsOnTheirNodes) {
  // Tri6 is complete quadratic; Quad8 reproduces 1, x, y, x^2, xy, y^2, x^2 y, x y^2.
  ShapeVector N;
  ShapeGradient dN;
  auto f = [](const Eigen::Vector2d& p) { return 1 + 2 * p.x() - p.y() + 3 * p.x() * p.x() - p.x() * p.y() + 0.5 * p.y() * p.y(); };
  for (Shape s : {Shape::Tri6, Shape::Quad8})
    for (const auto& xi : samples(s)) {
      shape_functions(s, xi, N, dN);
      double v = 0;
      for (int a = 0; a < n_nodes(s); ++a) v += N(a) * f(reference_node(s, a));
      EXPECT_NEAR(v, f(xi), 1e-13);
    }
}

TEST(FaceShapeFunctions, PartitionKroneckerAndDerivatives) {
  Eigen::Vector3d N, dN, Np, Nm, d;
  const double nodes_s[3] = {-1, 1, 0};
  for (int nf : {2, 3}) {
    for (int b = 0; b < nf; ++b) {
      face_shape_functions(nf, nodes_s[b], N, dN);
      for (int a = 0; a < nf; ++a) EXPECT_NEAR(N(a), a == b ? 1.0 : 0.0, 1e-15);
    }
    for (double s : {-0.8, -0.1, 0.3, 0.77}) {
      face_shape_functions(nf, s, N, dN);
      EXPECT_NEAR(N.sum(), 1.0, 1e-15);
      face_shape_functions(nf, s + 1e-6, Np, d);
      face_shape_functions(nf, s - 1e-6, Nm, d);
      EXPECT_LT(((Np - Nm) / 2e-6 - dN).norm(), 1e-9);
    }
  }
}
