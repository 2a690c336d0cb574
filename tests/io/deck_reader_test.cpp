// Every supported keyword read correctly into the Model.
#include <gtest/gtest.h>

#include "deck_test_support.hpp"
#include "tether/io/deck_reader.hpp"

using namespace tether;
using namespace tether::test;

namespace {

bool has_warning(const std::vector<DeckWarning>& w, const std::string& words, int line = -1) {
  for (const auto& x : w)
    if (x.message.find(words) != std::string::npos && (line < 0 || x.where.line == line)) return true;
  return false;
}

}  // namespace

TEST(DeckReader, ReadsMeshSetsMaterialSectionAndStep) {
  std::vector<DeckWarning> warnings;
  const Model m = read_deck_string(kDeck, "good.inp", &warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front().message;
  EXPECT_EQ(m.heading, "Two quads");
  EXPECT_EQ(m.deck_path, "good.inp");
  ASSERT_EQ(m.n_nodes(), 6);
  EXPECT_EQ(m.node_ids[5], 6);
  EXPECT_DOUBLE_EQ(m.coords[m.node_index.at(6)].x(), 2.0);
  EXPECT_DOUBLE_EQ(m.coords[m.node_index.at(6)].y(), 1.0);
  ASSERT_EQ(m.n_elements(), 2);
  EXPECT_EQ(m.elements[1].id, 2);
  EXPECT_EQ(m.elements[1].type.name, "CPE4");
  EXPECT_EQ(m.elements[1].nodes, (std::vector<int>{1, 2, 5, 4}));  // indices
  EXPECT_EQ(m.elements[1].where.line, line_of(kDeck, "2, 2, 3, 6, 5"));
  EXPECT_EQ(m.node_sets.at("ALL").size(), 6u);
  EXPECT_EQ(m.node_sets.at("LEFT"), (std::vector<int>{0, 3}));
  EXPECT_EQ(m.element_sets.at("PLATE"), (std::vector<int>{0, 1}));
  EXPECT_EQ(m.element_sets.at("E1"), (std::vector<int>{0}));
  ASSERT_EQ(m.materials.size(), 1u);
  EXPECT_EQ(m.materials[0].name, "STEEL");
  ASSERT_TRUE(m.materials[0].elastic);
  EXPECT_DOUBLE_EQ(m.materials[0].elastic->young, 200e3);
  EXPECT_DOUBLE_EQ(m.materials[0].elastic->poisson, 0.3);
  ASSERT_EQ(m.sections.size(), 1u);
  EXPECT_EQ(m.sections[0].material, 0);
  EXPECT_EQ(m.sections[0].elset, "PLATE");
  EXPECT_EQ(m.elements[0].section, 0);
  EXPECT_EQ(m.elements[1].section, 0);
  ASSERT_EQ(m.surfaces.count("TOP"), 1u);
  const Surface& top = m.surfaces.at("TOP");
  EXPECT_EQ(top.kind, Surface::Kind::ElementFaces);
  ASSERT_EQ(top.faces.size(), 2u);
  EXPECT_EQ(top.faces[1].element, 1);
  EXPECT_EQ(top.faces[1].face, 2);
  ASSERT_EQ(m.amplitudes.size(), 1u);
  EXPECT_EQ(m.amplitudes[0].times, (std::vector<double>{0, 1}));
  ASSERT_EQ(m.steps.size(), 1u);
  const Step& s = m.steps[0];
  EXPECT_EQ(s.name, "Step-1");
  EXPECT_FALSE(s.nlgeom);
  EXPECT_EQ(s.max_increments, 100);
  EXPECT_DOUBLE_EQ(s.period, 1.0);
  EXPECT_EQ(s.boundary.size(), 4u);  // LEFT (2 nodes) x dofs 1,2 from model data
  ASSERT_EQ(s.cloads.size(), 2u);
  EXPECT_EQ(s.cloads[0].dof, 0);
  EXPECT_DOUBLE_EQ(s.cloads[0].magnitude, 10.0);
}

TEST(DeckReader, IsCaseInsensitiveAndAcceptsQuotesAndTrailingCommas) {
  const std::string deck = R"(*node, nset="Left Edge"
1, 0., 0.,
2, 1.0E0, 0
3, 1, 1.D0
4, 0, 1
*Element, Type=cps3, Elset=tris
1, 1, 2, 3,
2, 1, 3, 4
*material, name=Rubber
*Hyperelastic, neo hooke
0.5, 0.01
*density
1.2e-9
*solid section, ELSET=TRIS, material=rubber
0.5
*step, nlgeom, inc=20, name=Load
*static, direct
0.1, 1.0
*boundary
"LEFT EDGE", encastre
*end step
)";
  const Model m = read_deck_string(deck, "case.inp");
  EXPECT_EQ(m.node_sets.at("LEFT EDGE").size(), 4u);
  EXPECT_DOUBLE_EQ(m.coords[2].y(), 1.0);
  EXPECT_EQ(m.elements[0].type.name, "CPS3");
  ASSERT_TRUE(m.materials[0].neo_hooke);
  EXPECT_DOUBLE_EQ(m.materials[0].neo_hooke->c10, 0.5);
  EXPECT_DOUBLE_EQ(m.materials[0].neo_hooke->d1, 0.01);
  EXPECT_DOUBLE_EQ(*m.materials[0].density, 1.2e-9);
  EXPECT_DOUBLE_EQ(m.sections[0].thickness, 0.5);
  const Step& s = m.steps.at(0);
  EXPECT_EQ(s.name, "Load");
  EXPECT_TRUE(s.nlgeom);
  EXPECT_EQ(s.max_increments, 20);
  EXPECT_TRUE(s.direct);
  EXPECT_DOUBLE_EQ(s.initial_increment, 0.1);
  EXPECT_EQ(s.boundary.size(), 8u);
}

