// The tether command line: exit codes, messages, files written.

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

namespace {

const char* kGoodDeck = R"(*HEADING
one CPE4 under tension
*NODE, NSET=ALL
1, 0, 0
2, 1, 0
3, 1, 1
4, 0, 1
*ELEMENT, TYPE=CPE4, ELSET=E
1, 1, 2, 3, 4
*NSET, NSET=LEFT
1, 4
*MATERIAL, NAME=M
*ELASTIC
1000, 0.3
*SOLID SECTION, ELSET=E, MATERIAL=M
*BOUNDARY
LEFT, 1
1, 2
*STEP
*STATIC
0.5, 1.
*CLOAD
2, 1, 1.
3, 1, 1.
*NODE PRINT, NSET=ALL
U
*END STEP
)";

}  // namespace

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


TEST(Cli, RestartContinuesAnAnalysisToTheSameFiles) {
  // tests/analysis/decks/restart_friction.inp: two NLGEOM steps with friction
  // and an augmented *EQUATION, *RESTART, WRITE every increment.
  const fs::path dir = scratch("restart");
  const std::string deck = slurp(fs::path(TETHER_SOURCE_DIR) / "tests/analysis/decks/restart_friction.inp");
  ASSERT_FALSE(deck.empty());
  write(dir / "job.inp", deck);
  write(dir / "step1.inp", deck.substr(0, deck.find("*STEP, NLGEOM, INC=100")));  // step 1 only
  const auto path = [&](const std::string& name) { return (dir / name).string(); };

  ASSERT_EQ(tether("run " + path("job.inp") + " -o " + path("full")).code, 0);
  ASSERT_EQ(tether("run " + path("step1.inp") + " -o " + path("s1")).code, 0);
  ASSERT_TRUE(fs::exists(dir / "s1" / "step1.rst"));
  EXPECT_FALSE(fs::exists(dir / "s1" / "step1.rst.tmp"));

  // Continue the whole deck from the end of step 1.
  const auto r = tether("run " + path("job.inp") + " --restart " + path("s1/step1.rst") + " -o " + path("resumed"));
  ASSERT_EQ(r.code, 0) << r.out;
  const std::string msg = slurp(dir / "resumed" / "job.msg");
  EXPECT_NE(msg.find("restarted from " + path("s1/step1.rst") + " at step 1, step time 1 (increment 4, total time 1, "
                     "end of the step)"),
            std::string::npos)
      << msg;
  // Only step 2 is written, numbered as in the uninterrupted run, byte for byte the same.
  int vtus = 0;
  for (const auto& entry : fs::directory_iterator(dir / "resumed")) {
    if (entry.path().extension() != ".vtu") continue;
    ++vtus;
    EXPECT_EQ(entry.path().filename().string().rfind("job_2_", 0), 0u) << entry.path();
    EXPECT_EQ(slurp(entry.path()), slurp(dir / "full" / entry.path().filename())) << entry.path();
  }
  // As many as the uninterrupted run wrote for step 2 (9-10: automatic
  // increments, see restart_test.cpp).
  int full_step_2 = 0;
  for (const auto& entry : fs::directory_iterator(dir / "full"))
    if (entry.path().extension() == ".vtu" && entry.path().filename().string().rfind("job_2_", 0) == 0) ++full_step_2;
  EXPECT_GE(full_step_2, 6);
  EXPECT_EQ(vtus, full_step_2);
  const std::string pvd = slurp(dir / "resumed" / "job.pvd");
  EXPECT_NE(pvd.find("file=\"job_2_1.vtu\""), std::string::npos) << pvd;
  EXPECT_EQ(pvd.find("job_1_"), std::string::npos) << pvd;
  // The .dat holds step 2 exactly as the uninterrupted run printed it (CDIS sums included).
  const std::string full_dat = slurp(dir / "full" / "job.dat"), resumed_dat = slurp(dir / "resumed" / "job.dat");
  ASSERT_FALSE(resumed_dat.empty());
  ASSERT_LT(resumed_dat.size(), full_dat.size());
  EXPECT_EQ(full_dat.substr(full_dat.size() - resumed_dat.size()), resumed_dat);
  EXPECT_EQ(slurp(dir / "resumed" / "job.rst"), slurp(dir / "full" / "job.rst"));

  // The same through the deck: *RESTART, READ, FILE= (relative to the deck).
  write(dir / "read.inp", "*RESTART, READ, STEP=1, INC=4, FILE=s1/step1.rst\n" + deck);
  const auto by_deck = tether("run " + path("read.inp") + " -o " + path("read"));
  EXPECT_EQ(by_deck.code, 0) << by_deck.out;
  const std::string last = "_2_" + std::to_string(full_step_2) + ".vtu";
  EXPECT_EQ(slurp(dir / "read" / ("read" + last)), slurp(dir / "full" / ("job" + last)));
}

