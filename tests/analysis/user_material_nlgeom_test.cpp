// *USER MATERIAL under NLGEOM: the UMAT is called in the polar-rotated frame
// with Hughes-Winget increments (docs/theory/user_material.md). Checked at a
// point against closed forms (log strain under uniaxial strain, objectivity
// under a 90-degree rotation, the Jaumann-rate oscillation under simple
// shear), the PK2 tangent against finite differences, and through the
// analysis against *PLASTIC under NLGEOM.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>

#include "run_deck.hpp"
#include "tether/core/error.hpp"
#include "tether/materials/user_material.hpp"

using namespace tether;

namespace {

constexpr double kE = 1000, kNu = 0.25;
constexpr double kLambda = kE * kNu / ((1 + kNu) * (1 - 2 * kNu)), kMu = kE / (2 * (1 + kNu));

UserMaterial hypoelastic(int n_statev = 1) {
  return UserMaterial("HYPO", TETHER_HYPOELASTIC_UMAT, "", {kE, kNu}, n_statev);
}

/// A point driven through a sequence of in-plane deformation gradients (F33 = 1), committing each.
struct Point {
  const UserMaterial& material;
  std::vector<double> state, next;
  MaterialResponse r;

  explicit Point(const UserMaterial& m)
      : material(m), state(static_cast<std::size_t>(m.n_state()), 0.0), next(state.size()) {}

  static Eigen::Matrix3d right_cauchy_green(const Eigen::Matrix2d& F) {
    Eigen::Matrix3d C = Eigen::Matrix3d::Identity();
    C.topLeftCorner<2, 2>() = F.transpose() * F;
    return C;
  }
  /// Updates to F without committing; returns the Cauchy stress sigma = F S F^T / J (in-plane and 33).
  Eigen::Matrix3d trial(const Eigen::Matrix2d& F) {
    Eigen::Matrix3d C = right_cauchy_green(F);
    PointContext where;
    where.element = 1, where.point = 1, where.dt = 1;
    material.update_finite_strain(C, false, state, next, where, r);
    Eigen::Matrix3d F3 = Eigen::Matrix3d::Identity();
    F3.topLeftCorner<2, 2>() = F;
    return F3 * from_voigt_stress(r.stress) * F3.transpose() / F.determinant();
  }
  Eigen::Matrix3d step(const Eigen::Matrix2d& F) {
    const Eigen::Matrix3d sigma = trial(F);
    state = next;
    return sigma;
  }
};

Eigen::Matrix2d rotation(double angle) {
  Eigen::Matrix2d R;
  R << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  return R;
}

/// Largest relative difference between the tangent and central differences of the PK2 stress over E
/// (engineering shear), at F after committing F0.
double tangent_mismatch(const UserMaterial& m, const Eigen::Matrix2d& F0, const Eigen::Matrix2d& F,
                        std::span<const double> committed = {}) {
  Point p(m);
  if (!committed.empty()) std::copy(committed.begin(), committed.end(), p.state.begin());
  p.step(F0);
  p.trial(F);
  const Mat6 D = p.r.tangent;
  const Eigen::Matrix3d C = Point::right_cauchy_green(F);
  const double h = 1e-6;
  double worst = 0, scale = D.topLeftCorner<4, 4>().cwiseAbs().maxCoeff();
  for (int k = 0; k < 4; ++k) {
    Vec6 s[2];
    for (int side = 0; side < 2; ++side) {
      Eigen::Matrix3d Ck = C;
      const double d = side == 0 ? h : -h;
      if (k < 3) Ck(k, k) += 2 * d;
      else Ck(0, 1) += d, Ck(1, 0) += d;
      std::vector<double> next(p.state.size());
      MaterialResponse r;
      PointContext where;
      where.element = 1, where.point = 1, where.dt = 1;
      m.update_finite_strain(Ck, false, p.state, next, where, r);
      s[side] = r.stress;
    }
    const Vec6 fd = (s[0] - s[1]) / (2 * h);
    for (int i = 0; i < 4; ++i) worst = std::max(worst, std::abs(fd(i) - D(i, k)) / scale);
  }
  return worst;
}

/// ABAQUS/Standard's own update in the global frame for the same hypoelastic law, written out:
/// A = (F1 - F0) ((F0 + F1) / 2)^-1, sigma1 = Q sigma0 Q^T + C : sym A with Q the Cayley rotation of skew A.
Eigen::Matrix3d global_hughes_winget(const std::vector<Eigen::Matrix2d>& path) {
  Eigen::Matrix3d sigma = Eigen::Matrix3d::Zero(), F0 = Eigen::Matrix3d::Identity();
  for (const Eigen::Matrix2d& F : path) {
    Eigen::Matrix3d F1 = Eigen::Matrix3d::Identity();
    F1.topLeftCorner<2, 2>() = F;
    const Eigen::Matrix3d A = (F1 - F0) * (0.5 * (F0 + F1)).inverse(), I = Eigen::Matrix3d::Identity();
    const Eigen::Matrix3d de = 0.5 * (A + A.transpose()), w = 0.5 * (A - A.transpose());
    const Eigen::Matrix3d Q = (I - 0.5 * w).inverse() * (I + 0.5 * w);
    sigma = Q * sigma * Q.transpose() + kLambda * de.trace() * I + 2 * kMu * de;
    F0 = F1;
  }
  return sigma;
}

}  // namespace

