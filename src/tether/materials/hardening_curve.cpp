#include "tether/materials/hardening_curve.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace tether {

HardeningCurve::HardeningCurve(std::vector<double> plastic_strain, std::vector<double> values)
    : p_(std::move(plastic_strain)), y_(std::move(values)) {
  if (p_.empty() || p_.size() != y_.size()) throw std::invalid_argument("hardening curve: empty or unequal columns");
  if (p_.front() != 0) throw std::invalid_argument("hardening curve: the first plastic strain must be 0");
  for (std::size_t i = 1; i < p_.size(); ++i)
    if (!(p_[i] > p_[i - 1]))
      throw std::invalid_argument("hardening curve: plastic strain not strictly increasing at row " +
                                  std::to_string(i + 1));
}

int HardeningCurve::segment(double p) const {
  // upper_bound: first point > p; the segment starts one before it.
  const auto it = std::upper_bound(p_.begin(), p_.end(), p);
  return std::max(0, static_cast<int>(it - p_.begin()) - 1);
}

double HardeningCurve::value(double p) const {
  const int i = segment(p);
  if (i + 1 >= n_points()) return y_.back();
  const double t = (std::max(p, 0.0) - p_[i]) / (p_[i + 1] - p_[i]);
  return y_[i] + t * (y_[i + 1] - y_[i]);
}

double HardeningCurve::slope(double p) const {
  const int i = segment(p);
  if (i + 1 >= n_points()) return 0;
  return (y_[i + 1] - y_[i]) / (p_[i + 1] - p_[i]);
}

double HardeningCurve::integral(double a, double b) const {
  // Trapezoids between a, the table points inside (a, b), and b.
  double total = 0, x = a, y = value(a);
  for (int i = segment(a) + 1; i < n_points() && p_[i] < b; ++i) {
    total += 0.5 * (y + y_[i]) * (p_[i] - x);
    x = p_[i];
    y = y_[i];
  }
  return total + 0.5 * (y + value(b)) * (b - x);
}

HardeningTable::HardeningTable(HardeningCurve curve) : t_{0.0} { curves_.push_back(std::move(curve)); }

HardeningTable::HardeningTable(std::vector<double> temperatures, std::vector<HardeningCurve> curves)
    : t_(std::move(temperatures)), curves_(std::move(curves)) {
  if (curves_.empty() || t_.size() != curves_.size())
    throw std::invalid_argument("hardening table: no curve, or not one temperature per curve");
  for (std::size_t i = 1; i < t_.size(); ++i)
    if (!(t_[i] > t_[i - 1]))
      throw std::invalid_argument("hardening table: temperature not strictly increasing at curve " +
                                  std::to_string(i + 1));
}

HardeningTable::Bracket HardeningTable::bracket(double T) const {
  const int n = n_temperatures();
  if (n == 1 || !(T > t_.front())) return {0, 0.0};  // below the range (and NaN): the first curve
  if (T >= t_.back()) return {n - 1, 0.0};
  const int k = static_cast<int>(std::upper_bound(t_.begin(), t_.end(), T) - t_.begin()) - 1;
  return {k, (T - t_[k]) / (t_[k + 1] - t_[k])};
}

template <class F>
double HardeningTable::mix(double T, F&& f) const {
  const Bracket b = bracket(T);
  const double lower = f(curves_[b.k]);
  if (b.w == 0) return lower;
  return (1 - b.w) * lower + b.w * f(curves_[b.k + 1]);
}

double HardeningTable::value(double p, double T) const {
  return mix(T, [p](const HardeningCurve& c) { return c.value(p); });
}

double HardeningTable::slope(double p, double T) const {
  return mix(T, [p](const HardeningCurve& c) { return c.slope(p); });
}

double HardeningTable::integral(double a, double b, double T) const {
  return mix(T, [a, b](const HardeningCurve& c) { return c.integral(a, b); });
}

int HardeningTable::n_points() const {
  int n = 0;
  for (const HardeningCurve& c : curves_) n += c.n_points();
  return n;
}

}  // namespace tether