TEST(Cli, RestartFromAnotherModelOrADamagedFileIsRefused) {
  const fs::path dir = scratch("restart_refused");
  const std::string deck = slurp(fs::path(TETHER_SOURCE_DIR) / "tests/analysis/decks/restart_friction.inp");
  write(dir / "step1.inp", deck.substr(0, deck.find("*STEP, NLGEOM, INC=100")));
  const auto path = [&](const std::string& name) { return (dir / name).string(); };
  ASSERT_EQ(tether("run " + path("step1.inp") + " -o " + path("s1")).code, 0);
  const std::string rst = path("s1/step1.rst");

  std::string moved = deck;
  moved.replace(moved.find("3, 0.5, 1.0\n"), 12, "3, 0.5001, 1.0\n");
  write(dir / "moved.inp", moved);
  auto r = tether("run " + path("moved.inp") + " --restart " + rst + " -o " + path("out_moved"));
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find(rst + ": error: cannot continue this deck from the restart file"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("node labels or coordinates differ"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(dir / "out_moved")) << "a refused restart must not touch the output";

  write(dir / "job.inp", deck);
  const std::string bytes = slurp(rst);
  write(dir / "truncated.rst", bytes.substr(0, bytes.size() / 2));
  r = tether("run " + path("job.inp") + " --restart " + path("truncated.rst") + " -o " + path("out_truncated"));
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find(path("truncated.rst") + ": error: not a usable tether restart file: truncated"),
            std::string::npos)
      << r.out;
  r = tether("run " + path("job.inp") + " --restart " + path("missing.rst"));
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find("missing.rst: error: cannot open the restart file"), std::string::npos) << r.out;

  write(dir / "nofile.inp", "*RESTART, READ\n" + deck);
  r = tether("run " + path("nofile.inp"));
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find("nofile.inp:1: error: *RESTART, READ without FILE="), std::string::npos) << r.out;
  write(dir / "wrongstep.inp", "*RESTART, READ, STEP=2\n" + deck);
  r = tether("run " + path("wrongstep.inp") + " --restart " + rst);
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find("wrongstep.inp:1: error: *RESTART, READ asks for step 2, but " + rst +
                       " holds step 1 increment 4"),
            std::string::npos)
      << r.out;
}

