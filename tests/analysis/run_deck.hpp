#pragma once
// Test helper: runs a deck given as text and records what the analysis reports;
// reads the decks of tests/analysis/decks and edits their text.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tether/analysis/static_analysis.hpp"
#include "tether/io/deck_reader.hpp"

namespace tether::testing {

/// Records every report of an analysis.
class Recorder final : public AnalysisObserver {
 public:
  void on_iteration(int iteration, const IterationNorms& n) override {
    if (iteration == 0) residuals.emplace_back(), norms.emplace_back();
    residuals.back().push_back(n.force_residual);
    norms.back().push_back(n);
  }
  void on_increment(const IncrementReport& r) override { increments.push_back(r); }
  void on_results(const IncrementResults& r, const Step&, bool) override { results.push_back(r); }
  void on_message(const std::string& m) override { messages.push_back(m); }

  std::vector<std::vector<double>> residuals;  ///< per Newton pass, per iteration: the max force residual
  std::vector<std::vector<IterationNorms>> norms;  ///< per Newton pass, per iteration: all norms
  std::vector<IncrementReport> increments;
  std::vector<IncrementResults> results;
  std::vector<std::string> messages;
};

struct Run {
  Model model;
  AnalysisSummary summary;
  Recorder recorder;
  /// Results of the last converged increment.
  [[nodiscard]] const IncrementResults& last() const { return recorder.results.back(); }
  /// Index of the node with label `id`.
  [[nodiscard]] int node(int id) const { return model.node_index.at(id); }
  /// Sum of the reactions over a node set, component c.
  [[nodiscard]] double reaction_sum(const std::string& set, int c) const {
    double s = 0;
    for (int n : model.node_sets.at(set)) s += last().reaction[n][c];
    return s;
  }
};

/// The largest differences between two runs of one model, with their scales
/// (the largest magnitudes of the first run): displacements over every
/// recorded increment, contact pressures at the end. The runs must have
/// recorded as many increments (checked).
struct RunDifferences {
  double displacement = 0, displacement_scale = 0;
  double pressure = 0, pressure_scale = 0;
};
inline RunDifferences run_differences(const Run& a, const Run& b) {
  RunDifferences d;
  EXPECT_EQ(a.recorder.results.size(), b.recorder.results.size());
  for (std::size_t i = 0; i < std::min(a.recorder.results.size(), b.recorder.results.size()); ++i)
    for (std::size_t n = 0; n < a.recorder.results[i].displacement.size(); ++n) {
      const Eigen::Vector2d& u = a.recorder.results[i].displacement[n];
      d.displacement_scale = std::max(d.displacement_scale, u.cwiseAbs().maxCoeff());
      d.displacement = std::max(d.displacement, (u - b.recorder.results[i].displacement[n]).cwiseAbs().maxCoeff());
    }
  for (std::size_t p = 0; p < a.last().contact.size(); ++p) {
    const ContactPairValues& x = a.last().contact[p];
    const ContactPairValues& y = b.last().contact.at(p);
    EXPECT_EQ(x.nodes.size(), y.nodes.size());
    for (std::size_t k = 0; k < std::min(x.nodes.size(), y.nodes.size()); ++k) {
      d.pressure_scale = std::max(d.pressure_scale, std::abs(x.nodes[k].pressure));
      d.pressure = std::max(d.pressure, std::abs(x.nodes[k].pressure - y.nodes[k].pressure));
    }
  }
  return d;
}

/// Reads `text` (named "test.inp") and runs it.
inline Run run_deck_text(const std::string& text, AnalysisOptions options = {}) {
  Run run;
  run.model = read_deck_string(text, "test.inp");
  StaticAnalysis analysis(run.model, run.recorder, options);
  run.summary = analysis.run();
  return run;
}

/// Reads `text` (named "test.inp") in `dialect` and runs it.
inline Run run_deck_text_in(const std::string& text, Dialect dialect, AnalysisOptions options = {}) {
  Run run;
  run.model = read_deck_string(text, "test.inp", nullptr, dialect);
  StaticAnalysis analysis(run.model, run.recorder, options);
  run.summary = analysis.run();
  return run;
}

/// Reads a deck file and runs it.
inline Run run_deck_file(const std::string& path, AnalysisOptions options = {}) {
  Run run;
  run.model = read_deck(path);
  StaticAnalysis analysis(run.model, run.recorder, options);
  run.summary = analysis.run();
  return run;
}

/// The text of the deck tests/analysis/decks/`name`.
inline std::string analysis_deck(const std::string& name) {
  std::ifstream in(std::string(TETHER_SOURCE_DIR) + "/tests/analysis/decks/" + name);
  EXPECT_TRUE(in.good()) << "no deck tests/analysis/decks/" << name;
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// `text` with its first `from` replaced by `to`; a test failure when it has none.
inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "deck has no '" << from << "'";
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

}  // namespace tether::testing
