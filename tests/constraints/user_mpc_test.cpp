// ABAQUS-style user MPCs (user_mpc.h, UserMpcConstraint): the worked example
// of examples/user_mpc against DistanceConstraint, finite-difference tangents
// of the multiplier element (the Hessian is itself numerical, hence 1e-6),
// the numerical Hessian against an exact one, what tether passes to the
// routine, and the errors for broken routines.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "support/error_message.hpp"
#include "support/tangent_check.hpp"
#include "tether/constraints/constraint_element.hpp"
#include "tether/constraints/distance_constraint.hpp"
#include "tether/constraints/user_mpc_constraint.hpp"
#include "tether/core/error.hpp"
#include "tether/dofs/dof_map.hpp"

using namespace tether;

namespace {

const std::string kExample = TETHER_USER_MPC_EXAMPLE;  // built from examples/user_mpc/user_mpc.cpp
const std::string kTest = TETHER_USER_MPC_TEST;        // user_mpc_misbehaving.cpp, symbol test_user_mpc

/// Four nodes labelled 10, 20, 30, 40 at these reference positions.
struct Fixture {
  DofMap dofs{std::vector<int>{10, 20, 30, 40}};
  std::vector<Eigen::Vector2d> x{{0.0, 0.0}, {0.3, -0.2}, {0.6, 1.4}, {1.4, 1.9}};

  std::vector<Eigen::Vector2d> at(const std::vector<int>& nodes) const {
    std::vector<Eigen::Vector2d> r;
    for (const int a : nodes) r.push_back(x[a]);
    return r;
  }
  std::vector<int> labels(const std::vector<int>& nodes) const {
    std::vector<int> r;
    for (const int a : nodes) r.push_back(10 * (a + 1));
    return r;
  }
  /// The example's rigid link: dependent u_y of node a, entries a, a, b, b.
  std::unique_ptr<UserMpcConstraint> link(int a, int b, UserMpcOptions options = {}) const {
    const std::vector<int> nodes{a, a, b, b};
    return std::make_unique<UserMpcConstraint>(kExample, "", UserMpcMode::Dof, 1, nodes, labels(nodes), at(nodes),
                                               dofs, "LINK-MPC", options);
  }
  /// The example's rotation: node p follows node b rotated about node c.
  std::unique_ptr<UserMpcConstraint> rotation(int p, int b, int c) const {
    const std::vector<int> nodes{p, b, c};
    return std::make_unique<UserMpcConstraint>(kExample, "", UserMpcMode::Node, 2, nodes, labels(nodes), at(nodes),
                                               dofs, "ROT-MPC");
  }
  UserMpcConstraint test(int jtype, std::vector<int> nodes, UserMpcMode mode = UserMpcMode::Dof,
                         UserMpcOptions options = {}) const {
    return {kTest, "test_user_mpc", mode, jtype, nodes, labels(nodes), at(nodes), dofs, "BAD", options};
  }
};

Eigen::VectorXd random_vector(Eigen::Index n, std::mt19937& rng, double scale) {
  std::uniform_real_distribution<double> d(-scale, scale);
  Eigen::VectorXd v(n);
  for (Eigen::Index i = 0; i < n; ++i) v[i] = d(rng);
  return v;
}

ConstraintOutput evaluate(const ConstraintFunction& f, const Eigen::VectorXd& u, bool hessian) {
  ConstraintInput in;
  in.u = u;
  in.u_start = Eigen::VectorXd::Zero(u.size());
  ConstraintOutput out;
  out.reset(f.n_equations(), static_cast<Eigen::Index>(f.dofs().size()), hessian);
  f.evaluate(in, out, hessian);
  return out;
}

template <class F>
std::string error_of(F&& f) {
  return tether::testing::model_error_of(std::forward<F>(f));
}

}  // namespace

