// Restart (*RESTART, WRITE / READ; StaticAnalysis::resume): an analysis
// continued from any saved state ends exactly where the uninterrupted run
// ends; a state of another model and a damaged file are refused with the
// file named. The deck (tests/analysis/decks/restart_friction.inp) has every
// kind of history: NLGEOM, frictional contact (pairing, committed slip and
// tangential force), an augmented-Lagrangian *EQUATION (Uzawa multiplier and
// update count), loads carried from step 1 into step 2, growing increments.

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

#include "run_deck.hpp"
#include "tether/output/restart_file.hpp"

using namespace tether;
namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string base_deck() { return slurp(fs::path(TETHER_SOURCE_DIR) / "tests/analysis/decks/restart_friction.inp"); }

using tether::testing::replaced;

/// Variants of the deck: as written (HARD by multipliers, exact stick), with
/// augmented-Lagrangian contact and penalty (elastic-slip) friction, whose
/// history is the Uzawa normal force and the committed tangential force, and
/// with mortar contact (history: the overlaps the slip is measured from,
/// total slip and dissipation).
std::vector<std::pair<std::string, std::string>> decks() {
  const std::string base = base_deck();
  std::string soft = replaced(base, "*FRICTION\n0.3\n",
                              "*SURFACE BEHAVIOR, ENFORCEMENT=AUGMENTED, PENALTY=1e5, TOLERANCE=1e-9\n"
                              "*FRICTION\n0.3, 20000\n");
  return {{"lagrange contact, exact stick", base},
          {"augmented contact, penalty friction", soft},
          {"mortar contact, exact stick", replaced(base, "TYPE=NODE TO SURFACE", "TYPE=SURFACE TO SURFACE")}};
}

/// Records results and the restart states (round-tripped through the file format).
class StateRecorder final : public AnalysisObserver {
 public:
  void on_results(const IncrementResults& r, const Step&, bool) override { results.push_back(r); }
  void on_restart_state(const RestartState& s) override {
    states.push_back(decode_restart(encode_restart(s), "memory.rst"));
  }
  void on_message(const std::string& m) override { messages.push_back(m); }
  std::vector<IncrementResults> results;
  std::vector<RestartState> states;
  std::vector<std::string> messages;
};

struct Outcome {
  AnalysisSummary summary;
  Eigen::VectorXd u;
  StateRecorder recorder;
};

Outcome run_model(const Model& model, const RestartState* from = nullptr, AnalysisOptions options = {}) {
  Outcome out;
  StaticAnalysis analysis(model, out.recorder, options);
  if (from) analysis.resume(*from, "memory.rst");
  out.summary = analysis.run();
  out.u = analysis.solution();
  return out;
}

/// Largest |a - b| / max|a| over the unknowns.
double relative_difference(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  EXPECT_EQ(a.size(), b.size());
  if (a.size() != b.size()) return INFINITY;
  return (a - b).cwiseAbs().maxCoeff() / std::max(a.cwiseAbs().maxCoeff(), 1e-300);
}

/// Largest relative difference of the output that carries history: contact
/// (forces, slip, dissipation, pairing) and multipliers (values, f).
/// `same_increment`: the two results must also have the same increment
/// number (not so for runs whose automatic incrementation may differ).
double output_difference(const IncrementResults& a, const IncrementResults& b, bool same_increment = true) {
  double d = 0;
  const auto rel = [&](double x, double y, double scale) { d = std::max(d, std::abs(x - y) / scale); };
  EXPECT_EQ(a.step, b.step);
  if (same_increment) EXPECT_EQ(a.increment, b.increment);
  EXPECT_EQ(a.total_time, b.total_time);
  EXPECT_EQ(a.contact.size(), b.contact.size());
  for (std::size_t p = 0; p < std::min(a.contact.size(), b.contact.size()); ++p) {
    EXPECT_EQ(a.contact[p].nodes.size(), b.contact[p].nodes.size());
    for (std::size_t k = 0; k < std::min(a.contact[p].nodes.size(), b.contact[p].nodes.size()); ++k) {
      const ContactNodeValues &x = a.contact[p].nodes[k], &y = b.contact[p].nodes[k];
      EXPECT_EQ(x.status, y.status);
      EXPECT_EQ(x.master_element, y.master_element);
      rel(x.normal_force, y.normal_force, 1), rel(x.tangential_force, y.tangential_force, 1);
      rel(x.total_slip, y.total_slip, 1e-2), rel(x.slip, y.slip, 1e-2), rel(x.dissipation, y.dissipation, 1e-2);
      rel(x.xi, y.xi, 1), rel(x.gap, y.gap, 1e-2);
    }
    rel(a.contact[p].dissipation, b.contact[p].dissipation, 1e-2);
  }
  EXPECT_EQ(a.multipliers.size(), b.multipliers.size());
  for (std::size_t c = 0; c < std::min(a.multipliers.size(), b.multipliers.size()); ++c)
    for (std::size_t k = 0; k < a.multipliers[c].value.size(); ++k) {
      rel(a.multipliers[c].value[k], b.multipliers[c].value.at(k), 1);
      rel(a.multipliers[c].constraint[k], b.multipliers[c].constraint.at(k), 1e-2);
    }
  for (std::size_t n = 0; n < a.displacement.size(); ++n)
    rel((a.displacement[n] - b.displacement.at(n)).cwiseAbs().maxCoeff(), 0, 1e-2);
  return d;
}

}  // namespace

