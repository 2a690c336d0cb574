// The material history of ContinuumElement: the tangent of a plastic element
// against finite differences from a committed plastic state, evaluate() that
// commits nothing, results that are the same before and after commit(), and
// the history carried through save_state / load_state.
#include <gtest/gtest.h>

#include <numeric>

#include "element_fixtures.hpp"
#include "tether/elements/continuum_element.hpp"
#include "tether/elements/face_pressure.hpp"
#include "tether/materials/j2_plasticity.hpp"

using namespace tether;
using namespace tether::test;

namespace {

J2Plasticity steel(J2Plasticity::Hardening h) {
  return {210.0, 0.3, HardeningCurve({0, 0.05, 0.2}, {0.2, 0.3, 0.32}), h};
}

struct PlasticElement {
  DofMap dofs;
  std::vector<Eigen::Vector2d> coords;  ///< the mesh's coordinate table
  std::unique_ptr<ContinuumElement> element;
  PlasticElement(const ElementType& type, const ConstitutiveModel& material)
      : dofs(std::vector<int>(n_nodes(type.shape), 0)), coords(distorted_element(type.shape)) {
    std::vector<int> nodes(n_nodes(type.shape));
    std::iota(nodes.begin(), nodes.end(), 0);
    element = std::make_unique<ContinuumElement>(3, type, nodes, coords, material, 0.5, dofs);
  }
};

/// A displacement of the distorted element that stretches it well past yield (strain ~ amp).
Eigen::VectorXd stretch(const ContinuumElement& e, double amp, unsigned seed) {
  Eigen::VectorXd u = random_vector(static_cast<int>(e.dofs().size()), 0.3 * amp, seed);
  const auto X = distorted_element(e.type().shape);
  for (std::size_t a = 0; a < X.size(); ++a) u(2 * a) += amp * X[a].x(), u(2 * a + 1) -= 0.5 * amp * X[a].y();
  return u;
}

std::vector<PointValues> values_at(const ContinuumElement& e, const Eigen::VectorXd& u) {
  std::vector<PointValues> p;
  e.point_values({u, u, 1, 1, 1, false}, p);
  return p;
}

}  // namespace

TEST(PlasticElement, TangentMatchesFiniteDifferencesFromACommittedPlasticState) {
  for (auto h : {J2Plasticity::Hardening::Isotropic, J2Plasticity::Hardening::Kinematic}) {
    const J2Plasticity m = steel(h);
    for (const ElementType& type : supported_types()) {
      PlasticElement pe(type, m);
      ContinuumElement& e = *pe.element;
      EXPECT_FALSE(e.linear_in_u(false));
      EXPECT_TRUE(e.residual_depends_on_time());  // its history changes at commit()
      const Eigen::VectorXd u1 = stretch(e, 0.004, 1);
      e.commit({u1, u1, 1, 1, 1, false});
      double peeq = 0;
      for (const PointValues& p : values_at(e, u1)) peeq = std::max(peeq, p.peeq);
      EXPECT_GT(peeq, 1e-3) << e.describe();
      // Further loading (plastic) and unloading (elastic) from the committed state.
      for (double scale : {1.6, 0.7}) {
        const Eigen::VectorXd u2 = scale * u1 + random_vector(u1.size(), 2e-4, 9);
        const LocalSystem sys = evaluate_at(e, u2, false);
        const Eigen::MatrixXd fd = fd_tangent(e, u2, false, 1e-8);
        EXPECT_LT(max_abs(sys.tangent - fd), 1e-6 * max_abs(sys.tangent))
            << e.describe() << " scale " << scale << " " << m.describe();
      }
    }
  }
}

