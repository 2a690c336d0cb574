// *USER MATERIAL: an ABAQUS UMAT from a shared library. The worked J2 example
// matches *PLASTIC, a Fortran UMAT built by gfortran matches *ELASTIC, PNEWDT
// < 1 cuts the increment back, and bad input is refused naming the line,
// the element and the point.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "run_deck.hpp"

using namespace tether;
namespace fs = std::filesystem;

namespace {

std::string cylinder_deck() { return tether::testing::analysis_deck("plastic_cylinder.inp"); }

using tether::testing::replaced;

/// The plastic cylinder with linear hardening (H = 1000) and tight equilibrium tolerances.
std::string hardening_cylinder(const std::string& material) {
  std::string d = replaced(cylinder_deck(), "*ELASTIC\n200000, 0.3\n*PLASTIC\n240., 0.\n", material);
  d = replaced(d, "BORE, P, 172.99", "BORE, P, 200.");
  d = replaced(d, "0.1, 1., 1e-6, 0.1\n", "0.1, 1., 1e-6, 0.1\n*CONTROLS, PARAMETERS=FIELD\n1e-12, 1e-12\n");
  return replaced(d, "*STATIC\n0.25, 1.\n", "*STATIC\n0.25, 1.\n*CONTROLS, PARAMETERS=FIELD\n1e-12, 1e-12\n");
}

/// A data line of the values, exactly (17 digits).
std::string numbers(std::initializer_list<double> values) {
  std::ostringstream s;
  s.precision(17);
  const char* separator = "";
  for (double v : values) s << separator << v, separator = ", ";
  return s.str() + "\n";
}

double relative(double a, double b, double scale) { return std::abs(a - b) / scale; }

std::string error_of(const std::string& deck) {
  try {
    const tether::testing::Run run = tether::testing::run_deck_text(deck);
    return run.summary.completed ? "(completed)" : run.summary.message;
  } catch (const std::exception& e) {
    return e.what();
  }
}

}  // namespace

TEST(UserMaterial, J2ExampleMatchesPlastic) {
  const auto builtin = tether::testing::run_deck_text(
      hardening_cylinder("*ELASTIC\n200000, 0.3\n*PLASTIC\n240., 0.\n1240., 1.\n"));
  const auto user = tether::testing::run_deck_text(hardening_cylinder(
      std::string("*USER MATERIAL, CONSTANTS=4, LIBRARY=") + TETHER_J2_UMAT + "\n200000., 0.3, 240., 1000.\n"
      "*DEPVAR\n5\n"));
  ASSERT_TRUE(builtin.summary.completed) << builtin.summary.message;
  ASSERT_TRUE(user.summary.completed) << user.summary.message;
  ASSERT_EQ(builtin.recorder.results.size(), user.recorder.results.size());
  double worst_u = 0, worst_s = 0, worst_w = 0;
  for (std::size_t k = 0; k < user.recorder.results.size(); ++k) {
    const IncrementResults &a = builtin.recorder.results[k], &b = user.recorder.results[k];
    double u_scale = 0;
    for (const auto& u : a.displacement) u_scale = std::max(u_scale, u.cwiseAbs().maxCoeff());
    for (std::size_t n = 0; n < a.displacement.size(); ++n)
      worst_u = std::max(worst_u, (a.displacement[n] - b.displacement[n]).cwiseAbs().maxCoeff() / u_scale);
    for (std::size_t e = 0; e < a.points.size(); ++e)
      for (std::size_t q = 0; q < a.points[e].size(); ++q)
        for (int c = 0; c < 4; ++c) worst_s = std::max(worst_s, relative(a.points[e][q].stress[c], b.points[e][q].stress[c], 240));
    ASSERT_TRUE(a.plastic_dissipation && b.plastic_dissipation);
    worst_w = std::max(worst_w, relative(*a.plastic_dissipation, *b.plastic_dissipation,
                                         std::max(*a.plastic_dissipation, 1e-30)));
  }
  std::printf("J2 UMAT against *PLASTIC: displacements %.2e, stresses %.2e, ALLPD %.2e (relative)\n", worst_u,
              worst_s, worst_w);
  EXPECT_LT(worst_u, 1e-10);
  EXPECT_LT(worst_s, 1e-10);
  EXPECT_LT(worst_w, 1e-10);
  EXPECT_GT(*user.last().plastic_dissipation, 0);
}

