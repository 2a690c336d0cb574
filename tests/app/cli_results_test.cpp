// `tether run` on decks of the newer features, read back from its files:
// temperature loads (.dat NT, thermal strains THE in the .dat and the VTU),
// bolt pretension (bolt force block, the cut in the VTU, a restart after the
// step that holds the bolt length) and ABAQUS/CAE instances (VTU arrays,
// analysis messages).

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
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

namespace {

/// The values of the ascii Float64 DataArray `name` in the PointData of a .vtu.
std::vector<double> ascii_point_doubles(const std::string& vtu, const std::string& name) {
  const auto begin = vtu.find("<PointData");
  const auto at = vtu.find("Name=\"" + name + "\"", begin);
  if (begin == std::string::npos || at == std::string::npos || at > vtu.find("</PointData", begin)) return {};
  const auto from = vtu.find('>', at) + 1;
  std::istringstream in(vtu.substr(from, vtu.find("</DataArray>", from) - from));
  std::vector<double> values;
  for (double v = 0; in >> v;) values.push_back(v);
  return values;
}

/// Rows (label, point, six components) of the .dat blocks whose title starts with `title`.
std::vector<std::vector<double>> dat_rows(const std::string& dat, const std::string& title) {
  std::vector<std::vector<double>> rows;
  std::istringstream in(dat);
  bool inside = false;
  for (std::string line; std::getline(in, line);) {
    if (line.find(" for set ") != std::string::npos) {
      inside = line.find(title) == 1;  // headers start with one blank
      continue;
    }
    std::istringstream fields(line);
    std::vector<double> row;
    for (double v = 0; fields >> v;) row.push_back(v);
    if (inside && row.size() == 8) rows.push_back(row);
  }
  return rows;
}

/// A free CPS8 plate 2 x 1 (two elements, quadratic: the exact displacement
/// of a linear temperature field is quadratic) held against rigid motion only.
/// Small strain: heated from 20 to T = 20 + 100 x (stress free). NLGEOM:
/// heated uniformly to 1020 (stress free; a non-uniform field is not under
/// finite strain). THE is requested in the .dat and the result files.
std::string heated_plate_deck(bool nlgeom) {
  std::string nodes, temperatures;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 5; ++i) {
      if (j == 1 && (i == 1 || i == 3)) continue;  // element centres: no node
      const int id = 1 + i + 5 * j;
      const double x = 0.5 * i;
      nodes += std::to_string(id) + ", " + std::to_string(x) + ", " + std::to_string(0.5 * j) + "\n";
      temperatures += std::to_string(id) + ", " + std::to_string(nlgeom ? 1020.0 : 20 + 100 * x) + "\n";
    }
  return "*HEADING\nfree plate\n*NODE, NSET=ALL\n" + nodes +
         "*ELEMENT, TYPE=CPS8, ELSET=E\n1, 1, 3, 13, 11, 2, 8, 12, 6\n2, 3, 5, 15, 13, 4, 10, 14, 8\n"
         "*MATERIAL, NAME=M\n*ELASTIC\n2e5, 0.3\n*EXPANSION, ZERO=20\n1.2e-5\n"
         "*SOLID SECTION, ELSET=E, MATERIAL=M\n*INITIAL CONDITIONS, TYPE=TEMPERATURE\nALL, 20\n"
         "*BOUNDARY\n1, 1, 2\n5, 2\n*STEP" + std::string(nlgeom ? ", NLGEOM" : "") +
         "\n*STATIC\n*TEMPERATURE\n" + temperatures +
         "*EL PRINT, ELSET=E\nE, THE\n*OUTPUT, FIELD\n*ELEMENT OUTPUT\nS, THE\n*END STEP\n";
}

}  // namespace

