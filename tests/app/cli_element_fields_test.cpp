// `tether run` builds the element fields of a *STATIC increment (nodal
// averages, element means) only when the result files are due; the .dat's
// *EL PRINT takes its own elements' points without them. Read back: a plate
// under uniform tension (exact stress p t and strain at every point), printed
// on a subset of its elements, without field output and with a .vtu at every
// second increment.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "cli_support.hpp"

namespace fs = std::filesystem;
using namespace cli_test;

namespace {

/// A 3 x 1 plate of CPS4 (E 1000, nu 0.25, thickness 1), x held at its left
/// edge, y at node 1, pulled by p = 10 per unit length at its right edge in
/// five DIRECT increments of 0.2: sigma_xx = 10 t, eps_xx = 0.01 t, plane stress
/// eps_yy = eps_zz = -0.0025 t at every point. *EL PRINT of elements 2 and 3 only.
std::string plate(const std::string& field_output) {
  return R"(*NODE, NSET=ALL
1, 0, 0
2, 1, 0
3, 2, 0
4, 3, 0
5, 0, 1
6, 1, 1
7, 2, 1
8, 3, 1
*ELEMENT, TYPE=CPS4, ELSET=PLATE
1, 1, 2, 6, 5
2, 2, 3, 7, 6
3, 3, 4, 8, 7
*ELSET, ELSET=SUB
2, 3
*MATERIAL, NAME=M
*ELASTIC
1000, 0.25
*SOLID SECTION, ELSET=PLATE, MATERIAL=M
1
*BOUNDARY
1, 1, 2
5, 1
*STEP
*STATIC, DIRECT
0.2, 1
*CLOAD
4, 1, 5
8, 1, 5
*EL PRINT, ELSET=SUB
S, E
*NODE PRINT, NSET=ALL
U
)" + field_output + "*END STEP\n";
}

/// One *EL PRINT block of the .dat: its heading's time and rows (element, point, six values).
struct PointBlock {
  bool stress = true;
  double time = 0;
  std::vector<std::vector<double>> rows;
};

std::vector<PointBlock> point_blocks(const fs::path& dat) {
  std::istringstream in(slurp(dat));
  std::vector<PointBlock> blocks;
  std::string line;
  const std::regex heading(R"(^ (stresses|strains) \(elem.* and time\s+(\S+))");
  PointBlock* open = nullptr;
  while (std::getline(in, line)) {
    std::smatch m;
    if (std::regex_search(line, m, heading)) {
      blocks.push_back({m[1] == "stresses", std::stod(m[2]), {}});
      open = &blocks.back();
      continue;
    }
    if (line.find("for set") != std::string::npos) open = nullptr;  // another block
    std::istringstream row(line);
    std::vector<double> v;
    double x = 0;
    while (row >> x) v.push_back(x);
    if (open && v.size() == 8) open->rows.push_back(v);
  }
  return blocks;
}

/// Checks every *EL PRINT block against the exact uniform state; returns their count.
int check_exact_points(const fs::path& dat) {
  const auto blocks = point_blocks(dat);
  for (const PointBlock& b : blocks) {
    EXPECT_EQ(b.rows.size(), 8u) << "two elements of four points at t = " << b.time;
    for (const auto& r : b.rows) {
      EXPECT_TRUE(r[0] == 2 || r[0] == 3) << "element " << r[0] << " is not in SUB";
      const std::vector<double> exact = b.stress ? std::vector<double>{10 * b.time, 0, 0, 0}
                                                 : std::vector<double>{0.01 * b.time, -0.0025 * b.time, -0.0025 * b.time, 0};
      for (std::size_t k = 0; k < 4; ++k) EXPECT_NEAR(r[2 + k], exact[k], 1e-9 + 1e-6 * std::abs(exact[k])) << b.time;
    }
  }
  return static_cast<int>(blocks.size());
}

}  // namespace

TEST(Cli, ElementPrintWithoutFieldOutputGivesItsElementsExactPoints) {
  const fs::path dir = scratch("element_fields_none");
  write(dir / "plate.inp", plate("*NODE FILE, FREQUENCY=0\nU\n"));
  const Result r = tether("run " + (dir / "plate.inp").string() + " -o " + (dir / "out").string() + " -q");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(check_exact_points(dir / "out" / "plate.dat"), 10);  // S and E at each of five increments
  for (const auto& entry : fs::directory_iterator(dir / "out"))
    EXPECT_NE(entry.path().extension(), ".vtu") << entry.path();

  // The same deck writing a .vtu at every increment (element fields built at
  // each) prints the same .dat, byte for byte.
  const fs::path every = scratch("element_fields_every");
  write(every / "plate.inp", plate("*NODE FILE, FREQUENCY=1\nU\n*EL FILE, FREQUENCY=1\nS, E\n"));
  const Result e = tether("run " + (every / "plate.inp").string() + " -o " + (every / "out").string() + " -q");
  ASSERT_EQ(e.code, 0) << e.out;
  EXPECT_EQ(slurp(dir / "out" / "plate.dat"), slurp(every / "out" / "plate.dat"));
}

TEST(Cli, FilesEverySecondIncrementHoldFullFieldsAndThePvdListsThem) {
  const fs::path dir = scratch("element_fields_every_second");
  write(dir / "plate.inp", plate("*NODE FILE, FREQUENCY=2\nU\n*EL FILE, FREQUENCY=2\nS, E\n"));
  const Result r =
      tether("run " + (dir / "plate.inp").string() + " -o " + (dir / "out").string() + " -q --ascii");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(check_exact_points(dir / "out" / "plate.dat"), 10);

  // Increments 2 and 4 (FREQUENCY=2) and 5 (the step's last), nothing else.
  const std::string pvd = slurp(dir / "out" / "plate.pvd");
  std::vector<std::pair<double, std::string>> listed;
  const std::regex dataset(R"re(timestep="([^"]+)"[^>]*file="([^"]+)")re");
  for (auto it = std::sregex_iterator(pvd.begin(), pvd.end(), dataset); it != std::sregex_iterator(); ++it)
    listed.emplace_back(std::stod((*it)[1]), (*it)[2]);
  ASSERT_EQ(listed.size(), 3u) << pvd;
  const std::vector<std::pair<double, std::string>> expected = {
      {0.4, "plate_1_2.vtu"}, {0.8, "plate_1_4.vtu"}, {1.0, "plate_1_5.vtu"}};
  int vtu_files = 0;
  for (const auto& entry : fs::directory_iterator(dir / "out")) vtu_files += entry.path().extension() == ".vtu";
  EXPECT_EQ(vtu_files, 3);
  for (std::size_t k = 0; k < expected.size(); ++k) {
    EXPECT_NEAR(listed[k].first, expected[k].first, 1e-12);
    EXPECT_EQ(listed[k].second, expected[k].second);
    // Full fields: the nodal stress S (the uniform 10 t at every node, first
    // component of the first node's six), its Mises, the strain E.
    const std::string vtu = slurp(dir / "out" / expected[k].second);
    for (const char* name : {"Name=\"S\"", "Name=\"S_Mises\"", "Name=\"E\""})
      EXPECT_NE(vtu.find(name), std::string::npos) << expected[k].second << " lacks " << name;
    const auto s = vtu.find("Name=\"S\"");
    ASSERT_NE(s, std::string::npos);
    std::istringstream values(vtu.substr(vtu.find('>', s) + 1));
    double sxx = 0;
    ASSERT_TRUE(values >> sxx) << expected[k].second;
    EXPECT_NEAR(sxx, 10 * expected[k].first, 1e-9) << expected[k].second;
  }
}
