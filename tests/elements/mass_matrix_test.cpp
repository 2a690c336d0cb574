// Element mass (elements/mass_matrix.*, ContinuumElement::mass): the rules it
// integrates with, exact totals against geometry computed independently
// (polygon formulas for straight-sided elements, Green's theorem along the
// quadratic edges of curved ones), textbook matrices, positivity of every
// lumped mass, kinetic energies of rigid motions, and the natural frequencies
// of single free elements against closed forms.
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <numeric>

#include "element_fixtures.hpp"
#include "tether/analysis/discretization.hpp"
#include "tether/elements/continuum_element.hpp"
#include "tether/elements/mass_matrix.hpp"
#include "tether/io/deck_reader.hpp"

using namespace tether;
using namespace tether::test;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kRho = 7.8;
constexpr double kThickness = 0.5;

bool is_axisymmetric(const ElementType& t) { return t.family == Family::Axisymmetric; }
bool is_linear(Shape s) { return s == Shape::Tri3 || s == Shape::Quad4; }

/// distorted_element() with the mid-side nodes moved to the midpoints of their
/// edges: straight sides (a polygon), corners still jittered.
std::vector<Eigen::Vector2d> straight_sided(Shape shape, unsigned seed) {
  std::vector<Eigen::Vector2d> x = distorted_element(shape, seed);
  for (int f = 0; f < n_faces(shape); ++f) {
    const auto fn = face_nodes(shape, f);
    if (fn[2] >= 0) x[fn[2]] = 0.5 * (x[fn[0]] + x[fn[1]]);
  }
  return x;
}

/// Integrals over a region: area and the moments of x, x^2, y, y^2.
struct Moments {
  double area = 0, x = 0, xx = 0, y = 0, yy = 0;
};

/// Polygon formulas over the corners (counter-clockwise):
/// A = 1/2 sum c_i, int x = 1/6 sum (x_i + x_j) c_i, int x^2 = 1/12 sum (x_i^2 + x_i x_j + x_j^2) c_i,
/// c_i = x_i y_j - x_j y_i, j = i + 1.
Moments polygon_moments(const std::vector<Eigen::Vector2d>& x, int n_corners) {
  Moments m;
  for (int i = 0; i < n_corners; ++i) {
    const Eigen::Vector2d& p = x[i];
    const Eigen::Vector2d& q = x[(i + 1) % n_corners];
    const double c = p.x() * q.y() - q.x() * p.y();
    m.area += c / 2;
    m.x += (p.x() + q.x()) * c / 6;
    m.y += (p.y() + q.y()) * c / 6;
    m.xx += (p.x() * p.x() + p.x() * q.x() + q.x() * q.x()) * c / 12;
    m.yy += (p.y() * p.y() + p.y() * q.y() + q.y() * q.y()) * c / 12;
  }
  return m;
}

