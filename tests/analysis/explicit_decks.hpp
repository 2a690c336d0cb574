// Decks and helpers shared by the explicit-dynamics tests: the steel bar's
// constants and wave speed, a free CPE4 square and its stable increment, the
// step system of a deck's first step, the bar against a rigid wall.
#pragma once

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "bar_decks.hpp"
#include "tether/analysis/discretization.hpp"
#include "tether/analysis/step_loads.hpp"
#include "tether/analysis/step_system.hpp"
#include "tether/io/deck_reader.hpp"

namespace tether::testing {

inline std::string num(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

inline constexpr double kE = 2e11, kNu = 0.3, kRho = 7800;
inline const double kLambda = kE * kNu / ((1 + kNu) * (1 - 2 * kNu)), kMu = kE / (2 * (1 + kNu));
/// 1D-strain (plane strain, rollers) wave speed.
inline const double kCp = std::sqrt((kLambda + 2 * kMu) / kRho);


/// A square CPE4 of side `a` (E, nu of the bar, density `rho`) free of
/// supports, one node pushed; `procedure` is the *DYNAMIC block.
inline std::string square_deck(const std::string& procedure, double a = 1, double rho = 1) {
  return "*NODE\n1, 0, 0\n2, " + num(a) + ", 0\n3, " + num(a) + ", " + num(a) + "\n4, 0, " + num(a) +
         "\n*ELEMENT, TYPE=CPE4, ELSET=ALL\n1, 1, 2, 3, 4\n*MATERIAL, NAME=M\n*ELASTIC\n" + num(kE) + ", " + num(kNu) +
         "\n*DENSITY\n" + num(rho) + "\n*SOLID SECTION, ELSET=ALL, MATERIAL=M\n"
         "*INITIAL CONDITIONS, TYPE=VELOCITY\n3, 1, 1.\n3, 2, 0.5\n*STEP\n" + procedure + "*END STEP\n";
}

/// The stable increment of a square CPE4 of side a with lumped mass: its
/// highest mode is the uniform dilatation, omega^2 = 8 (lambda + mu) / (rho a^2).
inline double square_stable_increment(double a, double rho) { return 2 / std::sqrt(8 * (kLambda + kMu) / (rho * a * a)); }

/// The step system of a deck's first step, with what it borrows.
struct Built {
  Model model;
  std::unique_ptr<Discretization> discretization;
  std::unique_ptr<StepSystem> system;
};

inline std::unique_ptr<Built> build(const std::string& deck) {
  auto b = std::make_unique<Built>();
  b->model = read_deck_string(deck, "test.inp");
  b->discretization = std::make_unique<Discretization>(b->model);
  const Discretization& disc = *b->discretization;
  const Step& step = b->model.steps.at(0);
  const Eigen::VectorXd u = Eigen::VectorXd::Zero(disc.dofs().n_dofs());
  b->system = std::make_unique<StepSystem>(disc, step, make_step_loads(step, disc.dofs(), u, {}, {}), u, 0.0,
                                           SolverSettings{});
  return b;
}

/// The bar of bar_deck at rest against a rigid wall (bar_decks.hpp) in an
/// explicit step of `period`.
inline std::string wall_deck(int n, double h, double v0, double period) {
  return tether::testing::wall_deck(n, h, v0, "*DYNAMIC, EXPLICIT\n, " + num(period) + "\n");
}

}  // namespace tether::testing
