#include "tether/contact/contact_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <utility>

#include "tether/fem/shape_functions.hpp"

namespace tether {

using Eigen::Vector2d;

MasterSurface::MasterSurface(std::span<const std::vector<int>> faces) {
  nodes_.reserve(faces.size());
  n_nodes_.reserve(faces.size());
  for (std::size_t s = 0; s < faces.size(); ++s) {
    const auto& f = faces[s];
    if (f.size() != 2 && f.size() != 3) {
      throw std::invalid_argument("master segment " + std::to_string(s) + " must have 2 or 3 nodes, got " +
                                  std::to_string(f.size()));
    }
    std::array<int, 3> n{-1, -1, -1};
    for (std::size_t k = 0; k < f.size(); ++k) {
      if (f[k] < 0) throw std::invalid_argument("master segment " + std::to_string(s) + " has a negative node index");
      n[k] = f[k];
      n_nodes_required_ = std::max(n_nodes_required_, f[k] + 1);
    }
    nodes_.push_back(n);
    n_nodes_.push_back(static_cast<int>(f.size()));
  }
  // Corner node -> segments touching it (sorted pairs), then per (segment, corner) the others.
  std::vector<std::pair<int, int>> by_node;  // (corner node, segment)
  by_node.reserve(2 * nodes_.size());
  for (int s = 0; s < n_segments(); ++s) {
    by_node.emplace_back(nodes_[s][0], s);
    if (nodes_[s][1] != nodes_[s][0]) by_node.emplace_back(nodes_[s][1], s);
  }
  std::sort(by_node.begin(), by_node.end());
  by_node.erase(std::unique(by_node.begin(), by_node.end()), by_node.end());
  neighbour_offsets_.assign(2 * nodes_.size() + 1, 0);
  for (int s = 0; s < n_segments(); ++s) {
    for (int corner = 0; corner < 2; ++corner) {
      const int node = nodes_[s][corner];
      auto [lo, hi] = std::equal_range(by_node.begin(), by_node.end(), std::pair{node, 0},
                                       [](const auto& a, const auto& b) { return a.first < b.first; });
      for (auto it = lo; it != hi; ++it) {
        if (it->second != s) neighbour_list_.push_back(it->second);
      }
      neighbour_offsets_[2 * s + corner + 1] = static_cast<int>(neighbour_list_.size());
    }
  }
}

std::span<const int> MasterSurface::neighbours(int s, int corner) const {
  const int b = neighbour_offsets_[2 * s + corner], e = neighbour_offsets_[2 * s + corner + 1];
  return {neighbour_list_.data() + b, static_cast<std::size_t>(e - b)};
}

namespace {

/// Slave points below which the search runs serially (thread start-up costs more).
constexpr std::int64_t kParallelSlaves = 2048;

/// Current node positions of one segment.
struct SegmentPoints {
  std::array<Vector2d, 3> y;
  int n = 0;
  std::span<const Vector2d> span() const { return {y.data(), static_cast<std::size_t>(n)}; }
};

SegmentPoints points_of(const MasterSurface& surface, std::span<const Vector2d> positions, int s) {
  SegmentPoints p;
  const auto nodes = surface.segment_nodes(s);
  p.n = static_cast<int>(nodes.size());
  for (int k = 0; k < p.n; ++k) p.y[k] = positions[nodes[k]];
  return p;
}

/// Point y(ξ) and outward unit normal n = t × e3 of a segment at ξ.
std::pair<Vector2d, Vector2d> point_and_normal(const SegmentPoints& seg, double xi) {
  Eigen::Vector3d N, dN;
  face_shape_functions(seg.n, xi, N, dN);
  Vector2d y = Vector2d::Zero(), a = Vector2d::Zero();
  for (int k = 0; k < seg.n; ++k) {
    y += N[k] * seg.y[k];
    a += dN[k] * seg.y[k];
  }
  const double m = a.norm();
  const Vector2d n = m > 0 ? Vector2d(a.y() / m, -a.x() / m) : Vector2d::Zero();
  return {y, n};
}

/// Axis-aligned box.
struct Box {
  Vector2d lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  Vector2d hi = -lo;
  void add(const Vector2d& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  double distance(const Vector2d& p) const {  // 0 inside
    const Vector2d d = (lo - p).cwiseMax(p - hi).cwiseMax(0.0);
    return d.norm();
  }
};

/// Box containing the segment for ξ ∈ [-1,1]: for 3 nodes the convex hull of
/// the Bézier control points y1, y2, 2 y3 - (y1 + y2)/2 contains the parabola.
Box segment_box(const SegmentPoints& seg) {
  Box b;
  b.add(seg.y[0]);
  b.add(seg.y[1]);
  if (seg.n == 3) b.add(2 * seg.y[2] - 0.5 * (seg.y[0] + seg.y[1]));
  return b;
}

/// Sparse uniform grid of bins over the inflated segment boxes.
class SegmentBins {
 public:
  SegmentBins(const MasterSurface& surface, std::span<const Vector2d> positions, double radius) : radius_(radius) {
    const int n = surface.n_segments();
    boxes_.reserve(n);
    double extent_sum = 0;
    for (int s = 0; s < n; ++s) {
      boxes_.push_back(segment_box(points_of(surface, positions, s)));
      const Box& b = boxes_.back();
      const Vector2d lo = b.lo.array() - radius, hi = b.hi.array() + radius;
      all_.add(lo);
      all_.add(hi);
      extent_sum += (hi - lo).maxCoeff();
    }
    if (n == 0) return;
    // Bin size: the mean inflated extent, so that a typical segment covers
    // at most 2×2 bins; at most 2^30 bins per axis so that keys fit 64 bits.
    cell_ = extent_sum / n;
    cell_ = std::max(cell_, (all_.hi - all_.lo).maxCoeff() / double(1 << 30));
    std::vector<std::pair<std::uint64_t, int>> entries;
    entries.reserve(4 * static_cast<std::size_t>(n));
    for (int s = 0; s < n; ++s) {
      const auto [ix0, iy0] = cell_of(boxes_[s].lo.array() - radius);
      const auto [ix1, iy1] = cell_of(boxes_[s].hi.array() + radius);
      for (std::uint64_t ix = ix0; ix <= ix1; ++ix)
        for (std::uint64_t iy = iy0; iy <= iy1; ++iy) entries.emplace_back(key(ix, iy), s);
    }
    std::sort(entries.begin(), entries.end());
    for (std::size_t i = 0; i < entries.size(); ++i) {
      if (i == 0 || entries[i].first != entries[i - 1].first) {
        keys_.push_back(entries[i].first);
        offsets_.push_back(static_cast<int>(i));
      }
      segments_.push_back(entries[i].second);
    }
    offsets_.push_back(static_cast<int>(segments_.size()));
  }

