// Body forces (*DLOAD GRAV, CENTRIF): the resultant force and moment of the
// nodal forces against integrals over the element, the centrifugal load
// stiffness under NLGEOM against finite differences, and which loads depend on u.
#include <gtest/gtest.h>

#include <numbers>

#include "element_fixtures.hpp"
#include "tether/elements/body_force.hpp"

using namespace tether;
using namespace tether::test;

namespace {

constexpr double kRho = 7.8e-3, kThickness = 0.5;

/// The reference element under x = A xi + shift: straight edges, mid-side
/// nodes at mid-sides, so its area and moments are known in closed form.
std::vector<Eigen::Vector2d> affine_element(Shape shape) {
  Eigen::Matrix2d A;
  A << 0.8, 0.3, -0.2, 0.9;
  std::vector<Eigen::Vector2d> x;
  for (int a = 0; a < n_nodes(shape); ++a) x.push_back(A * reference_node(shape, a) + Eigen::Vector2d(2.0, 0.5));
  return x;
}

/// Area, and integrals of x, y, x^2 and x y over a straight-sided element
/// (quadrilaterals as two triangles; exact formulas for triangles).
struct Moments {
  double area = 0, x = 0, y = 0, xx = 0, xy = 0;
};
Moments moments(Shape shape, const std::vector<Eigen::Vector2d>& x) {
  const auto triangle = [](const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& r) {
    Moments m;
    m.area = 0.5 * ((q - p).x() * (r - p).y() - (q - p).y() * (r - p).x());
    m.x = m.area * (p.x() + q.x() + r.x()) / 3;
    m.y = m.area * (p.y() + q.y() + r.y()) / 3;
    m.xx = m.area / 6 * (p.x() * p.x() + q.x() * q.x() + r.x() * r.x() + p.x() * q.x() + q.x() * r.x() + r.x() * p.x());
    m.xy = m.area / 12 * (2 * p.x() * p.y() + 2 * q.x() * q.y() + 2 * r.x() * r.y() + p.x() * q.y() + q.x() * p.y() +
                          q.x() * r.y() + r.x() * q.y() + r.x() * p.y() + p.x() * r.y());
    return m;
  };
  if (n_corners(shape) == 3) return triangle(x[0], x[1], x[2]);
  const Moments a = triangle(x[0], x[1], x[2]), b = triangle(x[0], x[2], x[3]);
  return {a.area + b.area, a.x + b.x, a.y + b.y, a.xx + b.xx, a.xy + b.xy};
}

BodyLoad gravity(Eigen::Vector3d direction) {
  BodyLoad b;
  b.direction = direction.normalized();
  return b;
}

BodyLoad centrifugal(const ElementType& type) {
  BodyLoad b;
  b.kind = BodyLoad::Kind::Centrifugal;
  const bool cax = type.family == Family::Axisymmetric;
  b.direction = cax ? Eigen::Vector3d(0, 1, 0) : Eigen::Vector3d(0, 0, 1);
  b.point = cax ? Eigen::Vector3d(0, 3, 0) : Eigen::Vector3d(0.4, -0.7, 2);
  return b;
}

std::unique_ptr<BodyForce> make(const ElementType& type, const std::vector<Eigen::Vector2d>& x, const BodyLoad& load,
                                const DofMap& dofs, double magnitude) {
  std::vector<int> nodes(x.size());
  for (std::size_t a = 0; a < x.size(); ++a) nodes[a] = static_cast<int>(a);
  auto f = std::make_unique<BodyForce>(7, type, nodes, x, kRho, kThickness, load, dofs);
  f->set_magnitude(magnitude);
  return f;
}

DofMap dof_map(std::size_t n) {
  std::vector<int> labels(n);
  for (std::size_t a = 0; a < n; ++a) labels[a] = static_cast<int>(a) + 1;
  return DofMap(labels);
}

}  // namespace

TEST(BodyForce, GravityResultantAndMomentAreThoseOfTheWeight) {
  for (const ElementType& type : supported_types()) {
    const auto x = affine_element(type.shape);
    const DofMap dofs = dof_map(x.size());
    const double g = 9.81;
    const Eigen::Vector3d dir(0.6, -0.8, 0);
    const auto force = make(type, x, gravity(dir), dofs, g);
    const Eigen::VectorXd f = force->nodal_forces(Eigen::VectorXd::Zero(dofs.n_dofs()), false);
    Eigen::Vector2d total = Eigen::Vector2d::Zero();
    double moment = 0;  // about the origin, z component
    for (std::size_t a = 0; a < x.size(); ++a) {
      const Eigen::Vector2d fa = f.segment<2>(static_cast<Eigen::Index>(2 * a));
      total += fa;
      moment += x[a].x() * fa.y() - x[a].y() * fa.x();
    }
    const Moments m = moments(type.shape, x);
    const bool cax = type.family == Family::Axisymmetric;
    // Plane: V = t A, first moments t (Sx, Sy). CAX: V = 2 pi int x dA, and the
    // moment density x b_y - y b_x weighted by 2 pi x.
    const double volume = cax ? 2 * std::numbers::pi * m.x : kThickness * m.area;
    const double mx = cax ? 2 * std::numbers::pi * m.xx : kThickness * m.x;
    const double my = cax ? 2 * std::numbers::pi * m.xy : kThickness * m.y;
    const Eigen::Vector2d weight = kRho * volume * g * dir.head<2>();
    EXPECT_NEAR((total - weight).norm(), 0, 1e-12 * weight.norm()) << type.name;
    const double exact_moment = kRho * g * (mx * dir.y() - my * dir.x());
    EXPECT_NEAR(moment, exact_moment, 1e-12 * std::abs(exact_moment)) << type.name;
  }
}