#ifdef TETHER_FORTRAN_UMAT
TEST(UserMaterial, FortranUmatBuiltByGfortranMatchesElastic) {
  std::string deck = cylinder_deck();
  deck = replaced(deck, "*MATERIAL, NAME=STEEL\n*ELASTIC\n200000, 0.3\n*PLASTIC\n240., 0.\n",
                  std::string("*MATERIAL, NAME=FORTRAN\n*USER MATERIAL, CONSTANTS=2, LIBRARY=") + TETHER_FORTRAN_UMAT +
                      "\n200000., 0.3\n");
  deck = replaced(deck, "MATERIAL=STEEL", "MATERIAL=FORTRAN");
  const auto user = tether::testing::run_deck_text(deck);
  std::string elastic = replaced(cylinder_deck(), "*PLASTIC\n240., 0.\n", "");
  const auto builtin = tether::testing::run_deck_text(elastic);
  ASSERT_TRUE(user.summary.completed) << user.summary.message;
  ASSERT_TRUE(builtin.summary.completed) << builtin.summary.message;
  ASSERT_EQ(builtin.recorder.results.size(), user.recorder.results.size());
  double worst = 0, scale = 0;
  for (std::size_t k = 0; k < builtin.recorder.results.size(); ++k)
    for (std::size_t n = 0; n < builtin.last().displacement.size(); ++n) {
      const Eigen::Vector2d a = builtin.recorder.results[k].displacement[n], b = user.recorder.results[k].displacement[n];
      scale = std::max(scale, a.cwiseAbs().maxCoeff());
      worst = std::max(worst, (a - b).cwiseAbs().maxCoeff());
    }
  std::printf("Fortran elastic UMAT against *ELASTIC: displacements %.2e (relative)\n", worst / scale);
  EXPECT_LT(worst, 1e-10 * scale);
  // Named otherwise, the routine sees another CMNAME and returns NaN (already in the call when the model is built).
  const std::string renamed = replaced(replaced(deck, "NAME=FORTRAN", "NAME=OTHER"), "MATERIAL=FORTRAN", "MATERIAL=OTHER");
  const std::string message = error_of(renamed);
  EXPECT_NE(message.find("test.inp:"), std::string::npos) << message;
  EXPECT_NE(message.find("NaN"), std::string::npos) << message;
  EXPECT_NE(message.find("zero strain"), std::string::npos) << message;
}
#endif

TEST(UserMaterial, NanDuringTheAnalysisNamesTheElementAndPoint) {
  // The J2 example handles NTENS = 4 only and returns NaN for plane stress.
  std::string deck = replaced(cylinder_deck(), "*ELASTIC\n200000, 0.3\n*PLASTIC\n240., 0.\n",
                              std::string("*USER MATERIAL, CONSTANTS=4, LIBRARY=") + TETHER_J2_UMAT +
                                  "\n200000., 0.3, 240., 1000.\n*DEPVAR\n5\n");
  deck = replaced(deck, "TYPE=CPE8R", "TYPE=CPS8R");
  const auto run = tether::testing::run_deck_text(deck);
  EXPECT_FALSE(run.summary.completed);
  bool named = false;
  for (const auto& m : run.recorder.messages) named = named || (m.find("NaN") != std::string::npos &&
                                                               m.find("element 1 (CPS8R)") != std::string::npos &&
                                                               m.find("integration point 1") != std::string::npos);
  for (const auto& r : run.recorder.increments)
    named = named || (r.note.find("NaN") != std::string::npos && r.note.find("element") != std::string::npos &&
                      r.note.find("integration point") != std::string::npos);
  EXPECT_TRUE(named) << run.summary.message;
  std::printf("%s\n", run.summary.message.c_str());
}