// (1) Uniaxial strain to lambda = 1.5 in 50 increments, no rotation: sigma_11 = (lambda + 2 mu) ln(lambda),
// sigma_22 = sigma_33 = lambda ln(lambda) with the exact log increments; the Hughes-Winget increment
// 2 (l1 - l0) / (l1 + l0) = 2 tanh(d ln l / 2) differs by d^3 / 12 per increment.
TEST(UserMaterialNlgeom, UniaxialStrainGivesLogStrain) {
  const UserMaterial m = hypoelastic();
  Point p(m);
  const int n = 50;
  const double stretch = 1.5;
  Eigen::Matrix3d sigma;
  for (int k = 1; k <= n; ++k) sigma = p.step(Eigen::Vector2d(1 + (stretch - 1) * k / n, 1).asDiagonal());
  const double log_strain = std::log(stretch);
  const double relative = std::max({std::abs(sigma(0, 0) / ((kLambda + 2 * kMu) * log_strain) - 1),
                                    std::abs(sigma(1, 1) / (kLambda * log_strain) - 1),
                                    std::abs(sigma(2, 2) / (kLambda * log_strain) - 1)});
  std::printf("uniaxial strain to 1.5 in %d increments: relative error %.2e, STRAN(1) %.12f, ln 1.5 %.12f\n", n,
              relative, p.state[6], log_strain);
  EXPECT_LT(relative, 2e-5);
  EXPECT_LT(std::abs(sigma(0, 1)), 1e-12 * kE);
  EXPECT_NEAR(p.state[6], log_strain, 2e-5);                      // STRAN: the accumulated log strain
  EXPECT_NEAR(p.state[UserMaterial::kHeader], log_strain, 2e-5);  // STATEV(1) carried
  EXPECT_NEAR(p.r.elastic_energy, 0.5 * sigma(0, 0) * log_strain, 1e-4 * sigma(0, 0));  // SSE returned
}

// (2) A prestressed point (uniaxial strain 1.2) rotated rigidly by 90 degrees in 90 increments: the Cauchy
// stress rotates with the body; rotation alone makes no stress.
TEST(UserMaterialNlgeom, RigidRotationIsObjective) {
  const UserMaterial m = hypoelastic();
  Point p(m);
  const Eigen::Matrix2d U = Eigen::Vector2d(1.2, 1).asDiagonal();
  Eigen::Matrix3d sigma0;
  for (int k = 1; k <= 10; ++k) sigma0 = p.step(Eigen::Vector2d(1 + 0.02 * k, 1).asDiagonal());
  Eigen::Matrix3d sigma;
  const int n = 90;
  for (int k = 1; k <= n; ++k) sigma = p.step(rotation(0.5 * std::numbers::pi * k / n) * U);
  // rotated by 90 degrees: sigma_11 and sigma_22 swap, sigma_12 stays 0
  const double scale = sigma0.cwiseAbs().maxCoeff();
  const double error = std::max({std::abs(sigma(0, 0) - sigma0(1, 1)), std::abs(sigma(1, 1) - sigma0(0, 0)),
                                 std::abs(sigma(0, 1)), std::abs(sigma(2, 2) - sigma0(2, 2))}) / scale;
  std::printf("90-degree rigid rotation in %d increments: stress error %.2e relative\n", n, error);
  EXPECT_LT(error, 1e-12);
  Point q(m);  // rotation alone: no stress
  for (int k = 1; k <= n; ++k) sigma = q.step(rotation(0.5 * std::numbers::pi * k / n));
  EXPECT_LT(sigma.cwiseAbs().maxCoeff(), 1e-12 * kE);
}

