// *SURFACE INTERACTION, *SURFACE BEHAVIOR, *FRICTION, *CONTACT PAIR, contact
// output: what they read, and every error path.

#include <gtest/gtest.h>

#include "deck_test_support.hpp"

using namespace tether;
using namespace tether::test;

namespace {

const std::string kSurfaces = "*SURFACE, NAME=SLAVE, TYPE=NODE\nRIGHT\n*SURFACE, NAME=MASTER\nE1, S1\n";

std::string with_contact(const std::string& block) { return replaced(kDeck, "*STEP", kSurfaces + block + "*STEP"); }

}  // namespace

TEST(ContactKeywords, InteractionLawsFrictionAndPairs) {
  const Model m = read_deck_string(
      with_contact("*SURFACE INTERACTION, NAME=SI\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=EXPONENTIAL\n0.01, 50.\n"
                   "*FRICTION, ELASTIC SLIP=1e-4\n0.3\n"
                   "*SURFACE INTERACTION, NAME=LIN\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n1e6\n"
                   "*SURFACE INTERACTION, NAME=TAB\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TABULAR\n0., 0., 10., "
                   "0.1\n100., 0.2\n*SURFACE INTERACTION, NAME=HARD\n"
                   "*CONTACT PAIR, INTERACTION=SI, SMALL SLIDING, ADJUST=0.01\nSLAVE, MASTER\n"),
      "c.inp");
  ASSERT_EQ(m.interactions.size(), 4u);
  const auto& si = m.interactions[0];
  EXPECT_EQ(si.behavior.law, PressureOverclosure::Law::Exponential);
  EXPECT_DOUBLE_EQ(si.behavior.c0, 0.01);
  EXPECT_DOUBLE_EQ(si.behavior.p0, 50.);
  ASSERT_TRUE(si.friction);
  EXPECT_DOUBLE_EQ(si.friction->mu, 0.3);
  EXPECT_DOUBLE_EQ(si.friction->elastic_slip, 1e-4);
  EXPECT_EQ(m.interactions[1].behavior.law, PressureOverclosure::Law::Linear);
  EXPECT_DOUBLE_EQ(m.interactions[1].behavior.stiffness, 1e6);
  EXPECT_EQ(m.interactions[2].behavior.table.size(), 3u);
  EXPECT_EQ(m.interactions[3].behavior.law, PressureOverclosure::Law::Hard);
  EXPECT_FALSE(m.interactions[3].friction);
  ASSERT_EQ(m.contact_pairs.size(), 1u);
  EXPECT_EQ(m.contact_pairs[0].slave, "SLAVE");
  EXPECT_EQ(m.contact_pairs[0].master, "MASTER");
  EXPECT_TRUE(m.contact_pairs[0].small_sliding);
  EXPECT_DOUBLE_EQ(m.contact_pairs[0].adjust, 0.01);
}

TEST(ContactKeywords, ContactOutputRequests) {
  const std::string deck = replaced(with_contact("*SURFACE INTERACTION, NAME=SI\n"),
                                    "*END STEP", "*CONTACT PRINT\nCSTR, CDIS\n*CONTACT FILE, FREQUENCY=2\nCSTR\n*END STEP");
  const Model m = read_deck_string(deck, "c.inp");
  ASSERT_EQ(m.steps[0].outputs.size(), 2u);
  EXPECT_EQ(m.steps[0].outputs[0].kind, OutputRequest::Kind::ContactPrint);
  EXPECT_EQ(m.steps[0].outputs[0].variables, (std::vector<std::string>{"CSTR", "CDIS"}));
  EXPECT_EQ(m.steps[0].outputs[1].frequency, 2);

  // CELS is accepted (ccx decks ask for it) but tether has no contact energy: said so.
  std::vector<DeckWarning> warnings;
  read_deck_string(replaced(with_contact("*SURFACE INTERACTION, NAME=SI\n"), "*END STEP", "*CONTACT PRINT\nCSTR, CELS\n*END STEP"),
                   "c.inp", &warnings);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].message.find("CELS"), std::string::npos);
  EXPECT_NE(warnings[0].message.find("not written"), std::string::npos);
}

