#include "tether/fem/shape_functions.hpp"

#include <cassert>

namespace tether {

int n_nodes(Shape shape) {
  switch (shape) {
    case Shape::Tri3: return 3;
    case Shape::Quad4: return 4;
    case Shape::Tri6: return 6;
    case Shape::Quad8: return 8;
  }
  return 0;
}

namespace {

void tri3(double r, double s, ShapeVector& N, ShapeGradient& dN) {
  N << 1 - r - s, r, s;
  dN << -1, -1, 1, 0, 0, 1;
}

void quad4(double r, double s, ShapeVector& N, ShapeGradient& dN) {
  static constexpr double xa[4] = {-1, 1, 1, -1};
  static constexpr double ya[4] = {-1, -1, 1, 1};
  for (int a = 0; a < 4; ++a) {
    N(a) = 0.25 * (1 + xa[a] * r) * (1 + ya[a] * s);
    dN(a, 0) = 0.25 * xa[a] * (1 + ya[a] * s);
    dN(a, 1) = 0.25 * ya[a] * (1 + xa[a] * r);
  }
}

void tri6(double r, double s, ShapeVector& N, ShapeGradient& dN) {
  const double t = 1 - r - s;
  N << t * (2 * t - 1), r * (2 * r - 1), s * (2 * s - 1), 4 * r * t, 4 * r * s, 4 * s * t;
  // dt/dr = dt/ds = -1
  dN << -(4 * t - 1), -(4 * t - 1),  //
      4 * r - 1, 0,                   //
      0, 4 * s - 1,                   //
      4 * (t - r), -4 * r,            //
      4 * s, 4 * r,                   //
      -4 * s, 4 * (t - s);
}

void quad8(double r, double s, ShapeVector& N, ShapeGradient& dN) {
  static constexpr double xa[4] = {-1, 1, 1, -1};
  static constexpr double ya[4] = {-1, -1, 1, 1};
  for (int a = 0; a < 4; ++a) {
    const double rr = xa[a] * r, ss = ya[a] * s;
    N(a) = 0.25 * (1 + rr) * (1 + ss) * (rr + ss - 1);
    dN(a, 0) = 0.25 * xa[a] * (1 + ss) * (2 * rr + ss);
    dN(a, 1) = 0.25 * ya[a] * (1 + rr) * (rr + 2 * ss);
  }
  // Mid-side nodes 5..8 on edges 1-2 (eta=-1), 2-3 (xi=1), 3-4 (eta=1), 4-1 (xi=-1).
  N(4) = 0.5 * (1 - r * r) * (1 - s);
  dN(4, 0) = -r * (1 - s);
  dN(4, 1) = -0.5 * (1 - r * r);
  N(5) = 0.5 * (1 + r) * (1 - s * s);
  dN(5, 0) = 0.5 * (1 - s * s);
  dN(5, 1) = -s * (1 + r);
  N(6) = 0.5 * (1 - r * r) * (1 + s);
  dN(6, 0) = -r * (1 + s);
  dN(6, 1) = 0.5 * (1 - r * r);
  N(7) = 0.5 * (1 - r) * (1 - s * s);
  dN(7, 0) = -0.5 * (1 - s * s);
  dN(7, 1) = -s * (1 - r);
}

}  // namespace

void shape_functions(Shape shape, const Eigen::Vector2d& xi, ShapeVector& N, ShapeGradient& dN) {
  const int n = n_nodes(shape);
  N.resize(n);
  dN.resize(n, 2);
  switch (shape) {
    case Shape::Tri3: tri3(xi.x(), xi.y(), N, dN); break;
    case Shape::Quad4: quad4(xi.x(), xi.y(), N, dN); break;
    case Shape::Tri6: tri6(xi.x(), xi.y(), N, dN); break;
    case Shape::Quad8: quad8(xi.x(), xi.y(), N, dN); break;
  }
}

Eigen::Vector2d reference_node(Shape shape, int node) {
  assert(node >= 0 && node < n_nodes(shape));
  static const Eigen::Vector2d tri[6] = {{0, 0}, {1, 0}, {0, 1}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}};
  static const Eigen::Vector2d quad[8] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1},
                                          {0, -1},  {1, 0},  {0, 1}, {-1, 0}};
  return (shape == Shape::Tri3 || shape == Shape::Tri6) ? tri[node] : quad[node];
}

void face_shape_functions(int n_face_nodes, double s, Eigen::Vector3d& N, Eigen::Vector3d& dN) {
  assert(n_face_nodes == 2 || n_face_nodes == 3);
  if (n_face_nodes == 2) {
    N << 0.5 * (1 - s), 0.5 * (1 + s), 0;
    dN << -0.5, 0.5, 0;
  } else {
    N << 0.5 * s * (s - 1), 0.5 * s * (s + 1), 1 - s * s;
    dN << s - 0.5, s + 0.5, -2 * s;
  }
}

TabulatedShapes tabulate_shapes(Shape shape, std::span<const QuadraturePoint> points) {
  TabulatedShapes t;
  for (const QuadraturePoint& p : points) {
    ShapeVector N;
    ShapeGradient dN;
    shape_functions(shape, p.xi, N, dN);
    t.N.push_back(N);
    t.dN.push_back(dN);
    t.weight.push_back(p.weight);
  }
  return t;
}

}  // namespace tether
