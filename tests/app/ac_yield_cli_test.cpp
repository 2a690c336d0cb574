// AC YIELD through the program: a one-element bar pulled elastically (step
// 1), plastically (step 2) and unloaded a little (step 3), in plane stress,
// plane strain and axisymmetry, small and finite strain, each hardening kind;
// `tether run` with every writer, the .dat blocks and each VTU read back.
#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "cli_support.hpp"

using namespace cli_test;

namespace {

struct Variant {
  std::string name, element, hardening;
  bool nlgeom = false;
};

/// The bar (1 x 1, one element; radially 1..2 for CAX4): E = 200000, nu =
/// 0.3, yield 200 (uniaxial yield strain 1e-3), the top pulled to 5e-4
/// (elastic), 3e-3 (plastic), back to 2.8e-3 (elastic unloading), two fixed
/// increments a step; *EL PRINT with `variables`.
std::string bar_deck(const Variant& v, const std::string& variables) {
  const bool axisymmetric = v.element == "CAX4";
  const double x0 = axisymmetric ? 1 : 0;
  std::ostringstream d;
  d << "*HEADING\nAC YIELD bar, " << v.name << "\n*NODE, NSET=ALL\n"
    << "1, " << x0 << ", 0\n2, " << x0 + 1 << ", 0\n3, " << x0 + 1 << ", 1\n4, " << x0 << ", 1\n"
    << "*ELEMENT, TYPE=" << v.element << ", ELSET=BAR\n1, 1, 2, 3, 4\n"
    << "*NSET, NSET=TOP\n3, 4\n*NSET, NSET=BOTTOM\n1, 2\n*MATERIAL, NAME=STEEL\n*ELASTIC\n200000, 0.3\n"
    << "*PLASTIC, HARDENING=" << v.hardening << "\n200., 0.\n1200., 0.1\n";
  if (v.hardening == "COMBINED") d << "*CYCLIC HARDENING\n200., 0.\n600., 0.1\n";
  d << "*SOLID SECTION, ELSET=BAR, MATERIAL=STEEL\n" << (axisymmetric ? "" : "1.\n") << "*BOUNDARY\nBOTTOM, 2, 2\n";
  if (!axisymmetric) d << "1, 1, 1\n";
  for (const char* top : {"0.0005", "0.003", "0.0028"}) {
    d << "*STEP" << (v.nlgeom ? ", NLGEOM" : "") << "\n*STATIC, DIRECT\n0.5, 1.\n*BOUNDARY\nTOP, 2, 2, " << top
      << "\n*EL PRINT, ELSET=BAR\n" << variables << "\n*NODE FILE\nU\n*EL FILE\nS, PEEQ, AC YIELD\n*END STEP\n";
  }
  return d.str();
}

/// The rows (element, point, value) of every .dat block whose title starts with `title`, block by block.
std::vector<std::vector<double>> dat_values(const std::string& dat, const std::string& title) {
  std::vector<std::vector<double>> blocks;
  for (auto at = dat.find("\n " + title); at != std::string::npos; at = dat.find("\n " + title, at + 1)) {
    std::istringstream rows(dat.substr(dat.find("\n\n", at + 1) + 2));
    std::vector<double> values;
    std::string line;
    while (std::getline(rows, line) && !line.empty()) {
      int element = 0, point = 0;
      double v = 0;
      if (std::sscanf(line.c_str(), "%d %d %lf", &element, &point, &v) == 3) values.push_back(v);
    }
    blocks.push_back(values);
  }
  return blocks;
}

}  // namespace