TEST(UserMpc, DofLinkHasTheDistanceConstraintsZeroSetAndGradientDirection) {
  const Fixture fx;
  const auto mpc = fx.link(1, 2);
  ASSERT_EQ(mpc->n_equations(), 1);
  // Node 1 appears twice in the node list but once in the dofs.
  EXPECT_EQ(std::vector<int>(mpc->dofs().begin(), mpc->dofs().end()), (std::vector<int>{2, 3, 4, 5}));
  EXPECT_EQ(mpc->dependent_dofs(), (std::vector<int>{3}));  // u_y of node 1
  const DistanceConstraint distance({2, 3, 4, 5}, fx.x[1], fx.x[2], "LINK");
  const double length = (fx.x[2] - fx.x[1]).norm();

  std::mt19937 rng(11);
  for (int trial = 0; trial < 5; ++trial) {
    Eigen::VectorXd u = random_vector(4, rng, 0.3);
    // Put u_y(a) on the constraint: the branch of the reference (y_a < y_b).
    const double dx = fx.x[1].x() + u[0] - fx.x[2].x() - u[2];
    u[1] = fx.x[2].y() + u[3] - std::sqrt(length * length - dx * dx) - fx.x[1].y();
    const ConstraintOutput m = evaluate(*mpc, u, false), d = evaluate(distance, u, false);
    EXPECT_NEAR(m.f[0], 0.0, 1e-14);
    EXPECT_NEAR(d.f[0], 0.0, 1e-14);
    // Same direction, normalised so that df/du_dep = 1.
    EXPECT_DOUBLE_EQ(m.gradient(0, 1), 1.0);
    EXPECT_LT((m.gradient - d.gradient / d.gradient(0, 1)).cwiseAbs().maxCoeff(), 1e-13) << m.gradient;

    // Off the constraint: f = u_y(a) - UE exactly, and to first order the distance
    // constraint's f is its df/du_y(a) times that.
    for (const double delta : {1e-3, -2e-3}) {
      Eigen::VectorXd v = u;
      v[1] += delta;
      const ConstraintOutput mv = evaluate(*mpc, v, false), dv = evaluate(distance, v, false);
      EXPECT_NEAR(mv.f[0], delta, 1e-14);
      EXPECT_NEAR(dv.f[0], d.gradient(0, 1) * mv.f[0], 10 * delta * delta);
    }
  }
}

TEST(UserMpc, DofLinkTangentUnderLagrangeMatchesFiniteDifferences) {
  Fixture fx;
  const int first = fx.dofs.add_multipliers(1, "LINK-MPC");
  const ConstraintElement element(fx.link(1, 2), {Enforcement::Method::Lagrange, 0.0}, first, "LINK-MPC", {1, 2});
  Enforcement penalty;
  penalty.method = Enforcement::Method::Penalty;
  penalty.penalty = 50;
  const ConstraintElement penalised(fx.link(1, 2), penalty, first, "LINK-MPC", {1, 2});
  std::mt19937 rng(13);
  for (int trial = 0; trial < 4; ++trial) {
    Eigen::VectorXd u = random_vector(fx.dofs.n_dofs(), rng, 0.3);
    u[first] = 4.0 * (trial + 1);  // a multiplier large enough for the curvature to matter
    const double e = tether::testing::tangent_error(element, EvaluationState{u, u});
    EXPECT_LT(e, 1e-6);
    EXPECT_LT(tether::testing::tangent_error(penalised, EvaluationState{u, u}), 1e-6);
  }
  // Without the curvature (numerical_hessian = false) the check fails: the Hessian matters.
  UserMpcOptions off;
  off.numerical_hessian = false;
  const ConstraintElement no_curvature(fx.link(1, 2, off), {Enforcement::Method::Lagrange, 0.0}, first, "L", {1, 2});
  Eigen::VectorXd u = Eigen::VectorXd::Zero(fx.dofs.n_dofs());
  u[first] = 5.0;
  EXPECT_GT(tether::testing::tangent_error(no_curvature, EvaluationState{u, u}), 1e-2);
}