// (3) Simple shear F = [[1, g], [0, 1]] to g = 2: the Jaumann-rate hypoelastic closed form sigma_12 = mu sin g,
// sigma_11 = -sigma_22 = mu (1 - cos g) (a Green-Naghdi or log rate gives neither the oscillation nor these
// values: at g = 2 they differ from it by more than 0.1 mu), approached at first order in the increment,
// and ABAQUS's own global-frame update (written out above) within 1.5/n of mu (1.2/n measured).
TEST(UserMaterialNlgeom, SimpleShearFollowsTheJaumannRate) {
  const UserMaterial m = hypoelastic();
  const double gamma = 2;
  const auto error_in = [&](int n) {
    Point p(m);
    Eigen::Matrix3d sigma;
    std::vector<Eigen::Matrix2d> path;
    for (int k = 1; k <= n; ++k) {
      Eigen::Matrix2d F = Eigen::Matrix2d::Identity();
      F(0, 1) = gamma * k / n;
      sigma = p.step(F);
      path.push_back(F);
    }
    const Eigen::Matrix3d abaqus = global_hughes_winget(path);
    std::printf("  ABAQUS's global-frame update: sigma_12 / mu %.6f, sigma_11 / mu %.6f; tether - ABAQUS %.2e of mu\n",
                abaqus(0, 1) / kMu, abaqus(0, 0) / kMu, (sigma - abaqus).cwiseAbs().maxCoeff() / kMu);
    const double error = std::max({std::abs(sigma(0, 1) - kMu * std::sin(gamma)),
                                   std::abs(sigma(0, 0) - kMu * (1 - std::cos(gamma))),
                                   std::abs(sigma(1, 1) + kMu * (1 - std::cos(gamma))), std::abs(sigma(2, 2))}) / kMu;
    std::printf("simple shear to 2 in %d increments: sigma_12 / mu %.6f (sin 2 = %.6f), sigma_11 / mu %.6f "
                "(1 - cos 2 = %.6f), error %.2e of mu\n", n, sigma(0, 1) / kMu, std::sin(gamma), sigma(0, 0) / kMu,
                1 - std::cos(gamma), error);
    EXPECT_LT((sigma - abaqus).cwiseAbs().maxCoeff() / kMu, 1.5 / n);
    return error;
  };
  // First order in the increment (as ABAQUS's own update: the stress increment C : sym A is added
  // unrotated, an O(dt^2) error per increment): 3.4e-3, 8.4e-4, 2.1e-4 of mu measured.
  const double coarse = error_in(100), finest = error_in(1600);
  EXPECT_LT(finest, 3e-4);
  EXPECT_GT(coarse / finest, 12);
}

// The PK2 tangent against central differences: exact (up to the differences) for the hypoelastic UMAT,
// whose returned stress is linear in the rotated start stress; for the J2 example in plastic flow DDSDDE
// is the derivative at a fixed rotated start stress, so the rotation part is only approximate.
TEST(UserMaterialNlgeom, TangentAgainstFiniteDifferences) {
  const UserMaterial m = hypoelastic();
  Eigen::Matrix2d F0, F;
  F0 << 1.1, 0.3, -0.05, 0.95;
  F << 1.14, 0.36, -0.02, 0.93;
  const double hypo = tangent_mismatch(m, F0, F);
  const UserMaterial j2("J2", TETHER_J2_UMAT, "", {200000., 0.3, 240., 1000.}, 5);
  Eigen::Matrix2d G0, G;
  G0 << 1.01, 0.002, 0.001, 0.996;
  G << 1.012, 0.004, 0.0005, 0.995;
  const double plastic = tangent_mismatch(j2, G0, G);
  std::printf("NLGEOM UMAT tangent against central differences (h = 1e-6): hypoelastic %.2e, J2 plastic %.2e\n",
              hypo, plastic);
  EXPECT_LT(hypo, 1e-6);
  EXPECT_LT(plastic, 1e-2);
}

