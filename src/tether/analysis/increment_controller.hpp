#pragma once
/// \file The time stepping of one step: increment sizes, cut-back and growth.
///
/// Pure bookkeeping, no solver: the controller proposes the next increment
/// (clamped to the end of the step, a last sliver snapped onto it), and the
/// procedure's outcome is fed back: accept() after a converged increment
/// (growth by the controls' factor after two easy increments in a row, unless
/// the increments are fixed), cut_back() after a failed attempt (by the
/// controls' factor, refused with fixed increments, after too many cut-backs
/// in a row, or below the minimum size). Shared by every procedure; its state
/// between increments is part of the restart state. See docs/theory/procedures.md.

#include <limits>
#include <string>
#include <vector>

#include "tether/model/model.hpp"
#include "tether/model/restart_state.hpp"

namespace tether {

/// A time for messages: 6 significant digits ("0.125", "1e-05").
std::string format_time(double t);

/// The times of one increment attempt, at its end.
struct IncrementTimes {
  double step_time = 0;   ///< step time at the end of the increment
  double total_time = 0;  ///< total time at the end of the increment
  double dt = 0;          ///< increment size
  double period = 1;      ///< the step's time period (loads ramp over it)
  bool ends_step = false; ///< the increment reaches the end of the step
};

class IncrementController {
 public:
  /// Why cut_back() ended the step, or Retry.
  enum class CutBack { Retry, FixedIncrements, TooManyCutBacks, BelowMinimum };

  /// The time stepping of `step` (period, initial/minimum/maximum increment,
  /// INC=, DIRECT, the controls' cut-back and growth) starting at total time
  /// `step_start_time`. A period of 0 counts as 1; an initial increment of 0
  /// is the whole period; the default minimum is 1e-5 of the period (or the
  /// initial increment when smaller); the default maximum is the period.
  IncrementController(const Step& step, double step_start_time);

  /// The step time has reached the end of the period (to a relative 1e-12).
  [[nodiscard]] bool finished() const;
  /// INC= converged increments have been made in this step.
  [[nodiscard]] bool out_of_increments() const { return increment_ >= max_increments_; }

  /// The next attempt: the increment is clamped to the end of the step, and
  /// taken to the end when less than 1e-9 of the period would be left after
  /// it; likewise it ends on the next time point (the step's time_points,
  /// and the marks of its TIME MARKS=YES output requests) without changing
  /// the increment size that growth and cut-back start from.
  [[nodiscard]] IncrementTimes next_attempt();
  /// The attempt `t` (from next_attempt()) converged in `iterations` Newton
  /// iterations: the step time moves to its end. With `scale` > 0 (the
  /// procedure's error estimate, e.g. HAFTOL's) the next increment is this
  /// one times `scale`, at most the growth factor, within [min, max];
  /// otherwise, after two easy increments in a row (at most the controls'
  /// easy_iterations) it grows by the growth factor, up to the maximum
  /// (never with fixed increments).
  void accept(const IncrementTimes& t, int iterations, double scale = 0);
  /// The attempt failed: shrinks the increment by `scale` when 0 < scale < 1
  /// (the procedure's estimate), else by the cut-back factor, or says why
  /// the step cannot go on. The increment is not changed for
  /// FixedIncrements and TooManyCutBacks; for BelowMinimum it has been cut.
  CutBack cut_back(double scale = 0);
  /// How a cut-back that ended the step reads after the solver's message:
  /// " with fixed increments (*STATIC, DIRECT)" (`keyword` names the
  /// procedure), " after 5 cut-backs", "; the increment would fall below the minimum 1e-05".
  [[nodiscard]] std::string stop_reason(CutBack why, const std::string& keyword) const;

  [[nodiscard]] double period() const { return period_; }
  [[nodiscard]] double step_time() const { return step_time_; }
  [[nodiscard]] double step_start_time() const { return step_start_time_; }
  [[nodiscard]] double dt() const { return dt_; }
  [[nodiscard]] double min_dt() const { return min_dt_; }
  [[nodiscard]] double max_dt() const { return max_dt_; }
  [[nodiscard]] int max_increments() const { return max_increments_; }
  /// Converged increments in this step.
  [[nodiscard]] int increment() const { return increment_; }
  /// Attempt of the next increment: 1, then 2, 3, ... after cut-backs.
  [[nodiscard]] int attempt() const { return attempt_; }
  [[nodiscard]] int easy_in_row() const { return easy_in_row_; }

  /// Restart: writes the position in the step (increment, step time, step
  /// start time) and the time stepping (dt, easy_in_row) into `state`.
  void save(RestartState& state) const;
  /// Continues from a state save() wrote in the same step (the minimum
  /// increment stays the one this step defines).
  void restore(const RestartState& state);

 private:
  double period_, max_dt_, dt_, min_dt_;
  int max_increments_;
  bool direct_;
  Controls controls_;
  double step_start_time_;
  std::vector<double> time_points_;  ///< step times increments end on (sorted)
  /// The size of the attempt under way (dt_, or shortened to a time point); infinite before one.
  double attempt_dt_ = std::numeric_limits<double>::infinity();
  double step_time_ = 0;
  int increment_ = 0, attempt_ = 1, easy_in_row_ = 0;
};

}  // namespace tether
