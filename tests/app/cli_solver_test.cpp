// The tether command line: memory budget, solver choice, bulk reuse and mortar condensation.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
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

TEST(Cli, NoReuseAssemblesAndFactorizesEveryIterationWithTheSameResults) {
  // A linear elastic step in two increments: by default the tangent is held
  // and its one factorization reused by the second increment; --no-reuse
  // assembles and factorizes at every iteration. The results are the same
  // to round-off (the held tangent's residual updates sum in another order:
  // the same words, every number within 1e-12 of the file's largest); the
  // timing line of the .msg says which was done.
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
  const auto words = [](const std::string& text) {
    std::istringstream in(text);
    return std::vector<std::string>(std::istream_iterator<std::string>(in), std::istream_iterator<std::string>());
  };
  const auto number = [](const std::string& w, double& x) {
    char* end = nullptr;
    x = std::strtod(w.c_str(), &end);
    return end != w.c_str() && *end == '\0';
  };
  const std::vector<std::string> a = words(read(dir / "held" / "plate.dat")), b = words(read(dir / "fresh" / "plate.dat"));
  ASSERT_EQ(a.size(), b.size());
  double largest = 0;
  for (const std::string& w : b)
    if (double x = 0; number(w, x)) largest = std::max(largest, std::abs(x));
  for (std::size_t k = 0; k < a.size(); ++k) {
    double x = 0, y = 0;
    if (a[k] == b[k]) continue;
    ASSERT_TRUE(number(a[k], x) && number(b[k], y)) << a[k] << " vs " << b[k];
    EXPECT_LE(std::abs(x - y), 1e-12 * largest) << a[k] << " vs " << b[k];
  }
  const std::string held_log = read(dir / "held" / "plate.msg"), fresh_log = read(dir / "fresh" / "plate.msg");
  EXPECT_NE(held_log.find("(1 factorizations, 1 reused)"), std::string::npos) << held_log;
  EXPECT_NE(held_log.find("linear bulk's tangent held in"), std::string::npos) << held_log;
  EXPECT_NE(fresh_log.find("(2 factorizations)"), std::string::npos) << fresh_log;
  EXPECT_EQ(fresh_log.find("held"), std::string::npos) << fresh_log;
}

namespace {

/// The Hertz example (5k dofs) with its pair made mortar (TYPE=SURFACE TO
/// SURFACE), written as DIR/hertz.inp; its path, empty if the example has no
/// node-to-surface pair to change.
std::string write_mortar_hertz(const fs::path& dir) {
  std::string deck = slurp(fs::path(TETHER_SOURCE_DIR) / "examples/hertz_mortar/hertz.inp");
  const std::string from = "TYPE=NODE TO SURFACE";
  if (deck.find(from) == std::string::npos) return {};
  deck.replace(deck.find(from), from.size(), "TYPE=SURFACE TO SURFACE");
  write(dir / "hertz.inp", deck);
  return (dir / "hertz.inp").string();
}

}  // namespace

TEST(Cli, MortarCondensationEliminatesTheMultipliersWithTheSameIterations) {
  // The Hertz example (5k dofs) with its pair made mortar: by default the
  // solver condenses onto the contact equations (the .msg's timing line says
  // "the rest of the contact equations only"); --mortar-condensation
  // eliminates the mortar multipliers instead and factorizes the condensed
  // matrix at every iteration, in the same number of Newton iterations.
  const fs::path dir = scratch("mortar_condensation");
  const std::string path = write_mortar_hertz(dir);
  ASSERT_FALSE(path.empty());
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

/// The ITRS column of each increment's row in a .sta file.
std::vector<int> sta_iterations(const std::string& sta) {
  std::vector<int> iterations;
  std::istringstream in(sta);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream row(line);
    int step = 0, increment = 0, attempt = 0, itrs = 0;
    if (row >> step >> increment >> attempt >> itrs) iterations.push_back(itrs);
  }
  return iterations;
}

