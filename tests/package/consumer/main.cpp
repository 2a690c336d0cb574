// Reads a deck given on the command line, solves it and prints the largest displacement.
#include <cstdio>

#include "tether/analysis/static_analysis.hpp"
#include "tether/io/deck_reader.hpp"

int main(int argc, char** argv) {
  if (argc != 2) return 1;
  const tether::Model model = tether::read_deck(argv[1]);
  tether::AnalysisObserver quiet;
  tether::StaticAnalysis analysis(model, quiet);
  const tether::AnalysisSummary summary = analysis.run();
  std::printf("%s: max |u| = %.6e\n", summary.message.c_str(), analysis.solution().cwiseAbs().maxCoeff());
  return summary.completed ? 0 : 2;
}
