// The calculix dialect against ccx on the same deck: two blocks pressed
// together through PRESSURE-OVERCLOSURE=EXPONENTIAL (c0 = 0.001, p0 = 100,
// p = 10; tests/smoke/decks/contact_exponential.inp). CalculiX's function is
// p = p0 exp(ln(100) h / c0), ABAQUS's another one, so the two dialects open
// the blocks by different amounts.
//
// Reference: ccx 2.20 (Debian calculix-ccx) on this deck, *NODE PRINT of the
// slave node 2 (x = 1/3 on the top block's bottom): u_y = -8.461832E-03.
// tether in the calculix dialect: -8.462615E-03 (the difference, 7.8e-7, is
// 0.16 % of the clearance of about 4.9e-4 there); in the abaqus dialect
// -8.337522E-03.

#include <gtest/gtest.h>

#include <cmath>

#include "analysis/run_deck.hpp"

using namespace tether;

namespace {

constexpr double kCcxSlaveUy = -8.461832e-3;

tether::testing::Run run_in(Dialect dialect) {
  tether::testing::Run run;
  run.model = read_deck(std::string(TETHER_SOURCE_DIR) + "/tests/smoke/decks/contact_exponential.inp", nullptr,
                        dialect);
  StaticAnalysis analysis(run.model, run.recorder, {});
  run.summary = analysis.run();
  return run;
}

}  // namespace

TEST(DialectAgainstCcx, ExponentialContactOpensAsInCalculix) {
  const auto calculix = run_in(Dialect::Calculix);
  const auto abaqus = run_in(Dialect::Abaqus);
  ASSERT_TRUE(calculix.summary.completed) << calculix.summary.message;
  ASSERT_TRUE(abaqus.summary.completed) << abaqus.summary.message;
  const double uy_calculix = calculix.last().displacement[static_cast<std::size_t>(calculix.node(2))].y();
  const double uy_abaqus = abaqus.last().displacement[static_cast<std::size_t>(abaqus.node(2))].y();
  EXPECT_NEAR(uy_calculix, kCcxSlaveUy, 2e-6);  // measured 7.8e-7
  EXPECT_GT(std::abs(uy_abaqus - kCcxSlaveUy), 1e-4);  // measured 1.24e-4: another law
  // Each slave node's gap and pressure lie on CalculiX's curve.
  const auto& pair = calculix.last().contact.at(0);
  ASSERT_FALSE(pair.nodes.empty());
  for (const auto& n : pair.nodes) {
    ASSERT_GT(n.pressure, 0);
    EXPECT_NEAR(n.gap, 0.001 * std::log(100 / n.pressure) / std::log(100.0), 1e-9);
  }
}