TEST(UserMpc, NodeRotationFollowsTheRigidRotationAndPassesTheTangentCheck) {
  Fixture fx;
  const auto rot = fx.rotation(3, 2, 1);  // node 3 follows node 2 rotated about node 1
  ASSERT_EQ(rot->n_equations(), 2);
  EXPECT_EQ(rot->dependent_dofs(), (std::vector<int>{6, 7}));
  // A rigid motion (rotation phi about node 1 plus a translation) satisfies it.
  const double phi = 0.7;
  const Eigen::Rotation2Dd r(phi);
  const Eigen::Vector2d t(0.2, -0.1);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(8);
  for (int a = 1; a <= 3; ++a)
    u.segment<2>(2 * a) = fx.x[1] + t + r * (fx.x[a] - fx.x[1]) - fx.x[a];
  u.segment<2>(4) += 0.3 * (r * (fx.x[2] - fx.x[1]));  // stretching c-b does not change the angle
  Eigen::VectorXd local(6);  // dofs(): node 3, node 2, node 1 (order of the node list)
  for (int i = 0; i < 6; ++i) local[i] = u[rot->dofs()[i]];
  EXPECT_EQ(std::vector<int>(rot->dofs().begin(), rot->dofs().end()), (std::vector<int>{6, 7, 4, 5, 2, 3}));
  const ConstraintOutput out = evaluate(*rot, local, false);
  EXPECT_LT(out.f.cwiseAbs().maxCoeff(), 1e-14) << out.f;
  EXPECT_TRUE(out.gradient.block(0, 0, 2, 2).isApprox(Eigen::Matrix2d::Identity(), 1e-14));

  const int first = fx.dofs.add_multipliers(2, "ROT-MPC");
  const ConstraintElement element(fx.rotation(3, 2, 1), {Enforcement::Method::Lagrange, 0.0}, first, "ROT-MPC",
                                  {3, 2, 1});
  std::mt19937 rng(17);
  for (int trial = 0; trial < 4; ++trial) {
    Eigen::VectorXd v = random_vector(fx.dofs.n_dofs(), rng, 0.3);
    v.segment<2>(first) = random_vector(2, rng, 5.0);
    EXPECT_LT(tether::testing::tangent_error(element, EvaluationState{v, v}), 1e-6);
  }
}

TEST(UserMpc, NumericalHessianMatchesTheExactOne) {
  const Fixture fx;
  // JTYPE 8: UE = (u_x(b)^2, sin u_y(b)), A(.,.,1) = M (not the identity).
  const UserMpcConstraint f = fx.test(8, {0, 3}, UserMpcMode::Node);
  Eigen::VectorXd u(4);
  u << 0.1, -0.2, 0.35, 0.8;
  const ConstraintOutput out = evaluate(f, u, true);
  EXPECT_NEAR(out.f[0], 0.1 - 0.35 * 0.35, 1e-15);
  EXPECT_NEAR(out.f[1], -0.2 - std::sin(0.8), 1e-15);
  Eigen::MatrixXd g(2, 4);
  g << 1, 0, -0.7, 0, 0, 1, 0, -std::cos(0.8);
  EXPECT_LT((out.gradient - g).cwiseAbs().maxCoeff(), 1e-14) << out.gradient;
  Eigen::MatrixXd h0 = Eigen::MatrixXd::Zero(4, 4), h1 = Eigen::MatrixXd::Zero(4, 4);
  h0(2, 2) = -2;
  h1(3, 3) = std::sin(0.8);
  ASSERT_EQ(out.hessian.size(), 2u);
  EXPECT_LT((out.hessian[0] - h0).cwiseAbs().maxCoeff(), 1e-8) << out.hessian[0];
  EXPECT_LT((out.hessian[1] - h1).cwiseAbs().maxCoeff(), 1e-8) << out.hessian[1];

  // Switched off: zero Hessians, same f and gradient.
  UserMpcOptions off;
  off.numerical_hessian = false;
  const ConstraintOutput plain = evaluate(fx.test(8, {0, 3}, UserMpcMode::Node, off), u, true);
  EXPECT_EQ(plain.gradient, out.gradient);
  EXPECT_EQ(plain.hessian[0], Eigen::MatrixXd::Zero(4, 4));
}

TEST(UserMpc, CoefficientsAreNormalisedByTheDependentOne) {
  const Fixture fx;
  // JTYPE 9: u_x(0) = 0.5 u_x(2) - 2 u_y(2), written with A = -4 (1, -0.5, 2).
  const UserMpcConstraint f = fx.test(9, {0, 2, 2});
  EXPECT_FALSE(f.linear());
  EXPECT_EQ(std::vector<int>(f.dofs().begin(), f.dofs().end()), (std::vector<int>{0, 1, 4, 5}));
  Eigen::VectorXd u(4);
  u << 0.3, 0.0, 0.2, -0.1;
  const ConstraintOutput out = evaluate(f, u, true);
  EXPECT_NEAR(out.f[0], 0.3 - (0.5 * 0.2 + 0.2), 1e-15);
  EXPECT_EQ(out.gradient, (Eigen::MatrixXd(1, 4) << 1, 0, -0.5, 2).finished());
  EXPECT_LT(out.hessian[0].cwiseAbs().maxCoeff(), 1e-9);
}

