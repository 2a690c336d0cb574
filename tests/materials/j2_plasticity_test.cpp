// Von Mises plasticity: tangents against finite differences on both branches,
// uniaxial load / unload / reverse against the closed form, the plane-stress
// return against the 3D return driven to sigma_33 = 0, the plastic work.
#include <gtest/gtest.h>

#include <cmath>
#include <Eigen/LU>
#include <random>

#include "tether/materials/j2_plasticity.hpp"
#include "support/error_message.hpp"

using namespace tether;

namespace {

constexpr double kE = 200000, kNu = 0.3;

/// Isotropic: (p, y) = (0, 200), (0.01, 300), (0.05, 350), flat beyond.
J2Plasticity isotropic() {
  return {kE, kNu, HardeningCurve({0, 0.01, 0.05}, {200, 300, 350}), J2Plasticity::Hardening::Isotropic};
}
/// Linear kinematic: y0 = 200, H = 10000 (up to p = 1).
J2Plasticity kinematic() {
  return {kE, kNu, HardeningCurve({0, 1}, {200, 10200}), J2Plasticity::Hardening::Kinematic};
}
/// Combined: back stress from (0, 200), (0.01, 260), (1, 1000); yield stress (0, 200), (0.005, 300), (1, 900).
J2Plasticity combined() {
  return {kE, kNu, HardeningCurve({0, 0.01, 1}, {200, 260, 1000}), J2Plasticity::Hardening::Combined,
          HardeningCurve({0, 0.005, 1}, {200, 300, 900})};
}

using State = std::vector<double>;

/// A random committed state: plastic strain (deviatoric, in-plane for plane
/// stress), deviatoric back stress, PEEQ.
State random_state(std::mt19937& gen, bool plane) {
  std::uniform_real_distribution<double> d(-1, 1);
  State s(J2Plasticity::kStateSize, 0.0);
  for (int i : {0, 1, 3}) s[i] = 2e-3 * d(gen);
  if (!plane) s[4] = 2e-3 * d(gen), s[5] = 2e-3 * d(gen);
  s[2] = -(s[0] + s[1]);
  for (int i : {6, 7, 9}) s[i] = 30 * d(gen);
  if (!plane) s[10] = 30 * d(gen), s[11] = 30 * d(gen);
  s[8] = -(s[6] + s[7]);
  s[12] = 0.02 * (1 + d(gen));  // away from 0; kinks at 0.01 are unlikely to be straddled
  return s;
}

/// Stress and tangent of one update.
MaterialResponse respond(const J2Plasticity& m, Vec6 eps, bool plane, const State& old, State* next = nullptr) {
  State scratch(old.size());
  MaterialResponse r;
  m.update_small_strain(eps, plane, old, next ? *next : scratch, {}, r);
  return r;
}

/// Checks the tangent against central differences; returns whether the point was plastic.
bool check_tangent(const J2Plasticity& m, const Vec6& eps, bool plane, const State& old) {
  State next(old.size());
  const MaterialResponse r = respond(m, eps, plane, old, &next);
  const bool plastic = next[12] > old[12];
  const double h = 1e-8;
  for (int j = 0; j < 6; ++j) {
    if (plane && (j == 2 || j > 3)) continue;  // plane stress: in-plane strains only
    Vec6 ep = eps, em = eps;
    ep(j) += h, em(j) -= h;
    const Vec6 fd = (respond(m, ep, plane, old).stress - respond(m, em, plane, old).stress) / (2 * h);
    EXPECT_LT((fd - r.tangent.col(j)).norm(), 1e-6 * r.tangent.norm())
        << "column " << j << (plastic ? " plastic" : " elastic") << (plane ? " plane stress" : " 3D") << "\nFD "
        << fd.transpose() << "\nD  " << r.tangent.col(j).transpose();
  }
  EXPECT_LT((r.tangent - r.tangent.transpose()).norm(), 1e-9 * r.tangent.norm());
  return plastic;
}

}  // namespace

