// The mortar contact element's tangent against central finite differences
// of its residual, at random non-trivial configurations: a slave surface of
// linear or quadratic faces over a finer or coarser master surface, both
// perturbed (curved, inclined, shifted), every slave node closed with a
// random pressure. The tangent includes the variation of the normals, of the
// projections and of the segmentation.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

#include "support/tangent_check.hpp"
#include "tether/contact/mortar_node.hpp"
#include "tether/contact/mortar_pair.hpp"

using namespace tether;

namespace {

struct MortarCase {
  bool quadratic_slave;
  bool quadratic_master;
  int n_slave_faces;
  int n_master_faces;
  double mu = 0;  ///< Coulomb friction (exact stick)
  PressureOverclosure law{};  ///< HARD, or a soft law of the mean overclosure
};

/// Soft laws whose pressure and slope are positive over the gaps of the
/// fixture (about -0.07...+0.05): λ_j = p(-g̃_j / D_j) is then not trivial.
PressureOverclosure soft_law(PressureOverclosure::Law kind, Dialect meaning = Dialect::Abaqus) {
  PressureOverclosure law;
  law.law = kind;
  law.meaning = meaning;
  law.stiffness = 1e5;  // LINEAR, starting at the clearance c0 = 0.2 (p = K (h + c0))
  law.c0 = 0.2;         // EXPONENTIAL: ABAQUS cut-off clearance / CalculiX 1 % clearance
  law.p0 = 1e4;
  law.table = {{0.0, -0.3}, {5e3, -0.05}, {2e4, 0.0}, {6e4, 0.1}};  // TABULAR (pressure, overclosure)
  return law;
}

/// Slave: the bottom of a body above y = 0 over x in [0.1, 1.9] (faces run
/// left to right); master: the top of a body below over x in [-0.2, 2.2]
/// (faces run right to left). Nodes are then jittered.
struct MortarFixture {
  std::vector<Eigen::Vector2d> reference;
  std::unique_ptr<MortarPair> pair;
  int n_disp = 0;

