#include "tether/constraints/periodic_pairs.hpp"

#include <limits>

namespace tether {

PeriodicPairing pair_by_translation(std::span<const Eigen::Vector2d> a, std::span<const Eigen::Vector2d> b,
                                    const Eigen::Vector2d& translation, double tolerance) {
  PeriodicPairing out;
  std::vector<bool> taken(b.size(), false);
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Eigen::Vector2d target = a[i] + translation;
    int best = -1;
    double best_distance = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < b.size(); ++j) {
      const double d = (b[j] - target).norm();
      if (!taken[j] && d < best_distance) best_distance = d, best = static_cast<int>(j);
    }
    if (best < 0 || best_distance > tolerance) {
      out.unpaired_a = static_cast<int>(i);
      return out;
    }
    taken[static_cast<std::size_t>(best)] = true;
    out.pairs.emplace_back(static_cast<int>(i), best);
  }
  for (std::size_t j = 0; j < b.size(); ++j)
    if (!taken[j]) {
      out.unpaired_b = static_cast<int>(j);
      break;
    }
  return out;
}

int IndependentPairs::root(int node) {
  if (node >= static_cast<int>(parent_.size())) {
    const int old = static_cast<int>(parent_.size());
    parent_.resize(static_cast<std::size_t>(node) + 1);
    for (int k = old; k <= node; ++k) parent_[static_cast<std::size_t>(k)] = k;
  }
  while (parent_[static_cast<std::size_t>(node)] != node) {
    int& p = parent_[static_cast<std::size_t>(node)];
    p = parent_[static_cast<std::size_t>(p)];  // path halving
    node = p;
  }
  return node;
}

bool IndependentPairs::add(int a, int b) {
  const int ra = root(a), rb = root(b);
  if (ra == rb) return false;
  parent_[static_cast<std::size_t>(ra)] = rb;
  return true;
}

}  // namespace tether
