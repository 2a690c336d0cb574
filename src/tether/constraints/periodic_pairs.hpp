#pragma once
/// \file Pairing of opposite boundary nodes of a periodic cell (`*PERIODIC`):
/// pure geometry and bookkeeping, no model.

#include <Eigen/Core>
#include <span>
#include <utility>
#include <vector>

namespace tether {

/// Nodes of two sets paired by a translation.
struct PeriodicPairing {
  std::vector<std::pair<int, int>> pairs;  ///< (position in a, position in b), in the order of a
  int unpaired_a = -1;  ///< first position in a with no partner in b within the tolerance (-1: none)
  int unpaired_b = -1;  ///< first position in b that no node of a took (-1: none)
};

/// Pairs every point a_i with the point b_j closest to a_i + translation,
/// accepted when that distance is at most `tolerance`. Each b_j is taken once.
PeriodicPairing pair_by_translation(std::span<const Eigen::Vector2d> a, std::span<const Eigen::Vector2d> b,
                                    const Eigen::Vector2d& translation, double tolerance);

/// Keeps a set of node pairs independent: a pair (a, b) whose nodes are already
/// connected through earlier pairs closes a cycle, and its periodicity equation
/// u_b - u_a = H (X_b - X_a) is the sum of the equations along the path (the
/// X differences telescope), so it must not be written again. This is how the
/// corners of a cell paired along x and along y are handled.
class IndependentPairs {
 public:
  /// True when the pair connects two nodes not yet connected (and records it).
  bool add(int a, int b);

 private:
  int root(int node);
  std::vector<int> parent_;  ///< union-find forest over node indices (grown on demand)
};

}  // namespace tether
