// Gmsh exports (gmsh -format inp): CPS3/4/6/8 meshes with T3D2/T3D3 line
// elements for physical curves and node sets per group, *INCLUDEd by a short
// deck. The fixtures are made by tests/io/decks/gmsh/make_fixtures.sh.
#include <gtest/gtest.h>

#include <set>

#include "deck_test_support.hpp"

using namespace tether;
using namespace tether::test;

namespace {

/// A short deck around a Gmsh export: material, section, boundary conditions,
/// a pressure on the RIGHT curve's faces, one step.
std::string deck_around(const std::string& fixture, const std::string& more = "") {
  return "*INCLUDE, INPUT=" + decks_dir() + "/gmsh/" + fixture + R"(
*MATERIAL, NAME=STEEL
*ELASTIC
200e3, 0.3
*SOLID SECTION, ELSET=PLATE, MATERIAL=STEEL
*SURFACE, NAME=LOADED
RIGHT
)" + more + R"(*BOUNDARY
LEFT, 1, 2
*STEP
*STATIC
*DSLOAD
LOADED, P, -10
*END STEP
)";
}

/// The (sorted) node labels of face `f`'s two corners.
std::pair<int, int> corner_labels(const Model& m, const ElementFace& f) {
  const Element& e = m.elements[static_cast<std::size_t>(f.element)];
  const auto local = face_nodes(e.type.shape, f.face);
  const int a = m.node_ids[static_cast<std::size_t>(e.nodes[static_cast<std::size_t>(local[0])])];
  const int b = m.node_ids[static_cast<std::size_t>(e.nodes[static_cast<std::size_t>(local[1])])];
  return {std::min(a, b), std::max(a, b)};
}

}  // namespace