TEST(BodyForce, CentrifugalResultantIsMassTimesOmegaSquaredTimesCentroidDistance) {
  for (const ElementType& type : supported_types()) {
    const auto x = affine_element(type.shape);
    const DofMap dofs = dof_map(x.size());
    const double omega2 = 400;
    const BodyLoad load = centrifugal(type);
    const auto force = make(type, x, load, dofs, omega2);
    const Eigen::VectorXd f = force->nodal_forces(Eigen::VectorXd::Zero(dofs.n_dofs()), false);
    Eigen::Vector2d total = Eigen::Vector2d::Zero();
    for (std::size_t a = 0; a < x.size(); ++a) total += f.segment<2>(static_cast<Eigen::Index>(2 * a));
    const Moments m = moments(type.shape, x);
    Eigen::Vector2d exact;
    if (type.family == Family::Axisymmetric)  // b = omega^2 (r, 0), dV = 2 pi r dA
      exact = Eigen::Vector2d(kRho * omega2 * 2 * std::numbers::pi * m.xx, 0);
    else  // b = omega^2 (x - p) in the plane
      exact = kRho * omega2 * kThickness *
              Eigen::Vector2d(m.x - m.area * load.point.x(), m.y - m.area * load.point.y());
    EXPECT_NEAR((total - exact).norm(), 0, 1e-12 * exact.norm()) << type.name;
  }
}

TEST(BodyForce, OnlyCentrifugalLoadsUnderNlgeomDependOnTheDisplacements) {
  const ElementType type = *find_element_type("CPE4");
  const auto x = distorted_element(type.shape);
  const DofMap dofs = dof_map(x.size());
  const Eigen::VectorXd u = random_vector(dofs.n_dofs(), 0.05, 11);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(dofs.n_dofs());
  const auto g = make(type, x, gravity({0, -1, 0}), dofs, 9.81);
  const auto c = make(type, x, centrifugal(type), dofs, 100);
  for (bool nlgeom : {false, true}) {
    EXPECT_TRUE(g->linear_in_u(nlgeom));
    EXPECT_EQ((g->nodal_forces(u, nlgeom) - g->nodal_forces(zero, nlgeom)).norm(), 0);
  }
  EXPECT_TRUE(c->linear_in_u(false));
  EXPECT_FALSE(c->linear_in_u(true));
  EXPECT_EQ((c->nodal_forces(u, false) - c->nodal_forces(zero, false)).norm(), 0);
  EXPECT_GT((c->nodal_forces(u, true) - c->nodal_forces(zero, true)).norm(), 1e-6);
  // The residual is the negated nodal force.
  const LocalSystem s = evaluate_at(*c, u, true);
  EXPECT_NEAR((s.residual + c->nodal_forces(u, true)).norm(), 0, 1e-15);
}

TEST(BodyForce, CentrifugalLoadStiffnessUnderNlgeomMatchesFiniteDifferences) {
  for (const ElementType& type : supported_types()) {
    const auto x = distorted_element(type.shape);
    const DofMap dofs = dof_map(x.size());
    const auto c = make(type, x, centrifugal(type), dofs, 250);
    const Eigen::VectorXd u = random_vector(dofs.n_dofs(), 0.05, 5);
    const LocalSystem s = evaluate_at(*c, u, true);
    const Eigen::MatrixXd fd = fd_tangent(*c, u, true, 1e-6);
    EXPECT_LT((s.tangent - fd).cwiseAbs().maxCoeff(), 1e-7 * s.tangent.cwiseAbs().maxCoeff()) << type.name;
    EXPECT_LT((s.tangent - s.tangent.transpose()).cwiseAbs().maxCoeff(), 1e-14 * s.tangent.cwiseAbs().maxCoeff());
    EXPECT_GT(s.tangent.cwiseAbs().maxCoeff(), 0) << type.name;
    const LocalSystem small = evaluate_at(*c, u, false);
    EXPECT_EQ(small.tangent.cwiseAbs().maxCoeff(), 0) << type.name;
  }
}

TEST(BodyForce, DescribesItselfAndRefusesAMissingDensity) {
  const ElementType type = *find_element_type("CPS4");
  const auto x = affine_element(type.shape);
  const DofMap dofs = dof_map(x.size());
  EXPECT_EQ(make(type, x, gravity({0, -1, 0}), dofs, 1)->describe(), "gravity on element 7 (CPS4)");
  EXPECT_EQ(make(type, x, centrifugal(type), dofs, 1)->describe(), "centrifugal load on element 7 (CPS4)");
  std::vector<int> nodes{0, 1, 2, 3};
  try {
    BodyForce bad(7, type, nodes, x, 0.0, kThickness, gravity({0, -1, 0}), dofs);
    ADD_FAILURE() << "a zero density was accepted";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("gravity on element 7 (CPS4)"), std::string::npos) << e.what();
  }
}