TEST(DeckReader, ReadsQuadraticElementsContinuedOverLines) {
  const std::string deck = R"(*NODE
1, 0, 0
2, 2, 0
3, 2, 2
4, 0, 2
5, 1, 0
6, 2.1, 1
7, 1, 2
8, 0, 1
*ELEMENT, TYPE=CAX8
10, 1, 2, 3, 4,
5, 6, 7, 8
*ELSET, ELSET=ALL
10
*MATERIAL, NAME=M
*ELASTIC
1000, 0.25
*SOLID SECTION, ELSET=ALL, MATERIAL=M
)";
  std::vector<DeckWarning> warnings;
  const Model m = read_deck_string(deck, "q.inp", &warnings);
  ASSERT_EQ(m.n_elements(), 1);
  EXPECT_EQ(m.elements[0].nodes.size(), 8u);
  EXPECT_EQ(m.elements[0].nodes[7], 7);
  EXPECT_EQ(m.elements[0].type.family, Family::Axisymmetric);
  EXPECT_DOUBLE_EQ(m.sections[0].thickness, 1.0);
  EXPECT_TRUE(m.steps.empty());
  EXPECT_TRUE(has_warning(warnings, "no *STEP"));
}

TEST(DeckReader, GeneratesSetsAndNestsSetNames) {
  const std::string deck = replaced(kDeck, "*STEP", R"(*NSET, NSET=ODD, GENERATE
1, 5, 2
*NSET, NSET=MIX
ODD, 2, RIGHT
*ELSET, ELSET=BOTH, GENERATE
1, 2
*ELSET, ELSET=AGAIN
E1, 2
*NSET, NSET=ODD
6
*STEP)");
  const Model m = read_deck_string(deck, "sets.inp");
  EXPECT_EQ(m.node_sets.at("ODD"), (std::vector<int>{0, 2, 4, 5}));  // extended by the second *NSET
  EXPECT_EQ(m.node_sets.at("MIX"), (std::vector<int>{0, 1, 2, 4, 5}));
  EXPECT_EQ(m.element_sets.at("BOTH"), (std::vector<int>{0, 1}));
  EXPECT_EQ(m.element_sets.at("AGAIN"), (std::vector<int>{0, 1}));
}

TEST(DeckReader, ReadsNodeSurfacesAndFacesByLabel) {
  const std::string deck = replaced(kDeck, "*MATERIAL", R"(*SURFACE, NAME=SIDE, TYPE=NODE
RIGHT
5
*SURFACE, NAME=EDGE
2, s2
1, S1
*MATERIAL)");
  const Model m = read_deck_string(deck, "surf.inp");
  const Surface& side = m.surfaces.at("SIDE");
  EXPECT_EQ(side.kind, Surface::Kind::Nodes);
  EXPECT_EQ(side.nodes, (std::vector<int>{2, 4, 5}));
  const Surface& edge = m.surfaces.at("EDGE");
  ASSERT_EQ(edge.faces.size(), 2u);
  EXPECT_EQ(edge.faces[0].element, 1);
  EXPECT_EQ(edge.faces[0].face, 1);
  EXPECT_EQ(edge.faces[1].face, 0);
}

