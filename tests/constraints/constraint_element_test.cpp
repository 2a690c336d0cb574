// Finite-difference checks of every constraint function and of the
// constraint element's residual and tangent under each enforcement.

#include <gtest/gtest.h>

#include <random>

#include "tether/constraints/beam_constraint.hpp"
#include "tether/constraints/constraint_element.hpp"
#include "tether/constraints/distance_constraint.hpp"
#include "tether/constraints/linear_constraint.hpp"
#include "tether/dofs/dof_map.hpp"
#include "support/tangent_check.hpp"

using namespace tether;

namespace {

constexpr int kDofs = 8;  // 4 nodes x 2 dofs; multipliers follow

std::unique_ptr<ConstraintFunction> make_function(int which) {
  switch (which) {
    case 0:
      return std::make_unique<LinearConstraint>(
          std::vector<std::vector<LinearTerm>>{{{0, 1.0}, {2, -1.0}}, {{1, 2.0}, {5, 0.5}, {7, -3.0}}}, "linear");
    case 1:
      return std::make_unique<DistanceConstraint>(std::array<int, 4>{2, 3, 6, 7}, Eigen::Vector2d(0.3, -0.2),
                                                  Eigen::Vector2d(1.4, 0.9), "link");
    default:
      return std::make_unique<SliderConstraint>(std::array<int, 6>{0, 1, 4, 5, 6, 7}, Eigen::Vector2d(0.5, 0.4),
                                                Eigen::Vector2d(0, 0), Eigen::Vector2d(1.2, 0.1), "slider");
  }
}

Eigen::VectorXd random_vector(int n, std::mt19937& rng, double scale) {
  std::uniform_real_distribution<double> d(-scale, scale);
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i) v[i] = d(rng);
  return v;
}

double tangent_error(const Contribution& c, const Eigen::VectorXd& u) {
  return tether::testing::tangent_error(c, EvaluationState{u, u});
}

}  // namespace

TEST(ConstraintFunctions, GradientAndHessianMatchFiniteDifferences) {
  std::mt19937 rng(7);
  for (int which = 0; which < 3; ++which) {
    auto f = make_function(which);
    const int n = static_cast<int>(f->dofs().size()), m = f->n_equations();
    for (int trial = 0; trial < 3; ++trial) {
      ConstraintInput in;
      in.u = random_vector(n, rng, 0.3);
      in.u_start = in.u;
      ConstraintOutput out;
      out.reset(m, n, true);
      f->evaluate(in, out, true);
      const double h = 1e-6;
      for (int j = 0; j < n; ++j) {
        ConstraintInput p = in, q = in;
        p.u[j] += h;
        q.u[j] -= h;
        ConstraintOutput op, oq;
        op.reset(m, n, false);
        oq.reset(m, n, false);
        f->evaluate(p, op, false);
        f->evaluate(q, oq, false);
        const Eigen::VectorXd dfdu = (op.f - oq.f) / (2 * h);
        EXPECT_LT((dfdu - out.gradient.col(j)).cwiseAbs().maxCoeff(), 1e-8) << f->describe() << " dof " << j;
        const Eigen::MatrixXd dg = (op.gradient - oq.gradient) / (2 * h);
        for (int k = 0; k < m; ++k) {
          const Eigen::VectorXd hk = f->linear() ? Eigen::VectorXd::Zero(n) : Eigen::VectorXd(out.hessian[k].col(j));
          EXPECT_LT((dg.row(k).transpose() - hk).cwiseAbs().maxCoeff(), 1e-7) << f->describe() << " dof " << j;
        }
      }
    }
  }
}

TEST(ConstraintElement, TangentMatchesFiniteDifferencesForEveryEnforcement) {
  std::mt19937 rng(11);
  const std::vector<Enforcement> methods = {
      {Enforcement::Method::Lagrange, 0.0},
      {Enforcement::Method::Lagrange, 0.1},
      {Enforcement::Method::Penalty, 0, 50.0},
      {Enforcement::Method::Augmented, 0, 50.0, 1e-14},
  };
  for (int which = 0; which < 3; ++which) {
    for (const auto& e : methods) {
      for (int trial = 0; trial < 3; ++trial) {
        auto f = make_function(which);
        const int m = f->n_equations();
        ConstraintElement element(std::move(f), e, kDofs, "c", {});
        Eigen::VectorXd u = random_vector(kDofs + m, rng, 0.3);
        if (e.method == Enforcement::Method::Augmented) {
          // Give lambda_bar a nonzero value first, so the curvature term is exercised.
          Eigen::VectorXd start = random_vector(kDofs + m, rng, 0.3);
          ASSERT_EQ(element.on_converged(EvaluationState{start, start}), Acceptance::Iterate);
        }
        EXPECT_LT(tangent_error(element, u), 1e-7) << to_string(e.method) << " eps " << e.epsilon << " function "
                                                   << which;
      }
    }
  }
}