TEST(ContactKeywords, ErrorsNameTheLine) {
  struct Case {
    std::string block, marker;
    std::vector<std::string> words;
  };
  const std::vector<Case> cases = {
      {"*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD\n", "*SURFACE BEHAVIOR", {"after *SURFACE INTERACTION"}},
      {"*FRICTION\n0.3\n", "*FRICTION", {"after *SURFACE INTERACTION"}},
      {"*SURFACE INTERACTION\n", "*SURFACE INTERACTION", {"NAME"}},
      {"*SURFACE INTERACTION, NAME=A\n*SURFACE INTERACTION, NAME=A\n", "*SURFACE INTERACTION, NAME=A\n*STEP",
       {"defined twice"}},
      {"*SURFACE INTERACTION, NAME=A\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n", "*SURFACE BEHAVIOR",
       {"needs a data line"}},
      {"*SURFACE INTERACTION, NAME=A\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n-5.\n", "-5.", {"K must be > 0"}},
      {"*SURFACE INTERACTION, NAME=A\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=EXPONENTIAL\n0.1\n", "0.1\n",
       {"c0, p0"}},
      {"*SURFACE INTERACTION, NAME=A\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TABULAR\n0., 0., 5.\n", "0., 0., 5.",
       {"pairs"}},
      {"*SURFACE INTERACTION, NAME=A\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TABULAR\n0., 0.1, 5., 0.1\n",
       "0., 0.1, 5.", {"increase strictly"}},
      {"*SURFACE INTERACTION, NAME=A\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=SOFT\n", "*SURFACE BEHAVIOR", {"SOFT"}},
      {"*SURFACE INTERACTION, NAME=A\n*FRICTION\n-0.1\n", "-0.1", {"mu >= 0"}},
      {"*SURFACE INTERACTION, NAME=A\n*FRICTION\nx\n", "x\n", {"'x'"}},
      {"*SURFACE INTERACTION, NAME=A\n*FRICTION\n", "*FRICTION", {"mu"}},
      {"*CONTACT PAIR, INTERACTION=NONE\nSLAVE, MASTER\n", "*CONTACT PAIR", {"undefined INTERACTION=NONE"}},
      {"*SURFACE INTERACTION, NAME=A\n*CONTACT PAIR\nSLAVE, MASTER\n", "*CONTACT PAIR", {"INTERACTION"}},
      {"*SURFACE INTERACTION, NAME=A\n*CONTACT PAIR, INTERACTION=A, TYPE=SURFACE TO SURFACE\nSLAVE, MASTER\n",
       "SLAVE, MASTER", {"node-based", "element faces"}},
      {"*SURFACE INTERACTION, NAME=A\n*CONTACT PAIR, INTERACTION=A, TYPE=MORTAR\nSLAVE, MASTER\n",
       "SLAVE, MASTER", {"node-based", "TYPE=MORTAR"}},
      {"*SURFACE INTERACTION, NAME=A\n*CONTACT PAIR, INTERACTION=A, TYPE=LINMORTAR\nMASTER, MASTER\n",
       "*CONTACT PAIR", {"LINMORTAR", "not modelled", "TYPE=MORTAR"}},
      {"*SURFACE INTERACTION, NAME=A\n*CONTACT PAIR, INTERACTION=A, TYPE=SURFACE TO SURFACE, SMOOTH=0.2\nSLAVE, "
       "MASTER\n",
       "*CONTACT PAIR", {"SMOOTH applies to TYPE=NODE TO SURFACE only"}},
      {"*SURFACE INTERACTION, NAME=A\n*CONTACT PAIR, INTERACTION=A\nSLAVE, NOPE\n", "SLAVE, NOPE",
       {"undefined master surface 'NOPE'"}},
      {"*SURFACE INTERACTION, NAME=A\n*CONTACT PAIR, INTERACTION=A\nMASTER, SLAVE\n", "MASTER, SLAVE",
       {"must be made of element faces"}},
      {"*SURFACE INTERACTION, NAME=A\n*CONTACT PAIR, INTERACTION=A\nSLAVE\n", "SLAVE\n*STEP",
       {"slave surface, master surface"}},
      {"*SURFACE INTERACTION, NAME=A\n*CONTACT PAIR, INTERACTION=A, ADJUST=-1\nSLAVE, MASTER\n", "*CONTACT PAIR",
       {"ADJUST"}},
      {"*SURFACE INTERACTION, NAME=A\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD, ENFORCEMENT=PENALTY\n",
       "*SURFACE BEHAVIOR", {"needs PENALTY=rho > 0"}},
      {"*SURFACE INTERACTION, NAME=A\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD, ENFORCEMENT=AUGMENTED, "
       "PENALTY=10, EPSILON=1\n",
       "*SURFACE BEHAVIOR", {"EPSILON applies to ENFORCEMENT=LAGRANGE only"}},
      {"*SURFACE INTERACTION, NAME=A\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD, EPSILON=-1\n", "*SURFACE BEHAVIOR",
       {"EPSILON must be >= 0"}},
      {"*SURFACE INTERACTION, NAME=A\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR, ENFORCEMENT=PENALTY\n10.\n",
       "*SURFACE BEHAVIOR", {"apply to PRESSURE-OVERCLOSURE=HARD only"}},
      {"*SURFACE INTERACTION, NAME=A\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD, ENFORCEMENT=ELIMINATION\n",
       "*SURFACE BEHAVIOR", {"ELIMINATION"}},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.block);
    expect_deck_error_at(with_contact(c.block), c.marker, c.words);
  }
}

