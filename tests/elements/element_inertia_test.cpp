// ElementInertia: its tangent against central differences, its residual against M a + C v.
#include <gtest/gtest.h>

#include <numeric>

#include "element_fixtures.hpp"
#include "tether/elements/element_inertia.hpp"
#include "tether/materials/linear_elastic.hpp"

namespace tether {
namespace {

struct InertiaSetup {
  DofMap dofs{std::vector<int>(4, 0)};
  LinearElastic material{1000.0, 0.3};
  MaterialData data;
  std::vector<Eigen::Vector2d> coords = test::distorted_element(Shape::Quad4, 5);  ///< the mesh's coordinate table
  std::unique_ptr<ContinuumElement> element;
  Eigen::VectorXd v_n, a_n, u_n;
  NewmarkIncrement increment;
  InertiaSetup() {
    data.name = "M";
    data.density = 2.5;
    data.where = {"deck.inp", 3};
    std::vector<int> nodes(4);
    std::iota(nodes.begin(), nodes.end(), 0);
    element = std::make_unique<ContinuumElement>(1, find_element_type("CPE4").value(), nodes, coords, material, 1.0,
                                                 dofs, &data);
    const int n = dofs.n_dofs();
    v_n = test::random_vector(n, 0.3, 11);
    a_n = test::random_vector(n, 2.0, 12);
    u_n = test::random_vector(n, 0.01, 13);
    increment.v_start = &v_n, increment.a_start = &a_n;
    increment.dt = 0.05;
    const double alpha = -0.1;
    increment.beta = (1 - alpha) * (1 - alpha) / 4, increment.gamma = 0.5 - alpha, increment.scale = 1 / (1 + alpha);
  }
  LocalSystem evaluate(const ElementInertia& m, const Eigen::VectorXd& u) const {
    const EvaluationState s{u, u_n, 1, 1, increment.dt, false};
    LocalSystem out;
    out.reset(8);
    m.evaluate(s, out, true);
    return out;
  }
};

TEST(ElementInertia, TangentMatchesCentralDifferences) {
  InertiaSetup setup;
  for (const MassKind kind : {MassKind::Consistent, MassKind::Lumped})
    for (const double beta_r : {0.0, 2e-3}) {
      const ElementInertia m(*setup.element, kind, 0.7, beta_r, setup.increment);
      const Eigen::VectorXd u = setup.u_n + test::random_vector(8, 0.01, 21);
      const Eigen::MatrixXd K = setup.evaluate(m, u).tangent;
      Eigen::MatrixXd fd(8, 8);
      const double h = 1e-6;
      for (int j = 0; j < 8; ++j) {
        Eigen::VectorXd up = u, um = u;
        up[j] += h, um[j] -= h;
        fd.col(j) = (setup.evaluate(m, up).residual - setup.evaluate(m, um).residual) / (2 * h);
      }
      EXPECT_LT(test::max_abs(K - fd), 1e-6 * test::max_abs(K)) << "beta_R " << beta_r;
    }
}

TEST(ElementInertia, ResidualIsMassTimesNewmarkAccelerationPlusDamping) {
  InertiaSetup setup;
  const ElementInertia m(*setup.element, MassKind::Consistent, 0.7, 2e-3, setup.increment);
  const Eigen::VectorXd u = setup.u_n + test::random_vector(8, 0.01, 31);
  const NewmarkIncrement& n = setup.increment;
  Eigen::VectorXd a(8), v(8);
  for (int i = 0; i < 8; ++i) {
    a[i] = (u[i] - setup.u_n[i] - n.dt * setup.v_n[i]) / (n.beta * n.dt * n.dt) - (0.5 / n.beta - 1) * setup.a_n[i];
    v[i] = setup.v_n[i] + n.dt * ((1 - n.gamma) * setup.a_n[i] + n.gamma * a[i]);
  }
  const Eigen::MatrixXd K = test::evaluate_at(*setup.element, u, false).tangent;
  const Eigen::VectorXd expected = n.scale * (m.mass() * (a + 0.7 * v) + 2e-3 * (K * v));
  EXPECT_LT((setup.evaluate(m, u).residual - expected).cwiseAbs().maxCoeff(), 1e-10 * expected.cwiseAbs().maxCoeff());
  // The kinetic energy of v is 1/2 v^T M v, and the damping force C v.
  EXPECT_NEAR(m.kinetic_energy(v), 0.5 * v.dot(m.mass() * v), 1e-12);
  Eigen::VectorXd force = Eigen::VectorXd::Zero(8);
  m.add_damping_force(EvaluationState{u, setup.u_n, 1, 1, n.dt, false}, v, force);
  EXPECT_LT((force - (0.7 * m.mass() * v + 2e-3 * K * v)).cwiseAbs().maxCoeff(), 1e-12 * force.cwiseAbs().maxCoeff());
}

// The inertia keeps the mass over the nodes (n lumped masses, or the n x n
// consistent matrix), not the (2n)^2 matrix over local dofs; what it hands
// out is bitwise ContinuumElement::mass, before and after redistribution.
TEST(ElementInertia, KeepsTheNodalMassAndHandsOutTheElementsMatrixBitwise) {
  LinearElastic material{1000.0, 0.3};
  MaterialData data;
  data.name = "M", data.density = 2.5, data.where = {"deck.inp", 3};
  NewmarkIncrement increment;
  for (const ElementType& type : test::supported_types()) {
    const int n = type.n_nodes;
    DofMap dofs{std::vector<int>(static_cast<std::size_t>(n), 0)};
    std::vector<int> nodes(static_cast<std::size_t>(n));
    std::iota(nodes.begin(), nodes.end(), 0);
    const std::vector<Eigen::Vector2d> coords = test::distorted_element(type.shape, 5);
    const ContinuumElement element(1, type, nodes, coords, material, 1.0, dofs, &data);
    for (const MassKind kind : {MassKind::Consistent, MassKind::Lumped}) {
      const std::string what = std::string(type.name) + (kind == MassKind::Lumped ? " lumped" : " consistent");
      Eigen::MatrixXd expected;
      element.mass(kind, expected);
      ElementInertia m(element, kind, 0, 0, increment);
      EXPECT_EQ(m.stored_mass_values(), kind == MassKind::Lumped ? n : n * n) << what;
      EXPECT_EQ(m.mass(), expected) << what;
      EXPECT_EQ(m.mass_diagonal(), Eigen::VectorXd(expected.diagonal())) << what;
      for (Eigen::Index i = 0; i < expected.rows(); ++i)
        for (Eigen::Index j = 0; j < expected.cols(); ++j) ASSERT_EQ(m.mass_entry(i, j), expected(i, j)) << what;
      // Redistribution away from node 0 keeps the (2n)^2 result of redistribute_mass.
      std::vector<bool> massless(static_cast<std::size_t>(n), false);
      massless[0] = true;
      Eigen::MatrixXd lumped;
      element.mass(MassKind::Lumped, lumped);
      Eigen::VectorXd weights(n);
      for (int a = 0; a < n; ++a) weights[a] = lumped(2 * a, 2 * a);
      ASSERT_TRUE(m.redistribute(massless)) << what;
      const Eigen::MatrixXd moved = redistribute_mass(expected, 2, weights, massless, kind == MassKind::Lumped);
      EXPECT_EQ(m.stored_mass_values(), 4 * n * n) << what;
      EXPECT_EQ(m.mass(), moved) << what;
      EXPECT_EQ(m.mass_entry(1, 1), moved(1, 1)) << what;
      EXPECT_EQ(m.mass_entry(0, 2), moved(0, 2)) << what;
    }
  }
}

}  // namespace
}  // namespace tether