/// Area and int x dA of an element with quadratic (possibly curved) edges by
/// Green's theorem: A = oint x dy, int x dA = oint x^2/2 dy, each edge
/// x(s) = s(s-1)/2 x1 + s(s+1)/2 x2 + (1-s^2) xm, 3-point Gauss on [-1,1]
/// (the integrands have degree <= 5).
Moments boundary_moments(Shape shape, const std::vector<Eigen::Vector2d>& x) {
  const double g = std::sqrt(0.6);
  const double s_pts[3] = {-g, 0, g}, w[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
  Moments m;
  for (int f = 0; f < n_faces(shape); ++f) {
    const auto fn = face_nodes(shape, f);
    const Eigen::Vector2d &a = x[fn[0]], &b = x[fn[1]], &c = x[fn[2]];
    for (int k = 0; k < 3; ++k) {
      const double s = s_pts[k];
      const Eigen::Vector2d p = s * (s - 1) / 2 * a + s * (s + 1) / 2 * b + (1 - s * s) * c;
      const Eigen::Vector2d dp = (s - 0.5) * a + (s + 0.5) * b - 2 * s * c;
      m.area += w[k] * p.x() * dp.y();
      m.x += w[k] * 0.5 * p.x() * p.x() * dp.y();
    }
  }
  return m;
}

/// Exact mass of a region with moments m: rho t A (plane) or rho 2 pi int r dA.
double exact_mass(const ElementType& type, const Moments& m) {
  return is_axisymmetric(type) ? kRho * 2 * kPi * m.x : kRho * kThickness * m.area;
}

/// Exact integral of xi^i eta^j over the unit triangle: i! j! / (i + j + 2)!.
double triangle_monomial(int i, int j) { return std::tgamma(i + 1) * std::tgamma(j + 1) / std::tgamma(i + j + 3); }
/// Exact integral of s^i over [-1, 1].
double line_monomial(int i) { return i % 2 ? 0.0 : 2.0 / (i + 1); }

double integrate(const std::vector<QuadraturePoint>& rule, int i, int j) {
  double sum = 0;
  for (const auto& p : rule) sum += p.weight * std::pow(p.xi.x(), i) * std::pow(p.xi.y(), j);
  return sum;
}

/// One element over nodes 0..n-1 of its own DofMap.
struct OneElement {
  DofMap dofs;
  LinearElastic steel{210.0, 0.3};
  MaterialData data;
  std::vector<Eigen::Vector2d> coords;  ///< the mesh's coordinate table (the element's nodes only)
  std::unique_ptr<ContinuumElement> element;
  OneElement(const ElementType& type, std::vector<Eigen::Vector2d> X, double thickness = kThickness)
      : dofs(std::vector<int>(X.size(), 0)), coords(std::move(X)) {
    data.name = "STEEL";
    data.density = kRho;
    data.where = {"deck.inp", 12};
    std::vector<int> nodes(coords.size());
    std::iota(nodes.begin(), nodes.end(), 0);
    element = std::make_unique<ContinuumElement>(5, type, nodes, coords, steel, thickness, dofs, &data);
  }
  [[nodiscard]] Eigen::MatrixXd mass(MassKind kind) const {
    Eigen::MatrixXd M;
    element->mass(kind, M);
    return M;
  }
  /// Small-strain tangent at u = 0.
  [[nodiscard]] Eigen::MatrixXd stiffness() const {
    return evaluate_at(*element, Eigen::VectorXd::Zero(dofs.n_dofs()), false).tangent;
  }
};

/// Generalized eigenvalues omega^2 of K phi = omega^2 M phi, ascending.
Eigen::VectorXd omega_squared(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M) {
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(K, M, Eigen::EigenvaluesOnly);
  EXPECT_EQ(solver.info(), Eigen::Success);
  return solver.eigenvalues();
}

const MassKind kKinds[] = {MassKind::Consistent, MassKind::Lumped};
const char* kind_name(MassKind k) { return k == MassKind::Consistent ? "consistent" : "lumped"; }

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
  // The mass rules: point counts documented in mass_matrix.hpp.
  EXPECT_EQ(mass_rule(Shape::Tri3, false).size(), 4u);
  EXPECT_EQ(mass_rule(Shape::Tri3, true).size(), 6u);
  EXPECT_EQ(mass_rule(Shape::Quad4, true).size(), 9u);
  EXPECT_EQ(mass_rule(Shape::Tri6, true).size(), 25u);
  EXPECT_EQ(mass_rule(Shape::Quad8, false).size(), 16u);
  EXPECT_EQ(mass_rule(Shape::Quad8, true).size(), 25u);
}

TEST(MassMatrix, TotalMassIsExactOnStraightSidedDistortedElements) {
  // Straight-sided (mid-side nodes at edge midpoints) so that the polygon
  // formulas give the exact area and int r dA independently.
  double worst = 0;
  int checked = 0;
  for (const ElementType& type : supported_types())
    for (unsigned seed : {1u, 2u, 3u, 4u}) {
      const auto X = straight_sided(type.shape, seed);
      const double exact = exact_mass(type, polygon_moments(X, n_corners(type.shape)));
      const double consistent = consistent_mass(type, X, kRho, kThickness).sum();
      const double lumped = lumped_mass(type, X, kRho, kThickness).sum();
      for (double m : {consistent, lumped}) {
        EXPECT_NEAR(m, exact, 1e-13 * exact) << type.name << " seed " << seed;
        worst = std::max(worst, std::abs(m - exact) / exact);
      }
      ++checked;
    }
  EXPECT_EQ(checked, 17 * 4);
  std::printf("[ figures  ] straight-sided totals: largest relative error %.2e\n", worst);
}

