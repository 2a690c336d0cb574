#pragma once
/// \file When an output request is due.
///
/// A request writes at every FREQUENCY-th increment, at the ends of NUMBER
/// INTERVAL equal intervals of the step, or at the multiples of TIME
/// INTERVAL, and always at the last increment of the step. In static and
/// implicit dynamic steps the increment that ends at or after a mark writes
/// (increments end on the marks with TIME MARKS=YES). In explicit steps
/// FREQUENCY counts explicit increments, as ABAQUS/Explicit and CalculiX
/// count them, and the marks are rounded to the step's nominal explicit
/// increments, at which the procedure ends a report (explicit_marks()).

#include <vector>

#include "tether/model/model.hpp"
#include "tether/model/results.hpp"

namespace tether {

/// The equal intervals of an explicit step's requests written without a
/// schedule (abaqus dialect), as ABAQUS/Explicit's default output: 20 for
/// field output (the result files), 200 for history output (the .dat).
inline constexpr int kExplicitDefaultIntervals = 20;
inline constexpr int kExplicitDefaultHistoryIntervals = 200;
/// ABAQUS/Standard's default output of dynamic steps: every 10th increment.
inline constexpr int kImplicitDynamicDefaultFrequency = 10;

/// True when `request` writes the increment of `results` (its increment,
/// step time, increment size, period and, in explicit steps, its span of
/// explicit increments): never when FREQUENCY is 0 (and no interval is given).
bool is_due(const OutputRequest& request, const IncrementResults& results, bool last_in_step);

/// The explicit increments (1-based counts from the step's start, in
/// increments of period / total) at which `request` writes in an explicit
/// step of `total` nominal increments, the last one (`total`) included
/// unless the request never writes. Sorted and unique.
std::vector<long> explicit_marks(const OutputRequest& request, long total, double period);

/// The step times at which static and implicit increments must end for the
/// TIME MARKS=YES requests of `step` (sorted, unique, within (0, period)).
std::vector<double> time_mark_points(const Step& step);

/// A request for the result files (*NODE FILE, *EL FILE, *CONTACT FILE, *OUTPUT, FIELD).
bool is_file_request(const OutputRequest& request);

/// The request the result files follow when a step has none of its own, as
/// ABAQUS's default output: every increment of a static step, every 10th of
/// an implicit dynamic one, 20 equal intervals of an explicit one.
OutputRequest default_file_request(StepProcedure procedure);

/// The procedure whose step produced `results` (explicit reports carry
/// their span, dynamic increments their energies).
StepProcedure procedure_of(const IncrementResults& results);

/// True when the result files (a `.vtu` and its `.pvd` entry) are written
/// for the increment of `results` in a step of `procedure` with `requests`:
/// when one of its file requests is due, or, without any, when
/// default_file_request(procedure) is. The only output that reads the
/// element fields (nodal averages, element means) of IncrementResults.
bool files_due(const std::vector<OutputRequest>& requests, StepProcedure procedure, const IncrementResults& results,
               bool last_in_step);

}  // namespace tether