TEST(J2Plasticity, TangentMatchesFiniteDifferencesOnBothBranches) {
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> d(-1, 1);
  for (const J2Plasticity& m : {isotropic(), kinematic(), combined()})
    for (bool plane : {false, true}) {
      int n_plastic = 0, n_elastic = 0;
      for (int k = 0; k < 40; ++k) {
        const State old = random_state(gen, plane);
        Vec6 eps = Eigen::Map<const Vec6>(old.data());  // the plastic strain: elastic strain zero
        const double amp = k % 2 == 0 ? 2e-4 : 5e-3;     // well inside, or well beyond, the yield surface
        for (int i : {0, 1, 2, 3}) eps(i) += amp * d(gen);
        if (!plane) eps(4) += amp * d(gen), eps(5) += amp * d(gen);
        if (plane) eps(2) = 0;
        (check_tangent(m, eps, plane, old) ? n_plastic : n_elastic) += 1;
      }
      EXPECT_GE(n_plastic, 10);
      EXPECT_GE(n_elastic, 10);
    }
}

namespace {

/// A uniaxial stress test on one material point: eps11 prescribed, the
/// lateral strains solved (Newton with the consistent tangent) so that the
/// other stresses vanish; each call is one increment.
struct UniaxialTest {
  const J2Plasticity& m;
  bool plane;
  State state = State(J2Plasticity::kStateSize, 0.0);
  Vec6 eps = Vec6::Zero();
  double dissipation = 0;

  double strain_to(double eps11) {
    eps(0) = eps11;
    State next(state.size());
    MaterialResponse r;
    for (int it = 0; it < 30; ++it) {
      Vec6 e = eps;
      m.update_small_strain(e, plane, state, next, {}, r);
      if (plane) {
        eps(2) = e(2);
        if (std::abs(r.stress(1)) < 1e-11 * 200) break;
        eps(1) -= r.stress(1) / r.tangent(1, 1);
      } else {
        if (std::abs(r.stress(1)) + std::abs(r.stress(2)) < 1e-11 * 200) break;
        const Eigen::Matrix2d K = r.tangent.block<2, 2>(1, 1);
        eps.segment<2>(1) -= K.inverse() * r.stress.segment<2>(1);
      }
    }
    state = next;
    dissipation += r.dissipation;
    return r.stress(0);
  }
};

/// Isotropic closed form: the PEEQ p >= p_from with p + y(p)/E = rhs.
double peeq_on_curve(double rhs) {
  const std::vector<double> p = {0, 0.01, 0.05, 1e9}, y = {200, 300, 350, 350};
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    const double slope = (y[i + 1] - y[i]) / (p[i + 1] - p[i]);
    // p + (y_i + slope (p - p_i)) / E = rhs, linear in p
    const double x = (rhs - y[i] / kE + slope * p[i] / kE) / (1 + slope / kE);
    if (x <= p[i + 1]) return x;
  }
  return -1;
}

double curve(double p) {
  if (p < 0.01) return 200 + 1e4 * p;
  if (p < 0.05) return 300 + 1250 * (p - 0.01);
  return 350;
}

}  // namespace

TEST(J2Plasticity, UniaxialLoadUnloadReverseIsotropicMatchesClosedForm) {
  const J2Plasticity m = isotropic();
  for (bool plane : {false, true}) {
    UniaxialTest t{m, plane};
    double worst = 0, eps1 = 0.03;
    // Load to eps1 (crossing the table point at p = 0.01) in 90 increments.
    for (int k = 1; k <= 90; ++k) {
      const double e = eps1 * k / 90;
      const double sigma = t.strain_to(e);
      const double expected = e * kE <= 200 ? e * kE : curve(peeq_on_curve(e));
      worst = std::max(worst, std::abs(sigma - expected) / 350);
    }
    const double p1 = peeq_on_curve(eps1), sigma1 = curve(p1), ep1 = eps1 - sigma1 / kE;
    EXPECT_NEAR(t.state[12], p1, 1e-12);
    // Unload and load in reverse to -0.03: elastic down to -sigma1, then
    // sigma = -y(p) with p = p1 + (ep1 - ep).
    for (int k = 1; k <= 120; ++k) {
      const double e = eps1 - 0.06 * k / 120;
      const double sigma = t.strain_to(e);
      const double elastic = sigma1 - kE * (eps1 - e);
      const double expected = elastic >= -sigma1 ? elastic : -curve(peeq_on_curve(p1 + ep1 - e));
      worst = std::max(worst, std::abs(sigma - expected) / 350);
    }
    EXPECT_LT(worst, 1e-8) << (plane ? "plane stress" : "3D");
    // Plastic work: sigma d eps_p = y(p) dp all along, the integral of the table.
    const double p2 = t.state[12];
    const double work = p2 <= 0.05 ? 0.5 * (200 + 300) * 0.01 + 0.5 * (300 + curve(p2)) * (p2 - 0.01)
                                   : 0.5 * (200 + 300) * 0.01 + 0.5 * (300 + 350) * 0.04 + 350 * (p2 - 0.05);
    EXPECT_NEAR(t.dissipation, work, 1e-9 * work) << (plane ? "plane stress" : "3D");
  }
}