// THE through `tether run`, read back from the .dat and the VTU, against the
// closed form alpha (T - T0) of a free heated plate (stress free): at every
// integration point THE is alpha (T(x) - T0) on xx, yy and zz and zero on
// shear, and E equals it (small strain) or THE + THE^2 / 2 (Green-Lagrange,
// NLGEOM); the VTU's nodal THE, the extrapolation, is alpha (T_node - T0).
TEST(Cli, ThermalStrainTheIsPrintedAndWrittenAsAlphaDeltaT) {
  const double alpha = 1.2e-5;
  for (const bool nlgeom : {false, true}) {
    SCOPED_TRACE(nlgeom ? "NLGEOM" : "small strain");
    const auto closed_form = [&](double x) { return alpha * (nlgeom ? 1000.0 : 100 * x); };
    const fs::path dir = scratch(nlgeom ? "the_nlgeom" : "the_small");
    write(dir / "the.inp", heated_plate_deck(nlgeom));
    const Result r = tether("run --ascii " + (dir / "the.inp").string() + " -o " + (dir / "out").string());
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_EQ(r.out.find("not available"), std::string::npos) << r.out;
    const std::string dat = slurp(dir / "out" / "the.dat");
    const auto the = dat_rows(dat, "thermal strains (elem, integ.pnt.,exx,eyy,ezz,exy,exz,eyz)");
    const auto e = dat_rows(dat, "strains (elem, integ.pnt.,exx,eyy,ezz,exy,exz,eyz)");
    ASSERT_EQ(the.size(), 18u) << dat;
    ASSERT_EQ(e.size(), 18u) << dat;
    // 3 x 3 Gauss points: x = centre + 0.5 (-sqrt 0.6, 0, sqrt 0.6), three points each.
    std::vector<double> expected, printed;
    for (const double centre : {0.5, 1.5})
      for (const double s : {-1.0, 0.0, 1.0})
        for (int k = 0; k < 3; ++k) expected.push_back(closed_form(centre + 0.5 * s * std::sqrt(0.6)));
    for (std::size_t k = 0; k < the.size(); ++k) {
      const auto& t = the[k];
      EXPECT_EQ(t[0], e[k][0]);
      EXPECT_EQ(t[1], e[k][1]);
      EXPECT_GT(t[2], 0.0);
      EXPECT_EQ(t[3], t[2]) << "yy";
      EXPECT_EQ(t[4], t[2]) << "zz";
      EXPECT_EQ(t[5], 0.0);
      for (int c = 6; c < 8; ++c) EXPECT_EQ(t[c], 0.0);
      const double total = nlgeom ? t[2] + 0.5 * t[2] * t[2] : t[2];
      for (int c = 2; c < 5; ++c) EXPECT_NEAR(e[k][c], total, 2e-6 * total) << "E against THE, column " << c;
      EXPECT_NEAR(e[k][5], 0.0, 1e-6 * total);
      printed.push_back(t[2]);
    }
    std::sort(expected.begin(), expected.end());
    std::sort(printed.begin(), printed.end());
    for (std::size_t k = 0; k < expected.size(); ++k) EXPECT_NEAR(printed[k], expected[k], 1e-6 * expected[k]) << k;
    // VTU: THE at the nodes, six components (XX, YY, ZZ, XY, YZ, XZ).
    const std::string vtu = slurp(dir / "out" / "the_1_1.vtu");
    const auto ids = ascii_ints(vtu, "PointData", "NodeId");
    const auto nodal = ascii_point_doubles(vtu, "THE");
    ASSERT_EQ(ids.size(), 13u);
    ASSERT_EQ(nodal.size(), 6u * ids.size()) << vtu.substr(0, 600);
    for (std::size_t i = 0; i < ids.size(); ++i) {
      const double eth = closed_form(0.5 * static_cast<double>((ids[i] - 1) % 5));
      for (std::size_t c = 0; c < 3; ++c) EXPECT_NEAR(nodal[6 * i + c], eth, 1e-12) << ids[i] << "," << c;
      for (std::size_t c = 3; c < 6; ++c) EXPECT_NEAR(nodal[6 * i + c], 0.0, 1e-15) << ids[i] << "," << c;
    }
  }
}

namespace {

/// (time, tightening, bolt force) of each pretension block of a .dat.
std::vector<std::array<double, 3>> bolt_rows(const std::string& dat) {
  const std::string title = " pretension section (node,tightening,bolt force) for set PRETENSION-CUT and time ";
  std::vector<std::array<double, 3>> rows;
  for (std::size_t at = dat.find(title); at != std::string::npos; at = dat.find(title, at + 1)) {
    double time = 0, tightening = 0, force = 0;
    int node = 0;
    if (std::sscanf(dat.c_str() + at + title.size(), "%lf %d %lf %lf", &time, &node, &tightening, &force) == 4)
      rows.push_back({time, tightening, force});
  }
  return rows;
}

}  // namespace