  MortarFixture(const MortarCase& c, std::mt19937& rng) {
    MortarPairSetup setup;
    setup.name = "TEST";
    const auto line = [&](double x0, double x1, int n_faces, bool quadratic, bool reverse, double y0) {
      std::vector<std::vector<int>> faces;
      const int per = quadratic ? 2 : 1;
      const int first = static_cast<int>(reference.size());
      for (int i = 0; i <= n_faces * per; ++i) {
        const double x = x0 + (x1 - x0) * i / (n_faces * per);
        reference.emplace_back(x, y0);
      }
      for (int k = 0; k < n_faces; ++k) {
        const int a = first + per * k, b = first + per * (k + 1);
        std::vector<int> f = reverse ? std::vector<int>{b, a} : std::vector<int>{a, b};
        if (quadratic) f.push_back(a + 1);
        faces.push_back(f);
      }
      return faces;
    };
    setup.slave_faces = line(0.1, 1.9, c.n_slave_faces, c.quadratic_slave, false, 0.0);
    setup.master_faces = line(-0.2, 2.2, c.n_master_faces, c.quadratic_master, true, -0.01);
    for (std::size_t f = 0; f < setup.master_faces.size(); ++f) setup.master_face_labels.emplace_back(static_cast<int>(f) + 1, 3);
    setup.slave_thickness.assign(setup.slave_faces.size(), 0.8);
    setup.search_radius = 1.0;
    setup.complementarity_stiffness = 100;
    setup.mu = c.mu;
    setup.law = c.law;
    n_disp = 2 * static_cast<int>(reference.size());
    pair = std::make_unique<MortarPair>(setup, reference, n_disp);
    (void)rng;
  }
};

class MortarTangent : public ::testing::TestWithParam<MortarCase> {};

TEST_P(MortarTangent, MatchesCentralFiniteDifferences) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> jitter(-0.03, 0.03), pressure(0.5, 2.0);
  for (int trial = 0; trial < 3; ++trial) {
    MortarFixture fx(GetParam(), rng);
    const int n = fx.n_disp + MortarPair::multipliers_per_slave(GetParam().mu) * fx.pair->n_slaves();
    Eigen::VectorXd u = Eigen::VectorXd::Zero(n), u_start = Eigen::VectorXd::Zero(n);
    for (int i = 0; i < fx.n_disp; ++i) u[i] = jitter(rng);
    // A rigid rotation by 0.2 rad and a curvature of the master, so that
    // normals vary and nothing is aligned with the axes.
    for (std::size_t a = 0; a < fx.reference.size(); ++a) {
      const Eigen::Vector2d X = fx.reference[a];
      const double bend = X.y() < 0 ? -0.05 * (X.x() - 1) * (X.x() - 1) : 0.0;
      const Eigen::Vector2d Y(X.x(), X.y() + bend);
      const Eigen::Rotation2Dd R(0.2);
      const Eigen::Vector2d y = R * Y;
      u[2 * static_cast<int>(a)] += y.x() - X.x();
      u[2 * static_cast<int>(a) + 1] += y.y() - X.y();
    }
    for (int i = 0; i < fx.pair->n_slaves(); ++i) {
      u[fx.pair->slave(i).multiplier] = 1e4 * pressure(rng);  // every node closed
      // Friction: stick (|λt| well inside μλn) in trials 0 and 2, slip in trial 1.
      if (fx.pair->slave(i).tangent_multiplier >= 0)
        u[fx.pair->slave(i).tangent_multiplier] =
            (trial == 1 ? 3.0 : 0.05) * GetParam().mu * u[fx.pair->slave(i).multiplier] * (i % 2 ? -1 : 1);
    }
    if (GetParam().mu > 0) {
      // The increment started with the slave 0.13 to the left (across master
      // nodes), rotated a little less: the slip increment is not trivial,
      // and the committed overlaps differ from the current ones.
      u_start = u;
      for (std::size_t a = 0; a < fx.reference.size(); ++a)
        if (fx.reference[a].y() >= 0) u_start[2 * static_cast<int>(a)] -= 0.13, u_start[2 * static_cast<int>(a) + 1] += 0.01;
      const EvaluationState start{u_start, u_start, 0, 0, 1, trial != 1};
      fx.pair->update_connectivity(start);
      fx.pair->commit(start);
    }
    // NLGEOM (current measure) and geometrically linear steps (reference measure).
    const EvaluationState state{u, u_start, 1, 1, 1, trial != 1};
    fx.pair->update_connectivity(state);
    int checked = 0;
    for (Contribution* c : fx.pair->nodes()) {
      const auto& node = dynamic_cast<const MortarNode&>(*c);
      ASSERT_TRUE(node.closed(state)) << node.describe();
      if (GetParam().mu > 0) {
        const MortarNode::Friction f = node.friction(state);
        EXPECT_EQ(f.stick, trial != 1) << node.describe() << " trial " << trial;
        EXPECT_NE(f.slip, 0.0);
      }
      EXPECT_LT(tether::testing::tangent_error(*c, state, 1e-6), 2e-6) << node.describe() << " trial " << trial;
      ++checked;
    }
    EXPECT_EQ(checked, fx.pair->n_slaves());
  }
}

INSTANTIATE_TEST_SUITE_P(Faces, MortarTangent,
                         ::testing::Values(MortarCase{false, false, 3, 7}, MortarCase{false, false, 5, 2},
                                           MortarCase{true, false, 2, 5}, MortarCase{false, true, 4, 3},
                                           MortarCase{true, true, 3, 2}, MortarCase{false, false, 3, 7, 0.3},
                                           MortarCase{false, false, 5, 2, 0.3}, MortarCase{true, true, 3, 4, 0.3}));