TEST(UserMaterialNlgeom, PlaneStressIsRefused) {
  const UserMaterial m = hypoelastic();
  std::vector<double> s(static_cast<std::size_t>(m.n_state()), 0.0), t(s.size());
  Eigen::Matrix3d C = Eigen::Matrix3d::Identity();
  MaterialResponse r;
  try {
    m.update_finite_strain(C, true, s, t, PointContext{}, r);
    FAIL() << "plane stress under NLGEOM was accepted";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("plane stress (CPS) under NLGEOM"), std::string::npos) << e.what();
  }
}

TEST(UserMaterialNlgeom, PnewdtCutsBackUnderNlgeom) {
  const UserMaterial m("HYPO", TETHER_HYPOELASTIC_UMAT, "", {kE, kNu, 0.01}, 1);
  Point p(m);
  EXPECT_THROW(p.trial(Eigen::Vector2d(1.05, 1).asDiagonal()), ModelError);
  EXPECT_NO_THROW(p.trial(Eigen::Vector2d(1.005, 1).asDiagonal()));
}

namespace {

using tether::testing::replaced;

std::string umat_bar() {
  return replaced(tether::testing::analysis_deck("umat_bar_nlgeom.inp"), "build/libj2_umat.so", TETHER_J2_UMAT);
}

/// Newton orders log(r2/r1) / log(r1/r0) from the last three residuals of each increment that are
/// decreasing and above round-off (1e-12 of the largest residual of the run), sorted. Only the last three:
/// the iteration after the first step of an increment contracts only linearly for tether's own
/// hyperelastic *ELASTIC on the same cantilever too (0.2, 7e-4, 3e-5, 6e-10), a property of the
/// increment's start, not of the material.
std::vector<double> newton_orders(const tether::testing::Run& run) {
  double largest = 0;
  for (const auto& all : run.recorder.residuals)
    for (double x : all) largest = std::max(largest, x);
  std::vector<double> orders;
  for (const auto& all : run.recorder.residuals) {
    std::vector<double> r;
    for (double x : all)
      if (x >= 1e-12 * largest) r.push_back(x);
    if (r.size() < 3) continue;
    const std::size_t k = r.size() - 2;
    if (r[k] >= r[k - 1] || r[k + 1] >= r[k]) continue;
    orders.push_back(std::log(r[k + 1] / r[k]) / std::log(r[k] / r[k - 1]));
  }
  std::sort(orders.begin(), orders.end());
  return orders;
}

std::string listed(const std::vector<double>& v) {
  std::ostringstream s;
  s.precision(3);
  for (double x : v) s << " " << x;
  return s.str();
}

/// A CPE4 cantilever (10 x 1, 20 x 2 elements) of `material`, clamped at x = 0, a tip load of `load`
/// (total, on the three end nodes) under NLGEOM in 10 increments.
std::string cantilever(const std::string& material, double load) {
  std::ostringstream d;
  d << "*NODE, NSET=ALL\n";
  const int nx = 20, ny = 2;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) d << 1 + i + (nx + 1) * j << ", " << 0.5 * i << ", " << 0.5 * j << "\n";
  d << "*ELEMENT, TYPE=CPE4, ELSET=BEAM\n";
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = 1 + i + (nx + 1) * j;
      d << 1 + i + nx * j << ", " << a << ", " << a + 1 << ", " << a + nx + 2 << ", " << a + nx + 1 << "\n";
    }
  d << "*NSET, NSET=ROOT\n1, " << nx + 2 << ", " << 2 * nx + 3 << "\n*NSET, NSET=TIP\n" << nx + 1 << ", "
    << 2 * nx + 2 << ", " << 3 * nx + 3 << "\n";
  d << "*MATERIAL, NAME=M\n" << material << "*SOLID SECTION, ELSET=BEAM, MATERIAL=M\n1.\n";
  d << "*BOUNDARY\nROOT, 1, 2\n*STEP, NLGEOM, INC=100\n*STATIC, DIRECT\n0.1, 1.\n*CONTROLS, PARAMETERS=FIELD\n"
       "1e-11, 1e-11\n";
  d << "*CLOAD\nTIP, 2, " << load / 3 << "\n*END STEP\n";
  return d.str();
}

}  // namespace

