#include "tether/output/vtu_writer.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "output/tiny_model.hpp"
#include "tether/output/pvd_writer.hpp"

namespace tether {
namespace {

using test::synthetic_results;
using test::tiny_model;

TEST(VtuWriter, CellTypesFollowVtk) {
  EXPECT_EQ(vtk_cell_type(Shape::Tri3), 5);
  EXPECT_EQ(vtk_cell_type(Shape::Quad4), 9);
  EXPECT_EQ(vtk_cell_type(Shape::Tri6), 22);
  EXPECT_EQ(vtk_cell_type(Shape::Quad8), 23);
}

TEST(VtuWriter, AsciiDocumentHasTheMeshAndFields) {
  const Model model = tiny_model();
  std::ostringstream out;
  VtuWriter(model, VtuEncoding::Ascii).write(synthetic_results(model, 2, 3, 1.5, 1.0), out);
  const std::string text = out.str();
  EXPECT_NE(text.find("<Piece NumberOfPoints=\"15\" NumberOfCells=\"5\">"), std::string::npos);
  EXPECT_NE(text.find("Name=\"TIME\" NumberOfTuples=\"1\" format=\"ascii\">1.5<"), std::string::npos);
  // connectivity = node indices in ABAQUS order (CPE8 102 second), offsets, types.
  EXPECT_NE(text.find("Name=\"connectivity\" format=\"ascii\">\n0 1 2 3 1 4\n5 2 6 7 8 9\n3 2 10 11 2 5\n"),
            std::string::npos);
  EXPECT_NE(text.find("Name=\"offsets\" format=\"ascii\">\n4 12 16 22 25\n"), std::string::npos);
  EXPECT_NE(text.find("Name=\"types\" format=\"ascii\">\n9 23 9 22 5\n"), std::string::npos);
  EXPECT_NE(text.find("Name=\"ElementId\" format=\"ascii\">\n101 102 103 104 105\n"), std::string::npos);
  // Node 0 (label 11, at the origin): U = (1.1e-5, -0, 0); node 1 (label 12, x = 1).
  EXPECT_NE(text.find("Name=\"U\" NumberOfComponents=\"3\" format=\"ascii\">\n1.1e-05 -0 0 0.001012 -0 0\n"),
            std::string::npos);
  for (const char* name : {"\"RF\"", "\"S\"", "\"E\"", "\"S_Mises\"", "\"NodeId\""})
    EXPECT_NE(text.find(std::string("Name=") + name), std::string::npos) << name;
  EXPECT_EQ(text.find("LAGRANGE_MULTIPLIER"), std::string::npos);  // none in these results
  EXPECT_EQ(text.substr(text.size() - 11), "</VTKFile>\n");
}

TEST(VtuWriter, NodesOutsideEveryElementGetVertexCells) {
  // Two nodes held only by constraints (labels 31, 32, after the mesh nodes):
  // one VTK_VERTEX cell each, after the elements, ElementId 0 and zero cell stress.
  Model model = tiny_model();
  for (const int label : {31, 32}) {
    model.node_index[label] = model.n_nodes();
    model.node_ids.push_back(label);
    model.coords.emplace_back(3.0, 0.5 * label);
  }
  std::ostringstream out;
  VtuWriter(model, VtuEncoding::Ascii).write(synthetic_results(model, 1, 1, 1.0, 1.0), out);
  const std::string text = out.str();
  EXPECT_NE(text.find("<Piece NumberOfPoints=\"17\" NumberOfCells=\"7\">"), std::string::npos);
  EXPECT_NE(text.find("Name=\"connectivity\" format=\"ascii\">\n0 1 2 3 1 4\n5 2 6 7 8 9\n3 2 10 11 2 5\n"
                      "10 8 12 13 5 14\n10 15 16\n"),
            std::string::npos);
  EXPECT_NE(text.find("Name=\"offsets\" format=\"ascii\">\n4 12 16 22 25 26\n27\n"), std::string::npos);
  EXPECT_NE(text.find("Name=\"types\" format=\"ascii\">\n9 23 9 22 5 1\n1\n"), std::string::npos);
  EXPECT_NE(text.find("Name=\"ElementId\" format=\"ascii\">\n101 102 103 104 105 0\n0\n"), std::string::npos);
  const auto at = text.find("Name=\"S_Mises\" format=\"ascii\">", text.find("<CellData"));
  ASSERT_NE(at, std::string::npos);
  const auto start = text.find('>', at) + 2;
  std::string mises = text.substr(start, text.find("</DataArray>", start) - start);
  mises.erase(mises.find_last_not_of(' ') + 1);  // the closing tag's indentation
  ASSERT_GE(mises.size(), 4u);
  EXPECT_EQ(mises.substr(mises.size() - 4), "0\n0\n") << mises;
  EXPECT_NE(text.find("Name=\"NodeId\" format=\"ascii\">\n11 12 13 14 19 20\n15 16 17 18 21 22\n23 24 25 31 32\n"),
            std::string::npos);
}

TEST(VtuWriter, LeavesOutFieldsTheResultsDoNotHave) {
  const Model model = tiny_model();
  auto results = synthetic_results(model, 1, 1, 1.0, 1.0);
  results.reaction.clear();
  results.nodal_stress.clear();
  results.nodal_strain.clear();
  results.points.clear();
  std::ostringstream out;
  VtuWriter(model).write(results, out);
  const std::string text = out.str();
  EXPECT_NE(text.find("Name=\"U\" NumberOfComponents=\"3\" format=\"binary\""), std::string::npos);
  for (const char* name : {"\"RF\"", "\"S\"", "\"E\"", "\"S_Mises\""})
    EXPECT_EQ(text.find(std::string("Name=") + name), std::string::npos) << name;
}

TEST(VtuWriter, RefusesResultsThatDoNotFitTheMesh) {
  const Model model = tiny_model();
  const auto dir = test::fresh_directory("vtu_refuse");
  const VtuWriter writer(model);
  writer.write(synthetic_results(model, 1, 1, 1.0, 1.0), dir / "a.vtu");
  const std::string before = test::read_text(dir / "a.vtu");
  auto bad = synthetic_results(model, 1, 2, 2.0, 2.0);
  bad.nodal_stress.pop_back();
  EXPECT_THROW(writer.write(bad, dir / "a.vtu"), std::invalid_argument);
  bad = synthetic_results(model, 1, 2, 2.0, 2.0);
  bad.multipliers.push_back({"EQUATION 1", {99}, {1.0}, {0.0}});
  EXPECT_THROW(writer.write(bad, dir / "a.vtu"), std::invalid_argument);
  EXPECT_EQ(test::read_text(dir / "a.vtu"), before);  // the old file survives a failed write
  EXPECT_EQ(test::count_temporary_files(dir), 0);
}

TEST(PvdWriter, RewritesTheWholeCollectionAfterEachDataset) {
  const auto dir = test::fresh_directory("pvd");
  PvdWriter pvd(dir / "job.pvd");
  EXPECT_FALSE(std::filesystem::exists(dir / "job.pvd"));
  pvd.add(0.25, "job_1_1.vtu");
  pvd.add(1.0, "a&b.vtu");
  EXPECT_EQ(test::read_text(dir / "job.pvd"),
            "<?xml version=\"1.0\"?>\n"
            "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
            "  <Collection>\n"
            "    <DataSet timestep=\"0.25\" group=\"\" part=\"0\" file=\"job_1_1.vtu\"/>\n"
            "    <DataSet timestep=\"1\" group=\"\" part=\"0\" file=\"a&amp;b.vtu\"/>\n"
            "  </Collection>\n"
            "</VTKFile>\n");
  EXPECT_EQ(test::count_temporary_files(dir), 0);
}

}  // namespace
}  // namespace tether