// Soft pressure-overclosure laws (λ_j = p(h_j), h_j = -g̃_j / D_j: the row's
// derivative includes that of D_j), frictionless and with friction.
INSTANTIATE_TEST_SUITE_P(
    SoftLaws, MortarTangent,
    ::testing::Values(MortarCase{false, false, 3, 7, 0, soft_law(PressureOverclosure::Law::Linear)},
                      MortarCase{true, false, 2, 5, 0, soft_law(PressureOverclosure::Law::Exponential)},
                      MortarCase{false, true, 4, 3, 0, soft_law(PressureOverclosure::Law::Exponential, Dialect::Calculix)},
                      MortarCase{true, true, 3, 2, 0, soft_law(PressureOverclosure::Law::Tabular)},
                      MortarCase{false, false, 5, 2, 0.3, soft_law(PressureOverclosure::Law::Exponential)},
                      MortarCase{true, true, 3, 4, 0.3, soft_law(PressureOverclosure::Law::Linear)}));

TEST(MortarTangent, OpenNodeHasTheTrivialRow) {
  std::mt19937 rng(3);
  MortarFixture fx(MortarCase{false, false, 3, 4}, rng);
  const int n = fx.n_disp + fx.pair->n_slaves();
  Eigen::VectorXd u = Eigen::VectorXd::Zero(n);
  for (std::size_t a = 0; a < fx.reference.size(); ++a)
    if (fx.reference[a].y() < 0) u[2 * static_cast<int>(a) + 1] = -0.1;  // master moved away
  const EvaluationState state{u, u, 1, 1, 1, true};
  fx.pair->update_connectivity(state);
  for (Contribution* c : fx.pair->nodes()) {
    const auto& node = dynamic_cast<const MortarNode&>(*c);
    EXPECT_FALSE(node.closed(state));
    LocalSystem out;
    out.reset(static_cast<Eigen::Index>(c->dofs().size()));
    c->evaluate(state, out, true);
    EXPECT_EQ(out.tangent.topLeftCorner(out.tangent.rows() - 1, out.tangent.cols() - 1).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_LT(out.tangent(out.tangent.rows() - 1, out.tangent.cols() - 1), 0.0);
  }
}

// The pair computes each term (slave face × master face) once per state and
// hands each node of the face its share (MortarTermCache): every node's
// residual and tangent must be, bit for bit, what a pair that evaluates that
// node alone computes, at a state, at another one and at the first again (a
// memo that handed out a stale term or another node's share would differ).
TEST(MortarTangent, SharedTermsAreThoseOfEachNodeAloneBitForBit) {
  for (const MortarCase& c : {MortarCase{false, false, 3, 7}, MortarCase{true, true, 3, 4, 0.3}}) {
    std::mt19937 rng(5);
    MortarFixture shared(c, rng);
    const int n = shared.n_disp + MortarPair::multipliers_per_slave(c.mu) * shared.pair->n_slaves();
    std::uniform_real_distribution<double> jitter(-0.02, 0.02);
    Eigen::VectorXd u1 = Eigen::VectorXd::Zero(n), u_start = Eigen::VectorXd::Zero(n);
    for (int i = 0; i < shared.n_disp; ++i) u1[i] = jitter(rng), u_start[i] = 0.5 * u1[i];
    for (int i = 0; i < shared.pair->n_slaves(); ++i) {
      u1[shared.pair->slave(i).multiplier] = 1e4;
      if (shared.pair->slave(i).tangent_multiplier >= 0) u1[shared.pair->slave(i).tangent_multiplier] = 100;
    }
    Eigen::VectorXd u2 = u1;
    u2[shared.n_disp - 1] += 1e-3;  // a master node moves
    const EvaluationState s1{u1, u_start, 1, 1, 1, false}, s2{u2, u_start, 1, 1, 1, false};
    shared.pair->update_connectivity(s1);
    const auto evaluate = [](const Contribution& node, const EvaluationState& s) {
      LocalSystem out;
      out.reset(static_cast<Eigen::Index>(node.dofs().size()));
      node.evaluate(s, out, true);
      return out;
    };
    for (const EvaluationState* s : {&s1, &s2, &s1}) {
      std::vector<LocalSystem> together;
      for (Contribution* node : shared.pair->nodes()) together.push_back(evaluate(*node, *s));
      for (int j = 0; j < shared.pair->n_slaves(); ++j) {
        std::mt19937 unused(5);
        MortarFixture alone(c, unused);
        alone.pair->update_connectivity(s1);
        const LocalSystem one = evaluate(*alone.pair->nodes()[static_cast<std::size_t>(j)], *s);
        const LocalSystem& t = together[static_cast<std::size_t>(j)];
        EXPECT_TRUE(one.residual == t.residual && one.tangent == t.tangent) << "slave " << j;
        EXPECT_NE(one.tangent.cwiseAbs().maxCoeff(), 0.0);
      }
    }
  }
}

// A slave sliding over many master faces: the memo keeps the terms of the
// master faces each slave face sums now, not of every face it has passed.
TEST(MortarTangent, TermMemoHoldsTheCurrentTermsOnly) {
  std::mt19937 rng(7);
  MortarFixture fx(MortarCase{false, false, 2, 24}, rng);
  const int n = fx.n_disp + fx.pair->n_slaves();
  Eigen::VectorXd u = Eigen::VectorXd::Zero(n);
  for (int i = 0; i < fx.pair->n_slaves(); ++i) u[fx.pair->slave(i).multiplier] = 1e4;
  std::size_t most = 0;
  for (int step = 0; step <= 10; ++step) {
    for (std::size_t a = 0; a < fx.reference.size(); ++a)
      if (fx.reference[a].y() >= 0) u[2 * static_cast<int>(a)] = -0.1 + 0.02 * step;  // 2 master faces over the slide
    const EvaluationState s{u, u, 1, 1, 1, false};
    fx.pair->update_connectivity(s);
    std::size_t current = 0;
    for (std::size_t e = 0; e < fx.pair->setup().slave_faces.size(); ++e)
      current += fx.pair->term_faces(static_cast<int>(e)).size();
    for (Contribution* node : fx.pair->nodes()) {
      LocalSystem out;
      out.reset(static_cast<Eigen::Index>(node->dofs().size()));
      node->evaluate(s, out, true);
    }
    EXPECT_LE(fx.pair->term_cache().size(), current) << "step " << step;
    most = std::max(most, current);
  }
  EXPECT_GE(most, 2u);
}

}  // namespace

