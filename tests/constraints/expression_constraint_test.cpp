// ExpressionConstraint: exact derivatives of formula constraints checked
// against finite differences and against the hand-written DistanceConstraint;
// linearity detection; every error path of the formula parser.

#include "support/tangent_check.hpp"
#include "tether/constraints/expression_constraint.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <utility>
#include <vector>

#if defined(__SANITIZE_ADDRESS__)
#define TETHER_TEST_LSAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define TETHER_TEST_LSAN 1
#endif
#endif
#ifdef TETHER_TEST_LSAN
#include <sanitizer/lsan_interface.h>
#endif

#include "tether/constraints/constraint_element.hpp"
#include "tether/constraints/distance_constraint.hpp"

using namespace tether;

namespace {

const SourceLocation kWhere{"deck.inp", 12};

/// Three nodes with global dofs {0,1}, {4,5}, {6,7} (dofs 2 and 3 belong to nobody).
std::vector<ExpressionNode> three_nodes() {
  return {{101, Eigen::Vector2d(0.3, -0.2), {0, 1}},
          {102, Eigen::Vector2d(1.4, 0.9), {4, 5}},
          {103, Eigen::Vector2d(-0.5, 1.1), {6, 7}}};
}

ExpressionConstraint make(std::vector<std::string> formulas, std::vector<ExpressionNode> nodes = three_nodes()) {
  return ExpressionConstraint(std::move(formulas), std::move(nodes), kWhere, "*CONSTRAINT, TYPE=EXPRESSION");
}

const std::string kLink = "sqrt((X2+U2-X1-U1)^2+(Y2+V2-Y1-V1)^2) - sqrt((X2-X1)^2+(Y2-Y1)^2)";

/// Formulas whose derivatives are checked; every function of the language appears.
const std::vector<std::vector<std::string>> kFormulas = {
    {"U1 - 2*V2 + 0.5*U3 - 0.01*T"},                                        // linear
    {kLink},                                                                 // LINK distance
    {"sin(U1 + X1) * cos(V2) - tan(0.3*U3) + atan2(Y2 + V2, X2 + U2)"},      // trigonometric
    {"(U1 - 0.1*T*V3)^2 + TSTEP*exp(V1) * U2 - sqrt(T)*log(2 + U3)"},        // time-dependent
    {"asin(0.5*U1) + acos(0.4*V1) + atan(U2*V2)", "sinh(U3) * cosh(V3) - tanh(U1*V2)"},  // two equations
    {"abs(U1 - V2 + 1) * U3 + pow(1.5 + V1, 2.5) - (1 + U2^2)^-1.5 + U1**3"},
};

Eigen::VectorXd random_vector(Eigen::Index n, std::mt19937& rng, double scale) {
  std::uniform_real_distribution<double> d(-scale, scale);
  Eigen::VectorXd v(n);
  for (Eigen::Index i = 0; i < n; ++i) v[i] = d(rng);
  return v;
}

ConstraintOutput evaluated(const ConstraintFunction& f, const ConstraintInput& in, bool with_hessian) {
  ConstraintOutput out;
  out.reset(f.n_equations(), static_cast<Eigen::Index>(f.dofs().size()), with_hessian);
  f.evaluate(in, out, with_hessian);
  return out;
}

ConstraintInput state(Eigen::VectorXd u, double total_time = 1.3, double step_time = 0.3) {
  ConstraintInput in;
  in.u_start = u;
  in.u = std::move(u);
  in.total_time = total_time;
  in.step_time = step_time;
  return in;
}

double tangent_error(const Contribution& c, const Eigen::VectorXd& u, double total_time) {
  return tether::testing::tangent_error(c, EvaluationState{u, u, 0.2, total_time});
}

/// The InputError message thrown for `formulas` (empty if none is thrown).
std::string error_of(std::vector<std::string> formulas, int n_nodes = 2) {
  auto nodes = three_nodes();
  nodes.resize(static_cast<std::size_t>(n_nodes));
  try {
    ExpressionConstraint(std::move(formulas), std::move(nodes), kWhere, "*CONSTRAINT, TYPE=EXPRESSION");
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 12);
    return e.what();
  }
  return "";
}

}  // namespace