TEST(UserMaterial, PnewdtBelowOneCutsTheIncrementBack) {
  // One increment of the whole load would strain the bore by about 1e-3; the routine accepts 3e-4.
  std::string deck = replaced(cylinder_deck(), "*ELASTIC\n200000, 0.3\n*PLASTIC\n240., 0.\n",
                              std::string("*USER MATERIAL, CONSTANTS=3, LIBRARY=") + TETHER_PNEWDT_UMAT +
                                  "\n200000., 0.3, 3e-4\n");
  deck = replaced(deck, "0.1, 1., 1e-6, 0.1", "1., 1., 1e-6, 1.");
  deck = deck.substr(0, deck.find("*STEP", deck.find("*END STEP")));
  const auto run = tether::testing::run_deck_text(deck);
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  EXPECT_GT(run.summary.cutbacks, 0);
  EXPECT_GT(run.summary.increments, 1);
}

TEST(UserMaterial, BadInputIsRefusedNamingTheLine) {
  const std::string base = cylinder_deck();
  const auto with = [&](const std::string& material) {
    return replaced(base, "*ELASTIC\n200000, 0.3\n*PLASTIC\n240., 0.\n", material);
  };
  const std::string lib = TETHER_J2_UMAT;
  std::string m = error_of(with("*USER MATERIAL, CONSTANTS=4, LIBRARY=" + lib + ", SYMBOL=nope\n1, 2, 3, 4\n"));
  EXPECT_NE(m.find("test.inp:"), std::string::npos) << m;
  EXPECT_NE(m.find("no routine 'nope'"), std::string::npos) << m;
  m = error_of(with("*USER MATERIAL, CONSTANTS=4, LIBRARY=" + lib + "\n1, 2, 3\n"));
  EXPECT_NE(m.find("3 constants: expected CONSTANTS=4"), std::string::npos) << m;
  m = error_of(with("*USER MATERIAL, CONSTANTS=2, LIBRARY=./no_such_library.so\n1, 2\n"));
  EXPECT_NE(m.find("no_such_library.so"), std::string::npos) << m;
  m = error_of(with("*ELASTIC\n200000, 0.3\n*DEPVAR\n3\n"));
  EXPECT_NE(m.find("*DEPVAR"), std::string::npos) << m;
  EXPECT_NE(m.find("without *USER MATERIAL"), std::string::npos) << m;
  m = error_of(with("*ELASTIC\n200000, 0.3\n*USER MATERIAL, CONSTANTS=4, LIBRARY=" + lib + "\n1, 2, 3, 4\n"));
  EXPECT_NE(m.find("whole mechanical behaviour"), std::string::npos) << m;
}

TEST(UserMaterial, RateDependentRoutineRelaxesAtAHeldStrain) {
  // One CPE4 whose every node is prescribed (eps_xx = 1e-3), then held for four
  // increments of 1: a Maxwell UMAT (tau = 2) loses 1/3 of its stress per
  // increment although the displacements do not change, so the committed
  // records must be told apart by the time too.
  const std::string deck = std::string(
      "*NODE\n1, 0., 0.\n2, 1., 0.\n3, 1., 1.\n4, 0., 1.\n"
      "*ELEMENT, TYPE=CPE4, ELSET=EALL\n1, 1, 2, 3, 4\n"
      "*NSET, NSET=LEFT\n1, 4\n*NSET, NSET=RIGHT\n2, 3\n*NSET, NSET=ALLN\n1, 2, 3, 4\n"
      "*MATERIAL, NAME=MAXWELL\n*USER MATERIAL, CONSTANTS=3, LIBRARY=") + TETHER_RELAXATION_UMAT +
      "\n1000., 0.25, 2.\n*DEPVAR\n4\n"
      "*SOLID SECTION, ELSET=EALL, MATERIAL=MAXWELL\n1.\n"
      "*BOUNDARY\nALLN, 2, 2\nLEFT, 1, 1\nRIGHT, 1, 1, 1e-3\n"
      "*STEP\n*STATIC, DIRECT\n1., 1.\n*END STEP\n"
      "*STEP\n*STATIC, DIRECT\n1., 4.\n*END STEP\n";
  const auto run = tether::testing::run_deck_text(deck);
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  ASSERT_EQ(run.recorder.results.size(), 5u);
  const double lambda = 1000. * 0.25 / (1.25 * 0.5), mu = 1000. / 2.5;
  for (std::size_t k = 0; k < 5; ++k) {
    const double expected = (lambda + 2 * mu) * 1e-3 * std::pow(2.0 / 3.0, static_cast<double>(k + 1));
    for (const auto& p : run.recorder.results[k].points[0])
      EXPECT_NEAR(p.stress[0], expected, 1e-12 * (lambda + 2 * mu) * 1e-3) << "increment " << k + 1;
  }
}