// (4) The J2 example under NLGEOM against *PLASTIC under NLGEOM, one CAX4 bar in uniaxial stress pulled to
// 1.2 and pushed to 0.9. They are different formulations: the UMAT integrates the Cauchy stress
// hypoelastically (Jaumann, Hughes-Winget increments of the log strain) and checks the yield condition on
// Cauchy; *PLASTIC is hyperelastic in the elastic log strain with the return map on the Kirchhoff stress
// tau = J sigma. In uniaxial stress both integrate the same one-dimensional law in the axial log strain,
// so the UMAT's Cauchy stress is *PLASTIC's Kirchhoff stress (to the Hughes-Winget error), and their
// Cauchy stresses differ by tau (1 - 1 / J), J = exp((1 - 2 nu) tau / E) (0.4 tau^2 / E: 0.35 at tau = 420).
TEST(UserMaterialNlgeom, J2ExampleAgainstPlasticUnderNlgeom) {
  const auto user = tether::testing::run_deck_text(umat_bar());
  const auto builtin = tether::testing::run_deck_text(
      replaced(umat_bar(), std::string("*USER MATERIAL, CONSTANTS=4, LIBRARY=") + TETHER_J2_UMAT +
                               "\n200000., 0.3, 240., 1000.\n*DEPVAR\n5\n",
               "*ELASTIC\n200000, 0.3\n*PLASTIC\n240., 0.\n1240., 1.\n"));
  ASSERT_TRUE(user.summary.completed) << user.summary.message;
  ASSERT_TRUE(builtin.summary.completed) << builtin.summary.message;
  ASSERT_EQ(user.recorder.results.size(), 40u);
  ASSERT_EQ(builtin.recorder.results.size(), 40u);
  const double E = 200000, nu = 0.3, s0 = 240;
  double worst_kirchhoff = 0, worst_cauchy = 0, worst_lateral = 0, peak = 0;
  for (std::size_t k = 0; k < user.recorder.results.size(); ++k) {
    for (std::size_t q = 0; q < 4; ++q) {
      const PointValues &a = user.recorder.results[k].points[0][q], &b = builtin.recorder.results[k].points[0][q];
      double tau = b.stress[1];
      for (int it = 0; it < 20; ++it) tau = b.stress[1] * std::exp((1 - 2 * nu) * tau / E);
      worst_kirchhoff = std::max(worst_kirchhoff, std::abs(a.stress[1] - tau) / s0);
      worst_cauchy = std::max(worst_cauchy, std::abs(a.stress[1] - b.stress[1]) / s0);
      worst_lateral = std::max({worst_lateral, std::abs(a.stress[0]) / s0, std::abs(a.stress[2]) / s0});
      peak = std::max(peak, std::abs(a.stress[1]));
    }
  }
  std::printf("J2 UMAT against *PLASTIC under NLGEOM (CAX4 bar to 1.2 and back to 0.9, peak %.1f): UMAT Cauchy - "
              "*PLASTIC Kirchhoff %.2e of s0, - *PLASTIC Cauchy %.2e of s0, lateral %.1e\n",
              peak, worst_kirchhoff, worst_cauchy, worst_lateral);
  EXPECT_LT(worst_kirchhoff, 1e-4);  // 2.6e-5 measured: the Hughes-Winget increments, sum of d^3 / 12
  EXPECT_GT(worst_cauchy, 2e-3);     // the two formulations do differ, by 0.4 tau^2 / E (1.0 at tau = 702)
  EXPECT_LT(worst_cauchy, 6e-3);
  EXPECT_LT(worst_lateral, 1e-8);
}