TEST(J2Plasticity, UniaxialLoadUnloadReverseKinematicMatchesClosedForm) {
  const J2Plasticity m = kinematic();
  const double H = 10000, s0 = 200;
  for (bool plane : {false, true}) {
    UniaxialTest t{m, plane};
    double worst = 0, eps1 = 0.02, work = 0;
    for (int k = 1; k <= 40; ++k) {
      const double e = eps1 * k / 40;
      const double expected = e * kE <= s0 ? e * kE : (H * e + s0) / (1 + H / kE);
      worst = std::max(worst, std::abs(t.strain_to(e) - expected) / s0);
    }
    const double sigma1 = (H * eps1 + s0) / (1 + H / kE), ep1 = eps1 - sigma1 / kE;
    work += 0.5 * (s0 + sigma1) * ep1;
    // Reverse: yields at sigma1 - 2 s0 (Bauschinger), then sigma (1 + H/E) = H eps - s0.
    double ep_end = 0, sigma_end = 0;
    for (int k = 1; k <= 80; ++k) {
      const double e = eps1 - 0.04 * k / 80;
      const double elastic = sigma1 - kE * (eps1 - e);
      const double expected = elastic >= sigma1 - 2 * s0 ? elastic : (H * e - s0) / (1 + H / kE);
      worst = std::max(worst, std::abs(t.strain_to(e) - expected) / s0);
      sigma_end = expected, ep_end = e - expected / kE;
    }
    EXPECT_LT(worst, 1e-8) << (plane ? "plane stress" : "3D");
    EXPECT_NEAR(t.state[0], ep_end, 1e-12);
    // Reverse plastic work: sigma runs linearly from sigma1 - 2 s0 to sigma_end as ep drops from ep1 to ep_end.
    work += 0.5 * ((sigma1 - 2 * s0) + sigma_end) * (ep_end - ep1);
    EXPECT_NEAR(t.dissipation, work, 1e-9 * std::abs(work)) << (plane ? "plane stress" : "3D");
  }
}

TEST(J2Plasticity, PlaneStressReturnEqualsTheGeneralReturnAtZeroOutOfPlaneStress) {
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> d(-1, 1);
  for (const J2Plasticity& m : {isotropic(), kinematic()})
    for (int k = 0; k < 20; ++k) {
      const State old = random_state(gen, true);
      Vec6 eps = Eigen::Map<const Vec6>(old.data());
      for (int i : {0, 1, 3}) eps(i) += 4e-3 * d(gen);
      eps(2) = 0;
      State ps_next(old.size()), g_next(old.size());
      MaterialResponse ps, g;
      Vec6 e_ps = eps;
      m.update_small_strain(e_ps, true, old, ps_next, {}, ps);
      EXPECT_EQ(ps.stress(2), 0.0);
      // General return with Newton on eps_33 until sigma_33 = 0.
      Vec6 e = eps;
      for (int it = 0; it < 40; ++it) {
        m.update_small_strain(e, false, old, g_next, {}, g);
        if (std::abs(g.stress(2)) < 1e-12 * 200) break;
        e(2) -= g.stress(2) / g.tangent(2, 2);
      }
      EXPECT_LT((ps.stress - g.stress).norm(), 1e-9 * 200);
      EXPECT_NEAR(e_ps(2), e(2), 1e-12);
      EXPECT_NEAR(ps_next[12], g_next[12], 1e-12);
      for (int i = 0; i < 12; ++i) EXPECT_NEAR(ps_next[i], g_next[i], i < 6 ? 1e-12 : 1e-8) << i;
    }
}

