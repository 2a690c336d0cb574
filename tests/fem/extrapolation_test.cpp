#include <gtest/gtest.h>

#include "tether/fem/extrapolation.hpp"
#include "tether/fem/shape_functions.hpp"

using namespace tether;

namespace {

double linear(const Eigen::Vector2d& p) { return 0.7 - 1.3 * p.x() + 2.1 * p.y(); }

}  // namespace

TEST(Extrapolation, ReproducesLinearFieldsForEveryShapeAndRule) {
  const std::pair<Shape, QuadratureRule> cases[] = {
      {Shape::Tri3, QuadratureRule::Triangle1}, {Shape::Tri6, QuadratureRule::Triangle3},
      {Shape::Quad4, QuadratureRule::Quad2x2},  {Shape::Quad8, QuadratureRule::Quad2x2},
      {Shape::Quad8, QuadratureRule::Quad3x3}, {Shape::Tri6, QuadratureRule::Triangle1}};
  for (auto [shape, rule] : cases) {
    const Eigen::MatrixXd& E = extrapolation_matrix(shape, rule);
    const auto pts = quadrature_points(rule);
    ASSERT_EQ(E.rows(), n_nodes(shape));
    ASSERT_EQ(E.cols(), static_cast<Eigen::Index>(pts.size()));
    // Every row sums to one: constants are reproduced.
    for (int a = 0; a < E.rows(); ++a) EXPECT_NEAR(E.row(a).sum(), 1.0, 1e-13);
    if (rule == QuadratureRule::Triangle1) continue;  // one point reproduces constants only
    Eigen::VectorXd values(pts.size());
    for (std::size_t q = 0; q < pts.size(); ++q) values(q) = linear(pts[q].xi);
    const Eigen::VectorXd nodal = E * values;
    for (int a = 0; a < n_nodes(shape); ++a)
      EXPECT_NEAR(nodal(a), linear(reference_node(shape, a)), 1e-13) << "shape " << static_cast<int>(shape) << " node " << a;
  }
}

TEST(Extrapolation, QuadraticFieldIsReproducedBy3x3) {
  auto f = [](const Eigen::Vector2d& p) { return p.x() * p.x() - 2 * p.x() * p.y() + 0.3 * p.y() * p.y() * p.x(); };
  const Eigen::MatrixXd& E = extrapolation_matrix(Shape::Quad8, QuadratureRule::Quad3x3);
  const auto pts = quadrature_points(QuadratureRule::Quad3x3);
  Eigen::VectorXd values(9);
  for (int q = 0; q < 9; ++q) values(q) = f(pts[q].xi);
  const Eigen::VectorXd nodal = E * values;
  for (int a = 0; a < 8; ++a) EXPECT_NEAR(nodal(a), f(reference_node(Shape::Quad8, a)), 1e-12);
}

TEST(Extrapolation, MismatchedRuleIsRefused) {
  EXPECT_THROW(extrapolation_matrix(Shape::Tri3, QuadratureRule::Quad2x2), std::invalid_argument);
}
