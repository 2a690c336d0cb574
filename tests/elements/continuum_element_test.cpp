// Every element type x family x material x {small, finite strain}: the residual
// is the gradient of the strain energy and the tangent is the Jacobian of the
// residual (central finite differences, several random states).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <algorithm>
#include <numeric>

#include "element_fixtures.hpp"
#include "tether/elements/continuum_element.hpp"

using namespace tether;
using namespace tether::test;

namespace {

constexpr double kRelTol = 1e-6;  // FD agreement relative to the largest entry

/// A single element embedded in a mesh of n+2 nodes with permuted indices, so
/// the dof gather is exercised.
struct SingleElement {
  DofMap dofs;
  std::unique_ptr<ContinuumElement> element;
  SingleElement(const ElementType& type, const ConstitutiveModel& material)
      : dofs(std::vector<int>(n_nodes(type.shape) + 2, 0)) {
    const int n = n_nodes(type.shape);
    std::vector<int> nodes(n);
    std::iota(nodes.begin(), nodes.end(), 0);
    std::reverse(nodes.begin(), nodes.end());
    for (int& i : nodes) i += 1;  // reversed order; nodes 0 and n+1 unused
    element = std::make_unique<ContinuumElement>(7, type, nodes, distorted_element(type.shape), material, 0.5, dofs);
  }
};

}  // namespace

TEST(ContinuumElement, ResidualIsEnergyGradientAndTangentMatchesFiniteDifferences) {
  const auto materials = test_materials();
  int checked = 0;
  for (const ElementType& type : supported_types())
    for (const auto& material : materials)
      for (bool nlgeom : {false, true})
        for (unsigned seed : {1u, 2u, 3u}) {
          SingleElement se(type, *material);
          const ContinuumElement& e = *se.element;
          const Eigen::VectorXd u = random_vector(se.dofs.n_dofs(), nlgeom ? 0.12 : 0.05, seed);
          const LocalSystem sys = evaluate_at(e, u, nlgeom);
          const std::string what = e.describe() + " " + material->describe() + (nlgeom ? " NLGEOM" : " small") +
                                   " seed " + std::to_string(seed);

          // Residual vs FD of the strain energy.
          const double h = 1e-6;
          Eigen::VectorXd grad(e.dofs().size());
          for (std::size_t j = 0; j < e.dofs().size(); ++j) {
            Eigen::VectorXd up = u, um = u;
            up(e.dofs()[j]) += h;
            um(e.dofs()[j]) -= h;
            grad(j) = (e.strain_energy({up, up, 1, 1, 1, nlgeom}) - e.strain_energy({um, um, 1, 1, 1, nlgeom})) / (2 * h);
          }
          EXPECT_LT(max_abs(grad - sys.residual), kRelTol * max_abs(sys.residual)) << what;

          // Tangent vs central FD of the residual.
          const Eigen::MatrixXd fd = fd_tangent(e, u, nlgeom, h);
          EXPECT_LT(max_abs(fd - sys.tangent), kRelTol * max_abs(sys.tangent)) << what;
          if (!nlgeom || material->describe().starts_with("linear")) {
            // Hyperelastic: the tangent is symmetric.
            EXPECT_LT(max_abs(sys.tangent - sys.tangent.transpose()), 1e-12 * max_abs(sys.tangent)) << what;
          }
          ++checked;
        }
  EXPECT_EQ(checked, 17 * 2 * 2 * 3);
}

TEST(ContinuumElement, DeclaredSymmetryAndLinearityHoldOnTheTangent) {
  // What the element declares (StepSystem picks the factorization from it):
  // a symmetric tangent, the same at every state under small strain only.
  const auto materials = test_materials();
  for (const ElementType& type : supported_types())
    for (const auto& material : materials)
      for (bool nlgeom : {false, true}) {
        SingleElement se(type, *material);
        const ContinuumElement& e = *se.element;
        const std::string what = e.describe() + " " + material->describe() + (nlgeom ? " NLGEOM" : " small");
        const LocalSystem a = evaluate_at(e, random_vector(se.dofs.n_dofs(), 0.1, 4), nlgeom);
        const LocalSystem b = evaluate_at(e, random_vector(se.dofs.n_dofs(), 0.1, 5), nlgeom);
        EXPECT_TRUE(e.symmetric_tangent(nlgeom)) << what;
        EXPECT_LT(max_abs(a.tangent - a.tangent.transpose()), 1e-10 * max_abs(a.tangent)) << what;
        EXPECT_EQ(e.linear_in_u(nlgeom), !nlgeom) << what;
        // Elastic, no history, no temperatures: the residual reads no time
        // (the assembler keeps it for the step); checked at other times and dt.
        EXPECT_FALSE(e.residual_depends_on_time()) << what;
        const Eigen::VectorXd u = random_vector(se.dofs.n_dofs(), 0.1, 4);
        LocalSystem later;
        later.reset(a.residual.size());
        e.evaluate(EvaluationState{u, Eigen::VectorXd::Zero(u.size()), 7.5, 9.25, 0.125, nlgeom}, later, false);
        EXPECT_EQ(later.residual, a.residual) << what;
        if (nlgeom)
          EXPECT_GT(max_abs(a.tangent - b.tangent), 1e-6 * max_abs(a.tangent)) << what;
        else
          EXPECT_EQ(max_abs(a.tangent - b.tangent), 0.0) << what;
      }
}