TEST(MassMatrix, TotalMassIsExactOnCurvedQuadraticElements) {
  // distorted_element() jitters the mid-side nodes: curved edges. Reference
  // by Green's theorem along the quadratic edges.
  double worst = 0;
  for (const ElementType& type : supported_types()) {
    if (is_linear(type.shape)) continue;
    for (unsigned seed : {1u, 2u, 3u, 4u}) {
      const auto X = distorted_element(type.shape, seed);
      const double exact = exact_mass(type, boundary_moments(type.shape, X));
      const double straight = exact_mass(type, polygon_moments(X, n_corners(type.shape)));
      ASSERT_GT(std::abs(exact - straight), 1e-4 * exact) << "edges not curved: the test would prove nothing";
      const double consistent = consistent_mass(type, X, kRho, kThickness).sum();
      const double lumped = lumped_mass(type, X, kRho, kThickness).sum();
      for (double m : {consistent, lumped}) {
        EXPECT_NEAR(m, exact, 1e-13 * exact) << type.name << " seed " << seed;
        worst = std::max(worst, std::abs(m - exact) / exact);
      }
    }
  }
  std::printf("[ figures  ] curved totals: largest relative error %.2e\n", worst);
}

TEST(MassMatrix, TextbookMatricesOfUndistortedElements) {
  const ElementType cpe3 = *find_element_type("CPE3"), cpe4 = *find_element_type("CPE4");
  const ElementType cpe6 = *find_element_type("CPE6"), cpe8 = *find_element_type("CPE8");
  const ElementType cax3 = *find_element_type("CAX3");
  const std::vector<Eigen::Vector2d> tri = {{1, 0.5}, {3, 0.2}, {1.5, 2}};
  const std::vector<Eigen::Vector2d> rect = {{1, 1}, {4, 1}, {4, 3}, {1, 3}};
  const double A_tri = polygon_moments(tri, 3).area, A_rect = 6.0;

  // CPE3: rho t A / 12 [2 1 1; 1 2 1; 1 1 2].
  Eigen::Matrix3d m3 = Eigen::Matrix3d::Constant(1) + Eigen::Matrix3d::Identity();
  EXPECT_LT(max_abs(consistent_mass(cpe3, tri, kRho, kThickness) - kRho * kThickness * A_tri / 12 * m3), 1e-13);
  // CPE4 rectangle: rho t A / 36 [4 2 1 2; 2 4 2 1; 1 2 4 2; 2 1 2 4].
  Eigen::Matrix4d m4;
  m4 << 4, 2, 1, 2, 2, 4, 2, 1, 1, 2, 4, 2, 2, 1, 2, 4;
  EXPECT_LT(max_abs(consistent_mass(cpe4, rect, kRho, kThickness) - kRho * kThickness * A_rect / 36 * m4), 1e-13);

  // HRZ fractions of the element mass (Hinton, Rock & Zienkiewicz 1976; the
  // consistent diagonals 6/180 and 32/180 of A for Tri6, 6/180 and 32/180 of
  // the square's area for Quad8, integrated by hand): Tri6 corners 3/57,
  // mid-sides 16/57; Quad8 corners 3/76, mid-sides 16/76.
  auto midpoints = [](std::vector<Eigen::Vector2d> x, Shape s) {
    for (int f = 0; f < n_faces(s); ++f) {
      const auto fn = face_nodes(s, f);
      x.push_back(0.5 * (x[fn[0]] + x[fn[1]]));
    }
    return x;
  };
  const Eigen::VectorXd l6 = lumped_mass(cpe6, midpoints(tri, Shape::Tri6), kRho, kThickness);
  const Eigen::VectorXd l8 = lumped_mass(cpe8, midpoints(rect, Shape::Quad8), kRho, kThickness);
  const double m_tri = kRho * kThickness * A_tri, m_rect = kRho * kThickness * A_rect;
  for (int a = 0; a < 6; ++a) EXPECT_NEAR(l6(a), m_tri * (a < 3 ? 3.0 : 16.0) / 57, 1e-13) << a;
  for (int a = 0; a < 8; ++a) EXPECT_NEAR(l8(a), m_rect * (a < 4 ? 3.0 : 16.0) / 76, 1e-13) << a;
  // Why HRZ: the row sum gives Tri6 corners zero and Quad8 corners negative mass.
  const Eigen::VectorXd row6 = consistent_mass(cpe6, midpoints(tri, Shape::Tri6), kRho, kThickness).rowwise().sum();
  const Eigen::VectorXd row8 = consistent_mass(cpe8, midpoints(rect, Shape::Quad8), kRho, kThickness).rowwise().sum();
  EXPECT_NEAR(row6(0), 0.0, 1e-13);
  EXPECT_NEAR(row8(0), -m_rect / 12, 1e-13);

  // CAX3: M_ab = 2 pi rho sum_k r_k int L_a L_b L_k dA with the barycentric
  // formula int L1^p L2^q L3^s dA = 2A p! q! s! / (p+q+s+2)!.
  Eigen::Matrix3d expected = Eigen::Matrix3d::Zero();
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      for (int k = 0; k < 3; ++k) {
        int power[3] = {0, 0, 0};
        ++power[a], ++power[b], ++power[k];
        double f = 2 * A_tri / 120.0;  // (p + q + s + 2)! = 5!
        for (int p : power) f *= std::tgamma(p + 1);
        expected(a, b) += 2 * kPi * kRho * tri[k].x() * f;
      }
  EXPECT_LT(max_abs(consistent_mass(cax3, tri, kRho, kThickness) - expected), 1e-12 * max_abs(expected));
}