TEST(J2Plasticity, UpdateLeavesTheCommittedStateAlone) {
  const J2Plasticity m = isotropic();
  const State old(J2Plasticity::kStateSize, 0.0);
  State next(old.size());
  Vec6 eps = Vec6::Zero();
  eps(0) = 0.01;
  MaterialResponse r;
  m.update_small_strain(eps, false, old, next, {}, r);
  EXPECT_GT(next[12], 0);
  for (double v : old) EXPECT_EQ(v, 0.0);
}

TEST(HardeningCurve, RefusesABadTable) {
  EXPECT_THROW(HardeningCurve({0, 0.1, 0.1}, {1, 2, 3}), std::invalid_argument);
  EXPECT_THROW(HardeningCurve({0.1, 0.2}, {1, 2}), std::invalid_argument);
  EXPECT_THROW(HardeningCurve({}, {}), std::invalid_argument);
  const HardeningCurve c({0, 1, 3}, {10, 20, 10});
  EXPECT_DOUBLE_EQ(c.value(2), 15);
  EXPECT_DOUBLE_EQ(c.slope(1), -5);
  EXPECT_DOUBLE_EQ(c.value(9), 10);
  EXPECT_DOUBLE_EQ(c.integral(0.5, 4), 0.5 * (15 + 20) * 0.5 + 0.5 * (20 + 10) * 2 + 10);
}

TEST(J2Plasticity, FactoryRefusesNegativeYieldStressNamingTheMaterial) {
  MaterialData d;
  d.name = "STEEL";
  d.where = {"deck.inp", 4};
  d.elastic = MaterialData::Elastic{kE, kNu};
  d.plastic = MaterialData::Plastic{};
  d.plastic->yield_stress = {-200};
  d.plastic->plastic_strain = {0};
  EXPECT_NE(tether::testing::model_error_of([&] { make_constitutive_model(d); }).find("deck.inp:4: material STEEL"),
            std::string::npos);
  d.plastic->yield_stress = {200};
  EXPECT_NE(dynamic_cast<J2Plasticity*>(make_constitutive_model(d).get()), nullptr);
}

namespace {

/// Strains of the tension-shear stress path O -> A -> B -> C (sigma_11, sigma_12)
/// for E = 195000, nu = 0.3, yield 181, tangent modulus 1930 (H = E Et / (E - Et)):
/// the rate solution d eps_p = 3/2 (d q / H) s / q while q = max q grows,
/// integrated with 20000 midpoint steps per leg. Returns (eps_11, gamma_12) at A, B, C.
std::vector<Eigen::Vector2d> nonradial_reference(const std::vector<Eigen::Vector2d>& corners, double E, double nu,
                                                 double y0, double H) {
  const double mu = E / (2 * (1 + nu));
  double ep11 = 0, gp12 = 0, q_max = y0;
  std::vector<Eigen::Vector2d> out;
  Eigen::Vector2d from(0, 0);
  for (const Eigen::Vector2d& to : corners) {
    const int n = 20000;
    for (int k = 0; k < n; ++k) {
      const Eigen::Vector2d s0 = from + (to - from) * (double(k) / n), s1 = from + (to - from) * (double(k + 1) / n);
      const Eigen::Vector2d mid = 0.5 * (s0 + s1);
      const double q1 = std::sqrt(s1(0) * s1(0) + 3 * s1(1) * s1(1));
      const double qm = std::sqrt(mid(0) * mid(0) + 3 * mid(1) * mid(1));
      if (q1 <= q_max) continue;
      const double dq = q1 - std::max(q_max, std::sqrt(s0(0) * s0(0) + 3 * s0(1) * s0(1)));
      q_max = q1;
      ep11 += mid(0) * dq / (H * qm);      // 3/2 (dq/H) (2/3 sigma) / q
      gp12 += 3 * mid(1) * dq / (H * qm);  // 2 * 3/2 (dq/H) tau / q
    }
    out.emplace_back(to(0) / E + ep11, to(1) / mu + gp12);
    from = to;
  }
  return out;
}

}  // namespace

