// Whole-analysis tests on small decks with exact answers.

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "run_deck.hpp"

using namespace tether;
using tether::testing::run_deck_text;

namespace {

/// A strip [0, L] x [0, H] of nx x ny 4-node elements of the given type, nodes
/// numbered row by row from 1; sets LEFT, RIGHT, CORNER (node 1), ALL.
std::string strip_mesh(int nx, int ny, double length, double height, const std::string& type) {
  std::ostringstream d;
  d << "*NODE, NSET=ALL\n";
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      d << j * (nx + 1) + i + 1 << ", " << length * i / nx << ", " << height * j / ny << "\n";
  d << "*ELEMENT, TYPE=" << type << ", ELSET=EALL\n";
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int n1 = j * (nx + 1) + i + 1;
      d << j * nx + i + 1 << ", " << n1 << ", " << n1 + 1 << ", " << n1 + nx + 2 << ", " << n1 + nx + 1 << "\n";
    }
  d << "*NSET, NSET=LEFT\n";
  for (int j = 0; j <= ny; ++j) d << j * (nx + 1) + 1 << (j < ny ? ", " : "\n");
  d << "*NSET, NSET=RIGHT\n";
  for (int j = 0; j <= ny; ++j) d << (j + 1) * (nx + 1) << (j < ny ? ", " : "\n");
  d << "*NSET, NSET=CORNER\n1\n";
  return d.str();
}

}  // namespace

TEST(StaticAnalysis, BarUnderEndLoadMatchesExactSolution) {
  // Plane stress, thickness 0.5: u(L) = F L / (E A) with A = H t; sigma_xx = F / A.
  const double length = 4, height = 1, thickness = 0.5, young = 1000, force = 10;
  std::ostringstream deck;
  deck << strip_mesh(4, 2, length, height, "CPS4")
       << "*MATERIAL, NAME=M\n*ELASTIC\n" << young << ", 0.25\n"
       << "*SOLID SECTION, ELSET=EALL, MATERIAL=M\n" << thickness << "\n"
       << "*BOUNDARY\nLEFT, 1\nCORNER, 2\n"
       << "*STEP\n*STATIC\n*CLOAD\n5, 1, 2.5\n10, 1, 5.\n15, 1, 2.5\n*END STEP\n";
  const auto run = run_deck_text(deck.str());
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  const double exact = force * length / (young * height * thickness);
  for (int id : {5, 10, 15}) EXPECT_NEAR(run.last().displacement[run.node(id)].x(), exact, 1e-12 * exact);
  EXPECT_NEAR(run.reaction_sum("LEFT", 0), -force, 1e-10 * force);
  for (const auto& element : run.last().points)
    for (const auto& p : element) {
      EXPECT_NEAR(p.stress[0], force / (height * thickness), 1e-9);
      EXPECT_NEAR(p.stress[1], 0, 1e-9);
      EXPECT_NEAR(p.stress[2], 0, 1e-12);  // plane stress
    }
  EXPECT_EQ(run.recorder.increments.size(), 1u);
  EXPECT_EQ(run.recorder.increments[0].iterations, 1);  // linear: one solve
}

TEST(StaticAnalysis, FloatingBodyIsReportedNamingNodeAndDof) {
  std::ostringstream deck;
  deck << strip_mesh(2, 1, 2, 1, "CPE4") << "*MATERIAL, NAME=M\n*ELASTIC\n1000, 0.3\n"
       << "*SOLID SECTION, ELSET=EALL, MATERIAL=M\n"
       << "*BOUNDARY\nLEFT, 1\n"  // y is free everywhere: rigid translation
       << "*STEP\n*STATIC\n*CLOAD\n3, 1, 1.\n*END STEP\n";
  const auto run = run_deck_text(deck.str());
  EXPECT_FALSE(run.summary.completed);
  EXPECT_NE(run.summary.message.find("singular"), std::string::npos) << run.summary.message;
  EXPECT_NE(run.summary.message.find("dof 2"), std::string::npos) << run.summary.message;
  EXPECT_NE(run.summary.message.find("node "), std::string::npos) << run.summary.message;
  EXPECT_TRUE(run.recorder.results.empty());
}