TEST(ExpressionConstraint, DofsAndEquations) {
  const auto f = make({"U1 - V3", "U2*V2"});
  EXPECT_EQ(std::vector<int>(f.dofs().begin(), f.dofs().end()), (std::vector<int>{0, 1, 4, 5, 6, 7}));
  EXPECT_EQ(f.n_equations(), 2);
  EXPECT_EQ(f.describe(), "*CONSTRAINT, TYPE=EXPRESSION");
}

// Central differences with h = 1e-6 at |u| <= 0.3: truncation ~1e-12 * f''',
// rounding ~1e-16/1e-6; 1e-8 (gradient) and 1e-7 (Hessian) leave wide margins.
TEST(ExpressionConstraint, GradientAndHessianMatchFiniteDifferences) {
  std::mt19937 rng(5);
  for (const auto& formulas : kFormulas) {
    const auto f = make(formulas);
    const int n = static_cast<int>(f.dofs().size()), m = f.n_equations();
    for (int trial = 0; trial < 4; ++trial) {
      const ConstraintInput in = state(random_vector(n, rng, 0.3));
      const ConstraintOutput out = evaluated(f, in, true);
      const double h = 1e-6;
      for (int j = 0; j < n; ++j) {
        ConstraintInput p = in, q = in;
        p.u[j] += h;
        q.u[j] -= h;
        const ConstraintOutput op = evaluated(f, p, false), oq = evaluated(f, q, false);
        const Eigen::VectorXd dfdu = (op.f - oq.f) / (2 * h);
        EXPECT_LT((dfdu - out.gradient.col(j)).cwiseAbs().maxCoeff(), 1e-8) << formulas[0] << " dof " << j;
        const Eigen::MatrixXd dg = (op.gradient - oq.gradient) / (2 * h);
        for (int k = 0; k < m; ++k)
          EXPECT_LT((dg.row(k).transpose() - out.hessian[k].col(j)).cwiseAbs().maxCoeff(), 1e-7)
              << formulas[k] << " dof " << j;
      }
      for (int k = 0; k < m; ++k) EXPECT_TRUE(out.hessian[k].isApprox(out.hessian[k].transpose()));
    }
  }
}

TEST(ExpressionConstraint, WithoutHessianGivesTheSameValueAndGradient) {
  std::mt19937 rng(9);
  const auto f = make(kFormulas[3]);
  const ConstraintInput in = state(random_vector(6, rng, 0.3));
  const ConstraintOutput a = evaluated(f, in, true), b = evaluated(f, in, false);
  EXPECT_EQ(a.f, b.f);
  EXPECT_EQ(a.gradient, b.gradient);
  EXPECT_TRUE(b.hessian.empty());
}