namespace {

// Each node memoizes its active-set decision per state (MortarNode::decision):
// asked at other displacements, it must decide afresh. The master is moved
// from 0.01 below the slave (open) to 0.01 above (closed) and back; each
// answer of a node asked in turn at both states is that of a fresh node.
TEST(MortarTangent, DecisionMemoFollowsTheDisplacements) {
  std::mt19937 rng(3);
  MortarFixture shared(MortarCase{false, false, 3, 4}, rng);
  const int n = shared.n_disp + shared.pair->n_slaves();
  Eigen::VectorXd open = Eigen::VectorXd::Zero(n), closed = open;
  for (std::size_t a = 0; a < shared.reference.size(); ++a)
    if (shared.reference[a].y() < 0) closed[2 * static_cast<int>(a) + 1] = 0.02;
  const EvaluationState s_open{open, open, 1, 1, 1, false}, s_closed{closed, closed, 1, 1, 1, false};
  shared.pair->update_connectivity(s_closed);
  int changed = 0;
  for (const EvaluationState* s : {&s_closed, &s_open, &s_closed, &s_open}) {
    for (int j = 0; j < shared.pair->n_slaves(); ++j) {
      std::mt19937 unused(3);
      MortarFixture alone(MortarCase{false, false, 3, 4}, unused);
      alone.pair->update_connectivity(s_closed);
      const auto node = [j](const MortarFixture& fx) {
        return dynamic_cast<const MortarNode*>(fx.pair->nodes()[static_cast<std::size_t>(j)]);
      };
      const bool expected = node(alone)->closed(*s);
      EXPECT_EQ(node(shared)->closed(*s), expected) << "slave " << j;
      if (s == &s_closed && expected && !node(alone)->closed(s_open)) ++changed;
    }
  }
  EXPECT_GT(changed, 0);  // the states decide differently
}

}  // namespace
