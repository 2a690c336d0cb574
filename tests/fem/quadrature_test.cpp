#include <gtest/gtest.h>

#include <cmath>

#include "tether/fem/quadrature.hpp"

using namespace tether;

namespace {

/// Exact integral of x^i y^j over the unit triangle: i! j! / (i + j + 2)!.
double triangle_monomial(int i, int j) {
  return std::tgamma(i + 1) * std::tgamma(j + 1) / std::tgamma(i + j + 3);
}

/// Exact integral of x^i over [-1, 1].
double line_monomial(int i) { return i % 2 ? 0.0 : 2.0 / (i + 1); }

double integrate(QuadratureRule rule, int i, int j) {
  double sum = 0;
  for (const auto& p : quadrature_points(rule)) sum += p.weight * std::pow(p.xi.x(), i) * std::pow(p.xi.y(), j);
  return sum;
}

}  // namespace

TEST(Quadrature, TriangleRulesAreExactToTheirDegree) {
  for (auto [rule, degree] : {std::pair{QuadratureRule::Triangle1, 1}, {QuadratureRule::Triangle3, 2}})
    for (int i = 0; i <= degree; ++i)
      for (int j = 0; i + j <= degree; ++j)
        EXPECT_NEAR(integrate(rule, i, j), triangle_monomial(i, j), 1e-15) << i << " " << j;
  // And not beyond: the 3-point rule misses x^3.
  EXPECT_GT(std::abs(integrate(QuadratureRule::Triangle3, 3, 0) - triangle_monomial(3, 0)), 1e-4);
}

TEST(Quadrature, QuadRulesAreExactPerDirection) {
  for (auto [rule, degree] : {std::pair{QuadratureRule::Quad2x2, 3}, {QuadratureRule::Quad3x3, 5}})
    for (int i = 0; i <= degree; ++i)
      for (int j = 0; j <= degree; ++j)
        EXPECT_NEAR(integrate(rule, i, j), line_monomial(i) * line_monomial(j), 1e-14) << i << " " << j;
  EXPECT_GT(std::abs(integrate(QuadratureRule::Quad2x2, 4, 0) - line_monomial(4)), 1e-3);
}

TEST(Quadrature, LineRulesAreExact) {
  for (int n : {2, 3})
    for (int i = 0; i <= 2 * n - 1; ++i) {
      double sum = 0;
      for (const auto& p : line_points(n)) sum += p.weight * std::pow(p.s, i);
      EXPECT_NEAR(sum, line_monomial(i), 1e-15);
    }
}

TEST(Quadrature, AbaqusPointOrderAndElementRules) {
  const auto q4 = quadrature_points(QuadratureRule::Quad2x2);
  ASSERT_EQ(q4.size(), 4u);
  EXPECT_LT(q4[0].xi.x(), 0);  // xi varies fastest
  EXPECT_GT(q4[1].xi.x(), 0);
  EXPECT_LT(q4[1].xi.y(), 0);
  EXPECT_GT(q4[2].xi.y(), 0);
  const auto q9 = quadrature_points(QuadratureRule::Quad3x3);
  ASSERT_EQ(q9.size(), 9u);
  EXPECT_DOUBLE_EQ(q9[4].xi.x(), 0.0);
  EXPECT_DOUBLE_EQ(q9[4].weight, 64.0 / 81.0);
  EXPECT_LT(q9[2].xi.y(), 0);
  EXPECT_GT(q9[2].xi.x(), 0);
  const auto t3 = quadrature_points(QuadratureRule::Triangle3);
  EXPECT_DOUBLE_EQ(t3[1].xi.x(), 2.0 / 3.0);

  auto rule_of = [](const char* name) { return default_rule(*find_element_type(name)); };
  EXPECT_EQ(rule_of("CPE3"), QuadratureRule::Triangle1);
  EXPECT_EQ(rule_of("CAX4"), QuadratureRule::Quad2x2);
  EXPECT_EQ(rule_of("CPS6"), QuadratureRule::Triangle3);
  EXPECT_EQ(rule_of("CPE8"), QuadratureRule::Quad3x3);
  EXPECT_EQ(rule_of("CAX8R"), QuadratureRule::Quad2x2);
}