TEST(ContinuumElement, RigidBodyMotionGivesZeroStressAndResidual) {
  const LinearElastic steel(210.0, 0.3);
  const NeoHooke rubber(40.0, 0.02);
  for (const ElementType& type : supported_types())
    for (const ConstitutiveModel* material : {static_cast<const ConstitutiveModel*>(&steel), static_cast<const ConstitutiveModel*>(&rubber)}) {
      const auto X = distorted_element(type.shape);
      DofMap dofs(std::vector<int>(X.size(), 0));
      std::vector<int> nodes(X.size());
      std::iota(nodes.begin(), nodes.end(), 0);
      const ContinuumElement e(12, type, nodes, X, *material, 1.0, dofs);
      // Axisymmetry admits only a translation along z; plane elements a large rotation.
      const double angle = type.family == Family::Axisymmetric ? 0.0 : 1.1;
      Eigen::Matrix2d Q;
      Q << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
      Eigen::VectorXd u(dofs.n_dofs());
      for (std::size_t a = 0; a < X.size(); ++a) u.segment<2>(2 * a) = Q * X[a] - X[a] + Eigen::Vector2d(angle == 0.0 ? 0.0 : 0.3, -0.7);
      const LocalSystem sys = evaluate_at(e, u, true);
      EXPECT_LT(max_abs(sys.residual), 1e-12 * max_abs(sys.tangent)) << e.describe();
      std::vector<PointValues> pv;
      e.point_values({u, u, 1, 1, 1, true}, pv);
      ASSERT_EQ(static_cast<int>(pv.size()), e.n_points());
      for (const auto& p : pv)
        for (int c = 0; c < 4; ++c) {
          EXPECT_NEAR(p.stress[c], 0.0, 1e-12) << e.describe();
          EXPECT_NEAR(p.strain[c], 0.0, 1e-14) << e.describe();
        }
    }
}

TEST(ContinuumElement, DescribesItselfAndRefusesInvertedElements) {
  const LinearElastic steel(210.0, 0.3);
  const ElementType cpe4 = *find_element_type("CPE4");
  std::vector<Eigen::Vector2d> X = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  DofMap dofs(std::vector<int>(4, 0));
  const ContinuumElement e(12, cpe4, {0, 1, 2, 3}, X, steel, 1.0, dofs);
  EXPECT_EQ(e.describe(), "element 12 (CPE4)");
  EXPECT_EQ(e.n_points(), 4);
  EXPECT_EQ(std::vector<int>(e.dofs().begin(), e.dofs().end()), (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7}));

  // Clockwise node order: refused at construction, naming the element.
  std::vector<Eigen::Vector2d> cw = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
  try {
    ContinuumElement bad(13, cpe4, {0, 1, 2, 3}, cw, steel, 1.0, dofs);
    ADD_FAILURE() << "clockwise element accepted";
  } catch (const ModelError& err) {
    EXPECT_NE(std::string(err.what()).find("element 13 (CPE4)"), std::string::npos) << err.what();
  }
  EXPECT_THROW(ContinuumElement(14, cpe4, {0, 1, 2}, {X[0], X[1], X[2]}, steel, 1.0, dofs), ModelError);
  EXPECT_THROW(ContinuumElement(15, *find_element_type("CPE4R"), {0, 1, 2, 3}, X, steel, 1.0, dofs), ModelError);
  EXPECT_THROW(ContinuumElement(16, *find_element_type("CAX4"), {0, 1, 2, 3},
                                {{-1, 0}, {1, 0}, {1, 1}, {-1, 1}}, steel, 1.0, dofs),
               ModelError);

  // Inverting the element under NLGEOM: ModelError naming it.
  Eigen::VectorXd u = Eigen::VectorXd::Zero(8);
  u(5) = -2.0;  // node 3 pushed below node 1
  u(7) = -2.0;
  try {
    evaluate_at(e, u, true);
    ADD_FAILURE() << "inverted element evaluated";
  } catch (const ModelError& err) {
    EXPECT_NE(std::string(err.what()).find("element 12 (CPE4)"), std::string::npos) << err.what();
  }
}

