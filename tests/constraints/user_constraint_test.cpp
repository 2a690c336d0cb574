// The user-constraint plug-in: the worked example (examples/user_constraint)
// against the built-in multiplier element, finite-difference tangent, what
// tether passes to the routine, and the errors for broken plug-ins.

#include <gtest/gtest.h>

#include <random>

#include "support/error_message.hpp"
#include "support/tangent_check.hpp"
#include "tether/constraints/constraint_element.hpp"
#include "tether/constraints/linear_constraint.hpp"
#include "tether/constraints/user_constraint_element.hpp"
#include "tether/core/error.hpp"
#include "tether/dofs/dof_map.hpp"

using namespace tether;

namespace {

const std::string kExample = TETHER_USER_CONSTRAINT_EXAMPLE;    // libequal_displacement built from examples/
const std::string kMisbehaving = TETHER_USER_CONSTRAINT_FAILING;  // user_constraint_failing.cpp

/// Four nodes labelled 10, 20, 30, 40 and one multiplier block of size 1.
struct Fixture {
  DofMap dofs{std::vector<int>{10, 20, 30, 40}};
  int first = dofs.add_multipliers(1, "constraint U");
  std::vector<Eigen::Vector2d> reference{{1.0, 0.0}, {1.0, 0.5}};

  /// The example tying component `component` (1 or 2) of nodes 1 and 3 (labels 20, 40).
  UserConstraintElement example(int component, double eps) const {
    return {kExample, "", 1, {1, 3}, {20, 40}, reference, {double(component), eps}, 1, first, dofs, "U"};
  }
  UserConstraintElement misbehaving(double mode, std::string symbol = "misbehaving_constraint") const {
    return {kMisbehaving, std::move(symbol), 2, {1, 3}, {20, 40}, reference, {mode}, 1, first, dofs, "BAD"};
  }
};

Eigen::VectorXd random_vector(int n, std::mt19937& rng, double scale) {
  std::uniform_real_distribution<double> d(-scale, scale);
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i) v[i] = d(rng);
  return v;
}

/// Residual and tangent of `c` scattered into global size.
std::pair<Eigen::VectorXd, Eigen::MatrixXd> global_system(const Contribution& c, const EvaluationState& state,
                                                          int n_dofs) {
  const auto dofs = c.dofs();
  const auto n = static_cast<Eigen::Index>(dofs.size());
  LocalSystem local;
  local.reset(n);
  c.evaluate(state, local, true);
  Eigen::VectorXd r = Eigen::VectorXd::Zero(n_dofs);
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(n_dofs, n_dofs);
  for (Eigen::Index i = 0; i < n; ++i) {
    r[dofs[i]] += local.residual[i];
    for (Eigen::Index j = 0; j < n; ++j) k(dofs[i], dofs[j]) += local.tangent(i, j);
  }
  return {r, k};
}

double tangent_error(const Contribution& c, const Eigen::VectorXd& u, const Eigen::VectorXd& u_start) {
  return tether::testing::tangent_error(c, EvaluationState{u, u_start});
}

template <class F>
std::string error_of(F&& f) {
  return tether::testing::model_error_of(std::forward<F>(f));
}

}  // namespace