TEST(Cli, AcYieldOfABarLoadedElasticallyPlasticallyThenUnloadedIsZeroOneZeroInTheDatAndTheVtu) {
  const std::vector<Variant> variants = {
      {"plane stress, isotropic", "CPS4", "ISOTROPIC"},
      {"plane strain, kinematic", "CPE4", "KINEMATIC"},
      {"axisymmetric, combined", "CAX4", "COMBINED"},
      {"plane stress, combined, NLGEOM", "CPS4", "COMBINED", true},
      {"plane strain, isotropic, NLGEOM", "CPE4", "ISOTROPIC", true},
      {"axisymmetric, kinematic, NLGEOM", "CAX4", "KINEMATIC", true},
  };
  // Per increment (two a step): elastic, elastic, plastic, plastic, unloading, unloading.
  const std::vector<double> expected = {0, 0, 1, 1, 0, 0};
  int n = 0;
  for (const Variant& v : variants) {
    SCOPED_TRACE(v.name);
    const fs::path dir = scratch("ac_yield_bar_" + std::to_string(++n));
    // ABAQUS's spelling with the blank, and without it (the same variable, printed once).
    write(dir / "bar.inp", bar_deck(v, "PEEQ, AC YIELD, ACYIELD"));
    const auto run = tether("run --ascii " + (dir / "bar.inp").string() + " -o " + (dir / "out").string());
    ASSERT_EQ(run.code, 0) << run.out;
    for (const std::string f : {".pvd", ".dat", ".sta", ".msg", "_3_2.vtu"})
      EXPECT_TRUE(fs::exists(dir / "out" / ("bar" + f))) << f;
    const std::string dat = slurp(dir / "out" / "bar.dat");
    const auto flags = dat_values(dat, "actively yielding (elem, integ.pnt.,ac yield) for set BAR");
    const auto peeq = dat_values(dat, "equivalent plastic strain");
    ASSERT_EQ(flags.size(), expected.size()) << dat;
    ASSERT_EQ(peeq.size(), expected.size());
    double peeq_before = 0;
    for (std::size_t k = 0; k < expected.size(); ++k) {
      ASSERT_EQ(flags[k].size(), 4u) << "increment " << k;
      for (double f : flags[k]) EXPECT_EQ(f, expected[k]) << "increment " << k;
      // The flag is PEEQ growing (7 printed digits are enough here: it grows by > 1e-4 when it grows).
      EXPECT_EQ(peeq[k][0] > peeq_before, expected[k] == 1) << "increment " << k;
      peeq_before = peeq[k][0];
      // The VTU of the increment: the nodes' and the cell's fractions of yielding points.
      const std::string vtu = slurp(dir / "out" / ("bar_" + std::to_string(k / 2 + 1) + "_" + std::to_string(k % 2 + 1) + ".vtu"));
      const std::vector<double> nodal = vtu_values(vtu, "AC_YIELD", 4);
      const std::vector<double> cell = vtu_values(vtu, "AC_YIELD", 1, vtu.find("<CellData"));
      ASSERT_EQ(nodal.size(), 4u) << "increment " << k;
      ASSERT_EQ(cell.size(), 1u) << "increment " << k;
      for (double f : nodal) EXPECT_EQ(f, expected[k]) << "increment " << k;
      EXPECT_EQ(cell[0], expected[k]) << "increment " << k;
    }
  }
}

TEST(Cli, AcYieldMisspelledIsNamedInTheWarningWithTheAvailableVariables) {
  const fs::path dir = scratch("ac_yield_misspelled");
  write(dir / "bar.inp", bar_deck({"plane stress", "CPS4", "ISOTROPIC"}, "PEEQ, AC YEILD"));
  const auto run = tether("run --ascii " + (dir / "bar.inp").string() + " -o " + (dir / "out").string());
  ASSERT_EQ(run.code, 0) << run.out;
  const std::string messages = run.out + slurp(dir / "out" / "bar.msg");
  EXPECT_NE(messages.find("output variable AC YEILD is not available"), std::string::npos) << messages;
  EXPECT_NE(messages.find("PE, AC YIELD, SDV)"), std::string::npos) << messages;
  EXPECT_EQ(slurp(dir / "out" / "bar.dat").find("actively yielding"), std::string::npos);
}