TEST(J2Plasticity, NonRadialTensionShearPathFollowsTheRateSolution) {
  const double E = 195000, nu = 0.3, y0 = 181, Et = 1930, H = E * Et / (E - Et);
  const std::vector<Eigen::Vector2d> corners = {{151.2, 93.1}, {257.3, 33.1}, {259.3, 0}};
  const auto reference = nonradial_reference(corners, E, nu, y0, H);
  const J2Plasticity m(E, nu, HardeningCurve({0, 1}, {y0, y0 + H}), J2Plasticity::Hardening::Isotropic);
  // Stress control, n increments per leg: Newton on the strains for sigma = target (sigma_22 = sigma_33 = 0).
  const auto largest_error = [&](bool plane, int n) {
    State state(J2Plasticity::kStateSize, 0.0), next(state.size());
    Vec6 eps = Vec6::Zero();
    Eigen::Vector2d from(0, 0);
    const std::vector<int> free = plane ? std::vector<int>{0, 1, 3} : std::vector<int>{0, 1, 2, 3};
    double worst = 0;
    for (std::size_t leg = 0; leg < corners.size(); ++leg) {
      for (int k = 1; k <= n; ++k) {
        const Eigen::Vector2d target = from + (corners[leg] - from) * (double(k) / n);
        Vec6 goal = Vec6::Zero();
        goal(0) = target(0), goal(3) = target(1);
        MaterialResponse r;
        for (int it = 0; it < 50; ++it) {
          Vec6 e = eps;
          m.update_small_strain(e, plane, state, next, {}, r);
          if (plane) eps(2) = e(2);
          Eigen::VectorXd residual(free.size());
          Eigen::MatrixXd K(free.size(), free.size());
          for (std::size_t a = 0; a < free.size(); ++a) {
            residual(a) = r.stress(free[a]) - goal(free[a]);
            for (std::size_t b = 0; b < free.size(); ++b) K(a, b) = r.tangent(free[a], free[b]);
          }
          if (residual.norm() < 1e-10 * y0) break;
          const Eigen::VectorXd d = K.lu().solve(residual);
          for (std::size_t a = 0; a < free.size(); ++a) eps(free[a]) -= d(a);
        }
        state = next;
      }
      const Eigen::Vector2d got(eps(0), eps(3));
      const double error = (got - reference[leg]).norm() / reference[leg].norm();
      std::printf("%s, %d increments per leg: corner %c: eps_11 %.6e gamma_12 %.6e, rate solution %.6e %.6e, "
                  "relative error %.2e\n", plane ? "plane stress" : "3D", n, static_cast<char>('A' + leg), got(0),
                  got(1), reference[leg](0), reference[leg](1), error);
      if (leg == 0) EXPECT_LT(error, 1e-12);  // radial: backward Euler is exact for linear hardening
      worst = std::max(worst, error);
      from = corners[leg];
    }
    return worst;
  };
  for (bool plane : {false, true}) {
    // Backward Euler is first order on the non-radial leg: 30 increments give
    // 0.6 %, and four times as many a quarter of that.
    const double coarse = largest_error(plane, 30), fine = largest_error(plane, 120);
    EXPECT_LT(coarse, 1e-2);
    EXPECT_LT(fine, 0.3 * coarse);
  }
}

TEST(J2Plasticity, UniaxialLoadUnloadReverseCombinedMatchesClosedForm) {
  // Combined (CalculiX's reading): yield stress c(p) = s0 + Hi p from the
  // cyclic table, back stress from the *PLASTIC table's slope Hk. Uniaxially,
  // with the back stress b = Hk ep: |sigma - b| = s0 + Hi p.
  const double s0 = 200, Hi = 5000, Hk = 10000, Hh = Hi + Hk;
  const J2Plasticity m{kE, kNu, HardeningCurve({0, 1}, {s0, s0 + Hk}), J2Plasticity::Hardening::Combined,
                       HardeningCurve({0, 1}, {s0, s0 + Hi})};
  for (bool plane : {false, true}) {
    UniaxialTest t{m, plane};
    double worst = 0;
    const double eps1 = 0.02;
    for (int k = 1; k <= 40; ++k) {
      const double e = eps1 * k / 40;
      const double expected = e * kE <= s0 ? e * kE : (s0 + Hh * e) / (1 + Hh / kE);
      worst = std::max(worst, std::abs(t.strain_to(e) - expected) / s0);
    }
    const double sigma1 = (s0 + Hh * eps1) / (1 + Hh / kE), ep1 = eps1 - sigma1 / kE;
    double work = (s0 + 0.5 * Hh * ep1) * ep1;
    EXPECT_NEAR(t.state[12], ep1, 1e-12);
    // Reverse: elastic down to Hk ep1 - (s0 + Hi ep1) (both the shift and the
    // growth show), then sigma (1 + Hh/E) = Hh eps - s0 - 2 Hi ep1.
    const double reverse_yield = Hk * ep1 - s0 - Hi * ep1;
    double sigma_end = 0, ep_end = 0;
    for (int k = 1; k <= 80; ++k) {
      const double e = eps1 - 0.04 * k / 80;
      const double elastic = sigma1 - kE * (eps1 - e);
      const double expected = elastic >= reverse_yield ? elastic : (Hh * e - s0 - 2 * Hi * ep1) / (1 + Hh / kE);
      worst = std::max(worst, std::abs(t.strain_to(e) - expected) / s0);
      sigma_end = expected, ep_end = e - expected / kE;
    }
    EXPECT_LT(worst, 1e-8) << (plane ? "plane stress" : "3D");
    EXPECT_NEAR(t.state[0], ep_end, 1e-12);
    EXPECT_NEAR(t.state[12], ep1 + (ep1 - ep_end), 1e-12);
    work += 0.5 * (reverse_yield + sigma_end) * (ep_end - ep1);
    EXPECT_NEAR(t.dissipation, work, 1e-9 * work) << (plane ? "plane stress" : "3D");
  }
}