TEST(MassMatrix, ConsistentIsSymmetricPositiveDefiniteAndLumpedMassesArePositive) {
  // Straight and curved distorted elements, plus a long thin one of each shape.
  for (const ElementType& type : supported_types()) {
    std::vector<std::vector<Eigen::Vector2d>> elements;
    for (unsigned seed : {1u, 2u, 3u, 4u, 5u}) {
      elements.push_back(distorted_element(type.shape, seed));
      elements.push_back(straight_sided(type.shape, seed));
    }
    std::vector<Eigen::Vector2d> thin = type.shape == Shape::Tri3 || type.shape == Shape::Tri6
                                            ? std::vector<Eigen::Vector2d>{{1, 0}, {6, 0}, {3.5, 0.2}}
                                            : std::vector<Eigen::Vector2d>{{1, 0}, {5, 0}, {3.1, 0.5}, {2.9, 0.5}};
    if (!is_linear(type.shape))
      for (int f = 0; f < n_faces(type.shape); ++f) {
        const auto fn = face_nodes(type.shape, f);
        thin.push_back(0.5 * (thin[fn[0]] + thin[fn[1]]));
      }
    elements.push_back(thin);
    for (const auto& X : elements) {
      const Eigen::MatrixXd M = consistent_mass(type, X, kRho, kThickness);
      EXPECT_LT(max_abs(M - M.transpose()), 1e-15 * max_abs(M)) << type.name;
      EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(M).eigenvalues().minCoeff(), 0) << type.name;
      OneElement e(type, X);
      EXPECT_EQ(Eigen::LLT<Eigen::MatrixXd>(e.mass(MassKind::Consistent)).info(), Eigen::Success) << type.name;
      const Eigen::VectorXd m = lumped_mass(type, X, kRho, kThickness);
      EXPECT_GT(m.minCoeff(), 0) << type.name;
      EXPECT_NEAR(m.sum(), M.sum(), 1e-13 * M.sum()) << type.name;
    }
  }
}

TEST(MassMatrix, KineticEnergyOfARigidTranslation) {
  const Eigen::Vector2d v(0.3, -0.7);
  for (const ElementType& type : supported_types())
    for (MassKind kind : kKinds) {
      const auto X = straight_sided(type.shape, 2);
      const double m = exact_mass(type, polygon_moments(X, n_corners(type.shape)));
      OneElement e(type, X);
      Eigen::VectorXd V(2 * X.size());
      for (std::size_t a = 0; a < X.size(); ++a) V.segment<2>(2 * a) = v;
      const double kinetic = 0.5 * V.dot(e.mass(kind) * V);
      EXPECT_NEAR(kinetic, 0.5 * m * v.squaredNorm(), 1e-13 * m) << type.name << " " << kind_name(kind);
    }
}