// A restart of the bolt deck after the step that holds the bolt length
// (*BOUNDARY, FIXED): the continued run carries the held length into a third
// step (head load 6: bolt force 10 + 0.6 x 6 = 13.6), as the uninterrupted run
// does, and leaves the first run's files alone. A deck whose step 2 holds the
// pretension node at 0 instead of FIXED has another load history and is
// refused (the restart check used to ignore FIXED).
TEST(Cli, PretensionRestartCarriesTheHeldBoltLengthAndRefusesAnotherHistory) {
  const fs::path dir = scratch("pretension_restart");
  const auto path = [&](const std::string& name) { return (dir / name).string(); };
  std::string two = slurp(fs::path(TETHER_SOURCE_DIR) / "tests/analysis/decks/bolt_joint.inp");
  const std::string fixed = "*BOUNDARY, FIXED\n100, 1\n";
  ASSERT_NE(two.find(fixed), std::string::npos);
  two.insert(two.find(fixed), "*RESTART, WRITE, FREQUENCY=1\n");
  const std::string three =
      two + "*STEP\n*STATIC\n1., 1.\n*CLOAD\n9, 2, 6.\n*NODE PRINT, NSET=PRET\nU, RF\n*END STEP\n";
  write(dir / "first.inp", two);
  write(dir / "job.inp", three);
  ASSERT_EQ(tether("run " + path("first.inp") + " -o " + path("first")).code, 0);
  ASSERT_EQ(tether("run " + path("job.inp") + " -o " + path("full")).code, 0);
  ASSERT_TRUE(fs::exists(dir / "first" / "first.rst"));
  const std::string first_dat = slurp(dir / "first" / "first.dat");

  const auto r = tether("run " + path("job.inp") + " --restart " + path("first/first.rst") + " -o " + path("resumed"));
  ASSERT_EQ(r.code, 0) << r.out;
  const std::string resumed = slurp(dir / "resumed" / "job.dat"), full = slurp(dir / "full" / "job.dat");
  const auto rows = bolt_rows(resumed);
  ASSERT_EQ(rows.size(), 1u) << resumed;  // step 3 only
  EXPECT_DOUBLE_EQ(rows[0][0], 3.0);
  EXPECT_NEAR(rows[0][1], 10. / 1500 + 10. / 1000, 1e-6 * 0.0166667);  // the length held since step 1
  EXPECT_NEAR(rows[0][2], 13.6, 1e-6 * 13.6);
  ASSERT_LT(resumed.size(), full.size());
  EXPECT_EQ(full.substr(full.size() - resumed.size()), resumed);
  EXPECT_EQ(slurp(dir / "first" / "first.dat"), first_dat);

  std::string held_at_zero = three;
  held_at_zero.replace(held_at_zero.find(fixed), fixed.size(), "*BOUNDARY\n100, 1\n");
  write(dir / "zero.inp", held_at_zero);
  const auto refused = tether("run " + path("zero.inp") + " --restart " + path("first/first.rst") + " -o " + path("zero"));
  EXPECT_EQ(refused.code, 1) << refused.out;
  EXPECT_NE(refused.out.find("cannot continue this deck from the restart file"), std::string::npos) << refused.out;
  EXPECT_NE(refused.out.find("the load history of steps 1..2 differs"), std::string::npos) << refused.out;
  EXPECT_FALSE(fs::exists(dir / "zero"));
  EXPECT_EQ(slurp(dir / "first" / "first.dat"), first_dat);
}