TEST(GmshDeck, LineElementsNameTheFacesOfTheSolidsTheyLieOn) {
  // plate_tri.inp: RIGHT is the curve x = 2 with nodes 2, 8, 3 (line elements 5: 2-8 and 6: 8-3).
  std::vector<DeckWarning> warnings;
  const Model m = read_deck_string(deck_around("plate_tri.inp"), "gmsh.inp", &warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front().message;
  EXPECT_EQ(m.n_elements(), 22);  // the CPS3 only: the 8 T3D2 carry no stiffness and are not in the model
  EXPECT_FALSE(m.element_index.count(5));
  EXPECT_EQ(m.elements[0].type.name, "CPS3");
  EXPECT_EQ(m.node_sets.at("RIGHT").size(), 3u);  // Mesh.SaveGroupsOfNodes = 1
  EXPECT_FALSE(m.element_sets.count("RIGHT"));     // a set of line elements only
  const Surface& s = m.surfaces.at("LOADED");
  ASSERT_EQ(s.faces.size(), 2u);
  const std::set<std::pair<int, int>> edges = {corner_labels(m, s.faces[0]), corner_labels(m, s.faces[1])};
  EXPECT_EQ(edges, (std::set<std::pair<int, int>>{{2, 8}, {3, 8}}));
  EXPECT_EQ(m.steps[0].pressures.size(), 2u);
}

TEST(GmshDeck, EveryElementTypeGmshWrites) {
  // RIGHT has 2 faces in every fixture; the quadratic ones check the mid-side nodes of T3D3 too.
  for (const char* fixture : {"plate_tri.inp", "plate_tri6.inp", "plate_quad4.inp", "plate_quad8.inp"}) {
    SCOPED_TRACE(fixture);
    const Model m = read_deck_string(deck_around(fixture), "gmsh.inp");
    EXPECT_EQ(m.surfaces.at("LOADED").faces.size(), 2u);
    for (const Element& e : m.elements) EXPECT_EQ(e.section, 0);
  }
  EXPECT_EQ(read_deck_string(deck_around("plate_tri6.inp"), "g.inp").elements[0].type.name, "CPS6");
  EXPECT_EQ(read_deck_string(deck_around("plate_quad4.inp"), "g.inp").elements[0].type.name, "CPS4");
  EXPECT_EQ(read_deck_string(deck_around("plate_quad8.inp"), "g.inp").elements[0].type.name, "CPS8");
}

TEST(GmshDeck, ASetOfSolidsWithoutFaceIdMeansItsExposedFaces) {
  // plate_quad4.inp: 4 x 2 quads; the boundary has 12 faces, every one exposed.
  const Model m = read_deck_string(deck_around("plate_quad4.inp", "*SURFACE, NAME=OUTSIDE\nPLATE\n"), "g.inp");
  EXPECT_EQ(m.surfaces.at("OUTSIDE").faces.size(), 12u);
  // One element alone: its faces shared with no other element (a corner quad has two).
  const Model one = read_deck_string(deck_around("plate_quad4.inp", "*SURFACE, NAME=CORNER\n5\n"), "g.inp");
  EXPECT_EQ(one.surfaces.at("CORNER").faces.size(), 2u);
}

TEST(GmshDeck, SolidSectionFamilyTurnsCpsIntoPlaneStrainOrAxisymmetric) {
  std::string deck = replaced(deck_around("plate_quad8.inp"), "MATERIAL=STEEL\n", "MATERIAL=STEEL, FAMILY=PLANE STRAIN\n");
  for (const Element& e : read_deck_string(deck, "g.inp").elements) EXPECT_EQ(e.type.name, "CPE8");
  deck = replaced(deck_around("plate_tri.inp"), "MATERIAL=STEEL\n", "MATERIAL=STEEL, FAMILY=AXISYMMETRIC\n");
  for (const Element& e : read_deck_string(deck, "g.inp").elements) EXPECT_EQ(e.type.name, "CAX3");
}

TEST(GmshDeck, LineElementsAnywhereElseAreErrorsAtTheLine) {
  const std::string deck = deck_around("plate_tri.inp");
  expect_deck_error_at(replaced(deck, "*SOLID SECTION, ELSET=PLATE", "*SOLID SECTION, ELSET=RIGHT"),
                       "*SOLID SECTION", {"element set 'RIGHT' holds only line elements (T3D2)", "no stiffness"});
  expect_deck_error_at(replaced(deck, "LOADED, P, -10\n", "LOADED, P, -10\n*DLOAD\n5, P1, 1\n"), "5, P1, 1",
                       {"element 5 is a line element (T3D2)"});
  expect_deck_error_at(replaced(deck, "RIGHT\n", "RIGHT, S1\n"), "RIGHT, S1", {"'RIGHT' names line elements", "S1"});
  // A line inside the mesh (between two triangles) and a line on no face.
  const std::string extra = "*ELEMENT, TYPE=T3D2, ELSET=INSIDE\n100, 13, 14\n*ELEMENT, TYPE=T2D2, ELSET=ACROSS\n101, 1, 3\n";
  expect_deck_error_at(replaced(deck_around("plate_tri.inp", "*SURFACE, NAME=S2\nINSIDE\n"), "*MATERIAL", extra + "*MATERIAL"),
                       "\nINSIDE\n", {"line element 100", "lies between solid elements", "inside the mesh"});
  expect_deck_error_at(replaced(deck_around("plate_tri.inp", "*SURFACE, NAME=S2\n101\n"), "*MATERIAL", extra + "*MATERIAL"),
                       "\n101\n", {"line element 101", "lies on no face"});
  expect_deck_error_at(replaced(deck, "*MATERIAL", "*ELEMENT, TYPE=T3D2\n9, 1, 2\n*MATERIAL"), "9, 1, 2",
                       {"duplicate element 9"});
  expect_deck_error_at(replaced(deck, "*MATERIAL", "*ELEMENT, TYPE=T3D3\n200, 1, 2\n*MATERIAL"), "200, 1, 2",
                       {"wrong number of nodes for T3D3"});
}