TEST(Restart, ContinuingFromEverySavedIncrementGivesTheUninterruptedAnswer) {
  for (const auto& [name, text] : decks()) {
    SCOPED_TRACE(name);
    const Model model = read_deck_string(text, "restart_friction.inp");
    const Outcome full = run_model(model);
    ASSERT_TRUE(full.summary.completed) << full.summary.message;
    // FREQUENCY=1: a state after every increment (the step ends once each).
    ASSERT_EQ(full.recorder.states.size(), full.recorder.results.size());
    ASSERT_GE(full.recorder.results.size(), 10u);
    EXPECT_TRUE(full.recorder.states[3].step_completed);  // step 1 ends at increment 4
    // The contact actually slides and the constraint carries force (history matters).
    const IncrementResults& last = full.recorder.results.back();
    EXPECT_GT(last.contact.at(0).dissipation, 1e-3);
    EXPECT_GT(std::abs(last.multipliers.at(0).value.at(0)), 1e-3);

    double worst_u = 0, worst_output = 0;
    for (std::size_t k = 0; k + 1 < full.recorder.states.size(); ++k) {
      const RestartState& state = full.recorder.states[k];
      SCOPED_TRACE("restart after step " + std::to_string(state.step) + " increment " +
                   std::to_string(state.increment));
      const Outcome resumed = run_model(model, &state);
      ASSERT_TRUE(resumed.summary.completed) << resumed.summary.message;
      // The resumed run reports the increments after the saved one, numbered on.
      ASSERT_EQ(resumed.recorder.results.size(), full.recorder.results.size() - k - 1);
      EXPECT_EQ(resumed.recorder.results.front().increment, full.recorder.results[k + 1].increment);
      EXPECT_EQ(resumed.summary.increments, full.summary.increments);
      EXPECT_EQ(resumed.summary.iterations, full.summary.iterations);
      EXPECT_EQ(resumed.summary.steps, full.summary.steps);
      ASSERT_FALSE(resumed.recorder.messages.empty());
      EXPECT_NE(resumed.recorder.messages.front().find("restarted from memory.rst at step " +
                                                       std::to_string(state.step)),
                std::string::npos)
          << resumed.recorder.messages.front();
      worst_u = std::max(worst_u, relative_difference(full.u, resumed.u));
      for (std::size_t i = 0; i < resumed.recorder.results.size(); ++i)
        worst_output = std::max(worst_output, output_difference(full.recorder.results[k + 1 + i],
                                                                resumed.recorder.results[i]));
      // The states the resumed run saves are those of the uninterrupted run, bit for bit.
      ASSERT_EQ(resumed.recorder.states.size(), full.recorder.states.size() - k - 1);
      EXPECT_EQ(encode_restart(resumed.recorder.states.back()), encode_restart(full.recorder.states.back()));
    }
    // Measured: bitwise equal (docs/robustness.md, "Restart").
    EXPECT_LE(worst_u, 1e-12);
    EXPECT_LE(worst_output, 1e-12);
    std::cout << "[ restart ] " << name << ": " << full.recorder.states.size() - 1
              << " restart points, max relative |du| = " << worst_u << ", max output difference = " << worst_output
              << "\n";
  }
}