TEST(ExpressionConstraint, LinkFormulaReproducesDistanceConstraint) {
  const auto nodes = three_nodes();
  const auto f = make({kLink}, {nodes[0], nodes[1]});
  const DistanceConstraint d({0, 1, 4, 5}, nodes[0].reference, nodes[1].reference, "link");
  std::mt19937 rng(3);
  for (int trial = 0; trial < 10; ++trial) {
    const ConstraintInput in = state(random_vector(4, rng, 0.8));
    const ConstraintOutput a = evaluated(f, in, true), b = evaluated(d, in, true);
    EXPECT_NEAR(a.f[0], b.f[0], 1e-12);
    EXPECT_LT((a.gradient - b.gradient).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_LT((a.hessian[0] - b.hessian[0]).cwiseAbs().maxCoeff(), 1e-12);
  }
}

TEST(ExpressionConstraint, ValuesFollowTheFormula) {
  const auto f = make({"U1 + 2^3^2 - -V1^2 + 1e-3*U2 + .5D0*V2 + 2*pi*T + TSTEP + X3*Y2"});
  const ConstraintInput in = state((Eigen::VectorXd(6) << 0.1, 0.2, 0.3, 0.4, 0.5, 0.6).finished(), 2.0, 0.5);
  const ConstraintOutput out = evaluated(f, in, true);
  // 2^3^2 = 2^9 (right associative); - -V1^2 = +(V1^2).
  EXPECT_NEAR(out.f[0], 0.1 + 512 + 0.04 + 0.3e-3 + 0.2 + 4 * M_PI + 0.5 + (-0.5) * 0.9, 1e-13);
  EXPECT_NEAR(out.gradient(0, 1), 0.4, 1e-15);  // d(V1^2)/dV1
}

TEST(ExpressionConstraint, NamesAreCaseInsensitive) {
  const auto a = make({"SIN(u1) * Exp(v2) + PI*t + x2"}), b = make({"sin(U1) * exp(V2) + pi*T + X2"});
  std::mt19937 rng(1);
  const ConstraintInput in = state(random_vector(6, rng, 0.3));
  const ConstraintOutput oa = evaluated(a, in, true), ob = evaluated(b, in, true);
  EXPECT_EQ(oa.f, ob.f);
  EXPECT_EQ(oa.gradient, ob.gradient);
  EXPECT_EQ(oa.hessian[0], ob.hessian[0]);
}

TEST(ExpressionConstraint, AbsHasTheZeroSubgradientAtItsKink) {
  const auto f = make({"abs(U1 - V1)"});
  const ConstraintOutput out = evaluated(f, state(Eigen::VectorXd::Zero(6)), true);
  EXPECT_EQ(out.f[0], 0.0);
  EXPECT_TRUE(out.gradient.allFinite());
  EXPECT_EQ(out.gradient.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_TRUE(out.hessian[0].isZero());
  const ConstraintOutput right = evaluated(f, state((Eigen::VectorXd(6) << 0.2, 0, 0, 0, 0, 0).finished()), false);
  EXPECT_EQ(right.gradient(0, 0), 1.0);
  EXPECT_EQ(right.gradient(0, 1), -1.0);
}

TEST(ExpressionConstraint, DetectsLinearFormulas) {
  EXPECT_TRUE(make({"U1 - 2*V2 + 0.5*T"}).linear());
  EXPECT_TRUE(make({"X1*U1 + Y2*V2 - sin(pi/6) + TSTEP^2", "U3 - V3"}).linear());
  EXPECT_TRUE(make({"(U1 + 1)^2 - U1^2"}).linear());  // expands to 2 U1 + 1
  EXPECT_FALSE(make({"U1*V1"}).linear());
  EXPECT_FALSE(make({"U1", "sin(V2)"}).linear());
  EXPECT_FALSE(make({"T*U1"}).linear());  // affine in u, but the gradient changes with time
  EXPECT_FALSE(make({kLink}).linear());
  // A linear function still reports its (constant) gradient and zero Hessians.
  const auto f = make({"U1 - 2*V2 + 0.5*T"});
  const ConstraintOutput out = evaluated(f, state(Eigen::VectorXd::Constant(6, 0.7), 4.0), true);
  EXPECT_DOUBLE_EQ(out.f[0], 0.7 - 1.4 + 2.0);
  EXPECT_EQ(out.gradient, (Eigen::MatrixXd(1, 6) << 1, 0, 0, -2, 0, 0).finished());
  EXPECT_TRUE(out.hessian[0].isZero());
}

TEST(ExpressionConstraint, ErrorsNameTheFileLineAndToken) {
  struct Case {
    std::vector<std::string> formulas;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {{"U1 + * V1"}, "deck.inp:12: error: in formula 1 of *CONSTRAINT, TYPE=EXPRESSION: unexpected token '*' at "
                      "column 6 (expected a number, variable, function or '(')"},
      {{"U1", "U1 - (U2))"}, "deck.inp:12: error: in formula 2 of *CONSTRAINT, TYPE=EXPRESSION: unexpected token ')' "
                             "at column 10 (expected an operator or the end of the formula)"},
      {{"U1 - W3"}, "in formula 1 of *CONSTRAINT, TYPE=EXPRESSION: unknown variable 'W3' at column 6 (expected Xk, "
                    "Yk, Uk, Vk for k = 1..2, T or TSTEP)"},
      {{"U0 - V1"}, "node number 0 in 'U0' at column 1 is out of range: the constraint has 2 nodes (k = 1..2)"},
      {{"V1 - u3"}, "node number 3 in 'u3' at column 6 is out of range: the constraint has 2 nodes (k = 1..2)"},
      {{"foo(U1)"}, "unknown function 'foo' at column 1 (known: sin, cos, tan, asin, acos, atan, atan2, sinh, cosh, "
                    "tanh, exp, log, ln, sqrt, abs, pow)"},
      {{"U1", "   "}, "deck.inp:12: error: in formula 2 of *CONSTRAINT, TYPE=EXPRESSION: the formula is empty"},
      {{"sin(U1"}, "missing ')' to close the argument list of 'sin' at column 1"},
      {{"(U1 + V1"}, "missing ')' to close the '(' at column 1"},
      {{"U1 +"}, "unexpected end of the formula at column 5 (expected a number, variable, function or '(')"},
      {{"atan2(U1)"}, "function 'atan2' at column 1 takes 2 arguments, got 1"},
      {{"sin + U1"}, "function 'sin' at column 1 needs its argument in parentheses, e.g. sin(U1)"},
      {{"2 U1"}, "unexpected token 'U1' at column 3 (expected an operator or the end of the formula)"},
      {{"U1(V1)"}, "'U1' at column 1 is a variable, not a function: write '*' to multiply"},
      {{"U1 $ V1"}, "unexpected character '$' at column 4"},
      {{"sin(U1,)"}, "unexpected token ')' at column 8 (expected a number, variable, function or '(')"},
      {{"X2 - X1 + T"}, "in formula 1 of *CONSTRAINT, TYPE=EXPRESSION: it does not depend on any displacement U1..V2 "
                        "(its gradient is identically zero)"},
      {{"U1 - U1"}, "it does not depend on any displacement"},
      {{"U1 + log(-1)"}, "'log' at column 6 has no real value for the argument -1"},
      {{"V1 - sqrt(X1 - X2)"}, "'sqrt' at column 6 has no real value for the argument -1.1"},
      {{"U1 * (-8)^(1/3)"}, "'^' at column 10 has no real value for the operands -8, 0.333333"},
      {{"U1 + 1e99999999"}, "number '1e99999999' at column 6 is out of range"},
      {{}, "deck.inp:12: error: *CONSTRAINT, TYPE=EXPRESSION: no formula given"},
  };
  for (const Case& c : cases) {
    const std::string message = error_of(c.formulas);
    EXPECT_NE(message.find(c.expected), std::string::npos)
        << "formulas: " << (c.formulas.empty() ? "" : c.formulas.back()) << "\nmessage: " << message;
    EXPECT_EQ(message.rfind("deck.inp:12: error: ", 0), 0u) << message;
  }
}

TEST(ExpressionConstraint, CoincidentReferenceCoordinatesInADenominatorAreAnError) {
  std::vector<ExpressionNode> nodes = {{1, Eigen::Vector2d(1, 2), {0, 1}}, {2, Eigen::Vector2d(1, 3), {2, 3}}};
  try {
    ExpressionConstraint({"U1/(X2 - X1)"}, nodes, kWhere, "*CONSTRAINT, TYPE=EXPRESSION");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("deck.inp:12: error: in formula 1 of *CONSTRAINT, TYPE=EXPRESSION: cannot "
                                         "be evaluated with the nodes' reference coordinates"),
              std::string::npos)
        << e.what();
  }
}

// A zero base to the power 0 or to a negative power: GiNaC's evaluation throws
// (pow(0,0) is undefined, division by zero), which tether reports. The power
// built for it must not outlive the exception: GiNaC::pow() put it on the heap
// and GiNaC never freed it (40 bytes per formula, found by the deck fuzzer).
// Under AddressSanitizer the test runs LeakSanitizer itself; elsewhere it
// checks the messages.
TEST(ExpressionConstraint, ZeroToAZeroOrNegativePowerIsAnErrorAndLeaksNothing) {
  // X1 == X2: the difference of the reference coordinates is 0.
  const std::vector<ExpressionNode> nodes = {{1, Eigen::Vector2d(1, 2), {0, 1}}, {2, Eigen::Vector2d(1, 3), {2, 3}}};
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"U1 + (X1+V2-X2-V2)^0", "pow(0,0) is undefined"},
      {"U1 + pow(X2 - X1, 0)", "pow(0,0) is undefined"},
      {"U1 * 0^0", "pow(0,0) is undefined"},
      {"U1 + (X2 - X1)^-1", "division by zero"},
      {"U1 + pow(0, -2)", "division by zero"},
      {"U1 + (X2 - X1)**(-1/2)", "division by zero"},
  };
  for (const auto& [formula, expected] : cases) {
    try {
      ExpressionConstraint({formula}, nodes, kWhere, "*CONSTRAINT, TYPE=EXPRESSION");
      ADD_FAILURE() << "no error for " << formula;
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind("deck.inp:12: error: in formula 1 of *CONSTRAINT, TYPE=EXPRESSION: cannot be evaluated "
                              "with the nodes' reference coordinates: ",
                              0),
                0u)
          << formula << ": " << message;
      EXPECT_NE(message.find(expected), std::string::npos) << formula << ": " << message;
    }
  }