TEST(StaticAnalysis, SecondStepContinuesFromFirst) {
  // Prescribed end displacement 0.01, then 0.03: the reaction triples, the
  // displacement ramps from the first step's value.
  std::ostringstream deck;
  deck << strip_mesh(3, 1, 3, 1, "CPE4") << "*MATERIAL, NAME=M\n*ELASTIC\n1000, 0.3\n"
       << "*SOLID SECTION, ELSET=EALL, MATERIAL=M\n"
       << "*BOUNDARY\nLEFT, 1\nCORNER, 2\n"
       << "*STEP\n*STATIC\n0.5, 1.\n*BOUNDARY\nRIGHT, 1, 1, 0.01\n*END STEP\n"
       << "*STEP\n*STATIC\n0.5, 1.\n*BOUNDARY\nRIGHT, 1, 1, 0.03\n*END STEP\n";
  const auto run = run_deck_text(deck.str());
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  ASSERT_EQ(run.recorder.results.size(), 4u);
  const auto& r = run.recorder.results;
  const int tip = run.node(8);
  EXPECT_NEAR(r[0].displacement[tip].x(), 0.005, 1e-14);
  EXPECT_NEAR(r[1].displacement[tip].x(), 0.01, 1e-14);
  EXPECT_NEAR(r[2].displacement[tip].x(), 0.02, 1e-14);
  EXPECT_NEAR(r[3].displacement[tip].x(), 0.03, 1e-14);
  EXPECT_NEAR(r[3].total_time, 2.0, 1e-14);
  double f1 = 0, f2 = 0;
  for (int n : run.model.node_sets.at("LEFT")) f1 += r[1].reaction[n].x(), f2 += r[3].reaction[n].x();
  EXPECT_LT(f1, 0);
  EXPECT_NEAR(f2, 3 * f1, 1e-10 * std::abs(f1));
}

namespace {

/// Cauchy stress of a compressible neo-Hookean bar in uniaxial stress at
/// stretch `lambda` (lateral stretches equal, found by bisection).
double neo_hooke_uniaxial_stress(double lambda, double c10, double d1, double* lateral) {
  auto lateral_stress = [&](double mu) {
    const double j = lambda * mu * mu, i1 = lambda * lambda + 2 * mu * mu;
    return 2 * c10 / j * std::pow(j, -2.0 / 3.0) * (mu * mu - i1 / 3) + 2 / d1 * (j - 1);
  };
  double lo = 0.2, hi = 1.5;
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (lateral_stress(mid) > 0 ? hi : lo) = mid;
  }
  const double mu = 0.5 * (lo + hi), j = lambda * mu * mu, i1 = lambda * lambda + 2 * mu * mu;
  *lateral = mu;
  return 2 * c10 / j * std::pow(j, -2.0 / 3.0) * (lambda * lambda - i1 / 3) + 2 / d1 * (j - 1);
}

std::string neo_hooke_strip(double stretch, const std::string& extra_step_lines) {
  std::ostringstream deck;
  deck << strip_mesh(2, 2, 2, 1, "CPS4") << "*MATERIAL, NAME=RUBBER\n*HYPERELASTIC, NEO HOOKE\n1.0, 0.1\n"
       << "*SOLID SECTION, ELSET=EALL, MATERIAL=RUBBER\n1.\n"
       << "*BOUNDARY\nLEFT, 1\nCORNER, 2\n"
       << "*STEP, NLGEOM, INC=200\n" << extra_step_lines << "*BOUNDARY\nRIGHT, 1, 1, " << 2 * (stretch - 1)
       << "\n*END STEP\n";
  return deck.str();
}

}  // namespace