TEST(DeckReader, ReadsAmplitudesOverSeveralLines) {
  const std::string deck = replaced(kDeck, "*BOUNDARY", R"(*AMPLITUDE, NAME=Pulse, TIME=TOTAL TIME
0, 0, 0.5, 1,
1, 0.5
2, 0
*BOUNDARY)");
  const Model m = read_deck_string(deck, "amp.inp");
  ASSERT_EQ(m.amplitudes.size(), 2u);
  const Amplitude& a = m.amplitudes[1];
  EXPECT_EQ(a.name, "PULSE");
  EXPECT_TRUE(a.total_time);
  EXPECT_EQ(a.times, (std::vector<double>{0, 0.5, 1, 2}));
  EXPECT_EQ(a.values, (std::vector<double>{0, 1, 0.5, 0}));
}

TEST(DeckReader, ReadsStaticDataAndStepParameters) {
  const std::string deck = replaced(replaced(kDeck, "*STEP", "*STEP, NLGEOM=NO, INC=7"), "*STATIC",
                                    "*STATIC\n0.25, 2.0, 1e-3, 0.5");
  const Model m_s = read_deck_string(deck, "st.inp");
  const Step& s = m_s.steps.at(0);
  EXPECT_FALSE(s.nlgeom);
  EXPECT_EQ(s.max_increments, 7);
  EXPECT_DOUBLE_EQ(s.initial_increment, 0.25);
  EXPECT_DOUBLE_EQ(s.period, 2.0);
  EXPECT_DOUBLE_EQ(s.min_increment, 1e-3);
  EXPECT_DOUBLE_EQ(s.max_increment, 0.5);
  EXPECT_FALSE(s.direct);
  const Model m_y = read_deck_string(replaced(kDeck, "*STEP", "*STEP, NLGEOM=yes"), "y.inp");
  const Step& y = m_y.steps.at(0);
  EXPECT_TRUE(y.nlgeom);
}

TEST(DeckReader, MapsBoundaryTypesAndRangesOntoTwoDofs) {
  const std::string deck = replaced(kDeck, "*CLOAD", R"(*BOUNDARY, AMPLITUDE=RAMP
2, XSYMM
3, YSYMM
5, 1, 1, 0.5
6, 2, 2, -0.25
*BOUNDARY
4, 1, 6
*BOUNDARY
5, 3
*CLOAD)");
  std::vector<DeckWarning> warnings;
  const Model m_s = read_deck_string(deck, "bc.inp", &warnings);
  const Step& s = m_s.steps.at(0);
  ASSERT_EQ(s.boundary.size(), 8u);  // 4 from model data + 2, 3, 5, 6
  auto find = [&](int node_label, int dof) -> const Prescribed* {
    for (const auto& p : s.boundary)
      if (p.node == node_label - 1 && p.dof == dof) return &p;
    return nullptr;
  };
  ASSERT_TRUE(find(2, 0));
  EXPECT_FALSE(find(2, 1));
  ASSERT_TRUE(find(3, 1));
  EXPECT_FALSE(find(3, 0));
  ASSERT_TRUE(find(5, 0));
  EXPECT_DOUBLE_EQ(find(5, 0)->value, 0.5);
  EXPECT_EQ(find(5, 0)->amplitude, 0);
  EXPECT_DOUBLE_EQ(find(6, 1)->value, -0.25);
  EXPECT_EQ(find(1, 0)->amplitude, -1);
  EXPECT_TRUE(has_warning(warnings, "dofs 3-6 ignored", line_of(deck, "4, 1, 6")));
  EXPECT_TRUE(has_warning(warnings, "dofs 3-6 ignored", line_of(deck, "5, 3")));
}

