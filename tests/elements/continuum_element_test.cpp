// Every element type x family x material x {small, finite strain}: the residual
// is the gradient of the strain energy and the tangent is the Jacobian of the
// residual (central finite differences, several random states).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <algorithm>
#include <numeric>
#include <span>
#include <type_traits>
#include <utility>

#include "element_fixtures.hpp"
#include "tether/elements/continuum_element.hpp"
#include "tether/model/model.hpp"

using namespace tether;
using namespace tether::test;

namespace {

constexpr double kRelTol = 1e-6;  // FD agreement relative to the largest entry

/// A single element embedded in a mesh of n+2 nodes with permuted indices, so
/// the dof gather and the coordinate lookup are exercised.
struct SingleElement {
  DofMap dofs;
  std::vector<Eigen::Vector2d> coords;  ///< the mesh's table, read through the node indices
  std::unique_ptr<ContinuumElement> element;
  SingleElement(const ElementType& type, const ConstitutiveModel& material)
      : dofs(std::vector<int>(n_nodes(type.shape) + 2, 0)) {
    const int n = n_nodes(type.shape);
    std::vector<int> nodes(n);
    std::iota(nodes.begin(), nodes.end(), 0);
    std::reverse(nodes.begin(), nodes.end());
    for (int& i : nodes) i += 1;  // reversed order; nodes 0 and n+1 unused
    coords = coordinate_table(nodes, distorted_element(type.shape));
    element = std::make_unique<ContinuumElement>(7, type, nodes, coords, material, 0.5, dofs);
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
  const ContinuumElement e(12, cpe4, std::vector<int>{0, 1, 2, 3}, X, steel, 1.0, dofs);
  EXPECT_EQ(e.describe(), "element 12 (CPE4)");
  EXPECT_EQ(e.n_points(), 4);
  EXPECT_EQ(std::vector<int>(e.dofs().begin(), e.dofs().end()), (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7}));

