#include "tether/analysis/increment_controller.hpp"

#include <algorithm>
#include <limits>
#include <sstream>

#include "tether/output/output_schedule.hpp"

namespace tether {

std::string format_time(double t) {
  std::ostringstream s;
  s.precision(6);
  s << t;
  return s.str();
}

IncrementController::IncrementController(const Step& step, double step_start_time)
    : period_(step.period > 0 ? step.period : 1.0),
      max_dt_(step.max_increment > 0 ? step.max_increment : period_),
      dt_(std::min(step.initial_increment > 0 ? step.initial_increment : period_, max_dt_)),
      min_dt_(step.min_increment > 0 ? step.min_increment : std::min(1e-5 * period_, dt_)),
      max_increments_(step.max_increments),
      direct_(step.direct),
      controls_(step.controls),
      step_start_time_(step_start_time) {
  // A dynamic step's increment is chosen for accuracy, not for Newton's ease:
  // without an error estimate (HAFTOL) it never grows past the initial one.
  if (step.procedure == StepProcedure::ImplicitDynamic && step.dynamic.half_increment_tolerance == 0)
    max_dt_ = std::min(max_dt_, dt_);
  time_points_ = step.time_points;
  if (step.procedure != StepProcedure::ExplicitDynamic) {  // explicit steps put their marks in time_points
    const std::vector<double> marks = time_mark_points(step);
    time_points_.insert(time_points_.end(), marks.begin(), marks.end());
  }
  std::sort(time_points_.begin(), time_points_.end());
}

bool IncrementController::finished() const { return step_time_ >= period_ * (1 - 1e-12); }

IncrementTimes IncrementController::next_attempt() {
  dt_ = std::min(dt_, period_ - step_time_);
  if (period_ - step_time_ - dt_ < 1e-9 * period_) dt_ = period_ - step_time_;
  double dt = dt_;
  // An increment reaching past the next time point (or within 1e-9 of the period short of it) ends on it.
  const auto next = std::upper_bound(time_points_.begin(), time_points_.end(), step_time_ + 1e-9 * period_);
  if (next != time_points_.end() && step_time_ + dt > *next - 1e-9 * period_) dt = *next - step_time_;
  attempt_dt_ = dt;
  const double t_new = step_time_ + dt;
  return IncrementTimes{t_new, step_start_time_ + t_new, dt, period_, t_new >= period_ * (1 - 1e-12)};
}

void IncrementController::accept(const IncrementTimes& t, int iterations, double scale) {
  attempt_dt_ = std::numeric_limits<double>::infinity();
  step_time_ = t.step_time;
  ++increment_;
  attempt_ = 1;
  if (direct_) return;
  if (scale > 0) {  // the procedure's error estimate decides, within the growth factor and the bounds
    dt_ = std::clamp(dt_ * std::min(scale, controls_.growth_factor), min_dt_, max_dt_);
    easy_in_row_ = 0;
    return;
  }
  easy_in_row_ = iterations <= controls_.easy_iterations ? easy_in_row_ + 1 : 0;
  if (easy_in_row_ >= 2) {
    dt_ = std::min(dt_ * controls_.growth_factor, max_dt_);
    easy_in_row_ = 0;
  }
}

IncrementController::CutBack IncrementController::cut_back(double scale) {
  if (direct_) return CutBack::FixedIncrements;
  if (attempt_ > controls_.max_cutbacks) return CutBack::TooManyCutBacks;
  dt_ = std::min(dt_, attempt_dt_) * (scale > 0 && scale < 1 ? scale : controls_.cutback_factor);
  easy_in_row_ = 0;
  ++attempt_;
  if (dt_ < min_dt_ * (1 - 1e-12)) return CutBack::BelowMinimum;
  return CutBack::Retry;
}

std::string IncrementController::stop_reason(CutBack why, const std::string& keyword) const {
  switch (why) {
    case CutBack::FixedIncrements:
      return " with fixed increments (" + keyword + ", DIRECT)";
    case CutBack::TooManyCutBacks:
      return " after " + std::to_string(controls_.max_cutbacks) + " cut-backs";
    case CutBack::BelowMinimum:
      return "; the increment would fall below the minimum " + format_time(min_dt_);
    case CutBack::Retry:
      break;
  }
  return "";
}

void IncrementController::save(RestartState& state) const {
  state.increment = increment_;
  state.step_time = step_time_;
  state.step_start_time = step_start_time_;
  state.dt = dt_;
  state.easy_in_row = easy_in_row_;
}

void IncrementController::restore(const RestartState& state) {
  step_time_ = state.step_time;
  step_start_time_ = state.step_start_time;
  increment_ = state.increment;
  dt_ = state.dt;
  easy_in_row_ = state.easy_in_row;
}

}  // namespace tether
