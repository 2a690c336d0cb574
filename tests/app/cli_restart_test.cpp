// The tether command line: restarts, and result files never written over an earlier run.

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
