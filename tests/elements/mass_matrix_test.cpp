// Integration rules of the element mass (fem/quadrature.hpp: gauss_legendre,
// exact_rule): exact on monomials up to their degree, and not beyond.
#include <gtest/gtest.h>

#include <cmath>

#include "tether/fem/quadrature.hpp"

using namespace tether;

namespace {

/// Exact integral of xi^i eta^j over the unit triangle: i! j! / (i + j + 2)!.
double triangle_monomial(int i, int j) { return std::tgamma(i + 1) * std::tgamma(j + 1) / std::tgamma(i + j + 3); }
/// Exact integral of s^i over [-1, 1].
double line_monomial(int i) { return i % 2 ? 0.0 : 2.0 / (i + 1); }

double integrate(const std::vector<QuadraturePoint>& rule, int i, int j) {
  double sum = 0;
  for (const auto& p : rule) sum += p.weight * std::pow(p.xi.x(), i) * std::pow(p.xi.y(), j);
  return sum;
}

}  // namespace

TEST(MassQuadrature, GaussLegendreAndExactRulesIntegrateTheirDegree) {
  // Tabulated 5-point Gauss-Legendre (Abramowitz & Stegun 25.4.30).
  const auto g5 = gauss_legendre(5);
  ASSERT_EQ(g5.size(), 5u);
  EXPECT_NEAR(g5[4].s, 0.906179845938663992797627, 1e-15);
  EXPECT_NEAR(g5[4].weight, 0.236926885056189087514264, 1e-15);
  EXPECT_NEAR(g5[3].s, 0.538469310105683091036314, 1e-15);
  EXPECT_NEAR(g5[2].weight, 128.0 / 225.0, 1e-15);
  for (int n = 1; n <= 8; ++n) {
    const auto g = gauss_legendre(n);
    for (int i = 0; i <= 2 * n - 1; ++i) {
      double sum = 0;
      for (const auto& p : g) sum += p.weight * std::pow(p.s, i);
      EXPECT_NEAR(sum, line_monomial(i), 1e-14) << n << " points, s^" << i;
    }
  }
  for (int degree = 0; degree <= 10; ++degree) {
    const auto tri = exact_rule(Shape::Tri3, degree);
    const auto quad = exact_rule(Shape::Quad8, degree);
    for (int i = 0; i <= degree; ++i)
      for (int j = 0; j <= degree; ++j) {
        if (i + j <= degree) EXPECT_NEAR(integrate(tri, i, j), triangle_monomial(i, j), 1e-15) << degree;
        EXPECT_NEAR(integrate(quad, i, j), line_monomial(i) * line_monomial(j), 1e-14) << degree;
      }
    for (const auto& p : tri) EXPECT_TRUE(p.xi.x() > 0 && p.xi.y() > 0 && p.xi.x() + p.xi.y() < 1);
  }
  // And not beyond what the point counts give: the square rule of degree 4
  // (3x3) misses xi^6, the triangle rule of degree 3 (3x2 points) misses eta^4.
  EXPECT_GT(std::abs(integrate(exact_rule(Shape::Quad4, 4), 6, 0) - line_monomial(6)), 1e-3);
  EXPECT_GT(std::abs(integrate(exact_rule(Shape::Tri3, 3), 0, 4) - triangle_monomial(0, 4)), 1e-5);
}