TEST(Cli, StepExtrapolationLinearPredictsALinearRampAndNoStartsFromTheConvergedState) {
  // kGoodDeck: a linear plate under a ramped load in two increments. With
  // EXTRAPOLATION=LINEAR (the default) the second increment starts from the
  // first one doubled, which is its solution: no iteration. With NO it
  // starts from the first increment's state and takes one.
  const fs::path dir = scratch("extrapolation");
  const std::string base = kGoodDeck;
  std::vector<std::string> dats;
  for (const auto& [parameter, second] : std::vector<std::pair<std::string, int>>{
           {"", 0}, {", EXTRAPOLATION=LINEAR", 0}, {", EXTRAPOLATION=NO", 1}}) {
    std::string text = base;
    text.replace(text.find("*STEP\n"), 6, "*STEP" + parameter + "\n");
    write(dir / "plate.inp", text);
    const auto r = tether("run " + (dir / "plate.inp").string() + " -o " + (dir / "out").string());
    ASSERT_EQ(r.code, 0) << r.out;
    const std::vector<int> iterations = sta_iterations(slurp(dir / "out" / "plate.sta"));
    ASSERT_EQ(iterations.size(), 2u) << parameter;
    EXPECT_EQ(iterations[0], 1) << parameter;
    EXPECT_EQ(iterations[1], second) << parameter;
    dats.push_back(slurp(dir / "out" / "plate.dat"));
  }
  // The same answer either way (a linear problem): the .dat's numbers within
  // 1e-15 (displacements of 1e-3; a zero one prints as round-off, +-3e-19).
  const auto numbers = [](const std::string& text) {
    std::vector<double> values;
    std::istringstream in(text);
    for (std::string token; in >> token;)
      if (token.find_first_of("0123456789") == 0 || token[0] == '-') values.push_back(std::strtod(token.c_str(), nullptr));
    return values;
  };
  const std::vector<double> linear = numbers(dats[0]), none = numbers(dats[2]);
  ASSERT_EQ(linear.size(), none.size());
  ASSERT_GT(linear.size(), 20u);
  for (std::size_t k = 0; k < linear.size(); ++k) EXPECT_NEAR(linear[k], none[k], 1e-15) << k;
  std::string parabolic = base;
  parabolic.replace(parabolic.find("*STEP\n"), 6, "*STEP, EXTRAPOLATION=PARABOLIC\n");
  write(dir / "plate.inp", parabolic);
  const auto r = tether("check " + (dir / "plate.inp").string());
  EXPECT_EQ(r.code, 1) << r.out;
  EXPECT_NE(r.out.find("plate.inp:19: error: EXTRAPOLATION=PARABOLIC"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("expected LINEAR (the default) or NO"), std::string::npos) << r.out;
}

namespace {

/// The numbers of a text file (every token that parses whole as a double), in order.
std::vector<double> numbers_of(const std::string& text) {
  std::vector<double> out;
  std::istringstream in(text);
  std::string token;
  while (in >> token) {
    char* end = nullptr;
    const double v = std::strtod(token.c_str(), &end);
    if (end != token.c_str() && *end == '\0') out.push_back(v);
  }
  return out;
}

/// The values of the ascii Float64 DataArray `name` of a .vtu.
std::vector<double> vtu_array(const std::string& vtu, const std::string& name) {
  const auto at = vtu.find("Name=\"" + name + "\"");
  if (at == std::string::npos) return {};
  const auto from = vtu.find('>', at) + 1;
  return numbers_of(vtu.substr(from, vtu.find("</DataArray>", from) - from));
}

}  // namespace

namespace {

/// The deck at `path` (in `dir`) run with every writer (.dat, .sta, .msg,
/// .pvd and ASCII .vtu per increment) by default and with
/// --mortar-condensation=kept: the default's .msg names the dual
/// elimination and a Cholesky, kept's an LU and none; the same increments
/// and iterations, the .dat's printed values the same to their printed
/// digits (1e-6 relative; 1e-9 of the file's largest value for those near
/// zero), the last .vtu's displacements within 1e-10 of the largest. A wrong
/// mode is refused.
void expect_dense_same_as_kept(const fs::path& dir, const std::string& path) {
  const auto dense = tether("run " + path + " -q --ascii -o " + (dir / "dense").string());
  const auto kept = tether("run " + path + " -q --ascii --mortar-condensation=kept -o " + (dir / "kept").string());
  ASSERT_EQ(dense.code, 0) << dense.out;
  ASSERT_EQ(kept.code, 0) << kept.out;
  const auto bad = tether("run " + path + " -q --mortar-condensation=diagonal -o " + (dir / "bad").string());
  EXPECT_NE(bad.code, 0);
  EXPECT_NE(bad.out.find("--mortar-condensation"), std::string::npos) << bad.out;
  for (const char* file : {"hertz.dat", "hertz.sta", "hertz.msg", "hertz.pvd", "hertz_1_1.vtu"}) {
    EXPECT_TRUE(fs::exists(dir / "dense" / file)) << file;
    EXPECT_TRUE(fs::exists(dir / "kept" / file)) << file;
  }
  const std::string dense_log = slurp(dir / "dense" / "hertz.msg"), kept_log = slurp(dir / "kept" / "hertz.msg");
  EXPECT_NE(dense_log.find("after the dual elimination of the contact multipliers"), std::string::npos) << dense_log;
  EXPECT_NE(dense_log.find(", Cholesky, reciprocal condition"), std::string::npos) << dense_log;
  EXPECT_EQ(kept_log.find("dual elimination"), std::string::npos) << kept_log;
  EXPECT_NE(kept_log.find(", LU, reciprocal condition"), std::string::npos) << kept_log;
  const std::vector<int> its = sta_iterations(slurp(dir / "dense" / "hertz.sta"));
  EXPECT_FALSE(its.empty());
  EXPECT_EQ(its, sta_iterations(slurp(dir / "kept" / "hertz.sta")));
  const std::vector<double> a = numbers_of(slurp(dir / "dense" / "hertz.dat"));
  const std::vector<double> b = numbers_of(slurp(dir / "kept" / "hertz.dat"));
  ASSERT_EQ(a.size(), b.size());
  ASSERT_GT(a.size(), 100u);
  double largest = 0;
  for (double v : b) largest = std::max(largest, std::abs(v));
  for (std::size_t k = 0; k < a.size(); ++k)
    EXPECT_NEAR(a[k], b[k], 1e-6 * std::abs(b[k]) + 1e-9 * largest) << "number " << k << " of the .dat";
  // The last increment's .vtu: the last file the .pvd lists.
  const std::string pvd = slurp(dir / "dense" / "hertz.pvd");
  const auto at = pvd.rfind("file=\"");
  ASSERT_NE(at, std::string::npos) << pvd;
  const std::string last = pvd.substr(at + 6, pvd.find('"', at + 6) - at - 6);
  const std::vector<double> u = vtu_array(slurp(dir / "dense" / last), "U");
  const std::vector<double> v = vtu_array(slurp(dir / "kept" / last), "U");
  ASSERT_FALSE(u.empty()) << last;
  ASSERT_EQ(u.size(), v.size());
  double umax = 0, du = 0;
  for (std::size_t k = 0; k < u.size(); ++k) umax = std::max(umax, std::abs(v[k])), du = std::max(du, std::abs(u[k] - v[k]));
  EXPECT_LT(du, 1e-10 * umax) << last;
}

}  // namespace

TEST(Cli, MortarMultipliersEliminatedFromTheDenseInterfaceSystemWithAllWriters) {
  // The Hertz example (5k dofs) with its pair made mortar, run with every
  // writer (.dat with node and contact prints, .sta, .msg, .pvd and ASCII
  // .vtu per increment): by default the mortar multipliers are eliminated
  // from the dense system of the contact equations (the .msg says so and
  // gives its size, 2 × (slave + master nodes) less the closed nodes);
  // --mortar-condensation=kept factorizes the whole interface system by LU.
  // The same increments and iterations, the .dat's printed values the same
  // to their printed digits (1e-6 relative; 1e-9 of the file's largest
  // value for those near zero), the last .vtu's displacements within 1e-10
  // of the largest. A wrong mode is refused.
  const fs::path dir = scratch("mortar_dense");
  const std::string path = write_mortar_hertz(dir);
  ASSERT_FALSE(path.empty());
  expect_dense_same_as_kept(dir, path);
}

TEST(Cli, NodeToSurfaceMultipliersEliminatedFromTheDenseInterfaceSystemWithAllWriters) {
  // The node-to-surface Hertz example (5k dofs) as it is: its closed normal
  // multipliers are eliminated from the dense system of the contact
  // equations like mortar ones (the .msg says so), with the same answers as
  // with them kept.
  const fs::path dir = scratch("nts_dense");
  fs::create_directories(dir);
  write(dir / "hertz.inp", slurp(fs::path(TETHER_SOURCE_DIR) / "examples/hertz/hertz.inp"));
  expect_dense_same_as_kept(dir, (dir / "hertz.inp").string());
}