#ifdef TETHER_TEST_LSAN
  EXPECT_EQ(__lsan_do_recoverable_leak_check(), 0) << "LeakSanitizer found a leak (its report is above)";
#endif
}

// A zero base to a power that is not a number has no derivative (log(0)):
// refused at the power's token, before GiNaC's differentiation would throw
// on it and lose a term of its own.
TEST(ExpressionConstraint, ZeroToAPowerThatIsNotANumberIsRefusedAtItsToken) {
  const std::vector<ExpressionNode> nodes = {{1, Eigen::Vector2d(1, 2), {0, 1}}, {2, Eigen::Vector2d(1, 3), {2, 3}}};
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"U1 + 0^U1", "'^' at column 7 raises 0 to a power that is not a number (U1)"},
      {"U1 + (X2 - X1)**T", "'**' at column 15 raises 0 to a power that is not a number (T)"},
      {"U1 + POW(X2 - X1, 2*U2)", "'POW' at column 6 raises 0 to a power that is not a number (2*U2)"},
  };
  for (const auto& [formula, expected] : cases) {
    try {
      ExpressionConstraint({formula}, nodes, kWhere, "*CONSTRAINT, TYPE=EXPRESSION");
      ADD_FAILURE() << "no error for " << formula;
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_EQ(message, "deck.inp:12: error: in formula 1 of *CONSTRAINT, TYPE=EXPRESSION: " + expected +
                             ": its derivative is undefined")
          << formula;
    }
  }
  // A constant exponent is a number by then, and a zero base to a numeric
  // power is GiNaC's to evaluate: 0^2 = 0, 0^pi = 0, 0^-sqrt(2) is a pole.
  EXPECT_NO_THROW(ExpressionConstraint({"U1 + (X2 - X1)^2 + pow(0, 1/2) + 0^pi"}, nodes, kWhere, "*CONSTRAINT"));
  EXPECT_NE(error_of({"U1 * (U2 - U2)^(-sqrt(2))"}).find("division by zero"), std::string::npos);