TEST(ContactKeywords, SmoothIsAFractionOfLinearMasterFaces) {
  const auto pair_with = [](const std::string& options) {
    return with_contact("*SURFACE INTERACTION, NAME=SI\n*CONTACT PAIR, INTERACTION=SI" + options + "\nSLAVE, MASTER\n");
  };
  EXPECT_DOUBLE_EQ(read_deck_string(pair_with(", SMOOTH=0.2"), "c.inp").contact_pairs.at(0).smoothing, 0.2);
  EXPECT_DOUBLE_EQ(read_deck_string(pair_with(", SMOOTH=0.5"), "c.inp").contact_pairs.at(0).smoothing, 0.5);
  EXPECT_DOUBLE_EQ(read_deck_string(pair_with(", SMOOTH=0"), "c.inp").contact_pairs.at(0).smoothing, 0.0);
  // tether's default is no smoothing (ABAQUS's is 0.2).
  EXPECT_DOUBLE_EQ(read_deck_string(pair_with(""), "c.inp").contact_pairs.at(0).smoothing, 0.0);

  expect_deck_error_at(pair_with(", SMOOTH=0.7"), "*CONTACT PAIR", {"SMOOTH=0.7", "0 < s <= 0.5"});
  expect_deck_error_at(pair_with(", SMOOTH=-0.1"), "*CONTACT PAIR", {"SMOOTH=-0.1"});
  expect_deck_error_at(pair_with(", SMOOTH=abc"), "*CONTACT PAIR", {"SMOOTH", "abc"});
  expect_deck_error_at(pair_with(", SMOOTH"), "*CONTACT PAIR", {"SMOOTH", "needs a value"});

  // A quadratic (CPE8) master is already curved: SMOOTH is refused on the pair's data line.
  const std::string quadratic = R"(*NODE
1, 0, 0
2, 1, 0
3, 1, 1
4, 0, 1
5, 0.5, 0
6, 1, 0.5
7, 0.5, 1
8, 0, 0.5
9, 0.5, 1.5
*ELEMENT, TYPE=CPE8, ELSET=QUAD
1, 1, 2, 3, 4, 5, 6, 7, 8
*SURFACE, NAME=MASTER
1, S3
*NSET, NSET=TIP
9
*SURFACE, NAME=SLAVE, TYPE=NODE
TIP
*MATERIAL, NAME=M
*ELASTIC
1000, 0.3
*SOLID SECTION, ELSET=QUAD, MATERIAL=M
*SURFACE INTERACTION, NAME=SI
*CONTACT PAIR, INTERACTION=SI, SMOOTH=0.2
SLAVE, MASTER
)";
  expect_deck_error_at(quadratic, "SLAVE, MASTER", {"SMOOTH", "linear (2-node)", "quadratic", "element 1"});
  EXPECT_NO_THROW(read_deck_string(replaced(quadratic, ", SMOOTH=0.2", ""), "c.inp"));
}