// Newton under NLGEOM with a user material: a cantilever bent through large rotations, elastic
// (hypoelastic UMAT) and past yield (the J2 example); the order of convergence from successive residuals.
TEST(UserMaterialNlgeom, NewtonConvergesOnALargeRotationCantilever) {
  const auto elastic = tether::testing::run_deck_text(cantilever(
      std::string("*USER MATERIAL, CONSTANTS=2, LIBRARY=") + TETHER_HYPOELASTIC_UMAT + "\n100., 0.3\n", 0.1));
  const auto plastic = tether::testing::run_deck_text(cantilever(
      std::string("*USER MATERIAL, CONSTANTS=4, LIBRARY=") + TETHER_J2_UMAT + "\n100., 0.3, 5., 10.\n*DEPVAR\n5\n",
      0.15));
  ASSERT_TRUE(elastic.summary.completed) << elastic.summary.message;
  ASSERT_TRUE(plastic.summary.completed) << plastic.summary.message;
  const auto svk = tether::testing::run_deck_text(cantilever("*ELASTIC\n100., 0.3\n", 0.1));
  const std::vector<double> o_elastic = newton_orders(elastic), o_plastic = newton_orders(plastic),
                            o_svk = newton_orders(svk);
  const auto tip = [](const tether::testing::Run& run) { return run.last().displacement[run.node(21)]; };
  std::printf("UMAT cantilever under NLGEOM: hypoelastic tip (%.4f, %.4f), %d increments, %d iterations, orders%s\n"
              "  J2 tip (%.4f, %.4f), %d increments, %d iterations, orders%s\n"
              "  *ELASTIC (St.Venant-Kirchhoff) %d iterations, orders%s\n",
              tip(elastic).x(), tip(elastic).y(), elastic.summary.increments, elastic.summary.iterations,
              listed(o_elastic).c_str(), tip(plastic).x(), tip(plastic).y(), plastic.summary.increments,
              plastic.summary.iterations, listed(o_plastic).c_str(), svk.summary.iterations, listed(o_svk).c_str());
  ASSERT_GE(o_elastic.size(), 5u);
  ASSERT_GE(o_plastic.size(), 5u);
  EXPECT_GE(o_elastic[o_elastic.size() / 2], 1.8);
  EXPECT_GE(o_plastic[o_plastic.size() / 2], 1.8);
  EXPECT_GE(o_elastic.front(), 1.4);  // 1.52 measured (the built-in *ELASTIC: 1.31)
  EXPECT_GE(o_plastic.front(), 1.4);  // 1.49 measured
}

// The hybrid CAX4H (mean dilatation: the material sees a modified C) under NLGEOM: on the homogeneous bar
// the same stresses as CAX4.
TEST(UserMaterialNlgeom, HybridElementMatchesTheBar) {
  const auto plain = tether::testing::run_deck_text(umat_bar());
  const auto hybrid = tether::testing::run_deck_text(replaced(umat_bar(), "TYPE=CAX4", "TYPE=CAX4H"));
  ASSERT_TRUE(hybrid.summary.completed) << hybrid.summary.message;
  ASSERT_EQ(plain.recorder.results.size(), hybrid.recorder.results.size());
  double worst = 0;
  for (std::size_t k = 0; k < plain.recorder.results.size(); ++k)
    for (std::size_t q = 0; q < 4; ++q)
      for (int i = 0; i < 4; ++i)
        worst = std::max(worst, std::abs(plain.recorder.results[k].points[0][q].stress[i] -
                                         hybrid.recorder.results[k].points[0][q].stress[i]) / 240);
  EXPECT_LT(worst, 1e-9);
}

TEST(UserMaterialNlgeom, PlaneStressElementsAreRefusedWhenTheDeckIsRead) {
  try {
    (void)tether::testing::run_deck_text(replaced(umat_bar(), "TYPE=CAX4", "TYPE=CPS4"));
    FAIL() << "a CPS4 user material under NLGEOM was accepted";
  } catch (const std::exception& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("test.inp:31"), std::string::npos) << message;  // the first *STEP, NLGEOM
    EXPECT_NE(message.find("plane-stress element 1 (CPS4) of user material J2UMAT"), std::string::npos) << message;
  }
}

