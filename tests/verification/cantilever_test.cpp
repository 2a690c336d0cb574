// Plane-stress cantilever under an end shear load against Timoshenko beam theory.
//
// Decks: tests/verification/decks/cantilever_*.inp, written by
// tools/make_verification_decks.py (tools/make_cantilever_deck.py): L = 10,
// H = 1 (L/H = 10), unit thickness, E = 200000, nu = 0.3, clamped root, shear
// P = 100 at the free end distributed parabolically over the depth.
//
// Beam theory: delta = P L^3 / (3 E I) + P L / (k G A), k = 5/6. The clamped 2D
// beam is a little stiffer than that at the root (the root section cannot
// contract or warp): the finest meshes converge to -0.19 % of the beam value
// (measured with CPS8 up to 80x8), a modelling difference, not a discretization
// error. So the tests require (a) the error to shrink under refinement and (b)
// CPS8 within 0.5 % of beam theory on the finest mesh (the brief asks 1 %).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "verification_support.hpp"

using namespace tether;
using namespace tether::verification;

namespace {

constexpr double kLength = 10, kHeight = 1, kLoad = 100, kYoung = 200000, kPoisson = 0.3;

double beam_tip_deflection() {
  const double inertia = kHeight * kHeight * kHeight / 12, area = kHeight;
  const double shear_modulus = kYoung / (2 * (1 + kPoisson));
  return kLoad * kLength * kLength * kLength / (3 * kYoung * inertia) + kLoad * kLength / (5.0 / 6.0 * shear_modulus * area);
}

/// Relative error of the tip deflection (node set TIPMID, on the beam axis) of a deck.
double tip_error(const std::string& name) {
  const auto run = tether::testing::run_deck_file(deck_path(name));
  EXPECT_TRUE(run.summary.completed) << name << ": " << run.summary.message;
  if (!run.summary.completed) return 1;
  EXPECT_EQ(run.model.materials.at(0).elastic->young, kYoung);
  EXPECT_EQ(run.model.materials.at(0).elastic->poisson, kPoisson);
  const int tip = run.model.node_sets.at("TIPMID").at(0);
  EXPECT_NEAR(run.model.coords[tip].x(), kLength, 1e-12);
  const double deflection = run.last().displacement[tip].y(), exact = beam_tip_deflection();
  // Global equilibrium: the root carries the end load.
  EXPECT_NEAR(run.reaction_sum("ROOT", 1), -kLoad, 1e-9 * kLoad) << name;
  EXPECT_NEAR(run.reaction_sum("ROOT", 0), 0, 1e-9 * kLoad) << name;
  const double error = deflection / exact - 1;
  std::printf("[ beam     ] %-22s tip deflection %.6f  beam theory %.6f  error %+.4f %%\n", name.c_str(), deflection,
              exact, 100 * error);
  return error;
}

TEST(Cantilever, Cps8ConvergesToBeamTheory) {
  // measured: 10x1 -0.95 %, 20x2 -0.34 %, 40x4 -0.23 %
  std::vector<double> errors;
  for (const char* deck : {"cantilever_cps8_10x1", "cantilever_cps8_20x2", "cantilever_cps8_40x4"})
    errors.push_back(tip_error(deck));
  for (std::size_t k = 1; k < errors.size(); ++k) EXPECT_LT(std::abs(errors[k]), std::abs(errors[k - 1]));
  EXPECT_LT(std::abs(errors.back()), 5e-3);
  EXPECT_LT(std::abs(errors.front()), 1.5e-2);  // even one element through the depth: within 1.5 %
}

TEST(Cantilever, Cps4ConvergesToBeamTheory) {
  // Fully integrated 4-node quadrilaterals lock in bending (parasitic shear):
  // measured 10x2 -29.4 %, 20x4 -9.7 %, 40x8 -2.8 %, 80x16 -0.86 %. The error
  // falls about 3x per halving of h (required: 2.5x), and the finest mesh is
  // within 1.2 %.
  std::vector<double> errors;
  for (const char* deck : {"cantilever_cps4_10x2", "cantilever_cps4_20x4", "cantilever_cps4_40x8", "cantilever_cps4_80x16"})
    errors.push_back(tip_error(deck));
  for (std::size_t k = 1; k < errors.size(); ++k) {
    EXPECT_LT(errors[k - 1], 0) << "locking makes the CPS4 beam too stiff";
    EXPECT_LT(std::abs(errors[k]), std::abs(errors[k - 1]) / 2.5) << "mesh " << k;
  }
  EXPECT_LT(std::abs(errors.back()), 1.2e-2);
}

}  // namespace