TEST(PlasticElement, FiniteStrainTangentMatchesFiniteDifferencesFromACommittedPlasticState) {
  // NLGEOM (isotropic and kinematic hardening; plane strain, axisymmetry and
  // plane stress): material and geometric stiffness.
  for (auto h : {J2Plasticity::Hardening::Isotropic, J2Plasticity::Hardening::Kinematic})
  for (const ElementType& type : supported_types()) {
    const J2Plasticity m = steel(h);
    PlasticElement pe(type, m);
    ContinuumElement& e = *pe.element;
    const Eigen::VectorXd u1 = stretch(e, 0.05, 1);
    e.commit({u1, u1, 1, 1, 1, true});
    std::vector<PointValues> p;
    e.point_values({u1, u1, 1, 1, 1, true}, p);
    double peeq = 0;
    for (const PointValues& v : p) peeq = std::max(peeq, v.peeq);
    EXPECT_GT(peeq, 0.01) << e.describe();
    for (double scale : {1.3, 0.995}) {  // further loading (plastic), unloading (elastic)
      const Eigen::VectorXd u2 = scale * u1 + random_vector(u1.size(), 2e-4, 9);
      const LocalSystem sys = evaluate_at(e, u2, true);
      const Eigen::MatrixXd fd = fd_tangent(e, u2, true, 1e-8);
      EXPECT_LT(max_abs(sys.tangent - fd), 1e-6 * max_abs(sys.tangent)) << e.describe() << " scale " << scale;
    }
  }
}

TEST(PlasticElement, EvaluateCommitsNothingAndCommitStoresTheConvergedTrialState) {
  const J2Plasticity m = steel(J2Plasticity::Hardening::Isotropic);
  const auto type = *find_element_type("CPE4");
  PlasticElement a(type, m), b(type, m);
  const Eigen::VectorXd u1 = stretch(*a.element, 0.004, 2), u2 = 1.5 * u1;
  // Evaluating anywhere (a rejected attempt) leaves the history alone.
  const LocalSystem fresh = evaluate_at(*b.element, u1, false);
  (void)evaluate_at(*a.element, u2, false);
  EXPECT_EQ(evaluate_at(*a.element, u1, false).residual, fresh.residual);
  // Results from the committed records equal those computed before commit, bit for bit.
  const std::vector<PointValues> before = values_at(*a.element, u1);
  const double energy_before = a.element->strain_energy({u1, u1, 1, 1, 1, false});
  const double dissipation_before = a.element->plastic_dissipation({u1, u1, 1, 1, 1, false});
  EXPECT_GT(dissipation_before, 0);
  a.element->commit({u1, u1, 1, 1, 1, false});
  const std::vector<PointValues> after = values_at(*a.element, u1);
  ASSERT_EQ(before.size(), after.size());
  for (std::size_t q = 0; q < before.size(); ++q) {
    EXPECT_EQ(before[q].stress, after[q].stress);
    EXPECT_EQ(before[q].strain, after[q].strain);
    EXPECT_EQ(before[q].peeq, after[q].peeq);
    EXPECT_EQ(before[q].plastic_strain, after[q].plastic_strain);
    EXPECT_GT(after[q].peeq, 0);
  }
  EXPECT_EQ(a.element->strain_energy({u1, u1, 1, 1, 1, false}), energy_before);
  EXPECT_EQ(a.element->plastic_dissipation({u1, u1, 1, 1, 1, false}), dissipation_before);
  // The increment's dissipation: all of it before the commit (virgin records), none after it; the
  // next increment's is plastic_dissipation beyond the committed total.
  EXPECT_EQ(b.element->plastic_dissipation_increment({u1, u1, 1, 1, 1, false}), dissipation_before);
  EXPECT_EQ(a.element->plastic_dissipation_increment({u1, u1, 1, 1, 1, false}), 0.0);
  const double next = a.element->plastic_dissipation_increment({u2, u1, 2, 2, 1, false});
  EXPECT_GT(next, 0);
  EXPECT_NEAR(next, a.element->plastic_dissipation({u2, u1, 2, 2, 1, false}) - dissipation_before,
              1e-12 * dissipation_before);
  EXPECT_GT(a.element->plastic_dissipation({u1, u1, 1, 1, 1, false}), 0);
  // After the commit the element starts from the new history: unloading to u = 0 leaves a residual stress.
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(u1.size());
  EXPECT_GT(evaluate_at(*a.element, zero, false).residual.norm(), 1e-3);
  EXPECT_EQ(evaluate_at(*b.element, zero, false).residual.norm(), 0.0);
}

