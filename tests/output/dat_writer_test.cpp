#include "tether/output/dat_writer.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "output/tiny_model.hpp"
#include "tether/core/error.hpp"

namespace tether {
namespace {

using test::fresh_directory;
using test::read_text;
using test::synthetic_results;
using test::tiny_model;

OutputRequest node_print(std::string set, std::vector<std::string> variables) {
  OutputRequest r;
  r.kind = OutputRequest::Kind::NodePrint;
  r.set = std::move(set);
  r.variables = std::move(variables);
  r.where = {"job.inp", 42};
  return r;
}

OutputRequest element_print(std::string set, std::vector<std::string> variables) {
  OutputRequest r = node_print(std::move(set), std::move(variables));
  r.kind = OutputRequest::Kind::ElementPrint;
  return r;
}

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (auto pos = text.find(what); pos != std::string::npos; pos = text.find(what, pos + 1)) ++n;
  return n;
}

TEST(DatWriter, WritesCalculixLayoutWithOriginalLabels) {
  const Model model = tiny_model();
  const auto file = fresh_directory("dat_layout") / "job.dat";
  auto rf = node_print("LEFT", {"U", "RF"});
  rf.totals = true;
  {
    DatWriter dat(model, file);
    dat.write_increment(synthetic_results(model, 1, 2, 0.5, 1.0), {rf, element_print("QUADS", {"S"})}, false);
  }
  const std::string expected =
      "\n"
      " displacements (vx,vy,vz) for set LEFT and time  0.5000000E+00\n"
      "\n"
      "        11  1.100000E-05  0.000000E+00  0.000000E+00\n"
      "        14  1.400000E-05 -2.000000E-03  0.000000E+00\n"
      "        22  2.200000E-05 -4.000000E-03  0.000000E+00\n"
      "\n"
      " forces (fx,fy,fz) for set LEFT and time  0.5000000E+00\n"
      "\n"
      "        11  1.100000E+01 -5.500000E+00  0.000000E+00\n"
      "        14  1.400000E+01 -7.000000E+00  0.000000E+00\n"
      "        22  2.200000E+01 -1.100000E+01  0.000000E+00\n"
      "\n"
      " total force (fx,fy,fz) for set LEFT and time  0.5000000E+00\n"
      "\n"
      "        4.700000E+01 -2.350000E+01  0.000000E+00\n"
      "\n"
      " stresses (elem, integ.pnt.,sxx,syy,szz,sxy,sxz,syz) for set QUADS and time  0.5000000E+00\n"
      "\n"
      "       101   1  1.010000E+02  0.000000E+00  0.000000E+00  1.010000E+00  0.000000E+00  0.000000E+00\n"
      "       101   2  1.020000E+02 -1.000000E+00  5.000000E-01  3.010000E+00  0.000000E+00  0.000000E+00\n"
      "       101   3  1.030000E+02 -2.000000E+00  1.000000E+00  5.010000E+00  0.000000E+00  0.000000E+00\n"
      "       101   4  1.040000E+02 -3.000000E+00  1.500000E+00  7.010000E+00  0.000000E+00  0.000000E+00\n"
      "       103   1  1.030000E+02  0.000000E+00  0.000000E+00  1.030000E+00  0.000000E+00  0.000000E+00\n"
      "       103   2  1.040000E+02 -1.000000E+00  5.000000E-01  3.030000E+00  0.000000E+00  0.000000E+00\n"
      "       103   3  1.050000E+02 -2.000000E+00  1.000000E+00  5.030000E+00  0.000000E+00  0.000000E+00\n"
      "       103   4  1.060000E+02 -3.000000E+00  1.500000E+00  7.030000E+00  0.000000E+00  0.000000E+00\n";
  EXPECT_EQ(read_text(file), expected);
}

TEST(DatWriter, CalculixDialectPrintsAxisymmetricForcesForCalculixsSegment) {
  // Element 101 made a CAX4: its nodes 11 and 14 print 1/180 of their force
  // in the calculix dialect (CalculiX's 2-degree segment); node 22 (plane
  // elements only) and the abaqus dialect print the full values.
  Model model = tiny_model();
  model.elements[0].type = *find_element_type("CAX4");
  auto rf = node_print("LEFT", {"RF"});
  rf.totals = true;
  const auto print = [&](Dialect d, const std::string& dir) {
    model.dialect = d;
    const auto file = fresh_directory(dir) / "job.dat";
    {
      DatWriter dat(model, file);
      dat.write_increment(synthetic_results(model, 1, 2, 0.5, 1.0), {rf}, false);
    }
    return read_text(file);
  };
  const std::string calculix = print(Dialect::Calculix, "dat_cax_calculix");
  EXPECT_NE(calculix.find("        11  6.111111E-02 -3.055556E-02  0.000000E+00\n"), std::string::npos) << calculix;
  EXPECT_NE(calculix.find("        14  7.777778E-02 -3.888889E-02  0.000000E+00\n"), std::string::npos) << calculix;
  EXPECT_NE(calculix.find("        22  2.200000E+01 -1.100000E+01  0.000000E+00\n"), std::string::npos) << calculix;
  EXPECT_NE(calculix.find("        2.213889E+01 -1.106944E+01  0.000000E+00\n"), std::string::npos) << calculix;
  const std::string abaqus = print(Dialect::Abaqus, "dat_cax_abaqus");
  EXPECT_NE(abaqus.find("        11  1.100000E+01 -5.500000E+00  0.000000E+00\n"), std::string::npos) << abaqus;
  EXPECT_NE(abaqus.find("        4.700000E+01 -2.350000E+01  0.000000E+00\n"), std::string::npos) << abaqus;
}

TEST(DatWriter, TotalsOnlyPrintsJustTheSum) {
  const Model model = tiny_model();
  const auto file = fresh_directory("dat_totals_only") / "job.dat";
  auto rf = node_print("LEFT", {"RF"});
  rf.totals_only = true;
  {
    DatWriter dat(model, file);
    dat.write_increment(synthetic_results(model, 1, 1, 1.0, 2.0), {rf}, true);
  }
  EXPECT_EQ(read_text(file),
            "\n"
            " total force (fx,fy,fz) for set LEFT and time  0.1000000E+01\n"
            "\n"
            "        9.400000E+01 -4.700000E+01  0.000000E+00\n");
}

TEST(DatWriter, DefaultSetsAreAllNodesAndAllElements) {
  const Model model = tiny_model();
  const auto file = fresh_directory("dat_all") / "job.dat";
  {
    DatWriter dat(model, file);
    dat.write_increment(synthetic_results(model, 1, 1, 1.0, 1.0), {node_print("", {"U"}), element_print("", {"E"})},
                        true);
  }
  const std::string text = read_text(file);
  EXPECT_NE(text.find(" displacements (vx,vy,vz) for set NALL and time  0.1000000E+01\n"), std::string::npos);
  EXPECT_NE(text.find(" strains (elem, integ.pnt.,exx,eyy,ezz,exy,exz,eyz) for set EALL and time  0.1000000E+01\n"),
            std::string::npos);
  // 15 node rows + 4 + 9 + 4 + 3 + 1 integration-point rows; the CPE8 has 9 points.
  EXPECT_EQ(count(text, "\n        "), 15);
  EXPECT_EQ(count(text, "\n       10"), 21);
  EXPECT_NE(text.find("\n       102   9  1.100000E-04 -8.000000E-06"), std::string::npos);
  EXPECT_NE(text.find("\n       105   1"), std::string::npos);
  EXPECT_EQ(text.find("\n       105   2"), std::string::npos);
}

TEST(DatWriter, HonoursFrequencyAndAlwaysWritesTheLastIncrement) {
  const Model model = tiny_model();
  const auto file = fresh_directory("dat_frequency") / "job.dat";
  auto every_second = node_print("LEFT", {"U"});
  every_second.frequency = 2;
  auto never = element_print("QUADS", {"S"});
  never.frequency = 0;
  {
    DatWriter dat(model, file);
    for (int inc = 1; inc <= 5; ++inc)
      dat.write_increment(synthetic_results(model, 1, inc, 0.2 * inc, 1.0), {every_second, never}, inc == 5);
  }
  const std::string text = read_text(file);
  EXPECT_EQ(count(text, "displacements"), 3);
  EXPECT_EQ(count(text, "and time  0.4000000E+00"), 1);
  EXPECT_EQ(count(text, "and time  0.8000000E+00"), 1);
  EXPECT_EQ(count(text, "and time  0.1000000E+01"), 1);
  EXPECT_EQ(count(text, "stresses"), 0);
}

TEST(DatWriter, RefusesUnknownSetsAndVariablesNamingTheDeckLine) {
  const Model model = tiny_model();
  const auto file = fresh_directory("dat_errors") / "job.dat";
  DatWriter dat(model, file);
  const auto results = synthetic_results(model, 1, 1, 1.0, 1.0);
  try {
    dat.write_increment(results, {node_print("LEFT", {"U"}), node_print("NOPE", {"U"})}, true);
    FAIL() << "unknown node set accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("job.inp:42"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("NOPE"), std::string::npos) << e.what();
  }
  EXPECT_THROW(dat.write_increment(results, {element_print("QUADS", {"ENER"})}, true), InputError);
  EXPECT_NO_THROW(DatWriter::check(model, element_print("QUADS", {"PEEQ", "PE"})));
  EXPECT_THROW(dat.write_increment(results, {element_print("LEFT", {"S"})}, true), InputError);
  EXPECT_THROW(DatWriter::check(model, node_print("", {"S"})), InputError);
  EXPECT_NO_THROW(DatWriter::check(model, element_print("QUADS", {"S", "E"})));
  EXPECT_EQ(read_text(file), "");  // a bad request writes nothing, not even the good ones
}

TEST(DatWriter, RefusesResultsThatDoNotFitTheMesh) {
  const Model model = tiny_model();
  DatWriter dat(model, fresh_directory("dat_sizes") / "job.dat");
  auto results = synthetic_results(model, 1, 1, 1.0, 1.0);
  results.reaction.clear();
  EXPECT_THROW(dat.write_increment(results, {node_print("LEFT", {"RF"})}, true), std::invalid_argument);
}

}  // namespace
}  // namespace tether
