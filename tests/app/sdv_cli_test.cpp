// SDV through the program: a user material's state variables in the .dat
// (CalculiX's block) and the VTU (SDV1, SDV2, ... per cell and per node),
// against the same J2 law given as *PLASTIC in the neighbouring element.
#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "cli_support.hpp"

using namespace cli_test;

namespace {

/// Two CPE4 side by side, element 1 the J2 UMAT example (STATEV: plastic
/// strain 11, 22, 33, engineering 12, then PEEQ), element 2 *PLASTIC with
/// the same constants (E 200000, nu 0.3, yield 240, hardening modulus 1000),
/// pulled to 5 times the yield strain in two increments; `umat` false gives
/// both elements the *PLASTIC material.
std::string two_elements(bool umat) {
  std::ostringstream d;
  d << "*NODE, NSET=ALL\n1, 0, 0\n2, 1, 0\n3, 2, 0\n4, 0, 1\n5, 1, 1\n6, 2, 1\n"
    << "*ELEMENT, TYPE=CPE4, ELSET=USER\n1, 1, 2, 5, 4\n*ELEMENT, TYPE=CPE4, ELSET=BUILTIN\n2, 2, 3, 6, 5\n"
    << "*ELSET, ELSET=BOTH\nUSER, BUILTIN\n*NSET, NSET=TOP\n4, 5, 6\n*NSET, NSET=BOTTOM\n1, 2, 3\n"
    << "*MATERIAL, NAME=UMATJ2\n*USER MATERIAL, CONSTANTS=4, LIBRARY=" << TETHER_J2_UMAT
    << "\n200000., 0.3, 240., 1000.\n*DEPVAR\n5\n"
    << "*MATERIAL, NAME=STEEL\n*ELASTIC\n200000, 0.3\n*PLASTIC\n240., 0.\n1240., 1.\n"
    << "*SOLID SECTION, ELSET=USER, MATERIAL=" << (umat ? "UMATJ2" : "STEEL") << "\n1.\n"
    << "*SOLID SECTION, ELSET=BUILTIN, MATERIAL=STEEL\n1.\n"
    << "*BOUNDARY\nBOTTOM, 2, 2\n1, 1, 1\n*STEP\n*STATIC, DIRECT\n0.5, 1.\n*BOUNDARY\nTOP, 2, 2, 0.006\n"
    << "*EL PRINT, ELSET=BOTH\nSDV, PEEQ, PE\n*NODE FILE\nU\n*EL FILE\nS, SDV\n*END STEP\n";
  return d.str();
}

/// The rows of every .dat block whose title starts with `title`: per block,
/// per line the numbers after the element and point labels.
std::vector<std::vector<std::vector<double>>> dat_rows(const std::string& dat, const std::string& title) {
  std::vector<std::vector<std::vector<double>>> blocks;
  for (auto at = dat.find("\n " + title); at != std::string::npos; at = dat.find("\n " + title, at + 1)) {
    std::istringstream lines(dat.substr(dat.find("\n\n", at + 1) + 2));
    std::vector<std::vector<double>> rows;
    std::string line;
    while (std::getline(lines, line) && !line.empty()) {
      std::istringstream fields(line);
      int element = 0, point = 0;
      fields >> element >> point;
      std::vector<double> values;
      for (double v = 0; fields >> v;) values.push_back(v);
      rows.push_back(values);
    }
    blocks.push_back(rows);
  }
  return blocks;
}

}  // namespace