  std::int64_t n_bins() const { return static_cast<std::int64_t>(keys_.size()); }

  /// Segments whose inflated box contains p, as (lower bound of the distance, segment), ascending.
  void candidates(const Vector2d& p, std::vector<std::pair<double, int>>& out) const {
    out.clear();
    if (keys_.empty() || !(p.x() >= all_.lo.x() && p.x() <= all_.hi.x() && p.y() >= all_.lo.y() && p.y() <= all_.hi.y()))
      return;
    const auto [ix, iy] = cell_of(p);
    const auto it = std::lower_bound(keys_.begin(), keys_.end(), key(ix, iy));
    if (it == keys_.end() || *it != key(ix, iy)) return;
    const std::size_t bin = static_cast<std::size_t>(it - keys_.begin());
    for (int k = offsets_[bin]; k < offsets_[bin + 1]; ++k) {
      const int s = segments_[k];
      const double lb = boxes_[s].distance(p);
      if (lb <= radius_) out.emplace_back(lb, s);
    }
    std::sort(out.begin(), out.end());
  }

 private:
  std::pair<std::uint64_t, std::uint64_t> cell_of(const Vector2d& p) const {
    const Vector2d c = ((p - all_.lo) / cell_).cwiseMax(0.0);
    return {static_cast<std::uint64_t>(c.x()), static_cast<std::uint64_t>(c.y())};
  }
  static std::uint64_t key(std::uint64_t ix, std::uint64_t iy) { return (ix << 32) | iy; }

