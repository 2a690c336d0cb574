#include "tether/fem/quadrature.hpp"

#include <array>
#include <cassert>
#include <cmath>

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

}  // namespace tether
