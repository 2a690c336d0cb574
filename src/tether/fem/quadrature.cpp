#include "tether/fem/quadrature.hpp"

#include <array>
#include <cassert>
#include <cmath>
#include <numbers>

namespace tether {

namespace {

const double kG2 = 1.0 / std::sqrt(3.0);
const double kG3 = std::sqrt(0.6);

const QuadraturePoint kTriangle1[] = {{{1.0 / 3.0, 1.0 / 3.0}, 0.5}};
const QuadraturePoint kTriangle3[] = {{{1.0 / 6.0, 1.0 / 6.0}, 1.0 / 6.0},
                                      {{2.0 / 3.0, 1.0 / 6.0}, 1.0 / 6.0},
                                      {{1.0 / 6.0, 2.0 / 3.0}, 1.0 / 6.0}};
const QuadraturePoint kQuad2x2[] = {
    {{-kG2, -kG2}, 1.0}, {{kG2, -kG2}, 1.0}, {{-kG2, kG2}, 1.0}, {{kG2, kG2}, 1.0}};

const LinePoint kLine2[] = {{-kG2, 1.0}, {kG2, 1.0}};
const LinePoint kLine3[] = {{-kG3, 5.0 / 9.0}, {0.0, 8.0 / 9.0}, {kG3, 5.0 / 9.0}};

std::array<QuadraturePoint, 9> make_quad3x3() {
  std::array<QuadraturePoint, 9> pts{};
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      pts[3 * j + i] = {{kLine3[i].s, kLine3[j].s}, kLine3[i].weight * kLine3[j].weight};
  return pts;
}

const std::array<QuadraturePoint, 9> kQuad3x3 = make_quad3x3();

}  // namespace

std::span<const QuadraturePoint> quadrature_points(QuadratureRule rule) {
  switch (rule) {
    case QuadratureRule::Triangle1: return kTriangle1;
    case QuadratureRule::Triangle3: return kTriangle3;
    case QuadratureRule::Quad2x2: return kQuad2x2;
    case QuadratureRule::Quad3x3: return kQuad3x3;
  }
  return {};
}

Shape rule_shape(QuadratureRule rule) {
  return (rule == QuadratureRule::Triangle1 || rule == QuadratureRule::Triangle3) ? Shape::Tri3
                                                                                  : Shape::Quad4;
}

QuadratureRule default_rule(const ElementType& type) {
  switch (type.shape) {
    case Shape::Tri3: return QuadratureRule::Triangle1;
    case Shape::Quad4: return QuadratureRule::Quad2x2;
    case Shape::Tri6: return QuadratureRule::Triangle3;
    case Shape::Quad8: return type.reduced ? QuadratureRule::Quad2x2 : QuadratureRule::Quad3x3;
  }
  return QuadratureRule::Quad2x2;
}

std::span<const LinePoint> line_points(int n_points) {
  assert(n_points == 2 || n_points == 3);
  if (n_points == 2) return kLine2;
  return kLine3;
}

std::vector<LinePoint> gauss_legendre(int n_points) {
  assert(n_points >= 1 && n_points <= 20);
  const int n = n_points;
  std::vector<LinePoint> out(static_cast<std::size_t>(n));
  for (int i = 0; i < (n + 1) / 2; ++i) {
    // Newton on P_n from the usual asymptotic guess of the i-th largest root.
    double z = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double dp = 1;
    for (int it = 0; it < 100; ++it) {
      double p1 = 1, p0 = 0;  // P_j and P_{j-1} at z
      for (int j = 1; j <= n; ++j) {
        const double p_prev = p0;
        p0 = p1;
        p1 = ((2 * j - 1) * z * p0 - (j - 1) * p_prev) / j;
      }
      dp = n * (z * p1 - p0) / (z * z - 1);  // P_n'(z)
      const double step = p1 / dp;
      z -= step;
      if (std::abs(step) < 1e-16) break;
    }
    const double w = 2 / ((1 - z * z) * dp * dp);
    out[static_cast<std::size_t>(i)] = {-z, w};
    out[static_cast<std::size_t>(n - 1 - i)] = {z, w};
  }
  if (n % 2 == 1) out[static_cast<std::size_t>(n / 2)].s = 0;  // exact middle point
  return out;
}

std::vector<QuadraturePoint> exact_rule(Shape shape, int degree) {
  assert(degree >= 0 && degree <= 37);
  std::vector<QuadraturePoint> out;
  if (shape == Shape::Quad4 || shape == Shape::Quad8) {
    const auto g = gauss_legendre((degree + 2) / 2);
    for (const LinePoint& pe : g)
      for (const LinePoint& px : g) out.push_back({{px.s, pe.s}, px.weight * pe.weight});
    return out;
  }
  // Triangle: (s, t) in [-1,1]^2 -> u = (1+s)/2, v = (1+t)/2; xi = u, eta = v (1-u);
  // d xi d eta = (1-u) du dv = (1-u)/4 ds dt.
  const auto gu = gauss_legendre((degree + 3) / 2);
  const auto gv = gauss_legendre((degree + 2) / 2);
  for (const LinePoint& pv : gv)
    for (const LinePoint& pu : gu) {
      const double u = 0.5 * (1 + pu.s), v = 0.5 * (1 + pv.s);
      out.push_back({{u, v * (1 - u)}, 0.25 * pu.weight * pv.weight * (1 - u)});
    }
  return out;
}

}  // namespace tether
