#include "tether/analysis/convergence.hpp"

#include <cmath>

namespace tether {

namespace {
/// |f| allowed at convergence on multiplier rows, relative to the model size.
constexpr double kConstraintTolerance = 1e-10;
}  // namespace

ConvergenceCriteria::ConvergenceCriteria(const Controls& controls, double length_scale)
    : controls_(controls), length_scale_(length_scale) {}

double ConvergenceCriteria::force_tolerance(double force_scale) const {
  if (force_scale <= controls_.zero_force_tolerance) return controls_.zero_force_tolerance;
  return controls_.residual_tolerance * force_scale;
}

bool ConvergenceCriteria::converged(const IterationNorms& n, int iteration, double force_scale) const {
  if (!std::isfinite(n.force_residual) || !std::isfinite(n.multiplier_residual)) return false;
  const double floor = 1e-12 * length_scale_;
  // Constraint rows (f - eps*lambda) must hold to round-off: quadratic
  // convergence gets there in at most one more iteration.
  if (n.multiplier_residual > kConstraintTolerance * length_scale_) return false;

  const bool zero_load = force_scale <= controls_.zero_force_tolerance;
  if (zero_load) return n.force_residual <= controls_.zero_force_tolerance && (iteration > 0 || n.increment == 0);

  // A residual at round-off level: the increment is linear, accept it. Not
  // at the predictor (iteration 0) unless it also meets the tolerance: an
  // extrapolated state may be that close without being round-off, and a
  // tolerance below 1e-8 asks for more. (After a solve the rule stays as it
  // was: a tolerance below round-off would otherwise never be met.)
  if (n.force_residual <= 1e-8 * force_scale &&
      (iteration > 0 || n.force_residual <= controls_.residual_tolerance * force_scale))
    return true;
  if (iteration == 0) return false;
  if (n.force_residual > controls_.residual_tolerance * force_scale) return false;

  const double allowed = controls_.correction_tolerance * n.increment + floor;
  if (n.correction <= allowed) return true;
  // Estimate of the next correction from the residual reduction (ABAQUS does
  // the same). It needs two corrections: after the first, the "previous"
  // residual is that of the new load, and the ratio says nothing about the rate.
  if (iteration >= 2 && n.previous_force_residual > 0) {
    const double ratio = n.force_residual / n.previous_force_residual;
    if (ratio < 1 && n.correction * ratio <= allowed) return true;
  }
  return false;
}

}  // namespace tether