  // Clockwise node order: refused at construction, naming the element.
  std::vector<Eigen::Vector2d> cw = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
  try {
    ContinuumElement bad(13, cpe4, std::vector<int>{0, 1, 2, 3}, cw, steel, 1.0, dofs);
    ADD_FAILURE() << "clockwise element accepted";
  } catch (const ModelError& err) {
    EXPECT_NE(std::string(err.what()).find("element 13 (CPE4)"), std::string::npos) << err.what();
  }
  EXPECT_THROW(ContinuumElement(14, cpe4, std::vector<int>{0, 1, 2}, X, steel, 1.0, dofs), ModelError);
  EXPECT_THROW(ContinuumElement(15, *find_element_type("CPE4R"), std::vector<int>{0, 1, 2, 3}, X, steel, 1.0, dofs),
               ModelError);
  const std::vector<Eigen::Vector2d> across_axis = {{-1, 0}, {1, 0}, {1, 1}, {-1, 1}};
  EXPECT_THROW(ContinuumElement(16, *find_element_type("CAX4"), std::vector<int>{0, 1, 2, 3}, across_axis, steel, 1.0,
                                dofs),
               ModelError);
  // A node index outside the coordinate table: refused, naming the element.
  try {
    ContinuumElement outside(17, cpe4, std::vector<int>{0, 1, 2, 4}, X, steel, 1.0, DofMap(std::vector<int>(5, 0)));
    ADD_FAILURE() << "node outside the coordinate table accepted";
  } catch (const ModelError& err) {
    EXPECT_NE(std::string(err.what()).find("element 17 (CPE4): node index 4 outside the table of 4 node coordinates"),
              std::string::npos)
        << err.what();
  }

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
// name kept only when it is not the label, its reference coordinates read
// from the mesh's table, its dofs and nodes in one block and no history record
// without a history (docs/performance.md): 88 bytes.
TEST(ContinuumElement, KeepsItsDataCompactAndNamesItselfAsBefore) {
  EXPECT_LE(sizeof(ContinuumElement), 88u);
  const LinearElastic steel(210.0, 0.3);
  const ElementType cpe4 = *find_element_type("CPE4");
  const std::vector<Eigen::Vector2d> X = {{0, 0}, {2, 0}, {2, 1}, {0, 1}};
  const std::vector<int> nodes = {4, 1, 2, 3};
  const std::vector<Eigen::Vector2d> table = coordinate_table(nodes, X);  // node 0 unused (NaN)
  DofMap dofs(std::vector<int>{7, 8, 9, 10, 11});
  ContinuumElement e(12, cpe4, nodes, table, steel, 1.0, dofs);
  EXPECT_EQ(&e.type(), &intern_element_type(cpe4));
  EXPECT_EQ(std::vector<int>(e.nodes().begin(), e.nodes().end()), nodes);
  EXPECT_EQ(std::vector<int>(e.dofs().begin(), e.dofs().end()), (std::vector<int>{8, 9, 2, 3, 4, 5, 6, 7}));
  EXPECT_FALSE(e.has_history());
  e.set_name("12");  // the label's text: describe() as without a name
  EXPECT_EQ(e.describe(), "element 12 (CPE4)");
  e.set_name("PART-1-1.3");
  EXPECT_EQ(e.describe(), "element PART-1-1.3 (CPE4)");
  e.set_name("");
  EXPECT_EQ(e.describe(), "element 12 (CPE4)");
  // The strain energy of u = 0.01 x over the 2 x 1 rectangle reads the
  // reference coordinates from the table through the node indices:
  // W = (lambda + 2 mu) eps^2 / 2 * area.
  Eigen::VectorXd u = Eigen::VectorXd::Zero(dofs.n_dofs());
  for (int a = 0; a < 4; ++a) u(e.dofs()[2 * a]) = 0.01 * X[static_cast<std::size_t>(a)].x();
  const double lambda = 210.0 * 0.3 / (1.3 * 0.4), mu = 210.0 / 2.6;
  EXPECT_NEAR(e.strain_energy({u, u, 1, 1, 1, false}), 0.5 * (lambda + 2 * mu) * 1e-4 * 2.0, 1e-12);
}

// The element keeps a pointer into the table: a temporary one is refused at
// compile time, a named one accepted.
static_assert(!std::is_constructible_v<ContinuumElement, int, const ElementType&, std::span<const int>,
                                       std::vector<Eigen::Vector2d>, const ConstitutiveModel&, double, const DofMap&>);
static_assert(std::is_constructible_v<ContinuumElement, int, const ElementType&, std::span<const int>,
                                      const std::vector<Eigen::Vector2d>&, const ConstitutiveModel&, double,
                                      const DofMap&>);

// Two elements of one mesh share its coordinate table (their common nodes once)
// and give, bit for bit, what each gives over a table of its own nodes only:
// residual, tangent, point values (the current positions X + u) and mass.
TEST(ContinuumElement, ReadsItsReferenceCoordinatesFromTheSharedTable) {
  const NeoHooke rubber(40.0, 0.02);
  MaterialData data;
  data.density = 7.8;
  for (const ElementType& type : supported_types()) {
    const int n = n_nodes(type.shape);
    const std::vector<Eigen::Vector2d> X = distorted_element(type.shape, 11);
    // The mesh: the element's nodes at 2n-1, 2n-3, ..., among other nodes
    // (the shared table has 2n nodes; the second element is the first moved
    // by (5, 0), its nodes the even indices).
    std::vector<Eigen::Vector2d> mesh(static_cast<std::size_t>(2 * n));
    std::vector<int> first(n), second(n);
    for (int a = 0; a < n; ++a) {
      first[a] = 2 * n - 1 - 2 * a;
      second[a] = 2 * a;
      mesh[static_cast<std::size_t>(first[a])] = X[static_cast<std::size_t>(a)];
      mesh[static_cast<std::size_t>(second[a])] = X[static_cast<std::size_t>(a)] + Eigen::Vector2d(5, 0);
    }
    std::vector<Eigen::Vector2d> moved = X;
    for (auto& x : moved) x += Eigen::Vector2d(5, 0);
    std::vector<int> own(n);
    std::iota(own.begin(), own.end(), 0);
    const DofMap mesh_dofs(std::vector<int>(static_cast<std::size_t>(2 * n), 0));
    const DofMap own_dofs(std::vector<int>(static_cast<std::size_t>(n), 0));
    const ContinuumElement a(1, type, first, mesh, rubber, 0.5, mesh_dofs, &data);
    const ContinuumElement b(2, type, second, mesh, rubber, 0.5, mesh_dofs, &data);
    const ContinuumElement a_own(1, type, own, X, rubber, 0.5, own_dofs, &data);
    const ContinuumElement b_own(2, type, own, moved, rubber, 0.5, own_dofs, &data);
    const Eigen::VectorXd u = random_vector(mesh_dofs.n_dofs(), 0.02, 5);
    for (const auto& [shared, alone] : {std::pair{&a, &a_own}, std::pair{&b, &b_own}}) {
      Eigen::VectorXd u_own(own_dofs.n_dofs());
      for (int i = 0; i < 2 * n; ++i) u_own(i) = u(shared->dofs()[static_cast<std::size_t>(i)]);
      for (const bool nlgeom : {false, true}) {
        const LocalSystem s1 = evaluate_at(*shared, u, nlgeom), s2 = evaluate_at(*alone, u_own, nlgeom);
        EXPECT_EQ(s1.residual, s2.residual) << shared->describe();
        EXPECT_EQ(s1.tangent, s2.tangent) << shared->describe();
        std::vector<PointValues> p1, p2;
        shared->point_values({u, u, 1, 1, 1, nlgeom}, p1);
        alone->point_values({u_own, u_own, 1, 1, 1, nlgeom}, p2);
        ASSERT_EQ(p1.size(), p2.size());
        for (std::size_t q = 0; q < p1.size(); ++q) {
          EXPECT_EQ(p1[q].x, p2[q].x) << shared->describe();
          EXPECT_EQ(p1[q].stress, p2[q].stress) << shared->describe();
        }
      }
      Eigen::MatrixXd m1, m2;
      shared->mass(MassKind::Consistent, m1);
      alone->mass(MassKind::Consistent, m2);
      EXPECT_EQ(m1, m2) << shared->describe();
    }
  }
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
