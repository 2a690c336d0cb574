#pragma once
/// \file Evaluation of `*AMPLITUDE` tables and of load/boundary magnitudes over a step.

#include "tether/model/model.hpp"

namespace tether {

/// Value of a tabular amplitude at the given times (piecewise linear, constant
/// beyond the first and last points). Uses step or total time as the amplitude asks.
double amplitude_value(const Amplitude& amplitude, double step_time, double total_time);

/// Magnitude of a load or prescribed value during a step: `target * a(t)` when
/// an amplitude is given, else a linear ramp from `start` (its value at the end
/// of the previous step) to `target` over the step period (ABAQUS's default for
/// static steps).
double step_magnitude(const Model& model, int amplitude, double start, double target, double step_time,
                      double period, double total_time);

/// Integral of a tabular amplitude over step times [from, to] (exact for the
/// piecewise linear table, constant beyond its ends); `step_start_total` is
/// the total time at the step's start, for TIME=TOTAL TIME amplitudes [time].
double amplitude_integral(const Amplitude& amplitude, double from, double to, double step_start_total);

/// Integral of step_magnitude() over step times [0, step_time] [magnitude * time].
double step_magnitude_integral(const Model& model, int amplitude, double start, double target, double step_time,
                               double period, double total_time);

}  // namespace tether