TEST(UserMpc, RoutineReceivesTheDocumentedInputs) {
  const Fixture fx;
  const UserMpcConstraint f(kTest, "test_user_mpc", UserMpcMode::Dof, 10, {0, 2, 3}, {10, 30, 40},
                            fx.at({0, 2, 3}), fx.dofs, "ECHO");
  ConstraintInput in;
  in.u = (Eigen::VectorXd(6) << 5, 0, 0, 0.25, 0, 0.5).finished();
  in.u_start = (Eigen::VectorXd(6) << 0, 0, 0.01, 0, 0.02, 0).finished();
  in.step_time = 0.5;
  in.total_time = 1.5;
  ConstraintOutput out;
  out.reset(1, 6, true);
  f.evaluate(in, out, true);
  EXPECT_DOUBLE_EQ(out.f[0], 5 - (0.5 + 150));  // UE = TIME(1) + 100 TIME(2) at the unperturbed call
  // A(k) = X(1,k) + 10 U(2,k) + 100 UINIT(1,k) on u_x of node entry k.
  EXPECT_DOUBLE_EQ(out.gradient(0, 2), 0.6 + 2.5 + 1.0);
  EXPECT_DOUBLE_EQ(out.gradient(0, 4), 1.4 + 5.0 + 2.0);
  EXPECT_DOUBLE_EQ(out.gradient(0, 0), 1.0);
  // d A(k) / d U(2,k) = 10 shows up in the (symmetrised) numerical Hessian.
  EXPECT_NEAR(out.hessian[0](2, 3), 5.0, 1e-6);
  EXPECT_NEAR(out.hessian[0](4, 5), 5.0, 1e-6);
}

TEST(UserMpc, MissingLibraryAndSymbolNameTheConstraint) {
  const Fixture fx;
  std::string what = error_of([&] {
    UserMpcConstraint("/nonexistent/libno_mpc.so", "my_mpc", UserMpcMode::Dof, 1, {0, 1}, {10, 20}, fx.at({0, 1}),
                      fx.dofs, "GONE");
  });
  EXPECT_NE(what.find("GONE"), std::string::npos) << what;
  EXPECT_NE(what.find("/nonexistent/libno_mpc.so"), std::string::npos) << what;
  EXPECT_NE(what.find("my_mpc"), std::string::npos) << what;
  EXPECT_NE(what.find("No such file"), std::string::npos) << what;
  // The test library has no routine under the default name.
  what = error_of([&] {
    UserMpcConstraint(kTest, "", UserMpcMode::Dof, 9, {0, 2, 2}, {10, 30, 30}, fx.at({0, 2, 2}), fx.dofs, "NOSYM");
  });
  EXPECT_NE(what.find("NOSYM"), std::string::npos) << what;
  EXPECT_NE(what.find("'tether_user_mpc'"), std::string::npos) << what;
  EXPECT_NE(what.find("undefined symbol"), std::string::npos) << what;
}

