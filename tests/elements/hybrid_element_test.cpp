// The hybrid (mean-dilatation, constant-pressure) elements CPE4H and CAX4H:
// the catalogue, the tangent against central finite differences (elastic and
// plastic, small and finite strain, plane strain and axisymmetry), its
// symmetry for hyperelastic materials, and the constant pressure that makes
// them hybrid. The patch test, rigid-body motion, mass and loads run over
// supported_types() (element_fixtures.hpp), which lists both.
#include <gtest/gtest.h>

#include <numeric>

#include "element_fixtures.hpp"
#include "tether/elements/continuum_element.hpp"
#include "tether/materials/j2_plasticity.hpp"

using namespace tether;
using namespace tether::test;

namespace {

constexpr double kRelTol = 1e-6;  // FD agreement, relative to the largest tangent entry (h = 1e-7 .. 1e-8)

struct HybridQuad {
  DofMap dofs;
  std::vector<Eigen::Vector2d> coords = distorted_element(Shape::Quad4);  ///< the mesh's coordinate table
  std::unique_ptr<ContinuumElement> element;
  HybridQuad(const char* name, const ConstitutiveModel& material) : dofs(std::vector<int>(4, 0)) {
    const ElementType type = *find_element_type(name);
    std::vector<int> nodes(4);
    std::iota(nodes.begin(), nodes.end(), 0);
    element = std::make_unique<ContinuumElement>(5, type, nodes, coords, material, 0.5, dofs);
  }
};

/// Hydrostatic Cauchy stress (s11 + s22 + s33)/3 at each point.
std::vector<double> point_pressures(const ContinuumElement& e, const Eigen::VectorXd& u, bool nlgeom) {
  std::vector<PointValues> pv;
  e.point_values({u, u, 1, 1, 1, nlgeom}, pv);
  std::vector<double> p;
  for (const PointValues& v : pv) p.push_back((v.stress[0] + v.stress[1] + v.stress[2]) / 3);
  return p;
}

double spread(const std::vector<double>& v) {
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  return *hi - *lo;
}

}  // namespace

TEST(HybridElement, CatalogueHasCpe4hAndCax4hAndRefusesTheOtherHybridNames) {
  for (const char* name : {"CPE4H", "cax4h"}) {
    const auto t = find_element_type(name);
    ASSERT_TRUE(t) << name;
    EXPECT_TRUE(t->hybrid);
    EXPECT_EQ(t->shape, Shape::Quad4);
    EXPECT_EQ(unsupported_reason(*t), "") << name;
  }
  EXPECT_FALSE(find_element_type("CPE4")->hybrid);
  for (const char* name : {"CPE3H", "CPE6H", "CPE8H", "CPE8RH", "CAX3H", "CAX6H", "CAX8H", "CAX8RH", "CPE4RH",
                           "CAX4RH"}) {
    const auto t = find_element_type(name);
    ASSERT_TRUE(t) << name;
    EXPECT_NE(unsupported_reason(*t).find("hybrid"), std::string::npos) << name << ": " << unsupported_reason(*t);
  }
  EXPECT_NE(unsupported_reason(*find_element_type("CAX4RH")).find("hourglass"), std::string::npos);
  EXPECT_NE(unsupported_reason(*find_element_type("CPE8H")).find("linearly"), std::string::npos);
  // CPS4H is listed (FAMILY=PLANE STRESS of *SOLID SECTION makes it of a CPE4H) and refused; other CPS*H are unknown.
  EXPECT_NE(unsupported_reason(*find_element_type("CPS4H")).find("plane-stress elements have no hybrid form"),
            std::string::npos);
  EXPECT_FALSE(find_element_type("CPS8H"));
  EXPECT_NE(unknown_element_reason("CPS8H").find("plane-stress elements have no hybrid form"), std::string::npos);
  EXPECT_NE(unknown_element_reason("cps8rh").find("use cps8r instead"), std::string::npos);
  EXPECT_NE(unknown_element_reason("C3D8").find("CAX4H"), std::string::npos);
}

