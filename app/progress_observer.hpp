#pragma once
/// \file Prints the analysis' progress on the terminal (the files are the Job's).

#include <fmt/core.h>

#include "tether/analysis/analysis_observer.hpp"

namespace tether {

/// One line per increment attempt and the analysis' messages (cut-backs,
/// augmented-Lagrangian updates), for a terminal.
class ProgressObserver final : public AnalysisObserver {
 public:
  void on_increment(const IncrementReport& r) override {
    fmt::print("step {} inc {:4d} att {} time {:.6g} dt {:.3g} iter {:2d} residual {:.3e} {}\n", r.step, r.increment,
               r.attempt, r.total_time, r.increment_size, r.iterations, r.residual,
               r.converged ? "" : "not converged");
  }
  void on_message(const std::string& message) override { fmt::print("  {}\n", message); }
};

}  // namespace tether
