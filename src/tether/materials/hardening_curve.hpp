#pragma once
/// \file Piecewise-linear hardening curve y(p) of the equivalent plastic strain.

#include <vector>

namespace tether {

/// A piecewise-linear function of the equivalent plastic strain p >= 0,
/// through the points (p_i, y_i) and constant beyond the last one (perfect
/// plasticity there, as ABAQUS extends a *PLASTIC table). One point: constant.
class HardeningCurve {
 public:
  /// plastic_strain: p_0 = 0 < p_1 < ... [-]; values: y_i, same size >= 1
  /// [stress]. Throws std::invalid_argument when the sizes differ, the table
  /// is empty, p_0 != 0 or the p_i do not increase strictly.
  HardeningCurve(std::vector<double> plastic_strain, std::vector<double> values);

  /// y(p) [stress]; p < 0 is treated as 0.
  [[nodiscard]] double value(double p) const;
  /// dy/dp of the segment p lies in [stress]; at a table point, the slope of
  /// the segment that starts there (0 beyond the last point).
  [[nodiscard]] double slope(double p) const;
  /// Integral of y over [a, b], 0 <= a <= b, exact [stress].
  [[nodiscard]] double integral(double a, double b) const;
  /// y(0) [stress].
  [[nodiscard]] double initial() const { return y_.front(); }
  [[nodiscard]] int n_points() const { return static_cast<int>(p_.size()); }

 private:
  /// Index i of the segment [p_i, p_i+1) holding p; n_points() - 1 beyond the end.
  [[nodiscard]] int segment(double p) const;

  std::vector<double> p_, y_;
};

}  // namespace tether