TEST(StaticAnalysis, NeoHookeanUniaxialStretchMatchesClosedForm) {
  const double stretch = 2.0;
  const auto run = run_deck_text(neo_hooke_strip(stretch, "*STATIC\n0.25, 1.\n*CONTROLS, PARAMETERS=FIELD\n1e-9, 1e-9\n"));
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  double lateral = 0;
  const double sigma = neo_hooke_uniaxial_stress(stretch, 1.0, 0.1, &lateral);
  // Reaction = Cauchy stress times the current cross-section H*mu * t*mu.
  EXPECT_NEAR(-run.reaction_sum("LEFT", 0), sigma * lateral * lateral, 1e-7 * sigma);
  EXPECT_NEAR(run.last().displacement[run.node(9)].y(), lateral - 1, 1e-8);
  for (const auto& element : run.last().points)
    for (const auto& p : element) EXPECT_NEAR(p.stress[0], sigma, 1e-7 * sigma);
}

TEST(StaticAnalysis, NewtonConvergesQuadraticallyOnFiniteStrain) {
  const auto run = run_deck_text(neo_hooke_strip(1.6, "*STATIC\n1., 1.\n*CONTROLS, PARAMETERS=FIELD\n1e-12, 1e-12\n"));
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  ASSERT_FALSE(run.recorder.residuals.empty());
  const auto& r = run.recorder.residuals.back();
  ASSERT_GE(r.size(), 4u);
  // Order estimate p = log(r3/r2) / log(r2/r1) over the last three iterations
  // before round-off: p close to 2 for a consistent tangent.
  std::vector<double> useful;
  for (double v : r)
    if (v > 1e-11 * r.front()) useful.push_back(v);
  ASSERT_GE(useful.size(), 3u);
  const std::size_t n = useful.size();
  const double order = std::log(useful[n - 1] / useful[n - 2]) / std::log(useful[n - 2] / useful[n - 3]);
  EXPECT_GT(order, 1.8) << "residual history ends " << useful[n - 3] << " " << useful[n - 2] << " " << useful[n - 1];
}

TEST(StaticAnalysis, LargeIncrementCutsBackAndAgreesWithSmallIncrements) {
  const std::string controls = "*CONTROLS, PARAMETERS=FIELD\n1e-10, 1e-10\n";
  // Compression to 15 % of the length in one increment: Newton's iterates
  // invert elements, so the increment must be cut back (one cut-back). At
  // 30 % the start-tangent predictor (docs/theory/newton.md) compresses the
  // strip uniformly and Newton converges without one.
  const auto coarse = run_deck_text(neo_hooke_strip(0.15, "*STATIC\n1., 1.\n" + controls));
  const auto fine = run_deck_text(neo_hooke_strip(0.15, "*STATIC, DIRECT\n0.02, 1.\n" + controls));
  ASSERT_TRUE(coarse.summary.completed) << coarse.summary.message;
  ASSERT_TRUE(fine.summary.completed) << fine.summary.message;
  EXPECT_EQ(fine.recorder.results.size(), 50u);
  const double a = coarse.reaction_sum("LEFT", 0), b = fine.reaction_sum("LEFT", 0);
  EXPECT_NEAR(a, b, 1e-8 * std::abs(b));
  EXPECT_GT(coarse.summary.cutbacks, 0);
}