TEST(UserMaterial, RoutineReadsTheTemperatureAtTheStartAndItsIncrement) {
  // One CPE4 held in x at both sides, heated from 20 to 220 in four
  // increments, then cooled to 120 in two. The UMAT integrates a thermal
  // strain whose secant coefficient varies with the temperature incrementally,
  // alpha(TEMP + DTEMP)(TEMP + DTEMP - T0) - alpha(TEMP)(TEMP - T0): it adds up
  // to the total only with both values right (with TEMP = DTEMP = 0 there is
  // no stress at all), and then equals *EXPANSION with the same table.
  const double young = 2e5, nu = 0.3, a0 = 1e-5, a1 = 2e-8, zero = 10;
  const auto deck = [&](const std::string& material) {
    return "*NODE\n1, 0., 0.\n2, 1., 0.\n3, 1., 1.\n4, 0., 1.\n"
           "*ELEMENT, TYPE=CPE4, ELSET=EALL\n1, 1, 2, 3, 4\n"
           "*NSET, NSET=LEFT\n1, 4\n*NSET, NSET=RIGHT\n2, 3\n*NSET, NSET=ALLN\n1, 2, 3, 4\n"
           "*MATERIAL, NAME=HOT\n" + material +
           "*SOLID SECTION, ELSET=EALL, MATERIAL=HOT\n1.\n"
           "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nALLN, 20.\n"
           "*BOUNDARY\nLEFT, 1, 1\nRIGHT, 1, 1\n1, 2, 2\n"
           "*STEP\n*STATIC, DIRECT\n0.25, 1.\n*TEMPERATURE\nALLN, 220.\n*END STEP\n"
           "*STEP\n*STATIC, DIRECT\n0.5, 1.\n*TEMPERATURE\nALLN, 120.\n*END STEP\n";
  };
  const auto user = tether::testing::run_deck_text(
      deck(std::string("*USER MATERIAL, CONSTANTS=5, LIBRARY=") + TETHER_THERMAL_UMAT + "\n" +
           numbers({young, nu, a0, a1, zero})));
  const auto builtin = tether::testing::run_deck_text(
      deck("*ELASTIC\n" + numbers({young, nu}) + "*EXPANSION, ZERO=" + numbers({zero}) + numbers({a0, 0.}) +
           numbers({a0 + 400 * a1, 400.})));
  ASSERT_TRUE(user.summary.completed) << user.summary.message;
  ASSERT_TRUE(builtin.summary.completed) << builtin.summary.message;
  ASSERT_EQ(user.recorder.results.size(), 6u);
  ASSERT_EQ(builtin.recorder.results.size(), 6u);
  // Closed form: eps_xx = eps_zz = 0, sigma_yy = 0.
  const double lambda = young * nu / ((1 + nu) * (1 - 2 * nu)), mu = young / (2 * (1 + nu));
  const auto secant = [&](double t) { return (a0 + a1 * t) * (t - zero); };
  const double temperatures[6] = {70, 120, 170, 220, 170, 120};
  for (std::size_t k = 0; k < 6; ++k) {
    const double eth = secant(temperatures[k]) - secant(20);
    const double eyy = 2 * lambda * eth / (lambda + 2 * mu);
    const double sxx = lambda * (eyy - 2 * eth) - 2 * mu * eth;
    for (std::size_t q = 0; q < 4; ++q) {
      const double s_user = user.recorder.results[k].points[0][q].stress[0];
      const double s_builtin = builtin.recorder.results[k].points[0][q].stress[0];
      EXPECT_NEAR(s_user, sxx, 1e-10 * std::abs(sxx)) << "increment " << k + 1;
      EXPECT_NEAR(s_user, s_builtin, 1e-10 * std::abs(sxx)) << "increment " << k + 1;
    }
  }
}
