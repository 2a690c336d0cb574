#include "tether/contact/pressure_overclosure.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace tether {

ContactPressure calculix_linear_pressure(double stiffness, double sigma_inf, double h) {
  const double eps = std::numbers::pi * sigma_inf / stiffness;
  const double x = h / eps;
  const double share = 0.5 + std::atan(x) / std::numbers::pi;
  return {stiffness * h * share, stiffness * (share + x / (std::numbers::pi * (1 + x * x)))};
}

double calculix_linear_reach(const PressureOverclosure& law, double tether_node_area) {
  const double c0 = law.reach_factor > 0 ? law.reach_factor : 1e-3;
  return c0 * std::sqrt(std::max(tether_node_area, 0.0) / 2);
}

ContactPressure contact_pressure(const PressureOverclosure& law, double h, double reach) {
  if (law.law != PressureOverclosure::Law::Linear || law.meaning != Dialect::Calculix) return contact_pressure(law, h);
  if (-h > reach) return {};  // beyond the reach: no contact element in CalculiX
  return calculix_linear_pressure(law.stiffness, law.sigma_inf, h);
}

ContactPressure contact_pressure(const PressureOverclosure& law, double h) {
  switch (law.law) {
    case PressureOverclosure::Law::Hard:
      throw std::invalid_argument("contact_pressure: HARD contact has no pressure function");
    case PressureOverclosure::Law::Linear: {
      if (law.meaning == Dialect::Calculix)
        throw std::invalid_argument("contact_pressure: CalculiX's LINEAR law needs the node's reach");
      const double x = h + law.c0;
      if (x < 0) return {};  // touching (x = 0) already has the slope K: a body resting on another is held
      return {law.stiffness * x, law.stiffness};
    }
    case PressureOverclosure::Law::Exponential: {
      if (law.meaning == Dialect::Calculix) {  // p = p0 exp(beta h), beta = ln(100) / c0: no cut-off
        const double beta = std::log(100.0) / law.c0;
        const double p = law.p0 * std::exp(beta * h);
        return {p, beta * p};
      }
      const double x = h / law.c0 + 1;  // 0 at h = -c0, 1 at h = 0
      if (x <= 0) return {};
      const double scale = law.p0 / (std::numbers::e - 1);
      const double ex = std::exp(x);
      return {scale * x * (ex - 1), scale * (ex - 1 + x * ex) / law.c0};
    }
    case PressureOverclosure::Law::Tabular: {
      const auto& t = law.table;  // (pressure, overclosure), overclosure increasing
      const std::size_t n = t.size();
      auto segment = [&](std::size_t i) {  // line through t[i], t[i+1]
        const double slope = (t[i + 1].first - t[i].first) / (t[i + 1].second - t[i].second);
        return ContactPressure{t[i].first + slope * (h - t[i].second), slope};
      };
      if (h < t.front().second || (h == t.front().second && t.front().first > 0)) {
        if (t.front().first == 0) return {};
        const ContactPressure c = segment(0);
        return c.p > 0 ? c : ContactPressure{};
      }
      for (std::size_t i = 0; i + 1 < n; ++i)
        if (h <= t[i + 1].second) return segment(i);
      return segment(n - 2);
    }
  }
  return {};
}

}  // namespace tether