TEST(Restart, RunStoppedMidStepContinuesFromItsLastState) {
  const Model model = read_deck_string(base_deck(), "restart_friction.inp");
  const Outcome full = run_model(model);
  ASSERT_TRUE(full.summary.completed) << full.summary.message;
  AnalysisOptions stop;
  stop.stop_after_increments = 6;  // step 2, increment 2
  const Outcome killed = run_model(model, nullptr, stop);
  EXPECT_FALSE(killed.summary.completed);
  EXPECT_NE(killed.summary.message.find("stopped after 6 increment(s)"), std::string::npos) << killed.summary.message;
  ASSERT_EQ(killed.recorder.states.size(), 6u);
  const RestartState& last = killed.recorder.states.back();
  EXPECT_EQ(last.step, 2);
  EXPECT_EQ(last.increment, 2);
  EXPECT_FALSE(last.step_completed);
  const Outcome resumed = run_model(model, &last);
  ASSERT_TRUE(resumed.summary.completed) << resumed.summary.message;
  EXPECT_EQ(relative_difference(full.u, resumed.u), 0.0);  // bitwise
  EXPECT_EQ(resumed.summary.increments, full.summary.increments);

  // The comparison sees history: the same state with the contact history
  // altered (the committed point of every slave moved by 0.05 in ξ, which
  // changes the slip measured in the next increment) ends elsewhere, at the
  // same time but not necessarily after as many automatic increments.
  RestartState altered = last;
  ASSERT_EQ(altered.contributions.size(), 2u);  // LEVEL, then the contact pair
  std::vector<double>& contact = altered.contributions.back().values;
  const std::size_t slaves = static_cast<std::size_t>(contact.at(1));
  for (std::size_t k = 0; k < slaves; ++k) contact.at(3 + 13 * k + 8) += 0.05;  // committed ξ
  const Outcome wrong = run_model(model, &altered);
  ASSERT_TRUE(wrong.summary.completed) << wrong.summary.message;
  EXPECT_GT(output_difference(full.recorder.results.back(), wrong.recorder.results.back(), false), 1e-6);

  // Stopping at the end of step 1 continues with step 2.
  stop.stop_after_increments = 4;
  const Outcome after_step_1 = run_model(model, nullptr, stop);
  EXPECT_FALSE(after_step_1.summary.completed);
  ASSERT_TRUE(after_step_1.recorder.states.back().step_completed);
  const Outcome resumed2 = run_model(model, &after_step_1.recorder.states.back());
  ASSERT_TRUE(resumed2.summary.completed) << resumed2.summary.message;
  EXPECT_EQ(relative_difference(full.u, resumed2.u), 0.0);
}

TEST(Restart, FrequencyWritesEveryNthIncrementAndTheEndOfEachStep) {
  const std::string deck = replaced(base_deck(), "*RESTART, WRITE, FREQUENCY=1", "*RESTART, WRITE, FREQUENCY=3");
  const Model model = read_deck_string(deck, "restart_friction.inp");
  const Outcome run = run_model(model);
  ASSERT_TRUE(run.summary.completed);
  std::vector<std::pair<int, int>> written;
  for (const RestartState& s : run.recorder.states) written.emplace_back(s.step, s.increment);
  // Every 3rd increment of each step and its last one. The number of
  // increments of each step comes from the run (automatic incrementation;
  // a round-off change in a stick/slip decision can change it by one):
  // step 1 has 4 increments (3, end = 4), step 2 9-10 (3, 6, 9, end).
  std::map<int, int> last_increment;
  for (const IncrementResults& r : run.recorder.results)
    last_increment[r.step] = std::max(last_increment[r.step], r.increment);
  ASSERT_EQ(last_increment.size(), 2u);
  EXPECT_EQ(last_increment[1], 4);
  EXPECT_GE(last_increment[2], 6);  // the frequency acts at least twice in step 2
  std::vector<std::pair<int, int>> expected;
  for (const auto& [step, n] : last_increment) {
    for (int k = 3; k < n; k += 3) expected.emplace_back(step, k);
    expected.emplace_back(step, n);
  }
  EXPECT_EQ(written, expected);
  // Without *RESTART, WRITE nothing is written.
  const Model quiet = read_deck_string(replaced(base_deck(), "*RESTART, WRITE, FREQUENCY=1\n", ""), "q.inp");
  EXPECT_TRUE(run_model(quiet).recorder.states.empty());
}