TEST(HybridElement, ElasticTangentMatchesFiniteDifferencesAndIsSymmetric) {
  const auto materials = test_materials();  // SVK under NLGEOM, neo-Hooke
  for (const char* name : {"CPE4H", "CAX4H"})
    for (const auto& material : materials)
      for (bool nlgeom : {false, true})
        for (unsigned seed : {11u, 12u, 13u}) {
          HybridQuad he(name, *material);
          const ContinuumElement& e = *he.element;
          const Eigen::VectorXd u = random_vector(8, nlgeom ? 0.15 : 0.05, seed);
          SCOPED_TRACE(e.describe() + " " + material->describe() + (nlgeom ? " NLGEOM" : " small") + " seed " +
                       std::to_string(seed));
          const LocalSystem sys = evaluate_at(e, u, nlgeom);
          EXPECT_LT(max_abs(fd_tangent(e, u, nlgeom, 1e-7) - sys.tangent), kRelTol * max_abs(sys.tangent));
          EXPECT_LT(max_abs(sys.tangent - sys.tangent.transpose()), 1e-12 * max_abs(sys.tangent));
          // The residual is the gradient of the energy sum W(E_bar) dV.
          Eigen::VectorXd grad(8);
          for (int j = 0; j < 8; ++j) {
            Eigen::VectorXd up = u, um = u;
            up(j) += 1e-6;
            um(j) -= 1e-6;
            grad(j) = (e.strain_energy({up, up, 1, 1, 1, nlgeom}) - e.strain_energy({um, um, 1, 1, 1, nlgeom})) / 2e-6;
          }
          EXPECT_LT(max_abs(grad - sys.residual), kRelTol * max_abs(sys.residual));
        }
}

TEST(HybridElement, PlasticTangentMatchesFiniteDifferencesOnBothBranches) {
  // J2 with isotropic and kinematic hardening, from a committed plastic
  // state: further loading (plastic branch) and unloading (elastic branch).
  for (auto hardening : {J2Plasticity::Hardening::Isotropic, J2Plasticity::Hardening::Kinematic}) {
    const J2Plasticity steel(210.0, 0.3, HardeningCurve({0, 0.05, 0.2}, {0.2, 0.3, 0.32}), hardening);
    for (const char* name : {"CPE4H", "CAX4H"})
      for (bool nlgeom : {false, true}) {
        HybridQuad he(name, steel);
        ContinuumElement& e = *he.element;
        const double amp = nlgeom ? 0.05 : 0.004;
        Eigen::VectorXd u1 = random_vector(8, 0.3 * amp, 1);
        const auto X = distorted_element(Shape::Quad4);
        for (int a = 0; a < 4; ++a) u1(2 * a) += amp * X[a].x(), u1(2 * a + 1) -= 0.5 * amp * X[a].y();
        e.commit({u1, u1, 1, 1, 1, nlgeom});
        std::vector<PointValues> pv;
        e.point_values({u1, u1, 1, 1, 1, nlgeom}, pv);
        for (const PointValues& p : pv) EXPECT_GT(p.peeq, 0.1 * amp) << e.describe();
        for (double scale : {1.3, 0.995}) {
          const Eigen::VectorXd u2 = scale * u1 + random_vector(8, 2e-4, 9);
          SCOPED_TRACE(e.describe() + (nlgeom ? " NLGEOM" : " small") + " scale " + std::to_string(scale));
          const LocalSystem sys = evaluate_at(e, u2, nlgeom);
          EXPECT_LT(max_abs(fd_tangent(e, u2, nlgeom, 1e-8) - sys.tangent), kRelTol * max_abs(sys.tangent));
        }
      }
  }
}

TEST(HybridElement, PressureIsConstantOverTheElementWhereThePlainElementsVaries) {
  // Linear elasticity (small strain) and the decoupled neo-Hooke law (NLGEOM):
  // the hydrostatic stress depends on the volume change only, which the
  // hybrid element replaces by its element mean -- the same at every point.
  const LinearElastic steel(210.0, 0.4);
  const NeoHooke rubber(40.0, 0.002);
  for (const char* name : {"CPE4", "CPE4H", "CAX4", "CAX4H"})
    for (bool nlgeom : {false, true}) {
      const ConstitutiveModel& m = nlgeom ? static_cast<const ConstitutiveModel&>(rubber) : steel;
      HybridQuad he(name, m);
      const Eigen::VectorXd u = random_vector(8, 0.05, 21);
      const std::vector<double> p = point_pressures(*he.element, u, nlgeom);
      const double size = std::abs(std::accumulate(p.begin(), p.end(), 0.0)) + 1e-300;
      if (he.element->type().hybrid)
        EXPECT_LT(spread(p), 1e-12 * size) << name << (nlgeom ? " NLGEOM" : " small");
      else
        EXPECT_GT(spread(p), 1e-2 * size) << name << (nlgeom ? " NLGEOM" : " small");
    }
}

TEST(HybridElement, InvertedElementIsReportedNotEvaluated) {
  const NeoHooke rubber(40.0, 0.02);
  HybridQuad he("CAX4H", rubber);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(8);
  const auto X = distorted_element(Shape::Quad4);
  for (int a = 0; a < 4; ++a) u(2 * a) = -2.5 * X[a].x();  // x -> -1.5 x: r < 0, inverted
  EXPECT_THROW(evaluate_at(*he.element, u, true), ModelError);
}
