// The tether command line: exit codes, messages and logs, dialects, check over decks.

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <sstream>
#include <vector>

#include "cli_support.hpp"

namespace fs = std::filesystem;
using namespace cli_test;


TEST(Cli, VersionAndHelp) {
  const auto v = tether("--version");
  EXPECT_EQ(v.code, 0);
  EXPECT_NE(v.out.find("tether "), std::string::npos);
  const auto h = tether("--help");
  EXPECT_EQ(h.code, 0);
  EXPECT_NE(h.out.find("run"), std::string::npos);
  EXPECT_NE(h.out.find("check"), std::string::npos);
}

TEST(Cli, UnknownArgumentsFail) {
  EXPECT_NE(tether("").code, 0);
  EXPECT_NE(tether("frobnicate").code, 0);
  EXPECT_NE(tether("run").code, 0);
  EXPECT_NE(tether("run x.inp --solver mumps").code, 0);
}

TEST(Cli, RunWritesResultsQuietlyWhenNotATerminal) {
  const fs::path dir = scratch("good");
  write(dir / "plate.inp", kGoodDeck);
  const auto r = tether((dir / "plate.inp").string() + " -o " + (dir / "out").string() + "");
  EXPECT_NE(r.code, 0);  // missing subcommand
  const auto run = tether("run " + (dir / "plate.inp").string() + " -o " + (dir / "out").string());
  EXPECT_EQ(run.code, 0) << run.out;
  EXPECT_EQ(run.out.find("inc "), std::string::npos) << "progress lines on a pipe:\n" << run.out;
  EXPECT_NE(run.out.find("analysis complete"), std::string::npos) << run.out;
  for (const char* f : {"plate.pvd", "plate.dat", "plate.sta", "plate_1_1.vtu", "plate_1_2.vtu"})
    EXPECT_TRUE(fs::exists(dir / "out" / f)) << f;
  std::ifstream sta(dir / "out" / "plate.sta");
  const std::string text((std::istreambuf_iterator<char>(sta)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("COMPLETED SUCCESSFULLY"), std::string::npos) << text;

  const auto quiet = tether("run -q " + (dir / "plate.inp").string() + " -o " + (dir / "out2").string());
  EXPECT_EQ(quiet.code, 0);
  EXPECT_TRUE(quiet.out.empty()) << quiet.out;
}

TEST(Cli, CheckValidatesWithoutSolving) {
  const fs::path dir = scratch("check");
  write(dir / "plate.inp", kGoodDeck);
  const auto r = tether("check " + (dir / "plate.inp").string());
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("4 nodes, 1 elements"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(dir / "plate"));
}

TEST(Cli, BadDeckGivesFileLineAndExitCodeOne) {
  const fs::path dir = scratch("bad");
  std::string deck = kGoodDeck;
  deck.replace(deck.find("1000, 0.3"), 9, "1000, 0.3x");  // line 14
  write(dir / "bad.inp", deck);
  for (const char* verb : {"check ", "run "}) {
    const auto r = tether(verb + (dir / "bad.inp").string());
    EXPECT_EQ(r.code, 1) << r.out;
    EXPECT_NE(r.out.find("bad.inp:14"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("0.3x"), std::string::npos) << r.out;
  }
  const auto missing = tether("run " + (dir / "nope.inp").string());
  EXPECT_EQ(missing.code, 1) << missing.out;
  EXPECT_NE(missing.out.find("nope.inp"), std::string::npos) << missing.out;
}

TEST(Cli, UnsolvableModelExitsTwoAndSaysWhy) {
  const fs::path dir = scratch("floating");
  std::string deck = kGoodDeck;
  deck.replace(deck.find("1, 2\n*STEP"), 4, "");  // remove the y support: rigid-body mode
  write(dir / "float.inp", deck);
  const auto r = tether("run " + (dir / "float.inp").string() + " -o " + (dir / "out").string());
  EXPECT_EQ(r.code, 2) << r.out;
  EXPECT_NE(r.out.find("singular"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("dof 2"), std::string::npos) << r.out;
  std::ifstream sta(dir / "out" / "float.sta");
  const std::string text((std::istreambuf_iterator<char>(sta)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("NOT BEEN COMPLETED"), std::string::npos) << text;
}

TEST(Cli, MessageLogRecordsIterationsAndUzawaUpdates) {
  const fs::path dir = scratch("augmented");
  std::string deck = kGoodDeck;
  // Tie node 3 to node 2 in y with an augmented Lagrangian: at least one Uzawa update.
  deck.replace(deck.find("*STEP"), 5, "*EQUATION, ENFORCEMENT=AUGMENTED, PENALTY=10., TOLERANCE=1e-12\n2\n3, 2, 1., 2, 2, -1.\n*STEP");
  write(dir / "aug.inp", deck);
  const auto r = tether("run " + (dir / "aug.inp").string() + " -o " + (dir / "out").string());
  ASSERT_EQ(r.code, 0) << r.out;
  std::ifstream msg(dir / "out" / "aug.msg");
  const std::string text((std::istreambuf_iterator<char>(msg)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("iteration  1: max force residual"), std::string::npos) << text;
  EXPECT_NE(text.find("converged state not accepted by EQUATION"), std::string::npos) << text;
  EXPECT_NE(text.find("Newton pass 2"), std::string::npos) << text;
  EXPECT_NE(text.find("step 1 increment 2 attempt 1"), std::string::npos) << text;
}

TEST(Cli, ContactRunLogsTheActiveSetPerIteration) {
  const fs::path dir = scratch("contact");
  // Element 2 pressed onto element 1: slave = its bottom face, master = the top face of element 1.
  const std::string deck = R"(*NODE
1, 0, 0
2, 1, 0
3, 1, 1
4, 0, 1
5, 0, 1
6, 1, 1
7, 1, 2
8, 0, 2
*ELEMENT, TYPE=CPE4, ELSET=E
1, 1, 2, 3, 4
2, 5, 6, 7, 8
*SURFACE, NAME=S
2, S1
*SURFACE, NAME=M
1, S3
*SURFACE INTERACTION, NAME=I
*CONTACT PAIR, INTERACTION=I, TYPE=NODE TO SURFACE
S, M
*MATERIAL, NAME=M
*ELASTIC
1000, 0.3
*SOLID SECTION, ELSET=E, MATERIAL=M
*BOUNDARY
1, 1, 2
2, 2
5, 1
*STEP
*STATIC
*CLOAD
7, 2, -1.
8, 2, -1.
*END STEP
)";
  write(dir / "contact.inp", deck);
  const auto r = tether("run " + (dir / "contact.inp").string() + " -o " + (dir / "out").string());
  ASSERT_EQ(r.code, 0) << r.out;
  std::ifstream msg(dir / "out" / "contact.msg");
  const std::string text((std::istreambuf_iterator<char>(msg)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("contact: 2 closed, 0 changed status, 0 re-paired"), std::string::npos) << text;
}

TEST(Cli, SlaveNodeOnTheMasterSurfaceIsRefusedWithItsDeckLine) {
  const fs::path dir = scratch("contact_shared");
  std::string deck = kGoodDeck;
  deck.replace(deck.find("*STEP"), 5,
               "*SURFACE, NAME=S, TYPE=NODE\nLEFT\n*SURFACE, NAME=M\nE, S4\n*SURFACE INTERACTION, NAME=I\n"
               "*CONTACT PAIR, INTERACTION=I\nS, M\n*STEP");
  write(dir / "contact.inp", deck);
  const auto r = tether("run " + (dir / "contact.inp").string() + " -o " + (dir / "out").string());
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find("belongs to both the slave surface S and the master surface M"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("contact.inp:"), std::string::npos) << r.out;
}



TEST(Cli, TerminalAndMessageLogSayEachThingOnce) {
  const fs::path dir = scratch("once");
  const auto path = [&](const std::string& name) { return (dir / name).string(); };
  std::string deck = kGoodDeck;
  const std::string step = "*STEP\n*STATIC\n0.5, 1.\n*CLOAD\n2, 1, 1.\n3, 1, 1.";
  deck.replace(deck.find(step), step.size(),
               "*STEP, NLGEOM\n*CONTROLS, PARAMETERS=TIME INCREMENTATION\n,,,2\n*STATIC, SOLVER=SPOOLES\n1., 1.\n"
               "*CLOAD\n2, 1, 300.\n3, 1, 300.");
  write(dir / "cut.inp", deck);
  const auto r = tether("run " + path("cut.inp") + " -o " + path("out"));
  ASSERT_EQ(r.code, 0) << r.out;
  const auto count = [](const std::string& text, const std::string& what) {
    int n = 0;
    for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
    return n;
  };
  EXPECT_EQ(count(r.out, "s: contact search"), 1) << r.out;  // the timing line
  EXPECT_EQ(count(r.out, "warning: SOLVER=SPOOLES ignored"), 1) << r.out;
  const std::string msg = slurp(dir / "out" / "cut.msg");
  EXPECT_EQ(count(msg, "warning: SOLVER=SPOOLES ignored"), 1) << msg;
  EXPECT_EQ(count(msg, "s: contact search"), 1) << msg;
  const int cutbacks = count(msg, "cut back to increment");
  EXPECT_GE(cutbacks, 1) << msg;
  EXPECT_EQ(count(msg, "no convergence in 2 iterations"), cutbacks) << msg;
  EXPECT_EQ(count(msg, "not converged"), cutbacks) << msg;
  // The results line: these files, and no .rst (no *RESTART).
  const auto results = r.out.substr(r.out.find("results: "));
  for (const char* f : {"cut.pvd", "cut.dat", "cut.sta", "cut.msg"})
    EXPECT_NE(results.find(f), std::string::npos) << results;
  EXPECT_EQ(results.find(".rst"), std::string::npos) << results;

  const auto quiet = tether("run -q " + path("cut.inp") + " -o " + path("quiet"));
  EXPECT_EQ(quiet.code, 0);
  EXPECT_TRUE(quiet.out.empty()) << quiet.out;
  EXPECT_EQ(count(slurp(dir / "quiet" / "cut.msg"), "warning: SOLVER=SPOOLES ignored"), 1);

  // On a terminal (script(1) from util-linux gives the program a pty): the
  // progress lines and messages, still each reason and the timing once.
  Result tty;
  const std::string command = "script -qec \"" + std::string(TETHER_CLI) + " run " + path("cut.inp") + " -o " +
                              path("tty") + "\" /dev/null 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  ASSERT_TRUE(pipe);
  std::array<char, 4096> buffer{};
  while (fgets(buffer.data(), buffer.size(), pipe)) tty.out += buffer.data();
  pclose(pipe);
  ASSERT_NE(tty.out.find("step 1 inc"), std::string::npos) << "no progress lines: " << tty.out;
  EXPECT_EQ(count(tty.out, "s: contact search"), 1) << tty.out;
  EXPECT_EQ(count(tty.out, "no convergence in 2 iterations"), cutbacks) << tty.out;
}

TEST(Cli, DialectIsChosenOnTheCommandLineAndNamedInTheLogs) {
  const fs::path dir = scratch("dialect");
  std::string deck = kGoodDeck;
  // NLGEOM=NO after an NLGEOM step: ABAQUS keeps NLGEOM on (warning), CalculiX turns it off.
  deck.replace(deck.find("*STEP\n"), 6, "*STEP, NLGEOM\n");
  deck += "*STEP, NLGEOM=NO\n*STATIC\n*END STEP\n";
  write(dir / "plate.inp", deck);
  const auto read_file = [](const fs::path& p) {
    std::ifstream in(p);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  };
  for (const std::string dialect : {"abaqus", "calculix"}) {
    const auto run = tether("run " + (dir / "plate.inp").string() + " --dialect " + dialect + " -o " +
                            (dir / dialect).string());
    EXPECT_EQ(run.code, 0) << run.out;
    EXPECT_EQ(run.out.find("stays on") != std::string::npos, dialect == "abaqus") << run.out;
    EXPECT_NE(read_file(dir / dialect / "plate.sta").find("job plate  dialect " + dialect), std::string::npos);
    EXPECT_NE(read_file(dir / dialect / "plate.msg").find("read in the " + dialect + " dialect"), std::string::npos);
  }
  const auto check = tether("check --dialect CalculiX " + (dir / "plate.inp").string());
  EXPECT_EQ(check.code, 0) << check.out;
  EXPECT_NE(check.out.find("(dialect calculix)"), std::string::npos) << check.out;
  const auto plain = tether("check " + (dir / "plate.inp").string());
  EXPECT_NE(plain.out.find("(dialect abaqus)"), std::string::npos) << plain.out;
  const auto bad = tether("check --dialect nastran " + (dir / "plate.inp").string());
  EXPECT_EQ(bad.code, 1) << bad.out;
  EXPECT_NE(bad.out.find("nastran"), std::string::npos) << bad.out;
}

TEST(Cli, CheckOverSeveralDecksTabulatesWhatTheyNeed) {
  const fs::path dir = scratch("survey");
  fs::create_directories(dir / "more");
  write(dir / "good.inp", kGoodDeck);
  std::string frequency = kGoodDeck;
  frequency.replace(frequency.find("*STATIC"), 7, "*FREQUENCY");
  write(dir / "more" / "frequency.inp", frequency);
  std::string needs = kGoodDeck;
  needs.replace(needs.find("TYPE=CPE4"), 9, "TYPE=C3D8");
  needs.replace(needs.find("*NSET, NSET=LEFT"), 16, "*NSET, NSET=LEFT, UNSORTED");
  needs.replace(needs.find("*STATIC"), 7, "*FREQUENCY");
  write(dir / "needs.inp", needs);
  std::string broken = kGoodDeck;
  broken.replace(broken.find("1000, 0.3"), 9, "1000, 0.3x");
  write(dir / "broken.inp", broken);
  const auto r = tether("check " + (dir / "good.inp").string() + " " + (dir / "needs.inp").string() + " " +
                        (dir / "broken.inp").string() + " " + (dir / "more").string());
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find("good.inp: OK"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("needs.inp: refused: *FREQUENCY, *NSET, UNSORTED, C3D8"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("broken.inp:14: error: bad number"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("4 deck(s): 1 read, 2 refused by the keyword table, 1 with other errors"), std::string::npos)
      << r.out;
  // The table: *FREQUENCY in two decks first, then the rest once each.
  const auto row = r.out.find("procedure        *FREQUENCY");
  ASSERT_NE(row, std::string::npos) << r.out;
  EXPECT_NE(r.out.find("     2           2", row), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("element type     C3D8"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("parameter        *NSET, UNSORTED"), std::string::npos) << r.out;
  EXPECT_LT(row, r.out.find("element type     C3D8")) << r.out;
  const auto all_good = tether("check " + (dir / "good.inp").string() + " " + (dir / "good.inp").string());
  EXPECT_EQ(all_good.code, 0) << all_good.out;
  const auto missing = tether("check " + (dir / "good.inp").string() + " " + (dir / "nope").string());
  EXPECT_EQ(missing.code, 1) << missing.out;
  EXPECT_NE(missing.out.find("no such deck or folder"), std::string::npos) << missing.out;
}