// The element is one of 115k at the 230k-dof Hertz deck: its type shared, its
// name kept only when it is not the label, its per-node arrays in one block
// and no history record without a history (docs/performance.md).
TEST(ContinuumElement, KeepsItsDataCompactAndNamesItselfAsBefore) {
  EXPECT_LE(sizeof(ContinuumElement), 96u);
  const LinearElastic steel(210.0, 0.3);
  const ElementType cpe4 = *find_element_type("CPE4");
  const std::vector<Eigen::Vector2d> X = {{0, 0}, {2, 0}, {2, 1}, {0, 1}};
  DofMap dofs(std::vector<int>{7, 8, 9, 10, 11});
  ContinuumElement e(12, cpe4, {4, 1, 2, 3}, X, steel, 1.0, dofs);
  EXPECT_EQ(&e.type(), &intern_element_type(cpe4));
  EXPECT_EQ(std::vector<int>(e.nodes().begin(), e.nodes().end()), (std::vector<int>{4, 1, 2, 3}));
  EXPECT_EQ(std::vector<int>(e.dofs().begin(), e.dofs().end()), (std::vector<int>{8, 9, 2, 3, 4, 5, 6, 7}));
  EXPECT_FALSE(e.has_history());
  e.set_name("12");  // the label's text: describe() as without a name
  EXPECT_EQ(e.describe(), "element 12 (CPE4)");
  e.set_name("PART-1-1.3");
  EXPECT_EQ(e.describe(), "element PART-1-1.3 (CPE4)");
  e.set_name("");
  EXPECT_EQ(e.describe(), "element 12 (CPE4)");
  // The strain energy of u = 0.01 x over the 2 x 1 square reads the reference
  // coordinates from the block: W = (lambda + 2 mu) eps^2 / 2 * area.
  Eigen::VectorXd u = Eigen::VectorXd::Zero(dofs.n_dofs());
  for (int a = 0; a < 4; ++a) u(e.dofs()[2 * a]) = 0.01 * X[static_cast<std::size_t>(a)].x();
  const double lambda = 210.0 * 0.3 / (1.3 * 0.4), mu = 210.0 / 2.6;
  EXPECT_NEAR(e.strain_energy({u, u, 1, 1, 1, false}), 0.5 * (lambda + 2 * mu) * 1e-4 * 2.0, 1e-12);
}

TEST(ContinuumElement, VolumeWeightsIntegrateAreaThicknessAndRevolution) {
  // Uniform hydrostatic strain field: residual of a unit square = boundary tractions.
  // Simpler check through the energy of a uniform strain: W * volume.
  const LinearElastic m(100.0, 0.25);
  for (const char* name : {"CPE4", "CPS8R", "CAX6", "CAX4"}) {
    const ElementType type = *find_element_type(name);
    std::vector<Eigen::Vector2d> X;
    for (int a = 0; a < n_nodes(type.shape); ++a) X.push_back(reference_node(type.shape, a) + Eigen::Vector2d(2, 0));
    DofMap dofs(std::vector<int>(X.size(), 0));
    std::vector<int> nodes(X.size());
    std::iota(nodes.begin(), nodes.end(), 0);
    const ContinuumElement e(1, type, nodes, X, m, 0.5, dofs);
    Eigen::VectorXd u(dofs.n_dofs());
    for (std::size_t a = 0; a < X.size(); ++a) u.segment<2>(2 * a) = 1e-3 * X[a];  // eps = 1e-3 I (hoop too)
    Vec6 eps = Vec6::Zero(), sigma;
    Mat6 D;
    eps.head<3>().setConstant(1e-3);
    if (type.family == Family::PlaneStrain) eps(2) = 0;
    if (type.family == Family::PlaneStress) eps(2) = -2 * 0.25 / 0.75 * 1e-3;
    const double w = m.small_strain_energy(eps);
    const bool tri = type.shape == Shape::Tri3 || type.shape == Shape::Tri6;
    // Tri: area 1/2, centroid r = 2 + 1/3; quad: area 4, centroid r = 2.
    const double volume = type.family == Family::Axisymmetric
                              ? 2 * std::numbers::pi * (tri ? 0.5 * (2 + 1.0 / 3) : 4 * 2.0)
                              : 0.5 * (tri ? 0.5 : 4.0);
    EXPECT_NEAR(e.strain_energy({u, u, 0, 0, 0, false}), w * volume, 1e-12 * w * volume) << name;
  }
}
