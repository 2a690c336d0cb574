#include "tether/output/output_schedule.hpp"

#include <algorithm>
#include <cmath>

namespace tether {

namespace {

/// Marks of equal intervals of `length` [time] within a period: the i-th at
/// i * length, i = 1, 2, ... while it lies before the end (1e-9 relative).
long interval_count(double length, double period) {
  return std::max(1L, static_cast<long>(std::ceil(period / length * (1 - 1e-9))));
}

/// The time of mark i of the request's intervals (NUMBER or TIME INTERVAL).
double mark_time(const OutputRequest& r, long i, double period) {
  return r.number_interval > 0 ? period * static_cast<double>(i) / r.number_interval : r.time_interval * static_cast<double>(i);
}

long mark_count(const OutputRequest& r, double period) {
  return r.number_interval > 0 ? r.number_interval : interval_count(r.time_interval, period);
}

bool has_intervals(const OutputRequest& r) { return r.number_interval > 0 || r.time_interval > 0; }

/// Explicit: mark i rounded to the nominal explicit increments.
long explicit_mark(const OutputRequest& r, long i, long total, double period) {
  return std::min(total, static_cast<long>(std::llround(mark_time(r, i, period) / period * static_cast<double>(total))));
}

bool explicit_due(const OutputRequest& r, const IncrementResults::ExplicitSpan& span, double period) {
  if (span.end >= span.total) return true;
  if (!has_intervals(r)) return span.end / r.frequency > span.start / r.frequency;
  const long n = mark_count(r, period);
  const double per = static_cast<double>(n) / static_cast<double>(span.total);
  const long first = std::max(1L, static_cast<long>(std::floor(static_cast<double>(span.start) * per)) - 1);
  for (long i = first; i <= n; ++i) {
    const long k = explicit_mark(r, i, span.total, period);
    if (k > span.end) break;
    if (k > span.start) return true;
  }
  return false;
}

}  // namespace

bool is_due(const OutputRequest& request, const IncrementResults& results, bool last_in_step) {
  if (!has_intervals(request) && request.frequency <= 0) return false;
  if (last_in_step) return true;
  if (results.explicit_span) return explicit_due(request, *results.explicit_span, results.period);
  if (!has_intervals(request)) return results.increment % request.frequency == 0;
  // The increment ending at or after a mark writes it: a mark in (start, end].
  const double tolerance = 1e-9 * results.period;
  const double length = mark_time(request, 1, results.period);
  const auto marks_before = [&](double t) { return static_cast<long>(std::floor((t + tolerance) / length)); };
  return marks_before(results.step_time) > marks_before(results.step_time - results.increment_size);
}

std::vector<long> explicit_marks(const OutputRequest& request, long total, double period) {
  std::vector<long> marks;
  if (!has_intervals(request)) {
    if (request.frequency <= 0) return marks;
    for (long k = request.frequency; k < total; k += request.frequency) marks.push_back(k);
  } else {
    const long n = mark_count(request, period);
    for (long i = 1; i <= n; ++i)
      if (const long k = explicit_mark(request, i, total, period); k > 0) marks.push_back(k);
  }
  marks.push_back(total);
  std::sort(marks.begin(), marks.end());
  marks.erase(std::unique(marks.begin(), marks.end()), marks.end());
  return marks;
}

std::vector<double> time_mark_points(const Step& step) {
  const double period = step.period > 0 ? step.period : 1;
  std::vector<double> points;
  for (const OutputRequest& r : step.outputs) {
    if (!r.time_marks || !has_intervals(r)) continue;
    const long n = mark_count(r, period);
    for (long i = 1; i <= n; ++i)
      if (const double t = mark_time(r, i, period); t < period * (1 - 1e-9)) points.push_back(t);
  }
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end(),
                           [period](double a, double b) { return std::abs(a - b) <= 1e-12 * period; }),
               points.end());
  return points;
}

bool is_file_request(const OutputRequest& request) {
  using K = OutputRequest::Kind;
  return request.kind == K::NodeFile || request.kind == K::ElementFile || request.kind == K::ContactFile;
}

OutputRequest default_file_request(StepProcedure procedure) {
  OutputRequest r;
  r.kind = OutputRequest::Kind::NodeFile;
  if (procedure == StepProcedure::ExplicitDynamic) r.number_interval = kExplicitDefaultIntervals;
  if (procedure == StepProcedure::ImplicitDynamic) r.frequency = kImplicitDynamicDefaultFrequency;
  return r;
}

StepProcedure procedure_of(const IncrementResults& results) {
  if (results.explicit_span) return StepProcedure::ExplicitDynamic;
  return results.energy ? StepProcedure::ImplicitDynamic : StepProcedure::Static;
}

bool files_due(const std::vector<OutputRequest>& requests, StepProcedure procedure, const IncrementResults& results,
               bool last_in_step) {
  if (std::none_of(requests.begin(), requests.end(), is_file_request))
    return is_due(default_file_request(procedure), results, last_in_step);
  return std::any_of(requests.begin(), requests.end(), [&](const OutputRequest& r) {
    return is_file_request(r) && is_due(r, results, last_in_step);
  });
}

}  // namespace tether