TEST(Restart, AnotherModelIsRefusedNamingTheFileAndTheDifference) {
  const Model model = read_deck_string(base_deck(), "restart_friction.inp");
  AnalysisOptions stop;
  stop.stop_after_increments = 6;
  const RestartState state = run_model(model, nullptr, stop).recorder.states.back();

  const auto refusal = [&](const std::string& deck) -> std::string {
    const Model other = read_deck_string(deck, "other.inp");
    StateRecorder quiet;
    StaticAnalysis analysis(other, quiet);
    try {
      analysis.resume(state, "out/job.rst");
    } catch (const InputError& e) {
      return e.what();
    }
    return "accepted";
  };
  const std::string base = base_deck();
  struct Case {
    std::string what, deck, expected;
  };
  const std::vector<Case> cases = {
      {"a node moved", replaced(base, "3, 0.5, 1.0\n", "3, 0.5001, 1.0\n"), "node labels or coordinates differ"},
      {"an extra node", replaced(base, "*ELEMENT, TYPE=CPE4, ELSET=TOP", "99, 5, 5\n*ELEMENT, TYPE=CPE4, ELSET=TOP"),
       "the deck has 25 nodes, the file 24"},
      {"other connectivity", replaced(base, "1, 1, 2, 7, 6\n", "1, 2, 7, 6, 1\n"),
       "element labels, types or connectivity differ"},
      {"a constraint by multipliers", replaced(base, "ENFORCEMENT=AUGMENTED, PENALTY=1e5", "ENFORCEMENT=LAGRANGE"),
       "multipliers"},
      {"a penalty constraint (no history)", replaced(base, "ENFORCEMENT=AUGMENTED", "ENFORCEMENT=PENALTY"),
       "a saved state for LEVEL, which has none in this deck"},
      {"another step-1 load", replaced(base, "8, 2, -0.5", "8, 2, -0.6"), "load history of steps 1..2 differs"},
      {"another step-2 target", replaced(base, "PUSHED, 1, 1, 0.05", "PUSHED, 1, 1, 0.06"),
       "load history of steps 1..2 differs"},
      {"one step only", base.substr(0, base.find("*STEP, NLGEOM, INC=100")), "has only 1 step(s)"},
      {"a body load in step 1",
       replaced(replaced(base, "*ELASTIC\n", "*DENSITY\n1e-6\n*ELASTIC\n"), "*CLOAD\n8, 2, -0.5",
                "*DLOAD\nTOP, GRAV, 1., 0., -1.\n*CLOAD\n8, 2, -0.5"),
       "load history of steps 1..2 differs"},
      {"initial temperatures", replaced(base, "*STEP, NLGEOM\n", "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nBASE, 20.\n*STEP, NLGEOM\n"),
       "load history of steps 1..2 differs"},
      {"temperatures in step 1", replaced(base, "*CLOAD\n8, 2, -0.5", "*TEMPERATURE\nBASE, 50.\n*CLOAD\n8, 2, -0.5"),
       "load history of steps 1..2 differs"},
      {"step 1's loads applied at once", replaced(base, "*STEP, NLGEOM\n*STATIC", "*STEP, NLGEOM, AMPLITUDE=STEP\n*STATIC"),
       "load history of steps 1..2 differs"},
  };
  for (const Case& c : cases) {
    const std::string message = refusal(c.deck);
    EXPECT_NE(message.find("out/job.rst: error: cannot continue this deck from the restart file"), std::string::npos)
        << c.what << ": " << message;
    EXPECT_NE(message.find(c.expected), std::string::npos) << c.what << ": " << message;
  }
  // Changing the controls or the output requests of the rest of the run is allowed (as in ABAQUS).
  EXPECT_EQ(refusal(replaced(base, "0.1, 1, 1e-4, 0.25", "0.05, 1, 1e-4, 0.25")), "accepted");

  // *RESTART, READ, STEP=, INC= must name the saved state (only the last one is kept).
  const std::string read_header = "*RESTART, READ, STEP=2, INC=2\n";
  EXPECT_EQ(refusal(read_header + base), "accepted");
  EXPECT_EQ(refusal("*RESTART, READ, STEP=2\n" + base), "accepted");
  const std::string wrong = refusal("*RESTART, READ, STEP=1, INC=4\n" + base);
  EXPECT_NE(wrong.find("other.inp:1: error: *RESTART, READ asks for step 1 increment 4, but out/job.rst holds step 2 "
                       "increment 2"),
            std::string::npos)
      << wrong;
}