// The .dat's contact rows of a CAE deck carry the part's labels when a pair's
// slave nodes (and its master elements) lie in one instance, as the node and
// element blocks of a set do: Upper-1's bottom nodes 1-3 (inside tether
// 11-13) on Lower-1's top elements.
TEST(Cli, CaeDeckContactRowsCarryPartLabels) {
  const fs::path dir = scratch("cae_contact_rows");
  std::string deck = slurp(fs::path(TETHER_SOURCE_DIR) / "tests/io/decks/cae/one_part_twice.inp");
  const auto end = deck.rfind("*End Step");
  ASSERT_NE(end, std::string::npos);
  deck.insert(end, "*Contact Print\nCSTRESS\n");
  write(dir / "contact.inp", deck);
  const auto run = tether("run " + (dir / "contact.inp").string() + " -o " + (dir / "out").string() + " -q");
  ASSERT_EQ(run.code, 0) << run.out;
  std::istringstream dat(slurp(dir / "out" / "contact.dat"));
  std::string line, block;
  int state_rows = 0, stress_rows = 0;
  while (std::getline(dat, line)) {
    if (line.find_first_of("abcdefghijklmnopqrstuvwxyz") != std::string::npos) block = line;  // a block's title
    std::istringstream row(line);
    std::vector<double> v;
    for (double x; row >> x;) v.push_back(x);
    if (v.empty() || block.empty()) continue;
    if (block.find("contact stress") != std::string::npos && v.size() == 4) {
      ++stress_rows;
      EXPECT_LE(v[0], 3) << line;  // a part label of Upper-1's bottom, not 11-13
    } else if (block.find("contact state") != std::string::npos && v.size() == 10) {
      ++state_rows;
      EXPECT_LE(v[0], 3) << line;
      EXPECT_LE(v[7], 4) << line;  // Lower-1's elements 1-4
    }
  }
  EXPECT_EQ(state_rows, 6);  // three slave nodes at each of the two increments
  EXPECT_GE(stress_rows, 1);
}

// A node-based slave surface of CAX8 elements through `tether run --dialect
// calculix`, read back from the .dat at t = 1: each slave node's u_y within
// 2e-8 of ccx 2.20's on the same deck (measured 1e-9, ccx's last digit; 1.1e-5
// when tether took the master face's area on the undeformed mesh), the base's
// total force as ccx prints it (its 2° segment: 10 pi (2² - 1) / 180 =
// 0.5235988) and the contact pressure within 1e-5 of ccx's at every slave node. Before session 12 the deck was
// refused (node-based slaves next to quadratic or axisymmetric elements).
TEST(Cli, NodeBasedSlaveOfCax8MatchesCcxInTheCalculixDialect) {
  const fs::path dir = scratch("node_slave_cax8");
  const fs::path deck = fs::path(TETHER_SOURCE_DIR) / "tests/verification/dialect/contact_node_slave_cax8_calculix.inp";
  const auto run = tether("run " + deck.string() + " --dialect calculix -q -o " + (dir / "out").string());
  ASSERT_EQ(run.code, 0) << run.out;
  const std::array<double, 7> ccx_uy = {-1.026738e-2, -1.213189e-2, -1.223135e-2, -1.251170e-2,
                                        -1.178785e-2, -1.117065e-2, -8.739308e-3};
  const std::array<double, 7> ccx_p = {2.561666, 3.265329, 2.893333, 3.100187, 2.838078, 3.156061, 2.345257};
  std::istringstream dat(slurp(dir / "out" / "contact_node_slave_cax8_calculix.dat"));
  std::string line, block;
  int u_rows = 0, p_rows = 0, totals = 0;
  while (std::getline(dat, line)) {
    if (line.find_first_of("abcdefghijklmnopqrstuvwxyz") != std::string::npos) block = line;  // a block's title
    if (block.find("time  0.1000000E+01") == std::string::npos && block.find("time 0.1000000E+01") == std::string::npos)
      continue;
    std::istringstream row(line);
    std::vector<double> v;
    for (double x; row >> x;) v.push_back(x);
    if (v.empty()) continue;
    if (block.find("displacements") != std::string::npos && v.size() == 4) {
      const auto k = static_cast<std::size_t>(v[0]) - 1;
      ASSERT_LT(k, ccx_uy.size()) << line;
      EXPECT_NEAR(v[2], ccx_uy[k], 2e-8) << line;
      ++u_rows;
    } else if (block.find("total force") != std::string::npos && v.size() == 3) {
      EXPECT_NEAR(v[1], 10 * std::acos(-1.0) * 3 / 180, 1e-6) << line;
      ++totals;
    } else if (block.find("contact stress") != std::string::npos && v.size() == 4) {
      const auto k = static_cast<std::size_t>(v[0]) - 1;
      ASSERT_LT(k, ccx_p.size()) << line;
      EXPECT_NEAR(v[1], ccx_p[k], 1e-5 * ccx_p[k]) << line;
      ++p_rows;
    }
  }
  EXPECT_EQ(u_rows, 7);
  EXPECT_EQ(p_rows, 7);
  EXPECT_EQ(totals, 1);
}