TEST(Cli, MemoryBudgetKeepsTheAnswerAndRefusesNonsense) {
  const fs::path dir = scratch("memory");
  write(dir / "plate.inp", kGoodDeck);
  const std::string deck = (dir / "plate.inp").string();
  for (const char* bad : {"--memory 0", "--memory -5", "--memory lots"}) {
    const auto r = tether("run " + deck + " " + bad + " -o " + (dir / "bad").string());
    EXPECT_NE(r.code, 0) << bad;
    EXPECT_NE(r.out.find("--memory"), std::string::npos) << bad << ": " << r.out;
  }
  // 1 MB: the MUMPS factors go out of core; the printed results are the same.
  const auto in_core = tether("run " + deck + " --solver mumps -o " + (dir / "in").string());
  const auto on_disk = tether("run " + deck + " --solver mumps --memory 1 -o " + (dir / "disk").string());
  ASSERT_EQ(in_core.code, 0) << in_core.out;
  ASSERT_EQ(on_disk.code, 0) << on_disk.out;
  const auto read = [](const fs::path& p) {
    std::ifstream f(p);
    return std::string((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  };
  EXPECT_EQ(read(dir / "in" / "plate.dat"), read(dir / "disk" / "plate.dat"));
  // The run says so, though there is no contact (no condensed solver to report it).
  EXPECT_NE(read(dir / "disk" / "plate.msg").find("factorization(s) were kept on disk"), std::string::npos)
      << read(dir / "disk" / "plate.msg");
  EXPECT_EQ(read(dir / "in" / "plate.msg").find("on disk"), std::string::npos);
}

TEST(Cli, MemoryBudgetRefusesAnUnusableTemporaryDirectoryByName) {
  const fs::path dir = scratch("memory_tmpdir");
  write(dir / "plate.inp", kGoodDeck);
  write(dir / "a_file", "not a directory\n");
  const std::string deck = (dir / "plate.inp").string();
  const std::string missing = (dir / "missing").string(), file = (dir / "a_file").string();
  const std::string too_long = (dir / std::string(130, 'd') / std::string(130, 'd')).string();
  fs::create_directories(too_long);
  for (const auto& [tmpdir, why] : {std::pair{missing, "does not exist"}, std::pair{file, "not a directory"},
                                    std::pair{too_long, "longer than MUMPS accepts"}}) {
    const auto r = tether("run " + deck + " --solver mumps --memory 1 -o " + (dir / "out").string(),
                          "TMPDIR=" + tmpdir);
    EXPECT_EQ(r.code, 2) << r.out;  // not completed; neither a crash (3) nor a silent in-core run (0)
    EXPECT_NE(r.out.find("'" + tmpdir + "' ($TMPDIR)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(why), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("set TMPDIR"), std::string::npos) << r.out;
  }
  // Without a budget nothing goes to disk and the directory does not matter;
  // nor with a solver that never writes its factors out (UMFPACK, CHOLMOD).
  const auto r = tether("run " + deck + " --solver mumps -o " + (dir / "out").string(), "TMPDIR=" + missing);
  EXPECT_EQ(r.code, 0) << r.out;
  for (const char* in_core_only : {"umfpack", "cholmod"}) {
    const auto q = tether("run " + deck + " --solver " + in_core_only + " --memory 1 -o " + (dir / "out").string(),
                          "TMPDIR=" + missing);
    EXPECT_EQ(q.code, 0) << in_core_only << ": " << q.out;
  }
  // Auto may use MUMPS, so it checks.
  EXPECT_EQ(tether("run " + deck + " --memory 1 -o " + (dir / "out").string(), "TMPDIR=" + missing).code, 2);
}

// MUMPS (LDLT) and CHOLMOD read one triangle only: asked for on a step whose
// tangent is unsymmetric (friction), the run is refused with the reason and
// the way out, not factorized as if the matrix were symmetric.
TEST(Cli, ASymmetricOnlySolverIsRefusedForAnUnsymmetricStep) {
  const fs::path dir = scratch("unsymmetric_solver");
  write(dir / "friction.inp", slurp(fs::path(TETHER_SOURCE_DIR) / "tests/analysis/decks/restart_friction.inp"));
  for (const char* solver : {"mumps", "cholmod"}) {
    const auto r = tether("run " + (dir / "friction.inp").string() + " --solver " + solver + " -o " +
                          (dir / solver).string());
    EXPECT_EQ(r.code, 2) << solver << ": " << r.out;  // the step cannot be solved as asked
    EXPECT_NE(r.out.find(std::string("--solver ") + solver), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("factorizes symmetric matrices only"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("use --solver auto or umfpack"), std::string::npos) << r.out;
  }
  EXPECT_EQ(tether("run " + (dir / "friction.inp").string() + " --solver umfpack -q -o " + (dir / "lu").string()).code,
            0);
}

// A restart never writes over the run it continues: `--restart JOB/JOB.rst`
// without -o used to truncate JOB/JOB.dat and rewrite its .sta.
TEST(Cli, RestartWritesToANewDirectoryAndNeverOverTheFirstRun) {
  const fs::path dir = scratch("restart_directory");
  write(dir / "job.inp", slurp(fs::path(TETHER_SOURCE_DIR) / "tests/analysis/decks/restart_friction.inp"));
  const auto path = [&](const std::string& name) { return (dir / name).string(); };
  ASSERT_EQ(tether("run " + path("job.inp")).code, 0);
  const std::string dat = slurp(dir / "job" / "job.dat"), sta = slurp(dir / "job" / "job.sta");
  ASSERT_FALSE(dat.empty());

  const auto first = tether("run " + path("job.inp") + " --restart " + path("job/job.rst"));
  EXPECT_EQ(first.code, 0) << first.out;
  EXPECT_NE(first.out.find("the results go to " + path("job-restart")), std::string::npos) << first.out;
  EXPECT_TRUE(fs::exists(dir / "job-restart" / "job.sta"));
  const auto second = tether("run -q " + path("job.inp") + " --restart " + path("job/job.rst"));
  EXPECT_EQ(second.code, 0) << second.out;
  EXPECT_TRUE(fs::exists(dir / "job-restart-2" / "job.sta"));
  // Into the first run's directory, or any holding results of the job: refused.
  for (const std::string& target : {std::string("job"), std::string("job-restart")}) {
    const auto refused = tether("run " + path("job.inp") + " --restart " + path("job/job.rst") + " -o " + path(target));
    EXPECT_EQ(refused.code, 1) << refused.out;
    EXPECT_NE(refused.out.find("holds the results of a run of job"), std::string::npos) << refused.out;
  }
  EXPECT_EQ(slurp(dir / "job" / "job.dat"), dat);
  EXPECT_EQ(slurp(dir / "job" / "job.sta"), sta);
  EXPECT_TRUE(fs::exists(dir / "job" / "job.rst"));
}

// A run replaces everything an earlier run of the same job left in its
// directory: no .vtu of more increments, no .pvd of a run that converged
// when this one did not; other jobs' files stay.
TEST(Cli, ARunLeavesNoResultFilesOfAnEarlierRunOfTheJob) {
  const fs::path dir = scratch("rerun");
  const auto path = [&](const std::string& name) { return (dir / name).string(); };
  std::string deck = kGoodDeck;
  write(dir / "plate.inp", deck);
  ASSERT_EQ(tether("run " + path("plate.inp") + " -o " + path("out")).code, 0);
  ASSERT_TRUE(fs::exists(dir / "out" / "plate_1_2.vtu"));
  write(dir / "out" / "other_1_1.vtu", "another job's file");
  write(dir / "out" / "plate_notes.vtu", "not an increment file");
  deck.replace(deck.find("0.5, 1."), 7, "1., 1.");  // one increment
  write(dir / "plate.inp", deck);
  const auto one = tether("run " + path("plate.inp") + " -o " + path("out"));
  ASSERT_EQ(one.code, 0) << one.out;
  EXPECT_TRUE(fs::exists(dir / "out" / "plate_1_1.vtu"));
  EXPECT_FALSE(fs::exists(dir / "out" / "plate_1_2.vtu"));
  EXPECT_EQ(slurp(dir / "out" / "plate.pvd").find("plate_1_2.vtu"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir / "out" / "other_1_1.vtu"));
  EXPECT_TRUE(fs::exists(dir / "out" / "plate_notes.vtu"));
  // A run with no converged increment leaves no .pvd or .vtu at all.
  deck.replace(deck.find("LEFT, 1\n1, 2"), 12, "LEFT, 1");  // free in y: singular
  write(dir / "plate.inp", deck);
  const auto bad = tether("run " + path("plate.inp") + " -o " + path("out"));
  EXPECT_EQ(bad.code, 2) << bad.out;
  EXPECT_FALSE(fs::exists(dir / "out" / "plate.pvd"));
  EXPECT_FALSE(fs::exists(dir / "out" / "plate_1_1.vtu"));
}

// What the program prints, it prints once: the timing line, each cut-back
// reason (the attempt line says "not converged", the cut-back message why);
// deck warnings go to the .msg too and -q keeps them off the terminal; the
// results line names only files that exist.
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

TEST(Cli, NoReuseAssemblesAndFactorizesEveryIterationWithTheSameResults) {
  // A linear elastic step in two increments: by default the tangent is held
  // and its one factorization reused by the second increment; --no-reuse
  // assembles and factorizes at every iteration. The results are the same
  // byte for byte; the timing line of the .msg says which was done.
  // The load follows an amplitude (1 then 3 at the increments' ends): under
  // a ramp the predictor, extrapolating the first increment, would already
  // be the solution and the second increment would not solve.
  const fs::path dir = scratch("reuse");
  std::string text = kGoodDeck;
  const std::string step = "*STEP\n*STATIC\n0.5, 1.\n*CLOAD\n";
  ASSERT_NE(text.find(step), std::string::npos);
  text.replace(text.find(step), step.size(),
               "*AMPLITUDE, NAME=A\n0., 0., 0.5, 1., 1., 3.\n*STEP\n*STATIC\n0.5, 1.\n*CLOAD, AMPLITUDE=A\n");
  write(dir / "plate.inp", text);
  const std::string deck = (dir / "plate.inp").string();
  const auto held = tether("run " + deck + " -o " + (dir / "held").string());
  const auto fresh = tether("run " + deck + " --no-reuse -o " + (dir / "fresh").string());
  ASSERT_EQ(held.code, 0) << held.out;
  ASSERT_EQ(fresh.code, 0) << fresh.out;
  const auto read = [](const fs::path& p) {
    std::ifstream f(p);
    return std::string((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  };
  EXPECT_EQ(read(dir / "held" / "plate.dat"), read(dir / "fresh" / "plate.dat"));
  const std::string held_log = read(dir / "held" / "plate.msg"), fresh_log = read(dir / "fresh" / "plate.msg");
  EXPECT_NE(held_log.find("(1 factorizations, 1 reused)"), std::string::npos) << held_log;
  EXPECT_NE(held_log.find("linear bulk's tangent held in"), std::string::npos) << held_log;
  EXPECT_NE(fresh_log.find("(2 factorizations)"), std::string::npos) << fresh_log;
  EXPECT_EQ(fresh_log.find("held"), std::string::npos) << fresh_log;
}

TEST(Cli, MortarCondensationEliminatesTheMultipliersWithTheSameIterations) {
  // The Hertz example (5k dofs) with its pair made mortar: by default the
  // solver condenses onto the contact equations (the .msg's timing line says
  // "the rest of the contact equations only"); --mortar-condensation
  // eliminates the mortar multipliers instead and factorizes the condensed
  // matrix at every iteration, in the same number of Newton iterations.
  const fs::path dir = scratch("mortar_condensation");
  std::string deck = slurp(fs::path(TETHER_SOURCE_DIR) / "examples/hertz_mortar/hertz.inp");
  const std::string from = "TYPE=NODE TO SURFACE";
  ASSERT_NE(deck.find(from), std::string::npos);
  deck.replace(deck.find(from), from.size(), "TYPE=SURFACE TO SURFACE");
  write(dir / "hertz.inp", deck);
  const std::string path = (dir / "hertz.inp").string();
  const auto schur = tether("run " + path + " -q -o " + (dir / "schur").string());
  const auto dual = tether("run " + path + " -q --mortar-condensation -o " + (dir / "dual").string());
  ASSERT_EQ(schur.code, 0) << schur.out;
  ASSERT_EQ(dual.code, 0) << dual.out;
  const std::string schur_log = slurp(dir / "schur" / "hertz.msg"), dual_log = slurp(dir / "dual" / "hertz.msg");
  EXPECT_NE(schur_log.find("the rest of the contact equations only"), std::string::npos) << schur_log;
  EXPECT_EQ(dual_log.find("the rest of the contact equations only"), std::string::npos) << dual_log;
  const auto iterations = [](const std::string& log) {  // Σ of "K iterations, converged" over the increments
    int total = 0;
    for (std::size_t at = log.find(" iterations, converged"); at != std::string::npos;
         at = log.find(" iterations, converged", at + 1))
      total += std::stoi(log.substr(log.rfind(' ', at - 1) + 1));
    return total;
  };
  EXPECT_EQ(iterations(schur_log), 20) << schur_log;  // 25 before the predictor
  EXPECT_EQ(iterations(dual_log), iterations(schur_log)) << dual_log;
}