TEST(Restart, TruncatedOrCorruptFilesAreRefusedCleanly) {
  const Model model = read_deck_string(base_deck(), "restart_friction.inp");
  AnalysisOptions stop;
  stop.stop_after_increments = 5;
  const RestartState state = run_model(model, nullptr, stop).recorder.states.back();
  const std::string bytes = encode_restart(state);
  EXPECT_EQ(bytes.substr(0, 7), "TETHRST");

  const auto refusal = [](std::string_view b) -> std::string {
    try {
      decode_restart(b, "job.rst");
    } catch (const InputError& e) {
      return e.what();
    }
    return "accepted";
  };
  EXPECT_EQ(refusal(bytes), "accepted");
  // Every truncation, and every single corrupted byte, is refused with the file named.
  for (std::size_t n = 0; n < bytes.size(); ++n) {
    const std::string message = refusal(std::string_view(bytes).substr(0, n));
    ASSERT_EQ(message.rfind("job.rst: error: not a usable tether restart file: ", 0), 0u) << n << ": " << message;
  }
  EXPECT_NE(refusal(""), "accepted");
  EXPECT_NE(refusal(bytes.substr(0, bytes.size() - 1)).find("truncated"), std::string::npos);
  for (std::size_t at = 0; at < bytes.size(); ++at) {
    std::string bad = bytes;
    bad[at] = static_cast<char>(bad[at] ^ 0x10);
    ASSERT_NE(refusal(bad), "accepted") << "byte " << at;
  }
  std::string flipped = bytes;
  flipped[bytes.size() / 2] ^= 1;
  EXPECT_NE(refusal(flipped).find("checksum mismatch"), std::string::npos) << refusal(flipped);
  EXPECT_NE(refusal(bytes + "x").find("truncated or extended"), std::string::npos);
  EXPECT_NE(refusal("*HEADING\nnot a restart file\n").find("magic"), std::string::npos);
  std::string v5 = bytes;  // a version this tether does not read (it reads 4)
  v5[8] = 5;
  EXPECT_NE(refusal(v5).find("format version 5"), std::string::npos) << refusal(v5);

  // A state with a contribution record that does not fit is refused by resume, naming the contribution.
  RestartState broken = state;
  ASSERT_FALSE(broken.contributions.empty());
  broken.contributions.back().values.resize(5);
  StateRecorder quiet;
  StaticAnalysis analysis(model, quiet);
  try {
    analysis.resume(broken, "job.rst");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("job.rst: error"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("SLAVE-MASTER"), std::string::npos) << e.what();
  }
  // ... and the analysis is left as it was: it runs from the beginning to the same answer.
  const AnalysisSummary summary = analysis.run();
  EXPECT_TRUE(summary.completed) << summary.message;
  EXPECT_EQ(relative_difference(run_model(model).u, analysis.solution()), 0.0);

  // Files: missing, and not a regular file.
  const fs::path dir = fs::path(TETHER_BINARY_DIR) / "tests" / "analysis" / "scratch" / "restart_files";
  fs::remove_all(dir);
  fs::create_directories(dir);
  EXPECT_THROW(read_restart_file(dir / "missing.rst"), InputError);
  EXPECT_THROW(read_restart_file(dir), InputError);
}