TEST(Cli, SdvOfAUserMaterialIsWrittenToTheDatAndTheVtuAndMatchesTheBuiltInLaw) {
  const fs::path dir = scratch("sdv_two_elements");
  write(dir / "two.inp", two_elements(true));
  const auto run = tether("run --ascii " + (dir / "two.inp").string() + " -o " + (dir / "out").string());
  ASSERT_EQ(run.code, 0) << run.out;
  for (const std::string f : {".pvd", ".dat", ".sta", ".msg", "_1_2.vtu"})
    EXPECT_TRUE(fs::exists(dir / "out" / ("two" + f))) << f;
  const std::string dat = slurp(dir / "out" / "two.dat");
  const auto sdv = dat_rows(dat, "internal state variables (elem, integ.pnt.,values) for set BOTH");
  const auto peeq = dat_rows(dat, "equivalent plastic strain");
  const auto pe = dat_rows(dat, "plastic strains");
  ASSERT_EQ(sdv.size(), 2u) << dat;  // two increments
  ASSERT_EQ(peeq.size(), 2u);
  ASSERT_EQ(pe.size(), 2u);
  for (std::size_t inc = 0; inc < 2; ++inc) {
    ASSERT_EQ(sdv[inc].size(), 8u);  // 2 elements x 4 points, element 1 first
    for (std::size_t k = 0; k < 8; ++k) ASSERT_EQ(sdv[inc][k].size(), 5u) << "row " << k;
    for (std::size_t k = 0; k < 4; ++k) {
      const double builtin_peeq = peeq[inc][4 + k][0];  // element 2, *PLASTIC
      EXPECT_GT(builtin_peeq, 1e-3);
      // STATEV(5) is the UMAT's PEEQ, STATEV(1..3) its plastic strain: those of
      // *PLASTIC at the same strain, to the printed 7 digits.
      EXPECT_NEAR(sdv[inc][k][4], builtin_peeq, 1e-6 * builtin_peeq) << "increment " << inc << " point " << k;
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(sdv[inc][k][static_cast<std::size_t>(c)], pe[inc][4 + k][static_cast<std::size_t>(c)],
                    1e-6 * builtin_peeq);
      EXPECT_NEAR(sdv[inc][k][3], 2 * pe[inc][4 + k][3], 1e-6 * builtin_peeq);  // engineering against tensor shear
      for (double v : sdv[inc][4 + k]) EXPECT_EQ(v, 0.0);  // *PLASTIC has no STATEV
    }
  }
  // The last VTU: per cell the mean of the element's points, per node the
  // extrapolation averaged over the elements around it (element 2 counts as zeros).
  const std::string vtu = slurp(dir / "out" / "two_1_2.vtu");
  const double p = sdv[1][0][4];
  const std::vector<double> cell = vtu_values(vtu, "SDV5", 2, vtu.find("<CellData"));
  ASSERT_EQ(cell.size(), 2u) << vtu;
  EXPECT_NEAR(cell[0], p, 1e-6 * p);
  EXPECT_EQ(cell[1], 0.0);
  const std::vector<double> nodal = vtu_values(vtu, "SDV5", 6);
  ASSERT_EQ(nodal.size(), 6u);
  for (int n : {0, 3}) EXPECT_NEAR(nodal[static_cast<std::size_t>(n)], p, 1e-6 * p) << "node " << n + 1;
  for (int n : {1, 4}) EXPECT_NEAR(nodal[static_cast<std::size_t>(n)], p / 2, 1e-6 * p) << "node " << n + 1;
  for (int n : {2, 5}) EXPECT_EQ(nodal[static_cast<std::size_t>(n)], 0.0) << "node " << n + 1;
  for (const std::string name : {"SDV1", "SDV2", "SDV3", "SDV4"})
    EXPECT_EQ(vtu_values(vtu, name, 1, vtu.find("<CellData")).size(), 1u) << name;
  EXPECT_TRUE(vtu_values(vtu, "SDV6", 1).empty());
}

TEST(Cli, SdvWithoutAUserMaterialSaysWhatCalculixWouldWriteAndWritesNothing) {
  const fs::path dir = scratch("sdv_without_umat");
  write(dir / "two.inp", two_elements(false));
  const auto run = tether("run --ascii " + (dir / "two.inp").string() + " -o " + (dir / "out").string());
  ASSERT_EQ(run.code, 0) << run.out;
  const std::string messages = run.out + slurp(dir / "out" / "two.msg");
  EXPECT_NE(messages.find("SDV: no section uses a user material with *DEPVAR"), std::string::npos) << messages;
  EXPECT_NE(messages.find("CalculiX also writes its built-in materials' internal variables"), std::string::npos);
  const std::string dat = slurp(dir / "out" / "two.dat");
  EXPECT_EQ(dat.find("internal state variables"), std::string::npos);
  EXPECT_NE(dat.find("equivalent plastic strain"), std::string::npos);
  EXPECT_EQ(slurp(dir / "out" / "two_1_2.vtu").find("SDV1"), std::string::npos);
}
