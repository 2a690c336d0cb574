// `tether run` on decks of the newer features, read back from its files:
// temperature loads (.dat NT), bolt pretension (bolt force block, the cut in
// the VTU) and ABAQUS/CAE instances (VTU arrays, analysis messages).

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cli_support.hpp"

namespace fs = std::filesystem;
using namespace cli_test;

// A thermal deck through `tether run`: the .dat's temperatures (NT) and
// displacements read back are the free expansion alpha dT x of the plate.
TEST(Cli, ThermalDeckPrintsTemperaturesAndTheFreeExpansion) {
  const fs::path dir = scratch("thermal");
  write(dir / "hot.inp", R"(*HEADING
free plate heated from 20 to 120
*NODE, NSET=ALL
1, 0, 0
2, 2, 0
3, 2, 1
4, 0, 1
*ELEMENT, TYPE=CPS4, ELSET=E
1, 1, 2, 3, 4
*MATERIAL, NAME=M
*ELASTIC
2e5, 0.3
*EXPANSION, ZERO=20
1.2e-5
*SOLID SECTION, ELSET=E, MATERIAL=M
*INITIAL CONDITIONS, TYPE=TEMPERATURE
ALL, 20
*BOUNDARY
1, 1, 2
4, 1
*STEP
*STATIC
*TEMPERATURE
ALL, 120
*NODE PRINT, NSET=ALL
U, NT
*END STEP
)");
  const Result r = tether("run " + (dir / "hot.inp").string() + " -o " + (dir / "out").string());
  ASSERT_EQ(r.code, 0) << r.out;
  std::ifstream dat(dir / "out" / "hot.dat");
  std::string line;
  std::map<int, std::vector<double>> u, nt;
  std::map<int, std::vector<double>>* block = nullptr;
  while (std::getline(dat, line)) {
    if (line.find("displacements") != std::string::npos) block = &u;
    else if (line.find("temperatures") != std::string::npos) block = &nt;
    std::istringstream in(line);
    int node = 0;
    if (block == nullptr || !(in >> node)) continue;
    double v = 0;
    while (in >> v) (*block)[node].push_back(v);
  }
  ASSERT_EQ(nt.size(), 4u);
  for (const auto& [node, t] : nt) EXPECT_DOUBLE_EQ(t.at(0), 120.0);
  ASSERT_EQ(u.size(), 4u);
  const double eth = 1.2e-5 * 100;  // printed to 7 digits
  EXPECT_NEAR(u[2].at(0), 2 * eth, 1e-9);
  EXPECT_NEAR(u[3].at(0), 2 * eth, 1e-9);
  EXPECT_NEAR(u[3].at(1), eth, 1e-9);
  EXPECT_NEAR(u[4].at(1), eth, 1e-9);
}

// Bolt pretension through `tether run`: every writer, and the bolt force and
// tightening read back from the .dat (tests/analysis/pretension_test.cpp
// holds the closed form: preload 10, then 10 + 0.6 x 4 with the length held).
TEST(Cli, PretensionDeckRunsWithAllWritersAndTheDatGivesTheBoltForce) {
  const fs::path dir = scratch("pretension");
  const fs::path deck = fs::path(TETHER_SOURCE_DIR) / "tests/analysis/decks/bolt_joint.inp";
  const auto run = tether("run --ascii " + deck.string() + " -o " + (dir / "out").string());
  ASSERT_EQ(run.code, 0) << run.out;
  for (const char* f : {"bolt_joint.pvd", "bolt_joint.dat", "bolt_joint.sta", "bolt_joint.msg", "bolt_joint_1_1.vtu",
                        "bolt_joint_2_1.vtu"})
    EXPECT_TRUE(fs::exists(dir / "out" / f)) << f;
  const std::string dat = slurp(dir / "out" / "bolt_joint.dat");
  const std::string title = " pretension section (node,tightening,bolt force) for set PRETENSION-CUT and time ";
  std::vector<std::array<double, 3>> rows;  // time, tightening, force
  for (std::size_t at = dat.find(title); at != std::string::npos; at = dat.find(title, at + 1)) {
    double time = 0, tightening = 0, force = 0;
    int node = 0;
    const std::string block = dat.substr(at + title.size());
    ASSERT_EQ(std::sscanf(block.c_str(), "%lf %d %lf %lf", &time, &node, &tightening, &force), 4) << block;
    EXPECT_EQ(node, 100);
    rows.push_back({time, tightening, force});
  }
  ASSERT_EQ(rows.size(), 2u) << dat;
  EXPECT_DOUBLE_EQ(rows[0][0], 1.0);
  EXPECT_NEAR(rows[0][1], 10. / 1500 + 10. / 1000, 1e-6 * 0.0166667);  // the .dat keeps 7 digits
  EXPECT_NEAR(rows[0][2], 10., 1e-6 * 10);
  EXPECT_DOUBLE_EQ(rows[1][0], 2.0);
  EXPECT_NEAR(rows[1][1], rows[0][1], 1e-6 * 0.0166667);
  EXPECT_NEAR(rows[1][2], 12.4, 1e-6 * 12.4);
  // The cut shows in the VTU: 15 mesh nodes, the pretension node and the two duplicates.
  const std::string vtu = slurp(dir / "out" / "bolt_joint_2_1.vtu");
  EXPECT_NE(vtu.find("NumberOfPoints=\"18\""), std::string::npos) << vtu.substr(0, 400);
}