TEST(DeckReader, ReadsConcentratedAndPressureLoads) {
  const std::string deck = replaced(kDeck, "*CLOAD\nRIGHT, 1, 10", R"(*CLOAD, AMPLITUDE=RAMP
6, 2, -3.5
*DLOAD
E1, P4, 2.0
PLATE, p1, 1.0
*DSLOAD
TOP, P, 7)");
  const Model m_s = read_deck_string(deck, "loads.inp");
  const Step& s = m_s.steps.at(0);
  ASSERT_EQ(s.cloads.size(), 1u);
  EXPECT_EQ(s.cloads[0].node, 5);
  EXPECT_EQ(s.cloads[0].dof, 1);
  EXPECT_DOUBLE_EQ(s.cloads[0].magnitude, -3.5);
  EXPECT_EQ(s.cloads[0].amplitude, 0);
  ASSERT_EQ(s.pressures.size(), 5u);  // E1 P4, PLATE P1 (2), TOP (2)
  EXPECT_EQ(s.pressures[0].face.element, 0);
  EXPECT_EQ(s.pressures[0].face.face, 3);
  EXPECT_DOUBLE_EQ(s.pressures[0].magnitude, 2.0);
  EXPECT_EQ(s.pressures[2].face.element, 1);
  EXPECT_EQ(s.pressures[2].face.face, 0);
  EXPECT_EQ(s.pressures[3].face.face, 2);
  EXPECT_DOUBLE_EQ(s.pressures[4].magnitude, 7.0);
}

TEST(DeckReader, MapsControlsOntoTetherControls) {
  const std::string deck = replaced(kDeck, "*CLOAD", R"(*CONTROLS, PARAMETERS=FIELD
1e-4, 1e-3, , , , 1e-9
*CONTROLS, PARAMETERS=TIME INCREMENTATION
4, 8, 9, 12, 10, 3, , 7
0.5, , , , , , 2.0
*CONTROLS, PARAMETERS=LINE SEARCH
5
*CLOAD)");
  std::vector<DeckWarning> warnings;
  const Model m_c = read_deck_string(deck, "ctl.inp", &warnings);
  const Controls& c = m_c.steps.at(0).controls;
  EXPECT_DOUBLE_EQ(c.residual_tolerance, 1e-4);
  EXPECT_DOUBLE_EQ(c.correction_tolerance, 1e-3);
  EXPECT_DOUBLE_EQ(c.zero_force_tolerance, 1e-9);
  EXPECT_EQ(c.max_iterations, 12);
  EXPECT_EQ(c.easy_iterations, 3);
  EXPECT_EQ(c.max_cutbacks, 7);
  EXPECT_DOUBLE_EQ(c.cutback_factor, 0.5);
  EXPECT_DOUBLE_EQ(c.growth_factor, 2.0);
  EXPECT_TRUE(c.line_search);
  // I0, IR, IP, IL are not used by tether: one warning naming them.
  EXPECT_TRUE(has_warning(warnings, "I0, IR, IP, IL", line_of(deck, "4, 8, 9")));
}

TEST(DeckReader, ControlsPersistAcrossStepsUntilReset) {
  std::string deck = replaced(kDeck, "*CLOAD", "*CONTROLS, PARAMETERS=FIELD\n1e-6\n*CLOAD");
  deck += "*STEP\n*STATIC\n*END STEP\n*STEP\n*STATIC\n*CONTROLS, RESET\n*END STEP\n";
  deck += "*STEP\n*STATIC\n*CONTROLS, PARAMETERS=LINE SEARCH\n*CONTROLS, PARAMETERS=LINE SEARCH\n0\n*END STEP\n";
  const Model m = read_deck_string(deck, "ctl2.inp");
  ASSERT_EQ(m.steps.size(), 4u);
  EXPECT_DOUBLE_EQ(m.steps[0].controls.residual_tolerance, 1e-6);
  EXPECT_DOUBLE_EQ(m.steps[1].controls.residual_tolerance, 1e-6);
  EXPECT_DOUBLE_EQ(m.steps[2].controls.residual_tolerance, Controls{}.residual_tolerance);
  EXPECT_FALSE(m.steps[3].controls.line_search);  // N_ls = 0 turns it off again
}