TEST(UserConstraint, ExampleEqualsBuiltInConstraintElement) {
  const Fixture fx;
  std::mt19937 rng(3);
  for (int component = 1; component <= 2; ++component) {
    for (const double eps : {0.0, 0.25}) {
      const UserConstraintElement user = fx.example(component, eps);
      ASSERT_EQ(user.dofs().size(), 5u);
      auto f = std::make_unique<LinearConstraint>(
          std::vector<std::vector<LinearTerm>>{
              {{fx.dofs.displacement(1, component - 1), 1.0}, {fx.dofs.displacement(3, component - 1), -1.0}}},
          "u_a - u_b");
      const ConstraintElement builtin(std::move(f), {Enforcement::Method::Lagrange, eps}, fx.first, "U", {1, 3});
      for (int trial = 0; trial < 3; ++trial) {
        const Eigen::VectorXd u = random_vector(fx.dofs.n_dofs(), rng, 2.0);
        const Eigen::VectorXd u_start = random_vector(fx.dofs.n_dofs(), rng, 2.0);
        const EvaluationState state{u, u_start};
        const auto [r_user, k_user] = global_system(user, state, fx.dofs.n_dofs());
        const auto [r_builtin, k_builtin] = global_system(builtin, state, fx.dofs.n_dofs());
        EXPECT_LE((r_user - r_builtin).cwiseAbs().maxCoeff(), 1e-14) << "component " << component << " eps " << eps;
        EXPECT_LE((k_user - k_builtin).cwiseAbs().maxCoeff(), 1e-14) << "component " << component << " eps " << eps;
        EXPECT_GT(r_user.cwiseAbs().maxCoeff(), 0.1);

        const MultiplierValues vu = user.values(state), vb = builtin.values(state, fx.dofs);
        EXPECT_EQ(vu.owner, "U");
        EXPECT_EQ(vu.nodes, (std::vector<int>{1, 3}));
        ASSERT_EQ(vu.value.size(), 1u);
        EXPECT_DOUBLE_EQ(vu.value[0], vb.value[0]);
        // The user element reports the multiplier row f - eps*lambda as "f".
        EXPECT_NEAR(vu.constraint[0], vb.constraint[0] - eps * vb.value[0], 1e-14);
      }
    }
  }
}

TEST(UserConstraint, TangentMatchesFiniteDifferences) {
  const Fixture fx;
  std::mt19937 rng(5);
  for (int component = 1; component <= 2; ++component) {
    const UserConstraintElement user = fx.example(component, 0.1);
    for (int trial = 0; trial < 3; ++trial) {
      const Eigen::VectorXd u = random_vector(fx.dofs.n_dofs(), rng, 0.5);
      const Eigen::VectorXd u_start = random_vector(fx.dofs.n_dofs(), rng, 0.5);
      EXPECT_LT(tangent_error(user, u, u_start), 1e-8) << "component " << component;
    }
  }
}

TEST(UserConstraint, RoutineReceivesTheDocumentedInputs) {
  const Fixture fx;
  const UserConstraintElement echo(kMisbehaving, "echo_constraint", 4, {1, 3}, {20, 40}, fx.reference, {2.5, -1.0}, 1,
                                   fx.first, fx.dofs, "ECHO", 9);
  Eigen::VectorXd u(9), u_start(9);
  u << 0, 0, 0.1, 0.2, 0, 0, 0.3, 0.4, 7.0;
  u_start << 0, 0, 0.05, 0.05, 0, 0, 0.1, 0.1, 1.0;
  EvaluationState state{u, u_start};
  state.step_time = 0.5;
  state.total_time = 1.5;
  state.dt = 0.25;
  LocalSystem s;
  s.reset(5);
  echo.evaluate(state, s, true);
  const Eigen::MatrixXd& k = s.tangent;
  EXPECT_TRUE(k.col(0).head(4).isApprox(Eigen::Vector4d(1.0, 0.0, 1.0, 0.5)));
  EXPECT_TRUE(k.col(1).head(4).isApprox(Eigen::Vector4d(0.1, 0.2, 0.3, 0.4)));
  EXPECT_TRUE(k.col(2).head(4).isApprox(Eigen::Vector4d(0.05, 0.15, 0.2, 0.3)));
  EXPECT_EQ(Eigen::VectorXd(k.col(3)), (Eigen::VectorXd(5) << 4, 9, 1, 20, 40).finished());
  EXPECT_EQ(Eigen::VectorXd(k.col(4)),
            (Eigen::VectorXd(5) << 0.5, 1.5, 0.25, TETHER_USER_CONSTRAINT_VERSION, 2).finished());
  EXPECT_EQ(s.residual.head(3), Eigen::Vector3d(2.5, -1.0, 7.0));
  // Local dofs: the nodes' x, y, then the multiplier.
  EXPECT_EQ(std::vector<int>(echo.dofs().begin(), echo.dofs().end()), (std::vector<int>{2, 3, 6, 7, 8}));
}

TEST(UserConstraint, ConstraintsNamingOneLibraryShareOneHandle) {
  const Fixture fx;
  const auto a = SharedLibrary::open(kExample);
  const auto b = SharedLibrary::open(kExample);
  EXPECT_EQ(a.get(), b.get());
  const UserConstraintElement x = fx.example(1, 0), y = fx.example(2, 0);
  EXPECT_EQ(x.library_path(), kExample);
  EXPECT_EQ(x.symbol(), TETHER_USER_CONSTRAINT_DEFAULT_SYMBOL);
}