TEST(StaticAnalysis, StopsBelowMinimumIncrementAndKeepsLastState) {
  // An element inverted by a huge compression cannot converge: the run must
  // stop with a message, after writing the converged increments. Both ends
  // are held vertically: with only a corner held, the strip pressed past
  // zero length folds over (the right element turned by 180 degrees, not
  // inverted), an equilibrium Newton finds from the start-tangent predictor.
  std::ostringstream deck;
  deck << strip_mesh(2, 1, 2, 1, "CPE4") << "*MATERIAL, NAME=M\n*HYPERELASTIC, NEO HOOKE\n1.0, 0.1\n"
       << "*SOLID SECTION, ELSET=EALL, MATERIAL=M\n*BOUNDARY\nLEFT, 1, 2\nRIGHT, 2\n"
       << "*STEP, NLGEOM\n*STATIC\n0.5, 1., 0.01\n*BOUNDARY\nRIGHT, 1, 1, -2.5\n*END STEP\n";
  const auto run = run_deck_text(deck.str());
  EXPECT_FALSE(run.summary.completed);
  EXPECT_NE(run.summary.message.find("last converged increment has been written"), std::string::npos)
      << run.summary.message;
  EXPECT_GT(run.summary.cutbacks, 0);
  // The inverted element is named, with the reason (which of the two
  // inverts first depends on the iterates: element 1 since the predictor).
  EXPECT_TRUE(run.summary.message.find("element 1 (CPE4)") != std::string::npos ||
              run.summary.message.find("element 2 (CPE4)") != std::string::npos)
      << run.summary.message;
  EXPECT_NE(run.summary.message.find("inverted"), std::string::npos) << run.summary.message;
  EXPECT_FALSE(run.recorder.results.empty());
}

TEST(StaticAnalysis, LineSearchGivesTheSameAnswer) {
  const std::string controls = "*CONTROLS, PARAMETERS=FIELD\n1e-10, 1e-10\n";
  const auto plain = run_deck_text(neo_hooke_strip(0.4, "*STATIC\n1., 1.\n" + controls));
  const auto searched =
      run_deck_text(neo_hooke_strip(0.4, "*STATIC\n1., 1.\n" + controls + "*CONTROLS, PARAMETERS=LINE SEARCH\n5\n"));
  ASSERT_TRUE(plain.summary.completed) << plain.summary.message;
  ASSERT_TRUE(searched.summary.completed) << searched.summary.message;
  ASSERT_TRUE(searched.model.steps[0].controls.line_search);
  const double a = plain.reaction_sum("LEFT", 0), b = searched.reaction_sum("LEFT", 0);
  EXPECT_NEAR(a, b, 1e-8 * std::abs(a));
  // The backtracking must not cost more failed attempts than plain Newton.
  EXPECT_LE(searched.summary.cutbacks, plain.summary.cutbacks);
}

TEST(StaticAnalysis, NodesOutsideEveryElementGetNoDofs) {
  // A stray node (as Gmsh writes for geometry points) must not make the model singular.
  std::ostringstream deck;
  deck << strip_mesh(2, 1, 2, 1, "CPE4") << "*NODE\n100, 5., 5.\n"
       << "*MATERIAL, NAME=M\n*ELASTIC\n1000, 0.3\n*SOLID SECTION, ELSET=EALL, MATERIAL=M\n"
       << "*BOUNDARY\nLEFT, 1\nCORNER, 2\n*STEP\n*STATIC\n*CLOAD\n3, 1, 1.\n*END STEP\n";
  const auto run = run_deck_text(deck.str());
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  EXPECT_EQ(run.last().displacement[run.node(100)].norm(), 0.0);
  EXPECT_EQ(run.last().reaction[run.node(100)].norm(), 0.0);
  EXPECT_GT(run.last().displacement[run.node(3)].x(), 0.0);
}