// A slave body 10 or more times stiffer than its master: a warning at the
// *CONTACT PAIR data line naming both surfaces, the ratio and the swap (the
// 100x stiff die as the slave of the ironing deck stops in its slide; as the
// master it completes: docs/verification_contact.md, finding 2). Not for the
// right roles, a ratio below 10, or a node-based slave (no material).
TEST(ContactKeywords, AStiffSlaveBodyIsWarnedAboutWithTheSwap) {
  const auto deck = [](const std::string& upper_modulus, const std::string& pair) {
    return "*NODE\n1, 0, 0\n2, 1, 0\n3, 1, 1\n4, 0, 1\n5, 0, 1\n6, 1, 1\n7, 1, 2\n8, 0, 2\n"
           "*ELEMENT, TYPE=CPE4, ELSET=LOW\n1, 1, 2, 3, 4\n*ELEMENT, TYPE=CPE4, ELSET=UP\n2, 5, 6, 7, 8\n"
           "*NSET, NSET=UPN\n5, 6\n"
           "*SURFACE, NAME=LOWTOP\nLOW, S3\n*SURFACE, NAME=UPBOTTOM\nUP, S1\n*SURFACE, NAME=UPNODES, TYPE=NODE\nUPN\n"
           "*MATERIAL, NAME=SOFT\n*ELASTIC\n1000, 0.3\n*MATERIAL, NAME=STIFF\n*ELASTIC\n" +
           upper_modulus + ", 0.3\n*SOLID SECTION, ELSET=LOW, MATERIAL=SOFT\n*SOLID SECTION, ELSET=UP, MATERIAL=STIFF\n"
           "*SURFACE INTERACTION, NAME=SI\n*CONTACT PAIR, INTERACTION=SI\n" +
           pair + "\n*STEP\n*STATIC\n*END STEP\n";
  };
  const auto warnings_of = [](const std::string& text) {
    std::vector<DeckWarning> w;
    read_deck_string(text, "pair.inp", &w);
    return w;
  };
  const std::vector<DeckWarning> stiff_slave = warnings_of(deck("1e5", "UPBOTTOM, LOWTOP"));
  ASSERT_EQ(stiff_slave.size(), 1u);
  EXPECT_EQ(stiff_slave[0].where.line, 32);  // the data line of *CONTACT PAIR
  for (const char* words : {"slave surface UPBOTTOM", "100 times stiffer", "master surface LOWTOP",
                            "E 100000 against 1000", "Swap them on the data line: LOWTOP, UPBOTTOM"})
    EXPECT_NE(stiff_slave[0].message.find(words), std::string::npos) << words << " in: " << stiff_slave[0].message;
  EXPECT_TRUE(warnings_of(deck("1e5", "LOWTOP, UPBOTTOM")).empty());  // the stiffer body is the master
  EXPECT_TRUE(warnings_of(deck("9e3", "UPBOTTOM, LOWTOP")).empty());  // 9 times: below the threshold
  EXPECT_EQ(warnings_of(deck("1e4", "UPBOTTOM, LOWTOP")).size(), 1u);  // 10 times
  EXPECT_TRUE(warnings_of(deck("1e5", "UPNODES, LOWTOP")).empty());  // node surface: no body to compare
}

TEST(ContactKeywords, NodeSurfaceReadsOneAreaPerNodeAndRefusesBadOnes) {
  const std::string head = "*NODE\n1, 0, 0\n2, 1, 0\n3, 2, 0\n*NSET, NSET=TWO\n2, 3\n";
  const Model m = read_deck_string(head + "*SURFACE, NAME=S, TYPE=NODE\n1\nTWO, 2.5\n", "n.inp");
  const Surface& s = m.surfaces.at("S");
  ASSERT_EQ(s.nodes.size(), 3u);
  ASSERT_EQ(s.node_areas.size(), 3u);
  EXPECT_EQ(s.node_areas[0], 1.0);  // default, as in ABAQUS
  EXPECT_EQ(s.node_areas[1], 2.5);
  EXPECT_EQ(s.node_areas[2], 2.5);
  const std::string zero = head + "*SURFACE, NAME=S, TYPE=NODE\n1, 0.\n";
  expect_deck_error_at(zero, "1, 0.", {"node area 0.", "expected an area > 0"});
  const std::string twice = head + "*SURFACE, NAME=S, TYPE=NODE\nTWO, 2.\n3, 3.\n";
  expect_deck_error_at(twice, "3, 3.", {"node 3 is given the area 3 here", "and 2 at bad.inp:8"});
  // The later line leaves the area out (then 1): named as such, no crash.
  const std::string omitted = head + "*SURFACE, NAME=S, TYPE=NODE\nTWO, 2.\n3\n";
  expect_deck_error(omitted, 9, {"node 3 is given the area 1 here (1 when omitted) and 2 at bad.inp:8"});
  const std::string same = head + "*SURFACE, NAME=S, TYPE=NODE\nTWO, 2.\n3, 2.\n";
  EXPECT_EQ(read_deck_string(same, "n.inp").surfaces.at("S").nodes.size(), 2u);
}
