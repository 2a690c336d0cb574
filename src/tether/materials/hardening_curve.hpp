#pragma once
/// \file Piecewise-linear hardening curve y(p) of the equivalent plastic
/// strain, and the table of such curves against temperature.

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

/// The *PLASTIC table with a temperature column: one HardeningCurve per
/// temperature T_0 < T_1 < ... . At a temperature T between T_k and T_k+1
/// the values are interpolated linearly in T between the two curves, each
/// evaluated at the same p: y(p, T) = (1 - w) y_k(p) + w y_k+1(p), w = (T -
/// T_k) / (T_k+1 - T_k); constant (the first or last curve) outside [T_0,
/// T_last], as ABAQUS does. Slopes and integrals are at fixed T. One curve:
/// independent of T (the table without a temperature column).
class HardeningTable {
 public:
  /// A temperature-independent table (implicit: a curve is a one-row table).
  HardeningTable(HardeningCurve curve);  // NOLINT(google-explicit-constructor)
  /// temperatures strictly increasing [temperature], one curve each (>= 1).
  /// Throws std::invalid_argument when the sizes differ, there is no curve or
  /// the temperatures do not increase strictly.
  HardeningTable(std::vector<double> temperatures, std::vector<HardeningCurve> curves);

  /// y(p, T) [stress].
  [[nodiscard]] double value(double p, double T) const;
  /// dy/dp at fixed T [stress] (HardeningCurve::slope of each curve).
  [[nodiscard]] double slope(double p, double T) const;
  /// Integral of y(., T) over [a, b], 0 <= a <= b [stress].
  [[nodiscard]] double integral(double a, double b, double T) const;
  /// y(0, T) [stress].
  [[nodiscard]] double initial(double T) const { return value(0, T); }
  [[nodiscard]] bool depends_on_temperature() const { return curves_.size() > 1; }
  [[nodiscard]] int n_temperatures() const { return static_cast<int>(curves_.size()); }
  /// Table rows over all temperatures.
  [[nodiscard]] int n_points() const;

 private:
  /// The bracketing curves k, k+1 and the weight w of k+1 (k+1 = k, w = 0 outside the range).
  struct Bracket {
    int k;
    double w;
  };
  [[nodiscard]] Bracket bracket(double T) const;
  template <class F>
  [[nodiscard]] double mix(double T, F&& f) const;

  std::vector<double> t_;
  std::vector<HardeningCurve> curves_;
};

}  // namespace tether