namespace {

/// The values of the ascii DataArray `name` in `section` ("PointData" or "CellData") of a .vtu.
std::vector<long long> ascii_ints(const std::string& vtu, const std::string& section, const std::string& name) {
  const auto begin = vtu.find("<" + section);
  const auto at = vtu.find("Name=\"" + name + "\"", begin);
  if (begin == std::string::npos || at == std::string::npos || at > vtu.find("</" + section, begin)) return {};
  const auto from = vtu.find('>', at) + 1;
  std::istringstream in(vtu.substr(from, vtu.find("</DataArray>", from) - from));
  std::vector<long long> values;
  for (long long v = 0; in >> v;) values.push_back(v);
  return values;
}

}  // namespace

// An ABAQUS/CAE deck with one part instanced twice: the VTU says which
// instance each node and element belongs to and its label in the part, and
// flat decks get none of those arrays.
TEST(Cli, CaeDeckVtuCarriesInstancesAndPartLabels) {
  const fs::path dir = scratch("cae_vtu");
  const fs::path deck = fs::path(TETHER_SOURCE_DIR) / "tests/io/decks/cae/one_part_twice.inp";
  const auto run = tether("run --ascii " + deck.string() + " -o " + (dir / "out").string());
  ASSERT_EQ(run.code, 0) << run.out;
  const std::string vtu = slurp(dir / "out" / "one_part_twice_1_2.vtu");
  // Instance names as VTK string arrays store them: character codes, each name ended by 0.
  std::string names;
  for (const std::string n : {"LOWER-1", "UPPER-1"}) {
    for (char c : n) names += std::to_string(static_cast<int>(c)) + " ";
    names += "0 ";
  }
  EXPECT_NE(vtu.find("Name=\"INSTANCE_NAMES\" NumberOfTuples=\"2\" format=\"ascii\">" + names + "</DataArray>"),
            std::string::npos)
      << vtu.substr(0, 800);
  const auto node_ids = ascii_ints(vtu, "PointData", "NodeId");
  const auto instance = ascii_ints(vtu, "PointData", "INSTANCE");
  const auto part_node = ascii_ints(vtu, "PointData", "PART_NODE_ID");
  ASSERT_EQ(node_ids.size(), 18u);
  ASSERT_EQ(instance.size(), 18u);
  ASSERT_EQ(part_node.size(), 18u);
  for (std::size_t i = 0; i < 18; ++i) {
    const bool upper = node_ids[i] > 10;  // inside tether the upper copy's nodes are 11-19
    EXPECT_EQ(instance[i], upper ? 2 : 1) << "node " << node_ids[i];
    EXPECT_EQ(part_node[i], upper ? node_ids[i] - 10 : node_ids[i]) << "node " << node_ids[i];
  }
  const auto element_ids = ascii_ints(vtu, "CellData", "ElementId");
  const auto cell_instance = ascii_ints(vtu, "CellData", "INSTANCE");
  const auto part_element = ascii_ints(vtu, "CellData", "PART_ELEMENT_ID");
  ASSERT_EQ(element_ids.size(), 8u);
  ASSERT_EQ(cell_instance.size(), 8u);
  ASSERT_EQ(part_element.size(), 8u);
  for (std::size_t c = 0; c < 8; ++c) {
    EXPECT_EQ(cell_instance[c], element_ids[c] > 10 ? 2 : 1);
    EXPECT_EQ(part_element[c], element_ids[c] > 10 ? element_ids[c] - 10 : element_ids[c]);
  }
  const auto flat = tether("run --ascii " + (fs::path(TETHER_SOURCE_DIR) / "tests/analysis/decks/bolt_joint.inp").string() +
                           " -o " + (dir / "flat").string());
  ASSERT_EQ(flat.code, 0) << flat.out;
  const std::string flat_vtu = slurp(dir / "flat" / "bolt_joint_1_1.vtu");
  EXPECT_EQ(flat_vtu.find("INSTANCE"), std::string::npos);
  EXPECT_EQ(flat_vtu.find("PART_NODE_ID"), std::string::npos);
}

// Analysis messages name the nodes of a CAE deck as its author knows them:
// the upper copy, no longer held sideways, floats, and the singular-model
// message names an Upper-1 node (inside tether its label is 11-19).
TEST(Cli, AnalysisMessagesNameInstanceNodesAsTheDeckDoes) {
  const fs::path dir = scratch("cae_messages");
  std::string deck = slurp(fs::path(TETHER_SOURCE_DIR) / "tests/io/decks/cae/one_part_twice.inp");
  const auto pos = deck.find("Upper-1.8, 1, 1\n");
  ASSERT_NE(pos, std::string::npos);
  deck.erase(pos, std::string("Upper-1.8, 1, 1\n").size());
  write(dir / "floating.inp", deck);
  const auto run = tether("run " + (dir / "floating.inp").string() + " -o " + (dir / "out").string());
  EXPECT_EQ(run.code, 2) << run.out;
  EXPECT_NE(run.out.find("node UPPER-1."), std::string::npos) << run.out;
  EXPECT_EQ(run.out.find("node 1"), std::string::npos) << run.out;  // no internal label 11-19
}