#ifdef TETHER_TEST_LSAN
  EXPECT_EQ(__lsan_do_recoverable_leak_check(), 0) << "LeakSanitizer found a leak (its report is above)";
#endif
}

// A constant that is exactly 0 only when evaluated, in a denominator: a
// division by zero, reported like a coincident coordinate. Left symbolic, it
// made GiNaC's evalf() throw with a product and a power of its own in flight
// (lost); the parser turns each constant into a number as soon as it is formed.
TEST(ExpressionConstraint, HiddenZeroInADenominatorIsAnErrorAndLeaksNothing) {
  for (const std::string formula : {"U1/(sqrt(2)*sqrt(3) - sqrt(6))", "U1 + (log(2) + log(3) - log(6))^-1"}) {
    try {
      ExpressionConstraint({formula}, three_nodes(), kWhere, "*CONSTRAINT, TYPE=EXPRESSION");
      ADD_FAILURE() << "no error for " << formula;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("division by zero"), std::string::npos) << formula << ": " << e.what();
    }
  }
#ifdef TETHER_TEST_LSAN
  EXPECT_EQ(__lsan_do_recoverable_leak_check(), 0) << "LeakSanitizer found a leak (its report is above)";
#endif
}

TEST(ExpressionConstraint, ErrorsUseTheFormulasOwnLineWhenGiven) {
  try {
    ExpressionConstraint({"U1", "U1 - Q"}, three_nodes(), kWhere, "*CONSTRAINT NAME=hinge",
                         {{"deck.inp", 13}, {"deck.inp", 14}});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 14);
    EXPECT_EQ(std::string(e.what()).rfind("deck.inp:14: error: in formula 2 of *CONSTRAINT NAME=hinge: unknown "
                                          "variable 'Q' at column 6 (expected Xk, Yk, Uk, Vk for k = 1..3, T or TSTEP)",
                                          0),
              0u)
        << e.what();
  }
}