TEST(Restart, TheFileIsCompleteAtEveryMoment) {
  // A reader polling the file while states are written over it (as a crash
  // or a second process would see it) only ever finds complete states: each
  // is written to JOB.rst.tmp and renamed onto JOB.rst.
  const Model model = read_deck_string(base_deck(), "restart_friction.inp");
  const std::vector<RestartState> states = run_model(model).recorder.states;
  const fs::path dir = fs::path(TETHER_BINARY_DIR) / "tests" / "analysis" / "scratch" / "restart_atomic";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path file = dir / "job.rst";
  write_restart_file(file, states.front());
  std::atomic<bool> done{false};
  std::atomic<int> reads{0}, failures{0};
  std::thread reader([&] {
    while (!done) {
      try {
        (void)read_restart_file(file);
        ++reads;
      } catch (const std::exception&) {
        ++failures;
      }
    }
  });
  // At least 20 rounds, and on until the reader has read 20 times (a loaded
  // machine may not schedule it during the first rounds), for at most 30 s.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  for (int round = 0; round < 20 || (reads.load() < 20 && std::chrono::steady_clock::now() < deadline); ++round)
    for (const RestartState& s : states) write_restart_file(file, s);
  done = true;
  reader.join();
  EXPECT_EQ(failures.load(), 0);
  EXPECT_GT(reads.load(), 0);
  EXPECT_FALSE(fs::exists(dir / "job.rst.tmp"));
  EXPECT_EQ(read_restart_file(file).increment, states.back().increment);
  EXPECT_EQ(slurp(file), encode_restart(states.back()));
}

TEST(Restart, KeywordIsReadAndChecked) {
  const std::string base = base_deck();
  const Model model =
      read_deck_string(replaced(base, "*RESTART, WRITE, FREQUENCY=1\n", "*RESTART, WRITE, FREQUENCY=2\n"), "a.inp");
  ASSERT_EQ(model.steps.size(), 2u);
  EXPECT_EQ(model.steps[0].restart_frequency, 2);
  EXPECT_EQ(model.steps[1].restart_frequency, 2);  // in force until changed
  EXPECT_FALSE(model.restart_read);
  // In a step it applies from that step on; FREQUENCY=0 stops writing.
  const Model changed = read_deck_string(
      replaced(base, "*STEP, NLGEOM, INC=100\n", "*STEP, NLGEOM, INC=100\n*RESTART, WRITE, FREQUENCY=0\n"), "b.inp");
  EXPECT_EQ(changed.steps[0].restart_frequency, 1);
  EXPECT_EQ(changed.steps[1].restart_frequency, 0);
  const Model read = read_deck_string("*RESTART, READ, STEP=2, INC=3, FILE=old/job.rst\n" + base, "c.inp");
  ASSERT_TRUE(read.restart_read);
  EXPECT_EQ(read.restart_read->step, 2);
  EXPECT_EQ(read.restart_read->increment, 3);
  EXPECT_EQ(read.restart_read->file, "old/job.rst");

  const auto error = [&](const std::string& deck) -> std::string {
    try {
      read_deck_string(deck, "e.inp");
    } catch (const InputError& e) {
      return e.what();
    }
    return "accepted";
  };
  EXPECT_NE(error("*RESTART\n" + base).find("needs READ"), std::string::npos);
  EXPECT_NE(error("*RESTART, READ, WRITE\n" + base).find("not both"), std::string::npos);
  EXPECT_NE(error("*RESTART, READ, INC=3\n" + base).find("INC= on *RESTART, READ needs STEP="), std::string::npos);
  EXPECT_NE(error("*RESTART, READ, FREQUENCY=2\n" + base).find("FREQUENCY= belongs to *RESTART, WRITE"),
            std::string::npos);
  EXPECT_NE(error("*RESTART, WRITE, STEP=2\n" + base).find("STEP= belongs to *RESTART, READ"), std::string::npos);
  EXPECT_NE(error(replaced(base, "*RESTART, WRITE, FREQUENCY=1", "*RESTART, WRITE, FREQUENCY=-1")).find("FREQUENCY=-1"),
            std::string::npos);
  EXPECT_NE(error(replaced(base, "*STEP, NLGEOM, INC=100\n", "*STEP, NLGEOM, INC=100\n*RESTART, READ\n"))
                .find("*RESTART, READ belongs in the model data"),
            std::string::npos);
  EXPECT_NE(error("*RESTART, READ\n*RESTART, READ\n" + base).find("second *RESTART, READ"), std::string::npos);
  EXPECT_NE(error("*RESTART, WRITE, NUMBER INTERVAL=2\n" + base).find("NUMBER INTERVAL"), std::string::npos);
}
