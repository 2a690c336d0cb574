#include "tether/fem/extrapolation.hpp"

#include <Eigen/LU>
#include <array>
#include <stdexcept>

#include "tether/fem/shape_functions.hpp"

namespace tether {

namespace {

/// Fitting basis with as many terms as the rule has points.
Eigen::RowVectorXd fit_basis(QuadratureRule rule, const Eigen::Vector2d& xi) {
  const double r = xi.x(), s = xi.y();
  Eigen::RowVectorXd b;
  switch (rule) {
    case QuadratureRule::Triangle1: b.resize(1); b << 1; break;
    case QuadratureRule::Triangle3: b.resize(3); b << 1, r, s; break;
    case QuadratureRule::Quad2x2: b.resize(4); b << 1, r, s, r * s; break;
    case QuadratureRule::Quad3x3: {
      b.resize(9);
      const double pr[3] = {1, r, r * r}, ps[3] = {1, s, s * s};
      for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) b(3 * j + i) = pr[i] * ps[j];
      break;
    }
  }
  return b;
}

Eigen::MatrixXd build(Shape shape, QuadratureRule rule) {
  const auto pts = quadrature_points(rule);
  const int np = static_cast<int>(pts.size());
  Eigen::MatrixXd P(np, np);
  for (int q = 0; q < np; ++q) P.row(q) = fit_basis(rule, pts[q].xi);
  const int nn = n_nodes(shape);
  Eigen::MatrixXd at_nodes(nn, np);
  for (int a = 0; a < nn; ++a) at_nodes.row(a) = fit_basis(rule, reference_node(shape, a));
  return at_nodes * P.inverse();
}

int rule_index(QuadratureRule rule) { return static_cast<int>(rule); }
int shape_index(Shape shape) { return static_cast<int>(shape); }

}  // namespace

const Eigen::MatrixXd& extrapolation_matrix(Shape shape, QuadratureRule rule) {
  static const auto table = [] {
    std::array<std::array<Eigen::MatrixXd, 4>, 4> t;
    for (Shape sh : {Shape::Tri3, Shape::Quad4, Shape::Tri6, Shape::Quad8})
      for (QuadratureRule ru : {QuadratureRule::Triangle1, QuadratureRule::Triangle3,
                                QuadratureRule::Quad2x2, QuadratureRule::Quad3x3}) {
        const bool tri_shape = sh == Shape::Tri3 || sh == Shape::Tri6;
        if (tri_shape == (rule_shape(ru) == Shape::Tri3))
          t[shape_index(sh)][rule_index(ru)] = build(sh, ru);
      }
    return t;
  }();
  const Eigen::MatrixXd& e = table[shape_index(shape)][rule_index(rule)];
  if (e.size() == 0) throw std::invalid_argument("extrapolation_matrix: rule does not match the shape");
  return e;
}

}  // namespace tether