// The element wrapping a formula constraint: tangent vs central FD of its
// residual, relative to the largest tangent entry, under every enforcement.
TEST(ExpressionConstraint, ConstraintElementTangentMatchesFiniteDifferences) {
  std::mt19937 rng(17);
  constexpr int kDofs = 8;  // the three nodes use dofs 0..7; multipliers follow
  const std::vector<Enforcement> methods = {
      {Enforcement::Method::Lagrange, 0.0},
      {Enforcement::Method::Lagrange, 0.1},
      {Enforcement::Method::Penalty, 0, 50.0},
      {Enforcement::Method::Augmented, 0, 50.0, 1e-14},
  };
  for (const auto& formulas : kFormulas) {
    for (const auto& e : methods) {
      for (int trial = 0; trial < 2; ++trial) {
        auto f = std::make_unique<ExpressionConstraint>(make(formulas));
        const int m = f->n_equations();
        ConstraintElement element(std::move(f), e, kDofs, "expression", {0, 1, 2});
        const Eigen::VectorXd u = random_vector(kDofs + m, rng, 0.3);
        if (e.method == Enforcement::Method::Augmented) {
          const Eigen::VectorXd start = random_vector(kDofs + m, rng, 0.3);
          ASSERT_EQ(element.on_converged(EvaluationState{start, start, 0.2, 1.1}), Acceptance::Iterate);
        }
        EXPECT_LT(tangent_error(element, u, 1.1), 1e-7) << to_string(e.method) << " eps " << e.epsilon << " "
                                                        << formulas[0];
      }
    }
  }
}

// GiNaC orders the terms of a sum and the factors of a product by hashes that
// include each symbol's serial number (and the address of its type's name,
// which moves with the library's load address): the same deck ran with the
// terms summed in another order from one process to the next, so that
// round-off, and with it the branch of abs(0), differed between runs
// (fuzz/seeds/formula_functions.inp gave two sets of multipliers). Here the
// symbols' serials are shifted by building other constraints in between; the
// compiled program must not change with them, down to the last bit.
TEST(ExpressionConstraint, ProgramDoesNotDependOnGinacTermOrder) {
  const std::vector<std::string> formulas = {"U1 + V1 + U2 + V2 + U3 + V3",
                                             "(1 + U1) * (1 + V1) * (1 + U2) * (1 + V2) * (1 + U3) * (1 + V3)"};
  // Sums and products whose value depends on the order of the operations.
  Eigen::VectorXd u(6);
  u << 1e16, 1.0, -1e16, 1.0, 3.0, -1e-3;
  Eigen::VectorXd w(6);
  w << 0.1, 0.2, 0.3, 0.7, 1e-9, 0.3;
  const ExpressionConstraint first = make(formulas);
  const ConstraintOutput a = evaluated(first, state(u), false), b = evaluated(first, state(w), false);
  for (int shift = 0; shift < 40; ++shift) {
    for (int k = 0; k < shift; ++k) make({"U1 + V2"});  // new symbols: later serial numbers
    const ExpressionConstraint again = make(formulas);
    const ConstraintOutput a2 = evaluated(again, state(u), false), b2 = evaluated(again, state(w), false);
    for (int k = 0; k < 2; ++k) {
      EXPECT_EQ(a2.f[k], a.f[k]) << "formula " << k + 1 << ", symbols shifted by " << shift;
      EXPECT_EQ(b2.f[k], b.f[k]) << "formula " << k + 1 << ", symbols shifted by " << shift;
    }
    EXPECT_EQ(again.n_instructions(), first.n_instructions());
  }
}