TEST(DeckReader, ReadsOutputRequestsAndCarriesThemIntoLaterSteps) {
  std::string deck = replaced(kDeck, "*END STEP", R"(*NODE PRINT, NSET=RIGHT, TOTALS=ONLY, FREQUENCY=2
RF
*EL PRINT, ELSET=E1
S, E, ENER, PEEQ
*NODE FILE
U
*EL FILE, FREQUENCY=0
S
*OUTPUT, FIELD, FREQUENCY=3
*NODE OUTPUT, NSET=LEFT
U, RF
*OUTPUT, HISTORY
*ELEMENT OUTPUT
E
*END STEP)");
  deck += "*STEP\n*STATIC\n*OUTPUT, FIELD, VARIABLE=PRESELECT\n*OUTPUT, HISTORY, VARIABLE=PRESELECT\n*END STEP\n";
  std::vector<DeckWarning> warnings;
  const Model m = read_deck_string(deck, "out.inp", &warnings);
  ASSERT_EQ(m.steps.size(), 2u);
  const auto& o = m.steps[0].outputs;
  ASSERT_EQ(o.size(), 6u);
  using K = OutputRequest::Kind;
  EXPECT_EQ(o[0].kind, K::NodePrint);
  EXPECT_EQ(o[0].set, "RIGHT");
  EXPECT_EQ(o[0].frequency, 2);
  EXPECT_TRUE(o[0].totals);
  EXPECT_TRUE(o[0].totals_only);
  EXPECT_EQ(o[0].variables, (std::vector<std::string>{"RF"}));
  EXPECT_EQ(o[1].kind, K::ElementPrint);
  EXPECT_EQ(o[1].variables, (std::vector<std::string>{"S", "E", "PEEQ"}));
  EXPECT_TRUE(has_warning(warnings, "ENER", line_of(deck, "S, E, ENER, PEEQ")));
  EXPECT_EQ(o[2].kind, K::NodeFile);
  EXPECT_EQ(o[2].set, "");
  EXPECT_EQ(o[3].kind, K::ElementFile);
  EXPECT_EQ(o[3].frequency, 0);
  EXPECT_EQ(o[4].kind, K::NodeFile);
  EXPECT_EQ(o[4].set, "LEFT");
  EXPECT_EQ(o[4].frequency, 3);
  EXPECT_EQ(o[5].kind, K::ElementPrint);
  EXPECT_EQ(o[5].frequency, 1);
  const auto& o2 = m.steps[1].outputs;
  // FIELD PRESELECT replaces step 1's file requests; HISTORY PRESELECT is
  // ABAQUS's whole-model energies (no request); step 1's prints carry over.
  ASSERT_EQ(o2.size(), 5u);
  EXPECT_EQ(o2[0].kind, K::NodeFile);
  EXPECT_EQ(o2[0].variables, (std::vector<std::string>{"U", "RF"}));
  EXPECT_EQ(o2[1].kind, K::ElementFile);
  EXPECT_EQ(o2[2].kind, K::NodePrint);
  EXPECT_EQ(o2[2].where.line, o[0].where.line);
  EXPECT_EQ(o2[3].kind, K::ElementPrint);
  EXPECT_EQ(o2[4].kind, K::ElementPrint);
}

TEST(DeckReader, WarnsAboutIgnoredInputButAcceptsIt) {
  const std::string deck = replaced(replaced(kDeck, "6, 2, 1", "6, 2, 1, 0.5"), "*STATIC", "*STATIC, SOLVER=SPOOLES");
  std::vector<DeckWarning> warnings;
  (void)read_deck_string(deck, "w.inp", &warnings);
  EXPECT_TRUE(has_warning(warnings, "z coordinate", line_of(deck, "6, 2, 1, 0.5")));
  EXPECT_TRUE(has_warning(warnings, "SOLVER=SPOOLES", line_of(deck, "*STATIC")));
}

TEST(DeckReader, AcceptsValidQuadraticTriangleAndSlightlyCurvedQuad) {
  const std::string deck = R"(*NODE
1, 0, 0
2, 1, 0
3, 0, 1
4, 0.5, -0.05
5, 0.55, 0.55
6, 0, 0.5
*ELEMENT, TYPE=CPE6, ELSET=T
1, 1, 2, 3, 4, 5, 6
*MATERIAL, NAME=M
*ELASTIC
1, 0
*SOLID SECTION, ELSET=T, MATERIAL=M
)";
  const Model m = read_deck_string(deck, "t6.inp");
  EXPECT_EQ(m.elements[0].type.shape, Shape::Tri6);
}