TEST(MassMatrix, KineticEnergyOfARigidRotationIsExactWithConsistentMass) {
  // v = omega e3 x (X - X0) is linear in X, so every element interpolates it
  // exactly and 1/2 V^T M V = 1/2 omega^2 rho t J0, J0 = int |X - X0|^2 dA.
  const double omega = 1.7;
  const Eigen::Vector2d X0(0.4, -0.2);
  for (const ElementType& type : supported_types()) {
    if (is_axisymmetric(type)) continue;  // a rotation in the r-z plane is not rigid
    for (unsigned seed : {1u, 2u}) {
      const auto X = straight_sided(type.shape, seed);
      const Moments p = polygon_moments(X, n_corners(type.shape));
      const double J0 = p.xx + p.yy - 2 * (X0.x() * p.x + X0.y() * p.y) + X0.squaredNorm() * p.area;
      OneElement e(type, X);
      Eigen::VectorXd V(2 * X.size());
      for (std::size_t a = 0; a < X.size(); ++a)
        V.segment<2>(2 * a) = omega * Eigen::Vector2d(-(X[a].y() - X0.y()), X[a].x() - X0.x());
      const double exact = 0.5 * omega * omega * kRho * kThickness * J0;
      EXPECT_NEAR(0.5 * V.dot(e.mass(MassKind::Consistent) * V), exact, 1e-13 * exact) << type.name;
    }
  }
}

TEST(ElementMass, ComesFromTheMaterialDensityAndNamesAMissingOne) {
  const ElementType cpe8 = *find_element_type("CPE8"), cpe8r = *find_element_type("CPE8R");
  const auto X = distorted_element(Shape::Quad8, 4);
  OneElement full(cpe8, X), reduced(cpe8r, X);
  Eigen::MatrixXd expanded;
  for (MassKind kind : kKinds) {
    expand_to_components(scalar_mass(kind, cpe8, X, kRho, kThickness), 2, expanded);
    EXPECT_EQ(full.mass(kind), expanded) << kind_name(kind);
    EXPECT_EQ(reduced.mass(kind), expanded) << "8R: same mass as 8, " << kind_name(kind);
  }
  EXPECT_EQ(expanded(2, 2), expanded(3, 3));  // lumped: the same mass in x and y
  EXPECT_EQ(expanded(2, 3), 0.0);

  OneElement no_density(cpe8, X);
  no_density.data.density.reset();
  try {
    (void)no_density.mass(MassKind::Lumped);
    ADD_FAILURE() << "mass without density";
  } catch (const ModelError& err) {
    EXPECT_EQ(std::string(err.what()), "element 5 (CPE8): *DENSITY missing for material STEEL (deck.inp:12)");
  }
  const DofMap dofs(std::vector<int>(8, 0));
  const LinearElastic steel(210.0, 0.3);
  const ContinuumElement bare(6, cpe8, std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7}, X, steel, 1.0, dofs);
  Eigen::MatrixXd M;
  EXPECT_THROW(bare.mass(MassKind::Consistent, M), ModelError);
}

TEST(ElementMass, DiscretizationPassesTheDeckDensity) {
  const std::string mesh = R"(*NODE
1, 0, 0
2, 2, 0
3, 2, 1
4, 0, 1
*ELEMENT, TYPE=CPS4, ELSET=PLATE
1, 1, 2, 3, 4
*MATERIAL, NAME=STEEL
*ELASTIC
210000, 0.3
)";
  const std::string rest = R"(*SOLID SECTION, ELSET=PLATE, MATERIAL=STEEL
0.5
*STEP
*STATIC
*END STEP
)";
  const Model with = read_deck_string(mesh + "*DENSITY\n7.8e-9\n" + rest, "dense.inp");
  const Discretization d(with);
  Eigen::MatrixXd M;
  d.elements()[0]->mass(MassKind::Lumped, M);
  EXPECT_NEAR(M.sum() / 2, 7.8e-9 * 2 * 0.5, 1e-22);  // rho A t, counted once per direction

  const Model without = read_deck_string(mesh + rest, "light.inp");
  const Discretization static_only(without);  // no density: fine until a mass is asked for
  try {
    static_only.elements()[0]->mass(MassKind::Consistent, M);
    ADD_FAILURE() << "mass without density";
  } catch (const ModelError& err) {
    EXPECT_EQ(std::string(err.what()), "element 1 (CPS4): *DENSITY missing for material STEEL (light.inp:8)");
  }
}