#ifdef TETHER_FORTRAN_UMAT
// (6) The fixed-form Fortran UMAT built by gfortran (hypoelastic, tests/analysis/elastic_umat.f) under
// NLGEOM on the CAX4 bar (elastic, E = 200000): the same answers as the C hypoelastic UMAT, and in uniaxial
// stress the axial Cauchy stress E times the sum of the Hughes-Winget increments 2 (l1 - l0) / (l1 + l0)
// (to round-off), which is E ln(lambda) to 2.1e-5 of E ln 1.2 after the 40 increments.
TEST(UserMaterialNlgeom, FortranUmatUnderNlgeom) {
  const std::string j2 = std::string("*MATERIAL, NAME=J2UMAT\n*USER MATERIAL, CONSTANTS=4, LIBRARY=") +
                         TETHER_J2_UMAT + "\n200000., 0.3, 240., 1000.\n*DEPVAR\n5\n";
  std::string fortran = replaced(umat_bar(), j2, std::string("*MATERIAL, NAME=FORTRAN\n*USER MATERIAL, CONSTANTS=2, "
                                                             "LIBRARY=") + TETHER_FORTRAN_UMAT + "\n200000., 0.3\n");
  fortran = replaced(fortran, "MATERIAL=J2UMAT", "MATERIAL=FORTRAN");
  const std::string c = replaced(umat_bar(), j2, std::string("*MATERIAL, NAME=J2UMAT\n*USER MATERIAL, CONSTANTS=2, "
                                                             "LIBRARY=") + TETHER_HYPOELASTIC_UMAT + "\n200000., 0.3\n");
  const auto a = tether::testing::run_deck_text(fortran), b = tether::testing::run_deck_text(c);
  ASSERT_TRUE(a.summary.completed) << a.summary.message;
  ASSERT_TRUE(b.summary.completed) << b.summary.message;
  ASSERT_EQ(a.recorder.results.size(), b.recorder.results.size());
  double worst_c = 0, worst_hw = 0, worst_log = 0, strain = 0, previous = 1;
  for (std::size_t k = 0; k < a.recorder.results.size(); ++k) {
    const IncrementResults& r = a.recorder.results[k];
    const double lambda = r.step == 1 ? 1 + 0.2 * r.step_time : 1.2 - 0.3 * r.step_time;
    strain += 2 * (lambda - previous) / (lambda + previous), previous = lambda;
    for (std::size_t q = 0; q < 4; ++q) {
      const PointValues &p = r.points[0][q], &o = b.recorder.results[k].points[0][q];
      for (int i = 0; i < 4; ++i) worst_c = std::max(worst_c, std::abs(p.stress[i] - o.stress[i]) / 36464);
      worst_hw = std::max(worst_hw, std::abs(p.stress[1] - 200000 * strain) / 36464);
      worst_log = std::max(worst_log, std::abs(p.stress[1] - 200000 * std::log(lambda)) / 36464);
    }
  }
  std::printf("Fortran UMAT under NLGEOM: against the C UMAT %.1e, against E x (sum of Hughes-Winget increments) "
              "%.1e, against E ln(lambda) %.1e (of E ln 1.2)\n", worst_c, worst_hw, worst_log);
  EXPECT_LT(worst_c, 1e-12);
  EXPECT_LT(worst_hw, 1e-9);
  EXPECT_LT(worst_log, 5e-5);
}
#endif

// A small-strain step (the bar pulled to 1.001 without NLGEOM) then an NLGEOM step (on to 1.2): the NLGEOM
// step starts from U = I + eps of the small-strain one, so the hypoelastic axial stress is E (0.001 + the sum
// of the Hughes-Winget increments from 1.001), to round-off (starting from U = I would count the first
// step's 0.001 twice: 200 too much).
TEST(UserMaterialNlgeom, NlgeomStepAfterASmallStrainStep) {
  std::string deck = replaced(umat_bar(), std::string("*USER MATERIAL, CONSTANTS=4, LIBRARY=") + TETHER_J2_UMAT +
                                              "\n200000., 0.3, 240., 1000.\n*DEPVAR\n5\n",
                              std::string("*USER MATERIAL, CONSTANTS=2, LIBRARY=") + TETHER_HYPOELASTIC_UMAT +
                                  "\n200000., 0.3\n");
  deck = replaced(deck, "*STEP, NLGEOM\n*STATIC, DIRECT\n0.05, 1.\n", "*STEP\n*STATIC, DIRECT\n0.5, 1.\n");
  deck = replaced(deck, "TOP, 2, 2, 0.2", "TOP, 2, 2, 0.001");
  deck = replaced(deck, "TOP, 2, 2, -0.1", "TOP, 2, 2, 0.2");
  const auto run = tether::testing::run_deck_text(deck);
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  double strain = 0.001, previous = 1.001;
  for (int k = 1; k <= 20; ++k) {
    const double lambda = 1.001 + 0.199 * k / 20.0;
    strain += 2 * (lambda - previous) / (lambda + previous), previous = lambda;
  }
  const double axial = run.last().points[0][0].stress[1];
  std::printf("NLGEOM after a small-strain step: axial stress %.6f, expected %.6f\n", axial, 200000 * strain);
  EXPECT_NEAR(axial, 200000 * strain, 1e-9 * axial);
}