// A step without NLGEOM after one with it stays geometrically nonlinear, as in
// ABAQUS and CalculiX. One CPE4 pulled along x under NLGEOM, then loaded in y
// in a second step that omits the parameter: the end state must equal the run
// with NLGEOM written on both steps, (0.1593, 0.0680) at node 2 as CalculiX
// gives; a small-strain second step gave (0.2128, 0.1040).
TEST(StaticAnalysis, NlgeomStaysOnInALaterStepThatOmitsIt) {
  const auto deck = [](const std::string& second_step) {
    return "*NODE, NSET=ALL\n1, 0, 0\n2, 1, 0\n3, 1, 1\n4, 0, 1\n*ELEMENT, TYPE=CPE4, ELSET=EALL\n1, 1, 2, 3, 4\n"
           "*MATERIAL, NAME=M\n*ELASTIC\n1000, 0.3\n*SOLID SECTION, ELSET=EALL, MATERIAL=M\n1.\n"
           "*BOUNDARY\n1, 1, 2\n4, 1, 1\n"
           "*STEP, NLGEOM\n*STATIC\n0.1, 1.\n*CLOAD\n2, 1, 100.\n3, 1, 100.\n*END STEP\n" +
           second_step + "\n*STATIC\n0.1, 1.\n*CLOAD\n2, 2, 10.\n3, 2, 10.\n*END STEP\n";
  };
  const auto carried = run_deck_text(deck("*STEP"));
  const auto written = run_deck_text(deck("*STEP, NLGEOM"));
  ASSERT_TRUE(carried.summary.completed) << carried.summary.message;
  ASSERT_TRUE(written.summary.completed) << written.summary.message;
  const Eigen::Vector2d u = carried.last().displacement[carried.node(2)];
  const Eigen::Vector2d expected = written.last().displacement[written.node(2)];
  EXPECT_NEAR(u.x(), expected.x(), 1e-12);
  EXPECT_NEAR(u.y(), expected.y(), 1e-12);
  EXPECT_NEAR(u.x(), 0.1593, 5e-4);  // CalculiX 2.20 on the same deck
  EXPECT_NEAR(u.y(), 0.0680, 5e-4);
}

// A pressure under NLGEOM acts on the current area of the face in every
// family: the current thickness of plane stress (h0 F33), the constant one of
// plane strain, the current radius of axisymmetry. One element pulled by a
// pressure of -10 on one face, free across the pull, is in homogeneous
// uniaxial stress, so the Cauchy stress along the pull is exactly 10
// (CalculiX 10.0001 for the CPS4); plane stress read 10.28 with the reference
// thickness. Plane elements are pulled along x (face S2, rollers on S4),
// axisymmetric ones along z (face S3, rollers on S1) so that the stress stays
// homogeneous.
TEST(StaticAnalysis, FollowerPressureEqualsTheCauchyStressInEveryFamily) {
  for (const std::string type : {"CPS4", "CPE4", "CAX4", "CPS8", "CAX8", "CPS3"}) {
    const bool quad8 = type.back() == '8', tri = type.back() == '3', axi = type.rfind("CAX", 0) == 0;
    std::ostringstream deck;
    deck << "*NODE, NSET=ALL\n1, 1, 0\n2, 2, 0\n3, 2, 1\n4, 1, 1\n";
    if (quad8) deck << "5, 1.5, 0\n6, 2, 0.5\n7, 1.5, 1\n8, 1, 0.5\n";
    deck << "*ELEMENT, TYPE=" << type << ", ELSET=EALL\n";
    if (tri)
      deck << "1, 1, 2, 3\n2, 1, 3, 4\n";
    else
      deck << "1, 1, 2, 3, 4" << (quad8 ? ", 5, 6, 7, 8" : "") << "\n";
    deck << "*MATERIAL, NAME=M\n*ELASTIC\n100, 0.3\n*SOLID SECTION, ELSET=EALL, MATERIAL=M\n0.1\n";
    if (axi)
      deck << "*BOUNDARY\n1, 2, 2\n2, 2, 2\n" << (quad8 ? "5, 2, 2\n" : "");
    else
      deck << "*BOUNDARY\n1, 1, 2\n4, 1, 1\n" << (quad8 ? "8, 1, 1\n" : "");
    deck << "*STEP, NLGEOM\n*STATIC\n0.25, 1.\n*DLOAD\n1, " << (axi ? "P3" : "P2") << ", -10.\n*END STEP\n";
    const auto run = run_deck_text(deck.str());
    ASSERT_TRUE(run.summary.completed) << type << ": " << run.summary.message;
    const int along = axi ? 1 : 0;
    const double stretch = 1 + run.last().displacement[run.node(3)][along] - run.last().displacement[run.node(1)][along];
    EXPECT_GT(stretch, 1.05) << type;  // finite strain indeed
    for (const auto& element : run.last().points)
      for (const auto& point : element) EXPECT_NEAR(point.stress[along], 10.0, 1e-5) << type;  // Newton tolerance
  }
}