TEST(ConstraintElement, DeclaredSymmetryAndLinearityHoldAtRandomStates) {
  // What the element declares (StepSystem picks the factorization from it)
  // is checked on its tangent: symmetric where it says so, and the same
  // matrix at different states where it says it is linear in u.
  std::mt19937 rng(5);
  const std::vector<Enforcement> methods = {{Enforcement::Method::Lagrange, 0.0},
                                            {Enforcement::Method::Lagrange, 0.1},
                                            {Enforcement::Method::Penalty, 0, 50.0},
                                            {Enforcement::Method::Augmented, 0, 50.0, 1e-14}};
  for (int which = 0; which < 3; ++which)
    for (const auto& e : methods) {
      auto f = make_function(which);
      const int m = f->n_equations();
      const ConstraintElement element(std::move(f), e, kDofs, "c", {});
      EXPECT_TRUE(element.symmetric_tangent(false));
      EXPECT_EQ(element.linear_in_u(true), which == 0) << "function " << which;
      const auto n = static_cast<Eigen::Index>(element.dofs().size());
      LocalSystem a, b;
      a.reset(n), b.reset(n);
      const Eigen::VectorXd ua = random_vector(kDofs + m, rng, 0.3), ub = random_vector(kDofs + m, rng, 0.3);
      element.evaluate(EvaluationState{ua, ua}, a, true);
      element.evaluate(EvaluationState{ub, ub}, b, true);
      EXPECT_LT((a.tangent - a.tangent.transpose()).norm(), 1e-12 * a.tangent.norm()) << "function " << which;
      const double change = (a.tangent - b.tangent).norm() / a.tangent.norm();
      if (element.linear_in_u(false))
        EXPECT_EQ(change, 0.0) << to_string(e.method);
      else
        EXPECT_GT(change, 1e-6) << "function " << which << " " << to_string(e.method);
    }
}

TEST(ConstraintElement, SeedEqualityExample) {
  // u_a - u_b = 0 with multiplier: r = [lambda, -lambda, u_a - u_b - eps lambda],
  // K = [[0, 0, 1], [0, 0, -1], [1, -1, -eps]] (seed, page 3, with our sign convention r = -seed r).
  auto f = std::make_unique<LinearConstraint>(std::vector<std::vector<LinearTerm>>{{{0, 1.0}, {1, -1.0}}}, "eq");
  ConstraintElement element(std::move(f), {Enforcement::Method::Lagrange, 0.25}, 2, "eq", {});
  Eigen::Vector3d u(0.7, 0.2, 3.0);
  LocalSystem s;
  s.reset(3);
  element.evaluate(EvaluationState{u, u}, s, true);
  EXPECT_TRUE(s.residual.isApprox(Eigen::Vector3d(3.0, -3.0, 0.5 - 0.25 * 3.0)));
  Eigen::Matrix3d k;
  k << 0, 0, 1, 0, 0, -1, 1, -1, -0.25;
  EXPECT_TRUE(s.tangent.isApprox(k));
}

TEST(ConstraintElement, AugmentedUpdatesUntilTolerance) {
  auto f = std::make_unique<LinearConstraint>(std::vector<std::vector<LinearTerm>>{{{0, 1.0}}}, "eq");
  ConstraintElement element(std::move(f), {Enforcement::Method::Augmented, 0, 10.0, 1e-6}, -1, "eq", {});
  Eigen::VectorXd u(1);
  u << 0.5;
  EXPECT_EQ(element.on_converged(EvaluationState{u, u}), Acceptance::Iterate);
  EXPECT_EQ(element.n_updates(), 1);
  const DofMap map({1});  // dof 0: x of the one node
  EXPECT_DOUBLE_EQ(element.values(EvaluationState{u, u}, map).value[0], 5.0 + 10.0 * 0.5);
  u << 1e-7;
  EXPECT_EQ(element.on_converged(EvaluationState{u, u}), Acceptance::Accept);
}

TEST(ConstraintElement, BeamTangentMatchesFiniteDifferences) {
  std::mt19937 rng(5);
  for (const auto& e : std::vector<Enforcement>{{Enforcement::Method::Lagrange, 0.0},
                                                {Enforcement::Method::Penalty, 0, 30.0}}) {
    for (int trial = 0; trial < 3; ++trial) {
      auto f = std::make_unique<BeamConstraint>(std::array<int, 5>{0, 1, 2, 3, 8}, Eigen::Vector2d(1.2, -0.4),
                                                Eigen::Vector2d(0.1, 0.3), "beam");
      ConstraintElement element(std::move(f), e, 9, "beam", {});
      Eigen::VectorXd u = random_vector(11, rng, 0.8);  // theta up to 0.8 rad
      EXPECT_LT(tangent_error(element, u), 1e-7) << to_string(e.method);
    }
  }
}