TEST(UserConstraint, MissingLibraryNamesPathSymbolAndLoaderError) {
  const Fixture fx;
  const std::string path = "/nonexistent/libnot_there.so";
  const std::string what = error_of([&] {
    UserConstraintElement(path, "my_routine", 1, {1, 3}, {20, 40}, fx.reference, {}, 1, fx.first, fx.dofs, "GONE");
  });
  EXPECT_NE(what.find(path), std::string::npos) << what;
  EXPECT_NE(what.find("my_routine"), std::string::npos) << what;
  EXPECT_NE(what.find("GONE"), std::string::npos) << what;
  EXPECT_NE(what.find("No such file"), std::string::npos) << what;  // dlerror()
}

TEST(UserConstraint, MissingSymbolNamesPathAndSymbol) {
  const Fixture fx;
  // The misbehaving library exports no tether_user_constraint.
  const std::string what = error_of([&] { fx.misbehaving(0, ""); });
  EXPECT_NE(what.find(kMisbehaving), std::string::npos) << what;
  EXPECT_NE(what.find("'tether_user_constraint'"), std::string::npos) << what;
  EXPECT_NE(what.find("undefined symbol"), std::string::npos) << what;  // dlerror()
}

TEST(UserConstraint, FailingRoutineIsAModelErrorWithItsMessage) {
  const Fixture fx;
  const Eigen::VectorXd u = Eigen::VectorXd::Zero(9);
  LocalSystem s;
  s.reset(5);
  const std::string what = error_of([&] { fx.misbehaving(1).evaluate(EvaluationState{u, u}, s, true); });
  EXPECT_NE(what.find("BAD"), std::string::npos) << what;
  EXPECT_NE(what.find("misbehaving_constraint"), std::string::npos) << what;
  EXPECT_NE(what.find(kMisbehaving), std::string::npos) << what;
  EXPECT_NE(what.find("status 7"), std::string::npos) << what;
  EXPECT_NE(what.find("properties make no sense for BAD"), std::string::npos) << what;
}

TEST(UserConstraint, NonFiniteOutputsAreModelErrors) {
  const Fixture fx;
  const Eigen::VectorXd u = Eigen::VectorXd::Zero(9);
  LocalSystem s;
  s.reset(5);
  std::string what = error_of([&] { fx.misbehaving(2).evaluate(EvaluationState{u, u}, s, false); });
  EXPECT_NE(what.find("non-finite residual"), std::string::npos) << what;
  EXPECT_NE(what.find("node 20 dof 1"), std::string::npos) << what;
  what = error_of([&] { fx.misbehaving(3).evaluate(EvaluationState{u, u}, s, true); });
  EXPECT_NE(what.find("non-finite stiffness"), std::string::npos) << what;
  EXPECT_NE(what.find("multiplier 1"), std::string::npos) << what;
  // Without a tangent request the stiffness is not used and not checked.
  EXPECT_NO_THROW(fx.misbehaving(3).evaluate(EvaluationState{u, u}, s, false));
}

TEST(UserConstraint, ExampleRejectsBadProperties) {
  const Fixture fx;
  const UserConstraintElement bad(kExample, "", 1, {1, 3}, {20, 40}, fx.reference, {3.0}, 1, fx.first, fx.dofs, "EQ");
  const Eigen::VectorXd u = Eigen::VectorXd::Zero(9);
  LocalSystem s;
  s.reset(5);
  const std::string what = error_of([&] { bad.evaluate(EvaluationState{u, u}, s, true); });
  EXPECT_NE(what.find("must be 1 or 2"), std::string::npos) << what;
}

TEST(UserConstraint, DeclaresItsTangentNeitherSymmetricNorLinear) {
  // The routine's tangent is its own: tether vouches for neither.
  Fixture fx;
  const UserConstraintElement user = fx.example(1, 0.0);
  for (bool nlgeom : {false, true}) {
    EXPECT_FALSE(user.symmetric_tangent(nlgeom));
    EXPECT_FALSE(user.linear_in_u(nlgeom));
  }
}