TEST(UserMpc, BrokenRoutinesAreModelErrorsNamingTheConstraint) {
  const Fixture fx;
  auto built = [&](int jtype, UserMpcMode mode = UserMpcMode::Dof) {
    return error_of([&] { fx.test(jtype, {0, 1, 2}, mode); });
  };
  std::string what = built(1);
  EXPECT_NE(what.find("user MPC BAD"), std::string::npos) << what;
  EXPECT_NE(what.find("status 7"), std::string::npos) << what;
  EXPECT_NE(what.find("JTYPE makes no sense for BAD"), std::string::npos) << what;
  EXPECT_NE(what.find("reference configuration"), std::string::npos) << what;
  EXPECT_NE(what.find(kTest), std::string::npos) << what;
  what = built(2);
  EXPECT_NE(what.find("non-finite UE(1)"), std::string::npos) << what;
  what = built(3);
  EXPECT_NE(what.find("JDOF(1) = 3"), std::string::npos) << what;
  EXPECT_NE(what.find("node 10"), std::string::npos) << what;
  what = built(4);
  EXPECT_NE(what.find("A(1) = 0"), std::string::npos) << what;
  what = built(5);
  EXPECT_NE(what.find("LMPC = 0"), std::string::npos) << what;
  what = built(7, UserMpcMode::Node);
  EXPECT_NE(what.find("singular block A(.,.,1)"), std::string::npos) << what;
  what = built(11, UserMpcMode::Node);
  EXPECT_NE(what.find("A(1,2,2)"), std::string::npos) << what;
  EXPECT_NE(what.find("JDOF(2,2) is 0"), std::string::npos) << what;
  // The example refuses a JTYPE in the wrong mode, with its own message.
  what = error_of([&] {
    UserMpcConstraint(kExample, "", UserMpcMode::Node, 1, {0, 0, 1, 1}, {10, 10, 20, 20}, fx.at({0, 0, 1, 1}),
                      fx.dofs, "WRONG");
  });
  EXPECT_NE(what.find("JTYPE 1 (rigid link) needs MODE=DOF"), std::string::npos) << what;

  // Built fine, then the routine switches its dependent dof during the analysis.
  const UserMpcConstraint switching = fx.test(6, {0, 1});
  Eigen::VectorXd u = Eigen::VectorXd::Zero(4);
  EXPECT_NO_THROW(evaluate(switching, u, true));
  u[2] = 1.0;
  what = error_of([&] { evaluate(switching, u, false); });
  EXPECT_NE(what.find("changed its dependent dof"), std::string::npos) << what;
}

TEST(UserMpc, LinkWithinAConstraintElementReportsTheDependentForce) {
  // In MODE=DOF, df/du_dep = 1: the multiplier is minus the force the MPC puts on the dependent dof.
  Fixture fx;
  const int first = fx.dofs.add_multipliers(1, "LINK-MPC");
  const ConstraintElement element(fx.link(1, 2), {Enforcement::Method::Lagrange, 0.0}, first, "LINK-MPC", {1, 2});
  Eigen::VectorXd u = Eigen::VectorXd::Zero(fx.dofs.n_dofs());
  u[first] = -3.0;
  const MultiplierValues v = element.values(EvaluationState{u, u}, fx.dofs);
  ASSERT_EQ(v.nodal_force.size(), 2u);
  EXPECT_EQ(v.nodal_force[0].node, 1);
  EXPECT_DOUBLE_EQ(v.nodal_force[0].force.y(), 3.0);
  // Equal and opposite on the two nodes (the link transmits a force along itself).
  EXPECT_LT((v.nodal_force[0].force + v.nodal_force[1].force).norm(), 1e-14);
  const Eigen::Vector2d along = fx.x[2] - fx.x[1];
  EXPECT_LT(std::abs(along.x() * v.nodal_force[0].force.y() - along.y() * v.nodal_force[0].force.x()), 1e-13);
}

