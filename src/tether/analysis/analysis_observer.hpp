#pragma once
/// \file What the analysis reports while it runs: increments, results, messages.

#include <string>

#include "tether/analysis/convergence.hpp"
#include "tether/model/model.hpp"
#include "tether/model/restart_state.hpp"
#include "tether/model/results.hpp"

namespace tether {

/// One line of the status log (an attempt of an increment).
struct IncrementReport {
  int step = 1;             ///< 1-based
  int increment = 1;        ///< 1-based, counts converged increments in the step (+1 for the attempt)
  int attempt = 1;          ///< 1 = first try; > 1 after cut-backs
  int iterations = 0;       ///< Newton iterations (linear solves) of this attempt
  int total_iterations = 0; ///< over the whole analysis so far
  double step_time = 0;     ///< at the end of the increment
  double total_time = 0;
  double increment_size = 0;
  double residual = 0;      ///< final max force residual
  bool converged = false;
  std::string note;         ///< why an attempt failed
};

/// Receives the analysis' progress. All methods have empty defaults.
class AnalysisObserver {
 public:
  virtual ~AnalysisObserver() = default;
  /// After each Newton iteration: `iteration` counts the solves done so far
  /// (0 = the residual of the starting state).
  virtual void on_iteration(int /*iteration*/, const IterationNorms& /*norms*/) {}
  /// After each attempt (converged or cut back).
  virtual void on_increment(const IncrementReport& /*report*/) {}
  /// After each converged increment, with its results. `last_in_step` is true for the final one.
  virtual void on_results(const IncrementResults& /*results*/, const Step& /*step*/, bool /*last_in_step*/) {}
  /// A restart point (`*RESTART, WRITE`): after every FREQUENCY-th converged
  /// increment of a step (after on_results) and at the end of every step. The
  /// state continues the analysis through StaticAnalysis::resume().
  virtual void on_restart_state(const RestartState& /*state*/) {}
  /// A line of information or warning for the log.
  virtual void on_message(const std::string& /*message*/) {}
};

}  // namespace tether
