// *DYNAMIC, EXPLICIT: the stable increment against its closed form and the
// model's highest frequency, divergence just above it, Rayleigh damping.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Eigenvalues>

#include "bar_decks.hpp"
#include "run_deck.hpp"
#include "tether/analysis/increment_controller.hpp"
#include "tether/analysis/stable_increment.hpp"
#include "tether/analysis/step_system.hpp"
#include "tether/io/deck_reader.hpp"
#include "tether/output/restart_file.hpp"
#include "explicit_decks.hpp"

namespace tether {
namespace {

using DeckRun = tether::testing::Run;
using tether::testing::run_deck_text;
using namespace tether::testing;  // explicit_decks.hpp, bar_decks.hpp

TEST(StableIncrement, SquareCpe4MatchesTheClosedForm) {
  for (const double side : {1.0, 0.01, 3.0}) {
    const auto b = build(square_deck("*DYNAMIC, EXPLICIT\n, 1.\n", side, 7));
    const Eigen::VectorXd u = Eigen::VectorXd::Zero(b->discretization->dofs().n_dofs());
    const StableIncrement s = stable_increment(b->system->inertia(), EvaluationState{u, u, 0, 0, 0, false});
    EXPECT_NEAR(s.dt / square_stable_increment(side, 7), 1, 1e-12) << "side " << side;
    EXPECT_EQ(s.element, 0);
  }
}

TEST(StableIncrement, BoundsTheHighestFrequencyOfADistortedMesh) {
  // Four distorted CPE4 and a CPE3: the assembled (K, M)'s highest frequency
  // is below the largest element's, and not far below it.
  const std::string deck =
      "*NODE\n1, 0, 0\n2, 1, 0\n3, 2.2, 0\n4, 0, 1\n5, 1.3, 0.8\n6, 2, 1.1\n7, 0, 2\n8, 0.9, 2.1\n9, 2.1, 2\n"
      "10, 3, 2\n*ELEMENT, TYPE=CPE4, ELSET=ALL\n1, 1, 2, 5, 4\n2, 2, 3, 6, 5\n3, 4, 5, 8, 7\n4, 5, 6, 9, 8\n"
      "*ELEMENT, TYPE=CPE3, ELSET=ALL\n5, 6, 10, 9\n*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.25\n*DENSITY\n2.\n"
      "*SOLID SECTION, ELSET=ALL, MATERIAL=M\n*STEP\n*DYNAMIC, EXPLICIT\n, 1.\n*END STEP\n";
  const auto b = build(deck);
  const Discretization& disc = *b->discretization;
  const auto n = static_cast<Eigen::Index>(disc.dofs().n_displacement_dofs());
  const Eigen::VectorXd u = Eigen::VectorXd::Zero(disc.dofs().n_dofs());
  const EvaluationState s{u, u, 0, 0, 0, false};
  Eigen::MatrixXd stiffness = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd mass = Eigen::VectorXd::Zero(n);
  LocalSystem local;
  for (const auto& m : b->system->inertia()) {
    const auto dofs = m->dofs();
    local.reset(static_cast<Eigen::Index>(dofs.size()));
    m->element().evaluate(s, local, true);
    for (std::size_t i = 0; i < dofs.size(); ++i) {
      mass[dofs[i]] += m->mass_entry(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(i));
      for (std::size_t j = 0; j < dofs.size(); ++j)
        stiffness(dofs[i], dofs[j]) += local.tangent(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
    }
  }
  const double mesh_omega = std::sqrt(largest_frequency_squared(stiffness, mass, "the mesh"));
  const StableIncrement estimate = stable_increment(b->system->inertia(), s);
  std::printf("mesh omega_max %.6g, element bound %.6g (element %d)\n", mesh_omega, estimate.omega_max, estimate.element);
  EXPECT_LE(mesh_omega, estimate.omega_max * (1 + 1e-12));
  EXPECT_GT(mesh_omega, 0.5 * estimate.omega_max);
}

TEST(StableIncrement, HeldElementsSetNoLimit) {
  // A free square (E of the bar, rho 1) beside a square 100 times stiffer whose
  // nodes are all held: the held one cannot vibrate and sets no limit.
  const std::string deck =
      "*NODE\n1, 0, 0\n2, 1, 0\n3, 1, 1\n4, 0, 1\n5, 2, 0\n6, 3, 0\n7, 3, 1\n8, 2, 1\n"
      "*ELEMENT, TYPE=CPE4, ELSET=SOFT\n1, 1, 2, 3, 4\n*ELEMENT, TYPE=CPE4, ELSET=STIFF\n2, 5, 6, 7, 8\n"
      "*MATERIAL, NAME=M\n*ELASTIC\n" + num(kE) + ", " + num(kNu) + "\n*DENSITY\n1.\n*MATERIAL, NAME=S\n*ELASTIC\n" +
      num(100 * kE) + ", " + num(kNu) + "\n*DENSITY\n1.\n*SOLID SECTION, ELSET=SOFT, MATERIAL=M\n"
      "*SOLID SECTION, ELSET=STIFF, MATERIAL=S\n*BOUNDARY\n5, 1, 2\n6, 1, 2\n7, 1, 2\n8, 1, 2\n"
      "*STEP\n*DYNAMIC, EXPLICIT\n, 1e-4\n*END STEP\n";
  const auto b = build(deck);
  const Eigen::VectorXd u = Eigen::VectorXd::Zero(b->discretization->dofs().n_dofs());
  const EvaluationState s{u, u, 0, 0, 0, false};
  const StableIncrement all = stable_increment(b->system->inertia(), s);
  EXPECT_EQ(all.element, 1);
  EXPECT_NEAR(all.dt / square_stable_increment(1, 1), 0.1, 1e-12);
  const EquationMap& equations = b->system->equations();
  const StableIncrement free = stable_increment(b->system->inertia(), s, [&](int d) { return equations.is_prescribed(d); });
  EXPECT_EQ(free.element, 0);
  EXPECT_NEAR(free.dt / square_stable_increment(1, 1), 1, 1e-12);
  // Through the procedure: the step uses the free square's increment.
  const DeckRun run = run_deck_text(deck);
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  EXPECT_NE(run.recorder.messages.front().find("stable time increment " + format_time(square_stable_increment(1, 1))),
            std::string::npos)
      << run.recorder.messages.front();
  // A partly held element: its free dofs only (the single element is the mesh: exact).
  std::string held = deck;
  held.replace(held.find("*STEP"), 5, "*BOUNDARY\n1, 1, 2\n2, 1, 2\n*STEP");
  const auto c = build(held);
  const EquationMap& eq = c->system->equations();
  const StableIncrement part = stable_increment(c->system->inertia(), s, [&](int d) { return eq.is_prescribed(d); });
  LocalSystem local;
  local.reset(8);
  c->system->inertia()[0]->element().evaluate(s, local, true);
  const std::vector<Eigen::Index> top{4, 5, 6, 7};
  const Eigen::VectorXd top_mass = c->system->inertia()[0]->mass().diagonal()(top);
  const double omega = std::sqrt(largest_frequency_squared(local.tangent(top, top), top_mass, "top"));
  EXPECT_NEAR(part.omega_max / omega, 1, 1e-12);
  EXPECT_LT(part.omega_max, free.omega_max);
}

/// A unit CPE4 (E 1000, nu 0.3, rho 1) held at nodes 1, 2, 4 and at node 3's
/// y: one free dof, node 3's x, started at velocity 1. `damping` is the
/// *DAMPING line (or empty), `procedure` the step's procedure block.
std::string one_dof_deck(const std::string& damping, const std::string& procedure) {
  return "*NODE\n1, 0, 0\n2, 1, 0\n3, 1, 1\n4, 0, 1\n*ELEMENT, TYPE=CPE4, ELSET=ALL\n1, 1, 2, 3, 4\n"
         "*MATERIAL, NAME=M\n*ELASTIC\n1000., 0.3\n*DENSITY\n1.\n" + damping +
         "*SOLID SECTION, ELSET=ALL, MATERIAL=M\n*NSET, NSET=HELD\n1, 2, 4\n*BOUNDARY\nHELD, 1, 2\n3, 2, 2\n"
         "*INITIAL CONDITIONS, TYPE=VELOCITY\n3, 1, 1.\n*STEP\n" + procedure + "*END STEP\n";
}

/// The free dof's frequency: its stiffness (the element's tangent at node 3's x) over its lumped mass 1/4.
double one_dof_omega() {
  const auto b = build(one_dof_deck("", "*DYNAMIC, EXPLICIT\n, 1.\n"));
  const Eigen::VectorXd u = Eigen::VectorXd::Zero(b->discretization->dofs().n_dofs());
  LocalSystem local;
  local.reset(8);
  b->system->inertia()[0]->element().evaluate(EvaluationState{u, u, 0, 0, 0, false}, local, true);
  return std::sqrt(local.tangent(4, 4) / 0.25);
}

TEST(ExplicitDamping, FreeVibrationDecaysAsExpOfMinusZetaOmegaT) {
  // zeta = 0.05 from the mass (alpha = 2 zeta omega) or from the stiffness
  // (beta = 2 zeta / omega): the amplitude sqrt(u^2 + ((v + zeta omega u) / omega_d)^2)
  // of u = A e^{-zeta omega t} sin(omega_d t) follows exp(-zeta omega t).
  const double omega = one_dof_omega(), zeta = 0.05, period = 2 * M_PI / omega;
  const double omega_d = omega * std::sqrt(1 - zeta * zeta);
  for (const bool mass : {true, false}) {
    SCOPED_TRACE(mass ? "alpha" : "beta");
    const std::string damping = mass ? "*DAMPING, ALPHA=" + num(2 * zeta * omega) + "\n"
                                     : "*DAMPING, BETA=" + num(2 * zeta / omega) + "\n";
    const DeckRun run =
        run_deck_text(one_dof_deck(damping, "*DYNAMIC, EXPLICIT, DIRECT\n" + num(period / 400) + ", " + num(4 * period) + "\n"));
    ASSERT_TRUE(run.summary.completed) << run.summary.message;
    const auto node = static_cast<std::size_t>(run.node(3));
    double worst = 0;
    for (const IncrementResults& r : run.recorder.results) {
      const double u = r.displacement[node].x(), v = r.velocity[node].x();
      const double amplitude = std::hypot(u, (v + zeta * omega * u) / omega_d);
      worst = std::max(worst, std::abs(amplitude / (std::exp(-zeta * omega * r.step_time) / omega_d) - 1));
    }
    const EnergyTotals& e = *run.last().energy;
    std::printf("%s: largest amplitude error %.3g over 4 periods (decayed to %.3g); ALLVD %.6g of %.6g, numerical %.3g\n",
                mass ? "mass-proportional" : "stiffness-proportional", worst, std::exp(-zeta * omega * 4 * period),
                e.viscous, 0.125, e.numerical);
    EXPECT_LT(worst, 2e-3);
    EXPECT_NEAR(e.viscous + e.kinetic + e.strain, 0.125, 1e-3 * 0.125);  // 1/2 m v0^2, m = 1/4
    EXPECT_GT(e.viscous, 0.9 * 0.125);
  }
}

TEST(ExplicitDamping, StiffnessDampingLowersTheStableIncrementAsThePredictedFormula) {
  // beta with xi = beta omega / 2 = 0.5 in the only mode: stable while
  // h <= (2 / omega)(sqrt(1 + xi^2) - xi) = 0.618 (2 / omega); the estimate says so,
  // 2 % below it the motion decays, 2 % above it diverges.
  const double omega = one_dof_omega(), xi = 0.5, beta = 2 * xi / omega;
  const double limit = (2 / omega) * (std::sqrt(1 + xi * xi) - xi);
  EXPECT_NEAR(damped_stable_increment(omega, beta) / limit, 1, 1e-14);
  const std::string damping = "*DAMPING, BETA=" + num(beta) + "\n";
  const DeckRun estimate = run_deck_text(one_dof_deck(damping, "*DYNAMIC, EXPLICIT\n, " + num(50 * limit) + "\n"));
  ASSERT_TRUE(estimate.summary.completed) << estimate.summary.message;
  EXPECT_NE(estimate.recorder.messages.front().find("stable time increment " + format_time(limit)), std::string::npos)
      << estimate.recorder.messages.front();
  const auto run_at = [&](double factor) {
    const double h = factor * limit;
    return run_deck_text(one_dof_deck(damping, "*DYNAMIC, EXPLICIT, DIRECT\n" + num(h) + ", " + num(3000 * h) + "\n"));
  };
  const DeckRun below = run_at(0.98);
  ASSERT_TRUE(below.summary.completed) << below.summary.message;
  EXPECT_LT(below.last().energy->kinetic + below.last().energy->strain, 1e-6 * 0.125);
  const DeckRun above = run_at(1.02);
  EXPECT_FALSE(above.summary.completed);
  EXPECT_NE(above.summary.message.find("diverged"), std::string::npos) << above.summary.message;
}

TEST(ExplicitDynamics, StableIncrementIsReportedAndUsed) {
  const double exact = square_stable_increment(1, 1);
  const DeckRun run = run_deck_text(square_deck("*DYNAMIC, EXPLICIT\n, " + num(50 * exact) + "\n"));
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  ASSERT_FALSE(run.recorder.messages.empty());
  const std::string& m = run.recorder.messages.front();
  EXPECT_NE(m.find("stable time increment " + format_time(exact)), std::string::npos) << m;
  EXPECT_NE(m.find("explicit increment " + format_time(0.9 * exact)), std::string::npos) << m;
  // 50 stable increments hold 56 explicit ones of 0.9 of it (rounded to fill the step): 56 reports.
  EXPECT_EQ(run.recorder.results.size(), 56u);
  // The bar's elements (side 0.01, rho 7800) with every y held: their x
  // dofs only, whose highest mode is the uniform stretch, omega^2 = 4 (lambda + 2 mu) / (rho a^2):
  // the increment is a / c_p, the 1D wave's Courant limit.
  const DeckRun bar = run_deck_text(bar_deck(4, 0.01, "", "*DYNAMIC, EXPLICIT\n, 1e-5\n"));
  ASSERT_TRUE(bar.summary.completed) << bar.summary.message;
  EXPECT_NE(bar.recorder.messages.front().find("stable time increment " + format_time(0.01 / kCp)), std::string::npos)
      << bar.recorder.messages.front();
}

TEST(ExplicitDynamics, AnIncrementJustAboveTheStableOneDivergesAndJustBelowDoesNot) {
  // One free element: the element-by-element bound is the model's own highest frequency.
  const double critical = square_stable_increment(1, 1);
  const auto run_at = [&](double factor) {
    const double dt = factor * critical;
    return run_deck_text(square_deck("*DYNAMIC, EXPLICIT, DIRECT\n" + num(dt) + ", " + num(2000 * dt) + "\n"));
  };
  const DeckRun below = run_at(0.98);
  ASSERT_TRUE(below.summary.completed) << below.summary.message;
  const double e0 = 0.5 * 0.25 * (1 + 0.25);  // lumped mass 1/4 at node 3, |v|^2 = 1.25
  // Central differences conserve v^2 + omega^2 (1 - omega^2 h^2 / 4) u^2 per mode: near the
  // limit the strain energy at full steps may reach e0 / (1 - 0.98^2), but it does not grow.
  for (const IncrementResults& r : below.recorder.results)
    EXPECT_LT(r.energy->kinetic + r.energy->strain, e0 / (1 - 0.98 * 0.98));
  const DeckRun above = run_at(1.02);
  EXPECT_FALSE(above.summary.completed);
  EXPECT_NE(above.summary.message.find("diverged"), std::string::npos) << above.summary.message;
  bool warned = false;
  for (const std::string& m : above.recorder.messages) warned = warned || m.find("exceeds the stable") != std::string::npos;
  EXPECT_TRUE(warned);
}

}  // namespace
}  // namespace tether