  double radius_ = 0;
  double cell_ = 1;
  Box all_;
  std::vector<Box> boxes_;
  std::vector<std::uint64_t> keys_;  // occupied bins, ascending
  std::vector<int> offsets_;         // CSR into segments_
  std::vector<int> segments_;        // ascending within a bin
};

/// Largest number of neighbour steps of the incremental re-pairing before the broad phase.
constexpr int kMaxWalkSteps = 3;

/// One narrow-phase result.
struct Candidate {
  int segment = -1;
  SegmentProjection projection;
};

/// Tolerance under which two distances count as equal (round-off of the projection).
double tie_tolerance(const Vector2d& slave, double d_min, double radius) {
  return 1e-13 * (slave.cwiseAbs().maxCoeff() + d_min + radius);
}

/// Evaluates the candidates in the order given, skipping those whose lower
/// bound exceeds the best distance found (+ tie tolerance); then applies the
/// selection rule of the theory page.
class Selector {
 public:
  Selector(const MasterSurface& surface, std::span<const Vector2d> positions, const SearchOptions& options,
           SearchStatistics& stats)
      : surface_(surface), positions_(positions), options_(options), stats_(stats) {}

  /// Forgets the projections of the previous slave point.
  void next_slave() { cache_.clear(); }

  ContactPairing select(const Vector2d& slave, std::span<const std::pair<double, int>> ordered) {
    found_.clear();
    double d_min = std::numeric_limits<double>::infinity();
    for (const auto& [lb, s] : ordered) {
      if (lb > d_min + tie_tolerance(slave, d_min, options_.search_radius)) break;
      const SegmentProjection p = projection(slave, s);
      if (p.status == ProjectionStatus::degenerate || p.clamped_distance > options_.search_radius) continue;
      found_.push_back({s, p});
      d_min = std::min(d_min, p.clamped_distance);
    }
    ContactPairing out;
    if (found_.empty()) return out;
    const double tol = tie_tolerance(slave, d_min, options_.search_radius);
    // Closest point inside a segment: smallest distance, ties by segment index.
    const Candidate* best = nullptr;
    for (const Candidate& c : found_) {
      if (!c.projection.inside || c.projection.clamped_distance > d_min + tol) continue;
      if (!best || c.segment < best->segment) best = &c;
    }
    if (best) {
      const SegmentPoints seg = points_of(surface_, positions_, best->segment);
      const auto [y, n] = point_and_normal(seg, best->projection.xi);
      out.segment = best->segment;
      out.xi = best->projection.xi;
      out.gap = (slave - y).dot(n);
      out.distance = (slave - y).norm();
      return out;
    }
    // Corner: the closest point is a segment end. Among the segments reaching
    // it, the one whose end normal is closest to the direction corner → slave
    // (largest (y_s - y_end)·n_end / |y_s - y_end|), ties by segment index.
    double best_alignment = -std::numeric_limits<double>::infinity();
    for (const Candidate& c : found_) {
      if (c.projection.clamped_distance > d_min + tol) continue;
      const SegmentPoints seg = points_of(surface_, positions_, c.segment);
      const auto [y, n] = point_and_normal(seg, c.projection.clamped_xi);
      const Vector2d d = slave - y;
      const double dn = d.norm() > 0 ? d.dot(n) / d.norm() : 0.0;
      const bool better = !out.found() || dn > best_alignment + 1e-12 ||
                          (std::abs(dn - best_alignment) <= 1e-12 && c.segment < out.segment);
      if (!better) continue;
      best_alignment = dn;
      out.segment = c.segment;
      out.xi = c.projection.clamped_xi;
      out.distance = d.norm();
      out.gap = d.dot(n) >= 0 ? out.distance : -out.distance;
      out.at_corner = true;
    }
    return out;
  }

 private:
  /// project() of the current slave point, each segment projected once per slave.
  SegmentProjection projection(const Vector2d& slave, int s) {
    for (const Candidate& c : cache_)
      if (c.segment == s) return c.projection;
    const SegmentPoints seg = points_of(surface_, positions_, s);
    cache_.push_back({s, project(slave, seg.span(), options_.projection)});
    ++stats_.n_projections;
    return cache_.back().projection;
  }

