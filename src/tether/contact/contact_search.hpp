#pragma once
/// \file Contact search of 2D node-to-segment contact: pairs each slave point
/// with its closest master segment. Broad phase: a uniform grid of bins over
/// the segments' bounding boxes inflated by the search radius, stored sparsely
/// (only occupied bins, sorted); narrow phase: project() of
/// segment_geometry.hpp. Pure functions of current positions; no assembly.
/// Rules (hand-over, convex and concave corners) and costs:
/// docs/theory/contact_geometry.md, section "Search".

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "tether/contact/segment_geometry.hpp"

namespace tether {

/// Topology of a master surface: its segments (faces) and, at each corner
/// node, the other segments sharing that node. Built once; positions are
/// passed to the search.
class MasterSurface {
 public:
  /// `faces[s]` holds the 2 or 3 global node indices of segment s in
  /// face_nodes() order (corners first, counter-clockwise around the master
  /// element, mid-side node last). Throws std::invalid_argument on another
  /// node count or a negative node index.
  explicit MasterSurface(std::span<const std::vector<int>> faces);

  int n_segments() const { return static_cast<int>(n_nodes_.size()); }
  /// Global node indices of segment s (2 or 3 of them).
  std::span<const int> segment_nodes(int s) const { return {nodes_[s].data(), static_cast<std::size_t>(n_nodes_[s])}; }
  /// Segments other than s sharing corner `corner` (0: ξ = -1, 1: ξ = +1) of
  /// segment s, ascending. One entry on a manifold curve, none at an open
  /// end, several at a non-manifold node.
  std::span<const int> neighbours(int s, int corner) const;
  /// Largest global node index + 1: positions passed to the search must hold at least this many.
  int n_nodes_required() const { return n_nodes_required_; }

 private:
  std::vector<std::array<int, 3>> nodes_;
  std::vector<int> n_nodes_;
  std::vector<int> neighbour_offsets_;  ///< CSR over (segment, corner) = 2 s + corner
  std::vector<int> neighbour_list_;
  int n_nodes_required_ = 0;
};

/// Controls of the search.
struct SearchOptions {
  /// Segments farther than this from a slave point are not candidates [length].
  /// Must be > 0; typically a few master element sizes (the broad-phase cost
  /// per slave grows with the number of segments within this radius).
  double search_radius = 0;
  /// SMALL SLIDING: a slave point with a previous pairing keeps its segment,
  /// whatever ξ* becomes (projection on the extended segment, no radius test);
  /// a slave without one stays unpaired. Only the first search (no previous
  /// pairings passed) pairs.
  bool keep_pairing = false;
  ProjectionOptions projection;
};

/// Pairing of one slave point.
struct ContactPairing {
  int segment = -1;     ///< paired segment index; -1: no candidate within the search radius
  double xi = 0;        ///< ξ* on that segment (the end, ±1, for a corner pairing)
  double gap = 0;       ///< signed normal gap [length], > 0 open (segment_geometry convention)
  double distance = 0;  ///< |y_s - y(ξ)| [length]
  /// The closest point of the surface is a segment end that no candidate
  /// contains in its interior (slave in the shadow of a convex corner, or
  /// beyond an open end): the normal is not defined there; xi is the end,
  /// gap = ±distance with the sign of (y_s - y_end)·n_end of the chosen segment.
  bool at_corner = false;
  bool found() const { return segment >= 0; }
};

/// Work counters of a search (for cost checks; counting, not timing).
struct SearchStatistics {
  std::int64_t n_slaves = 0;
  std::int64_t n_projections = 0;     ///< narrow-phase project() calls
  std::int64_t n_broad_phase = 0;     ///< slaves that needed the bins
  std::int64_t n_local = 0;           ///< slaves re-paired from previous segment + neighbours alone
  std::int64_t n_bins = 0;            ///< occupied bins of the last broad phase built (0 if not built)
};

/// Pairs each slave point with its closest master segment.
///
/// `positions`: current coordinates of all nodes, indexed by global node index
/// (size ≥ surface.n_nodes_required()). `slaves`: current slave points.
/// `previous`: empty for a full search, or one pairing per slave (the last
/// pairing) for the incremental update used during Newton: a walk from the
/// previous segment — it and its neighbours are projected, and while the
/// chosen segment has a neighbour not yet projected, that neighbour's
/// neighbours are added (at most 3 steps); the result is kept when the chosen
/// segment's neighbours were all candidates, otherwise (nothing within the
/// radius, or the walk did not close) the slave goes through the broad phase.
/// The walk cannot see a distant part of the surface that became closer: run a
/// full search (empty `previous`) at least once per increment. The bins are
/// built only if some slave needs them (cost O(n log n), n segments).
/// Selection rule (section "Search" of the theory page): the closest point
/// over all candidates within the radius; if some segment contains it in
/// [-1,1], that segment (concave corner, or a node shared by two segments:
/// smallest distance, ties within round-off by smallest segment index);
/// otherwise a corner pairing (at_corner). Deterministic: the result does not
/// depend on the order of segments in the bins; the incremental walk gives
/// the full search's answer whenever the closest point lies on the walked
/// segments.
/// Throws std::invalid_argument if search_radius ≤ 0, positions is too short,
/// previous is neither empty nor of slaves' size, or names a segment the
/// surface does not have.
std::vector<ContactPairing> find_closest(const MasterSurface& surface, std::span<const Eigen::Vector2d> positions,
                                         std::span<const Eigen::Vector2d> slaves, const SearchOptions& options,
                                         std::span<const ContactPairing> previous = {},
                                         SearchStatistics* statistics = nullptr);

}  // namespace tether