TEST(J2Plasticity, APointOnTheYieldSurfaceGetsTheLoadingTangentWithinAStep) {
  // A point yields; the next increment's first iteration evaluates it at the
  // same strain from the committed state, on the yield surface. Within a step
  // its tangent is the plastic branch's at dp = 0 (the one-sided derivative
  // for further loading); in a step's first increment (and without times) the
  // elastic one (the one-sided derivative for unloading). The stress is the
  // same either way.
  PointContext continuing, first;
  continuing.step_time = 0.5, continuing.dt = 0.1;
  first.step_time = 0.1, first.dt = 0.1;
  const auto at = [](const J2Plasticity& m, Vec6 eps, bool plane, const State& old, const PointContext& where) {
    State next(old.size());
    MaterialResponse r;
    m.update_small_strain(eps, plane, old, next, where, r);
    return r;
  };
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> d(-1, 1);
  for (const J2Plasticity& m : {isotropic(), kinematic(), combined()})
    for (bool plane : {false, true})
      for (int k = 0; k < 6; ++k) {
        const State old = random_state(gen, plane);
        Vec6 step = Vec6::Zero();  // the strain increment that makes the point yield
        for (int i : {0, 1, 3}) step(i) = 5e-3 * d(gen);
        if (!plane) step(2) = 5e-3 * d(gen), step(4) = 5e-3 * d(gen), step(5) = 5e-3 * d(gen);
        Vec6 eps = Eigen::Map<const Vec6>(old.data()) + step;
        if (plane) eps(2) = 0;
        State yielded(old.size());
        const MaterialResponse converged = respond(m, eps, plane, old, &yielded);
        ASSERT_GT(yielded[12], old[12]);
        const MaterialResponse loading = at(m, eps, plane, yielded, continuing);
        const MaterialResponse elastic = at(m, eps, plane, yielded, first);
        const MaterialResponse untimed = at(m, eps, plane, yielded, PointContext{});
        EXPECT_LT((loading.stress - converged.stress).norm(), 1e-10 * 200);
        EXPECT_LT((elastic.stress - loading.stress).norm(), 1e-12 * 200);  // round-off: plane stress sums beta + eta
        EXPECT_EQ(untimed.tangent, elastic.tangent);
        // One-sided differences from the committed state: further along the
        // increment that made it yield (plastic), and back (elastic).
        const double h = 1e-7;
        for (double sense : {1.0, -1.0}) {
          Vec6 moved = eps + sense * h * step;
          if (plane) moved(2) = eps(2);
          const Vec6 fd = (at(m, moved, plane, yielded, continuing).stress - loading.stress) / h;
          const Vec6 predicted = (sense > 0 ? loading : elastic).tangent * (sense * step);
          EXPECT_LT((fd - predicted).norm(), 1e-5 * predicted.norm())
              << (sense > 0 ? "loading" : "unloading") << (plane ? " plane stress" : " 3D") << "\nFD "
              << fd.transpose() << "\nD  " << predicted.transpose();
        }
        EXPECT_GT((loading.tangent - elastic.tangent).norm(), 0.1 * elastic.tangent.norm());
      }
}