TEST(ElementFrequencies, FreeUnitSquareMatchesTheClosedForm) {
  // CPE4/CPS4 on the unit square, x, y measured from its centre, 2x2
  // Gauss stiffness. By the square's symmetry the generalized eigenvectors are
  // the rigid modes and these fields (nodal values = field at the corners,
  // x, y = +-1/2); omega^2 = phi^T K phi / phi^T M phi = 2U / (2T/omega^2):
  //   mode         2U / t              |phi|^2  int |u|^2 dA
  //   (x, y)       2 (C11 + C12)       2        1/6
  //   (x, -y)      2 (C11 - C12)       2        1/6
  //   (y, x)       4 mu  (gamma = 2)   2        1/6
  //   (xy, 0)      (C11 + mu) / 12     1/4      1/144   (eps_xx = y, gamma = x)
  //   (0, xy)      (C11 + mu) / 12     1/4      1/144
  // Lumped: phi^T M phi = rho t/4 |phi|^2; consistent: rho t int |u|^2 dA.
  // So rho omega^2 = 4(C11+C12), 4(C11-C12), 8 mu, 4(C11+mu)/3 (x2) lumped;
  // 12(C11+C12), 12(C11-C12), 24 mu, 12(C11+mu) (x2) consistent; plus 3 zeros.
  const double E = 210.0, nu = 0.3;
  const double mu = E / (2 * (1 + nu));
  for (const char* name : {"CPE4", "CPS4"}) {
    const ElementType type = *find_element_type(name);
    const bool strain = type.family == Family::PlaneStrain;
    const double C11 = strain ? E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)) : E / (1 - nu * nu);
    const double C12 = strain ? E * nu / ((1 + nu) * (1 - 2 * nu)) : E * nu / (1 - nu * nu);
    const OneElement e(type, {{0, 0}, {1, 0}, {1, 1}, {0, 1}});
    const Eigen::MatrixXd K = e.stiffness();
    for (MassKind kind : kKinds) {
      const bool lumped = kind == MassKind::Lumped;
      std::vector<double> expected = {0, 0, 0};
      for (double v : lumped ? std::vector<double>{4 * (C11 + C12), 4 * (C11 - C12), 8 * mu, 4 * (C11 + mu) / 3,
                                                   4 * (C11 + mu) / 3}
                             : std::vector<double>{12 * (C11 + C12), 12 * (C11 - C12), 24 * mu, 12 * (C11 + mu),
                                                   12 * (C11 + mu)})
        expected.push_back(v / kRho);
      std::sort(expected.begin(), expected.end());
      const Eigen::VectorXd w2 = omega_squared(K, e.mass(kind));
      std::printf("[ figures  ] %s %s rho omega^2:", name, kind_name(kind));
      for (int i = 0; i < 8; ++i) {
        EXPECT_NEAR(w2(i), expected[i], 1e-12 * expected.back()) << name << " " << kind_name(kind) << " mode " << i;
        std::printf(" %.6g (%.6g)", kRho * w2(i), kRho * expected[i]);
      }
      std::printf("\n");
    }
  }
}

TEST(ElementFrequencies, EverySingleElementHasItsRigidModesAndConsistentBoundsLumped) {
  // Zero eigenvalues: 3 rigid modes in the plane; 1 (z translation) for CAX,
  // whose r translation and rotation strain the hoop direction; plus the
  // zero-energy modes of under-integration: K has rank at most
  // n_points x n_strains (3 in the plane, 4 with the hoop strain), so
  // zeros = n_dofs - min(n_dofs - rigid, n_points n_strains): one more for
  // CPE8R/CPS8R (12 < 13) and CAX3 (4 < 5), none for CAX8R (16 >= 15), whose
  // hourglass mode the hoop strain stiffens only weakly (omega^2 a few 1e-7
  // of the largest): zeros are below 1e-11 of the largest (rounding gives
  // about 1e-16), nonzero ones above 1e-8.
  // For 3- and 4-node elements M_lumped - M_consistent is a weighted graph
  // Laplacian (off-diagonals -int rho N_a N_b dV <= 0, zero row sums), hence
  // positive semidefinite, so by Courant-Fischer every consistent omega_k^2 >=
  // the lumped one. HRZ has no such ordering; there it is only reported.
  for (const ElementType& type : supported_types())
    for (unsigned seed : {1u, 2u}) {
      const OneElement e(type, distorted_element(type.shape, seed));
      const Eigen::MatrixXd K = e.stiffness();
      const Eigen::VectorXd consistent = omega_squared(K, e.mass(MassKind::Consistent));
      const Eigen::VectorXd lumped = omega_squared(K, e.mass(MassKind::Lumped));
      const int n_dofs = static_cast<int>(K.rows()), rigid = is_axisymmetric(type) ? 1 : 3;
      const int n_strains = is_axisymmetric(type) ? 4 : 3;
      const int expected_zeros = n_dofs - std::min(n_dofs - rigid, e.element->n_points() * n_strains);
      for (const Eigen::VectorXd* w2 : {&consistent, &lumped}) {
        const double scale = w2->maxCoeff();
        const int zeros = static_cast<int>(((*w2).array().abs() < 1e-11 * scale).count());
        EXPECT_EQ(zeros, expected_zeros) << type.name << " seed " << seed;
        EXPECT_GT((*w2)(expected_zeros), 1e-8 * scale) << type.name;
        EXPECT_GT(w2->minCoeff(), -1e-11 * scale) << type.name;
      }
      if (is_linear(type.shape)) {
        for (Eigen::Index i = expected_zeros; i < consistent.size(); ++i)
          EXPECT_GE(consistent(i), lumped(i) * (1 - 1e-12)) << type.name << " mode " << i;
      } else if (seed == 1) {
        const Eigen::ArrayXd ratio = consistent.tail(consistent.size() - expected_zeros).array() /
                                     lumped.tail(lumped.size() - expected_zeros).array();
        std::printf("[ figures  ] %s omega^2 consistent/lumped (HRZ): min %.3f max %.3f\n",
                    std::string(type.name).c_str(), ratio.minCoeff(), ratio.maxCoeff());
      }
    }
}