TEST(PlasticElement, SavedHistoryLoadsIntoAFreshElement) {
  const J2Plasticity m = steel(J2Plasticity::Hardening::Kinematic);
  const auto type = *find_element_type("CAX8R");
  PlasticElement a(type, m), b(type, m);
  const Eigen::VectorXd u1 = stretch(*a.element, 0.005, 3), u2 = -0.5 * u1;
  a.element->commit({u1, u1, 1, 1, 1, false});
  std::vector<double> saved;
  a.element->save_state(saved);
  std::span<const double> in(saved);
  b.element->load_state(in);
  EXPECT_TRUE(in.empty());
  EXPECT_EQ(evaluate_at(*a.element, u2, false).residual, evaluate_at(*b.element, u2, false).residual);
  EXPECT_EQ(values_at(*a.element, u1)[0].peeq, values_at(*b.element, u1)[0].peeq);
  EXPECT_EQ(a.element->plastic_dissipation({u1, u1, 1, 1, 1, false}),
            b.element->plastic_dissipation({u1, u1, 1, 1, 1, false}));
  // A record of another kind or size is refused.
  std::vector<double> bad(saved.begin(), saved.end() - 1);
  std::span<const double> short_in(bad);
  EXPECT_THROW(b.element->load_state(short_in), std::runtime_error);
  // Elastic elements keep nothing.
  const LinearElastic elastic(210, 0.3);
  PlasticElement c(type, elastic);
  std::vector<double> none;
  c.element->save_state(none);
  EXPECT_TRUE(none.empty());
  EXPECT_TRUE(c.element->linear_in_u(false));
}

TEST(PlasticElement, PlaneStressPressureTangentFollowsTheThicknessOfTheHistory) {
  // A follower pressure on each face of a plane-stress element with a
  // committed plastic history: its thickness stretch F33 comes from the
  // element's points (their history), and dF33/du is the consistent one:
  // central differences at random states of further loading (plastic
  // branch) and unloading (elastic branch).
  for (auto h : {J2Plasticity::Hardening::Isotropic, J2Plasticity::Hardening::Kinematic})
    for (const ElementType& type : supported_types()) {
      if (type.family != Family::PlaneStress) continue;
      const J2Plasticity m = steel(h);
      PlasticElement pe(type, m);
      ContinuumElement& e = *pe.element;
      const Eigen::VectorXd u1 = stretch(e, 0.05, 1);
      e.commit({u1, u1, 1, 1, 1, true});
      std::vector<int> nodes(e.nodes().begin(), e.nodes().end());
      for (int face = 0; face < n_faces(type.shape); ++face) {
        FacePressure load(3, type, nodes, distorted_element(type.shape), face, 0.5, m, pe.dofs);
        load.set_pressure(-0.3);
        EXPECT_THROW(evaluate_at(load, u1, true), ModelError);  // no element: its thickness is unknown
        load.set_element(e);
        for (double scale : {1.3, 0.995})
          for (unsigned seed : {3u, 4u}) {
            const Eigen::VectorXd u2 = scale * u1 + random_vector(u1.size(), 2e-4, seed);
            SCOPED_TRACE(load.describe() + " scale " + std::to_string(scale) + " seed " + std::to_string(seed));
            const LocalSystem sys = evaluate_at(load, u2, true);
            const Eigen::MatrixXd fd = fd_tangent(load, u2, true, 1e-8);
            EXPECT_LT(max_abs(fd - sys.tangent), 1e-6 * max_abs(sys.tangent));
            // The thickness block (the element's nodes off the face) is not zero.
            EXPECT_GT(max_abs(sys.tangent.rightCols(sys.tangent.cols() - 2 * n_face_nodes(type.shape))),
                      1e-3 * max_abs(sys.tangent));
          }
      }
    }
}