TEST(UserMpc, ExampleDeckProblemSolvedByNewtonMatchesTheExactAnswer) {
  // examples/user_mpc/user_mpc.inp without the deck: pin A (node 0) fixed, B
  // (node 1) on a rigid link of length 2 to A (JTYPE 1, u_y(B) dependent), x_B
  // driven from L cos 80 deg to L cos 10 deg in 20 increments, P = 3 down on B;
  // C (node 2) rotates rigidly with AB about A (JTYPE 2), Q = 1 down on C.
  const double length = 2, pi = std::acos(-1.0), p_load = 3, q_load = 1;
  DofMap dofs(std::vector<int>{1, 2, 3});
  const std::vector<Eigen::Vector2d> x{
      {0, 0}, {length * std::cos(80 * pi / 180), -length * std::sin(80 * pi / 180)}, {1.5, -1.0}};
  const int link_first = dofs.add_multipliers(1, "LINK");
  const int rot_first = dofs.add_multipliers(2, "ROTATE");
  auto at = [&](std::vector<int> nodes) {
    std::vector<Eigen::Vector2d> r;
    for (const int a : nodes) r.push_back(x[a]);
    return r;
  };
  const ConstraintElement link(
      std::make_unique<UserMpcConstraint>(kExample, "", UserMpcMode::Dof, 1, std::vector<int>{1, 1, 0, 0},
                                          std::vector<int>{2, 2, 1, 1}, at({1, 1, 0, 0}), dofs, "LINK"),
      {Enforcement::Method::Lagrange, 0.0}, link_first, "LINK", {1, 0});
  const ConstraintElement rotate(
      std::make_unique<UserMpcConstraint>(kExample, "", UserMpcMode::Node, 2, std::vector<int>{2, 1, 0},
                                          std::vector<int>{3, 2, 1}, at({2, 1, 0}), dofs, "ROTATE"),
      {Enforcement::Method::Lagrange, 0.0}, rot_first, "ROTATE", {2, 1, 0});
  const int n = dofs.n_dofs();
  const std::vector<int> free{3, 4, 5, link_first, rot_first, rot_first + 1};
  Eigen::VectorXd f_ext = Eigen::VectorXd::Zero(n);
  f_ext[3] = -p_load;
  f_ext[5] = -q_load;
  Eigen::VectorXd u = Eigen::VectorXd::Zero(n);
  const double x_end = length * std::cos(10 * pi / 180);
  int iterations = 0;
  for (int inc = 1; inc <= 20; ++inc) {
    const Eigen::VectorXd u_start = u;
    u[2] = (x_end - x[1].x()) * inc / 20.0;
    for (int it = 0; it < 20; ++it, ++iterations) {
      Eigen::VectorXd r = -f_ext;
      Eigen::MatrixXd k = Eigen::MatrixXd::Zero(n, n);
      for (const ConstraintElement* c : {&link, &rotate}) {
        LocalSystem s;
        s.reset(static_cast<Eigen::Index>(c->dofs().size()));
        c->evaluate(EvaluationState{u, u_start}, s, true);
        for (Eigen::Index i = 0; i < s.residual.size(); ++i) {
          r[c->dofs()[i]] += s.residual[i];
          for (Eigen::Index j = 0; j < s.residual.size(); ++j) k(c->dofs()[i], c->dofs()[j]) += s.tangent(i, j);
        }
      }
      Eigen::VectorXd rf(6);
      Eigen::MatrixXd kf(6, 6);
      for (int i = 0; i < 6; ++i) {
        rf[i] = r[free[i]];
        for (int j = 0; j < 6; ++j) kf(i, j) = k(free[i], free[j]);
      }
      if (rf.norm() < 1e-11) break;
      const Eigen::VectorXd du = kf.fullPivLu().solve(-rf);
      for (int i = 0; i < 6; ++i) u[free[i]] += du[i];
    }
  }
  EXPECT_LE(iterations, 20 * 5);  // quadratic convergence: a few iterations per increment
  const Eigen::Vector2d b(x_end, -length * std::sin(10 * pi / 180));
  const Eigen::Vector2d c = Eigen::Rotation2Dd(70 * pi / 180) * x[2];
  EXPECT_NEAR(u[2] + x[1].x(), b.x(), 1e-12);
  EXPECT_NEAR(u[3] + x[1].y(), b.y(), 1e-10);
  EXPECT_LT((u.segment<2>(4) + x[2] - c).norm(), 1e-10);
  EXPECT_NEAR(u[rot_first], 0.0, 1e-10);
  EXPECT_NEAR(u[rot_first + 1], -q_load, 1e-10);
  EXPECT_NEAR(u[link_first], -p_load - q_load * c.x() * b.x() / (length * length), 1e-10);
}

TEST(UserMpc, ElementDeclaresANonlinearTangentThatIsNotVouchedSymmetric) {
  // The Hessians are symmetrised central differences, but user MPCs are
  // solved as unsymmetric (LU), as they always were: declared so.
  Fixture fx;
  const int first = fx.dofs.add_multipliers(1, "LINK-MPC");
  const ConstraintElement element(fx.link(1, 2), {Enforcement::Method::Lagrange, 0.0}, first, "LINK-MPC", {1, 2});
  for (bool nlgeom : {false, true}) {
    EXPECT_FALSE(element.symmetric_tangent(nlgeom));
    EXPECT_FALSE(element.linear_in_u(nlgeom));
  }
}