// Mass redistribution for impact (redistribute_mass): the flagged nodes carry
// nothing, the total mass and the kinetic energy of rigid translations stay,
// a lumped matrix stays diagonal, and an element with every node flagged
// keeps its mass.
TEST(MassRedistribution, FlaggedNodesLoseTheirMassToTheOthers) {
  const ElementType cpe8 = *find_element_type("CPE8");
  const std::vector<Eigen::Vector2d> X = {{0, 0}, {2, 0.2}, {2.2, 1.5}, {-0.1, 1.2},
                                          {1, 0.05}, {2.15, 0.8}, {1.1, 1.4}, {-0.05, 0.6}};
  const std::vector<bool> flagged = {true, true, false, false, true, false, false, false};  // edge 1-2 with its midside
  for (const MassKind kind : {MassKind::Consistent, MassKind::Lumped}) {
    Eigen::MatrixXd M;
    expand_to_components(scalar_mass(kind, cpe8, X, kRho, kThickness), 2, M);
    const Eigen::VectorXd weights = lumped_mass(cpe8, X, kRho, kThickness);
    const Eigen::MatrixXd R = redistribute_mass(M, 2, weights, flagged, kind == MassKind::Lumped);
    EXPECT_LT((R - R.transpose()).cwiseAbs().maxCoeff(), 1e-14 * M.cwiseAbs().maxCoeff());
    for (int a = 0; a < 8; ++a)
      if (flagged[static_cast<std::size_t>(a)])
        EXPECT_EQ(R.row(2 * a).cwiseAbs().maxCoeff() + R.row(2 * a + 1).cwiseAbs().maxCoeff(), 0.0) << a;
    Eigen::VectorXd translation(16);
    for (int a = 0; a < 8; ++a) translation.segment<2>(2 * a) = Eigen::Vector2d(0.3, -1.7);
    EXPECT_NEAR(translation.dot(R * translation), translation.dot(M * translation), 1e-12 * translation.dot(M * translation));
    if (kind == MassKind::Lumped) EXPECT_EQ((R - Eigen::MatrixXd(R.diagonal().asDiagonal())).cwiseAbs().maxCoeff(), 0.0);
    // Positive definite on the unflagged nodes' dofs.
    std::vector<int> kept;
    for (int a = 0; a < 8; ++a)
      if (!flagged[static_cast<std::size_t>(a)]) kept.push_back(2 * a), kept.push_back(2 * a + 1);
    Eigen::MatrixXd sub(kept.size(), kept.size());
    for (std::size_t i = 0; i < kept.size(); ++i)
      for (std::size_t j = 0; j < kept.size(); ++j) sub(i, j) = R(kept[i], kept[j]);
    EXPECT_EQ(Eigen::LLT<Eigen::MatrixXd>(sub).info(), Eigen::Success);
  }
  Eigen::MatrixXd M;
  expand_to_components(consistent_mass(cpe8, X, kRho, kThickness), 2, M);
  const Eigen::VectorXd weights = lumped_mass(cpe8, X, kRho, kThickness);
  EXPECT_EQ(redistribute_mass(M, 2, weights, std::vector<bool>(8, true), false), M);
  EXPECT_EQ(redistribute_mass(M, 2, weights, std::vector<bool>(8, false), false), M);
}