  const MasterSurface& surface_;
  std::span<const Vector2d> positions_;
  const SearchOptions& options_;
  SearchStatistics& stats_;
  std::vector<Candidate> found_;
  std::vector<Candidate> cache_;
};

}  // namespace

std::vector<ContactPairing> find_closest(const MasterSurface& surface, std::span<const Vector2d> positions,
                                         std::span<const Vector2d> slaves, const SearchOptions& options,
                                         std::span<const ContactPairing> previous, SearchStatistics* statistics) {
  if (!(options.search_radius > 0)) throw std::invalid_argument("contact search radius must be > 0");
  if (static_cast<int>(positions.size()) < surface.n_nodes_required())
    throw std::invalid_argument("contact search: positions hold " + std::to_string(positions.size()) +
                                " nodes, the master surface needs " + std::to_string(surface.n_nodes_required()));
  if (!previous.empty() && previous.size() != slaves.size())
    throw std::invalid_argument("contact search: previous pairings must be empty or one per slave point");
  for (const ContactPairing& p : previous)
    if (p.segment >= surface.n_segments())
      throw std::invalid_argument("contact search: previous pairing names segment " + std::to_string(p.segment) +
                                  " of a surface with " + std::to_string(surface.n_segments()));

  SearchStatistics local_stats;
  SearchStatistics& stats = statistics ? *statistics : local_stats;
  stats.n_slaves += static_cast<std::int64_t>(slaves.size());
  std::unique_ptr<SegmentBins> bins;  // built on first need, once
  std::once_flag bins_built;
  std::vector<ContactPairing> result(slaves.size());
  const auto n_slaves = static_cast<std::int64_t>(slaves.size());

  // Each slave point is paired independently: the loop runs in parallel
  // (per-thread selector, buffers and counters) and gives the serial answer.
#pragma omp parallel if (n_slaves >= kParallelSlaves)
  {
    SearchStatistics thread_stats;
    Selector selector(surface, positions, options, thread_stats);
    std::vector<std::pair<double, int>> ordered;
#pragma omp for schedule(dynamic, 128)
    for (std::int64_t k = 0; k < n_slaves; ++k) {
      const auto i = static_cast<std::size_t>(k);
      const Vector2d& slave = slaves[i];
      const ContactPairing* prev = previous.empty() ? nullptr : &previous[i];
      selector.next_slave();
      if (prev && options.keep_pairing) {  // SMALL SLIDING: the extended segment of the first pairing
        if (prev->found()) {
          const SegmentPoints seg = points_of(surface, positions, prev->segment);
          const SegmentProjection p = project(slave, seg.span(), options.projection);
          ++thread_stats.n_projections;
          ContactPairing& out = result[i];
          out.segment = prev->segment;
          out.xi = p.status == ProjectionStatus::degenerate ? prev->xi : p.xi;
          const auto [y, n] = point_and_normal(seg, out.xi);
          out.gap = (slave - y).dot(n);
          out.distance = (slave - y).norm();
        }
        continue;
      }
      if (prev && prev->found()) {  // walk from the previous segment over neighbours
        ordered.clear();
        auto add_with_neighbours = [&](int s) {
          ordered.emplace_back(0.0, s);
          for (int corner = 0; corner < 2; ++corner)
            for (int q : surface.neighbours(s, corner)) ordered.emplace_back(0.0, q);
          std::sort(ordered.begin(), ordered.end());
          ordered.erase(std::unique(ordered.begin(), ordered.end()), ordered.end());
        };
        auto evaluated = [&](int s) { return std::binary_search(ordered.begin(), ordered.end(), std::pair{0.0, s}); };
        add_with_neighbours(prev->segment);
        bool accepted = false;
        for (int step = 0; step < kMaxWalkSteps; ++step) {
          const ContactPairing local = selector.select(slave, ordered);
          if (!local.found()) break;
          bool closed = true;  // every neighbour of the chosen segment was a candidate
          for (int corner = 0; corner < 2; ++corner)
            for (int q : surface.neighbours(local.segment, corner)) closed = closed && evaluated(q);
          if (closed) {
            result[i] = local;
            accepted = true;
            break;
          }
          add_with_neighbours(local.segment);
        }
        if (accepted) {
          ++thread_stats.n_local;
          continue;
        }
      }
      std::call_once(bins_built,
                     [&] { bins = std::make_unique<SegmentBins>(surface, positions, options.search_radius); });
      bins->candidates(slave, ordered);
      result[i] = selector.select(slave, ordered);
      ++thread_stats.n_broad_phase;
    }
#pragma omp critical(contact_search_statistics)
    {
      stats.n_projections += thread_stats.n_projections;
      stats.n_broad_phase += thread_stats.n_broad_phase;
      stats.n_local += thread_stats.n_local;
    }
  }
  if (bins) stats.n_bins = bins->n_bins();
  return result;
}

}  // namespace tether
