// Contact search: bins + projection against an all-pairs search, hand-over at
// segment ends, convex and concave corners, determinism, small sliding, and
// the number of narrow-phase projections per slave as the surface grows.

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <omp.h>
#include <cmath>
#include <iostream>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "tether/contact/contact_search.hpp"

using namespace tether;
using Eigen::Vector2d;

namespace {

struct Mesh {
  std::vector<Vector2d> positions;
  std::vector<std::vector<int>> faces;
};

/// Straight master along y = 0, x ∈ [0, n h], body below (outward normal +y):
/// faces run right to left (counter-clockwise around the body).
Mesh flat_master(int n, double h) {
  Mesh m;
  for (int i = 0; i <= n; ++i) m.positions.emplace_back(i * h, 0.0);
  for (int i = 0; i < n; ++i) m.faces.push_back({i + 1, i});
  return m;
}

/// Circle of radius R around the origin (body inside), n segments with 2 or 3
/// nodes, counter-clockwise.
Mesh circle_master(int n, double R, int nodes_per_face) {
  Mesh m;
  const double dth = 2 * std::numbers::pi / n;
  for (int i = 0; i < n; ++i) m.positions.emplace_back(R * std::cos(i * dth), R * std::sin(i * dth));
  for (int i = 0; i < n; ++i) {
    if (nodes_per_face == 3) {
      m.positions.emplace_back(R * std::cos((i + 0.5) * dth), R * std::sin((i + 0.5) * dth));
      m.faces.push_back({i, (i + 1) % n, n + i});
    } else {
      m.faces.push_back({i, (i + 1) % n});
    }
  }
  return m;
}

std::vector<Vector2d> points_of(const Mesh& m, int s) {
  std::vector<Vector2d> p;
  for (int node : m.faces[s]) p.push_back(m.positions[node]);
  return p;
}

/// Outward normal at the end ξ = ±1 (independent of the library's helper).
Vector2d end_normal(const std::vector<Vector2d>& y, double xi) {
  Vector2d a = y[1] - y[0];
  if (y.size() == 3) a = (xi - 0.5) * y[0] + (xi + 0.5) * y[1] - 2 * xi * y[2];
  a.normalize();
  return {a.y(), -a.x()};
}

/// All-pairs reference: every segment projected, the rule of the theory page.
ContactPairing brute_force(const Mesh& m, const Vector2d& ys, double radius) {
  struct C {
    int s;
    SegmentProjection p;
  };
  std::vector<C> cs;
  double d_min = std::numeric_limits<double>::infinity();
  for (int s = 0; s < static_cast<int>(m.faces.size()); ++s) {
    const auto y = points_of(m, s);
    const SegmentProjection p = project(ys, y);
    if (p.status == ProjectionStatus::degenerate || p.clamped_distance > radius) continue;
    cs.push_back({s, p});
    d_min = std::min(d_min, p.clamped_distance);
  }
  ContactPairing out;
  if (cs.empty()) return out;
  const double tol = 1e-13 * (ys.cwiseAbs().maxCoeff() + d_min + radius);
  for (const C& c : cs) {
    if (c.p.inside && c.p.clamped_distance <= d_min + tol) {
      const auto y = points_of(m, c.s);
      const SegmentGeometry g = segment_geometry(ys, y, ContactDerivatives::none);
      out.segment = c.s;
      out.xi = g.projection.xi;
      out.gap = g.gap;
      out.distance = (ys - g.point).norm();
      return out;  // lowest index first
    }
  }
  double best = -2;
  for (const C& c : cs) {
    if (c.p.clamped_distance > d_min + tol) continue;
    const auto y = points_of(m, c.s);
    const Vector2d end = c.p.clamped_xi > 0 ? y[1] : y[0];
    const Vector2d d = ys - end;
    const double dn = d.dot(end_normal(y, c.p.clamped_xi)) / d.norm();
    if (dn > best + 1e-12) {
      best = dn;
      out.segment = c.s;
      out.xi = c.p.clamped_xi;
      out.distance = d.norm();
      out.gap = dn >= 0 ? out.distance : -out.distance;
      out.at_corner = true;
    }
  }
  return out;
}

void expect_same(const ContactPairing& a, const ContactPairing& b, const std::string& what) {
  ASSERT_EQ(a.segment, b.segment) << what;
  if (!a.found()) return;
  EXPECT_NEAR(a.xi, b.xi, 1e-12) << what;
  EXPECT_NEAR(a.gap, b.gap, 1e-12) << what;
  EXPECT_NEAR(a.distance, b.distance, 1e-12) << what;
  EXPECT_EQ(a.at_corner, b.at_corner) << what;
}

void check_against_brute_force(const Mesh& m, const std::vector<Vector2d>& slaves, double radius) {
  const MasterSurface surface(m.faces);
  SearchOptions options;
  options.search_radius = radius;
  const auto full = find_closest(surface, m.positions, slaves, options);
  int n_found = 0;
  for (std::size_t i = 0; i < slaves.size(); ++i) {
    expect_same(full[i], brute_force(m, slaves[i], radius), "slave " + std::to_string(i));
    n_found += full[i].found();
  }
  EXPECT_GT(n_found, static_cast<int>(slaves.size()) / 2);
  // Incremental path from a stale pairing (the neighbouring segment): same answer.
  std::vector<ContactPairing> stale = full;
  for (auto& p : stale)
    if (p.found()) p.segment = (p.segment + 1) % surface.n_segments();
  const auto incremental = find_closest(surface, m.positions, slaves, options, stale);
  for (std::size_t i = 0; i < slaves.size(); ++i)
    expect_same(incremental[i], full[i], "incremental slave " + std::to_string(i));
}

}  // namespace

TEST(MasterSurface, NeighboursShareCornerNodes) {
  const Mesh m = circle_master(5, 1.0, 3);
  const MasterSurface s(m.faces);
  ASSERT_EQ(s.n_segments(), 5);
  for (int i = 0; i < 5; ++i) {
    ASSERT_EQ(s.neighbours(i, 0).size(), 1u);
    ASSERT_EQ(s.neighbours(i, 1).size(), 1u);
    EXPECT_EQ(s.neighbours(i, 0)[0], (i + 4) % 5);
    EXPECT_EQ(s.neighbours(i, 1)[0], (i + 1) % 5);
  }
  const Mesh f = flat_master(3, 1.0);
  const MasterSurface open(f.faces);
  EXPECT_TRUE(open.neighbours(0, 1).empty());  // open ends
  EXPECT_TRUE(open.neighbours(2, 0).empty());
  EXPECT_THROW(MasterSurface(std::vector<std::vector<int>>{{0}}), std::invalid_argument);
}

TEST(ContactSearch, FlatMasterMatchesAllPairs) {
  const Mesh m = flat_master(200, 0.05);  // x ∈ [0, 10]
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> ux(-0.5, 10.5), uy(-0.2, 0.2);
  std::vector<Vector2d> slaves;
  for (int i = 0; i < 3000; ++i) slaves.emplace_back(ux(rng), uy(rng));
  check_against_brute_force(m, slaves, 0.12);
}

TEST(ContactSearch, CurvedQuadraticMasterMatchesAllPairs) {
  for (int n : {12, 97}) {
    const Mesh m = circle_master(n, 1.0, 3);
    std::mt19937 rng(11 + n);
    std::uniform_real_distribution<double> ur(0.8, 1.2), ut(0, 2 * std::numbers::pi);
    std::vector<Vector2d> slaves;
    for (int i = 0; i < 3000; ++i) {
      const double r = ur(rng), t = ut(rng);
      slaves.emplace_back(r * std::cos(t), r * std::sin(t));
    }
    check_against_brute_force(m, slaves, 0.15);
  }
}

TEST(ContactSearch, StarPolygonWithConvexAndConcaveCornersMatchesAllPairs) {
  // Closed star: 2-node segments, radius alternating 1 and 0.6 (convex tips, concave notches).
  Mesh m;
  const int n = 40;
  for (int i = 0; i < n; ++i) {
    const double r = i % 2 ? 0.6 : 1.0, t = 2 * std::numbers::pi * i / n;
    m.positions.emplace_back(r * std::cos(t), r * std::sin(t));
    m.faces.push_back({i, (i + 1) % n});
  }
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-1.2, 1.2);
  std::vector<Vector2d> slaves;
  for (int i = 0; i < 4000; ++i) slaves.emplace_back(u(rng), u(rng));
  check_against_brute_force(m, slaves, 0.25);
}

TEST(ContactSearch, GapAgreesWithSegmentGeometry) {
  const Mesh m = circle_master(40, 2.0, 3);
  const MasterSurface surface(m.faces);
  SearchOptions options;
  options.search_radius = 0.5;
  const std::vector<Vector2d> slaves{{2.1, 0.3}, {-1.8, 0.7}, {0.01, -2.05}};
  const auto r = find_closest(surface, m.positions, slaves, options);
  for (std::size_t i = 0; i < slaves.size(); ++i) {
    ASSERT_TRUE(r[i].found());
    ASSERT_FALSE(r[i].at_corner);
    const SegmentGeometry g = segment_geometry(slaves[i], points_of(m, r[i].segment), ContactDerivatives::none);
    EXPECT_NEAR(r[i].gap, g.gap, 1e-12);
    EXPECT_NEAR(r[i].xi, g.projection.xi, 1e-12);
  }
  EXPECT_GT(r[0].gap, 0);  // open outside the disc
  EXPECT_LT(r[1].gap, 0);  // penetrating
}

TEST(ContactSearch, HandOverAcrossSegmentEndKeepsGapContinuous) {
  const double h = 0.1, g = 0.013;
  const Mesh m = flat_master(10, h);
  const MasterSurface surface(m.faces);
  SearchOptions options;
  options.search_radius = 0.3;
  // Slide from x = 0.23 to 0.37 across the node at x = 0.3 (segment 2 = nodes 3→2, segment 3 = nodes 4→3).
  std::vector<ContactPairing> pairing = find_closest(surface, m.positions, std::vector<Vector2d>{{0.23, g}}, options);
  ASSERT_EQ(pairing[0].segment, 2);
  SearchStatistics stats;
  double previous_gap = pairing[0].gap;
  bool handed_over = false;
  for (int k = 1; k <= 140; ++k) {
    const Vector2d slave(0.23 + 1e-3 * k, g);
    const std::vector<Vector2d> slaves{slave};
    const auto next = find_closest(surface, m.positions, slaves, options, pairing, &stats);
    ASSERT_TRUE(next[0].found());
    EXPECT_FALSE(next[0].at_corner);
    EXPECT_NEAR(next[0].gap, previous_gap, 1e-12);
    EXPECT_NEAR(next[0].gap, g, 1e-12);
    if (next[0].segment != pairing[0].segment) {
      EXPECT_EQ(next[0].segment, 3);
      EXPECT_NEAR(pairing[0].xi, -1.0, 0.021);  // segment 2 runs right to left: x = 0.3 is its ξ = -1
      EXPECT_NEAR(next[0].xi, 1.0, 0.021);
      handed_over = true;
    }
    expect_same(next[0], find_closest(surface, m.positions, slaves, options)[0], "step " + std::to_string(k));
    previous_gap = next[0].gap;
    pairing = next;
  }
  EXPECT_TRUE(handed_over);
  EXPECT_EQ(pairing[0].segment, 3);
  EXPECT_EQ(stats.n_broad_phase, 0);  // every re-pairing found among the neighbours
  // Exactly on the shared node: both contain it, the lower index wins.
  const auto on_node = find_closest(surface, m.positions, std::vector<Vector2d>{{0.3, g}}, options);
  EXPECT_EQ(on_node[0].segment, 2);
}

TEST(ContactSearch, ConvexCornerUsesTheNearerSegmentEnd) {
  // Body: the square [-1,0]², corner at the origin. Segment 0: right face
  // (0,-1)→(0,0), normal +x; segment 1: top face (0,0)→(-1,0), normal +y.
  Mesh m;
  m.positions = {{0, -1}, {0, 0}, {-1, 0}};
  m.faces = {{0, 1}, {1, 2}};
  const MasterSurface surface(m.faces);
  SearchOptions options;
  options.search_radius = 1.0;
  const std::vector<Vector2d> slaves{{0.1, 0.3}, {0.3, 0.1}, {0.2, 0.2}, {-0.1, -0.3}, {-0.3, -0.1}, {0.0, 0.4}};
  const auto r = find_closest(surface, m.positions, slaves, options);
  // Shadow wedge: corner pairing, gap = +distance to the corner.
  EXPECT_EQ(r[0].segment, 1);
  EXPECT_TRUE(r[0].at_corner);
  EXPECT_EQ(r[0].xi, -1.0);
  EXPECT_NEAR(r[0].gap, std::hypot(0.1, 0.3), 1e-15);
  EXPECT_EQ(r[1].segment, 0);
  EXPECT_TRUE(r[1].at_corner);
  EXPECT_EQ(r[1].xi, 1.0);
  EXPECT_NEAR(r[1].gap, std::hypot(0.3, 0.1), 1e-15);
  EXPECT_EQ(r[2].segment, 0);  // bisector: tie, lower index
  EXPECT_TRUE(r[2].at_corner);
  // Inside the body both faces contain the projection: the nearer one.
  EXPECT_EQ(r[3].segment, 0);
  EXPECT_FALSE(r[3].at_corner);
  EXPECT_NEAR(r[3].gap, -0.1, 1e-15);
  EXPECT_EQ(r[4].segment, 1);
  EXPECT_NEAR(r[4].gap, -0.1, 1e-15);
  // On the wedge boundary the top face still contains the projection (ξ = -1): the gap is continuous.
  EXPECT_EQ(r[5].segment, 1);
  EXPECT_FALSE(r[5].at_corner);
  EXPECT_NEAR(r[5].gap, 0.4, 1e-15);
  const auto just_inside_wedge = find_closest(surface, m.positions, std::vector<Vector2d>{{1e-9, 0.4}}, options);
  EXPECT_TRUE(just_inside_wedge[0].at_corner);
  EXPECT_NEAR(just_inside_wedge[0].gap, 0.4, 1e-15);
  for (std::size_t i = 0; i < slaves.size(); ++i) expect_same(r[i], brute_force(m, slaves[i], 1.0), "corner");
}

TEST(ContactSearch, ConcaveCornerTakesTheNearerSegment) {
  // Body: everything but the first quadrant. Segment 0: (1,0)→(0,0), normal +y;
  // segment 1: (0,0)→(0,1), normal +x.
  Mesh m;
  m.positions = {{1, 0}, {0, 0}, {0, 1}};
  m.faces = {{0, 1}, {1, 2}};
  const MasterSurface surface(m.faces);
  SearchOptions options;
  options.search_radius = 1.0;
  const std::vector<Vector2d> slaves{{0.3, 0.1}, {0.1, 0.3}, {0.2, 0.2}, {-0.1, -0.05}};
  const auto r = find_closest(surface, m.positions, slaves, options);
  EXPECT_EQ(r[0].segment, 0);
  EXPECT_NEAR(r[0].gap, 0.1, 1e-15);
  EXPECT_EQ(r[1].segment, 1);
  EXPECT_NEAR(r[1].gap, 0.1, 1e-15);
  EXPECT_EQ(r[2].segment, 0);  // both contain it at equal distance: lower index
  EXPECT_FALSE(r[2].at_corner);
  // Penetrating behind the corner: no face contains the projection; corner
  // pairing, negative gap = -distance to the corner node.
  EXPECT_TRUE(r[3].at_corner);
  EXPECT_EQ(r[3].segment, 0);
  EXPECT_NEAR(r[3].gap, -std::hypot(0.1, 0.05), 1e-15);
  // Same surface listed in the other order: ties go to the new lower index.
  Mesh swapped = m;
  std::swap(swapped.faces[0], swapped.faces[1]);
  const auto s = find_closest(MasterSurface(swapped.faces), swapped.positions, slaves, options);
  EXPECT_EQ(s[0].segment, 1);
  EXPECT_EQ(s[1].segment, 0);
  EXPECT_EQ(s[2].segment, 0);
}

TEST(ContactSearch, NoCandidateWithinTheRadius) {
  const Mesh m = flat_master(10, 0.1);
  SearchOptions options;
  options.search_radius = 0.05;
  const auto r = find_closest(MasterSurface(m.faces), m.positions, std::vector<Vector2d>{{0.5, 0.06}, {5, 5}}, options);
  EXPECT_FALSE(r[0].found());
  EXPECT_FALSE(r[1].found());
  ContactPairing bad;
  bad.segment = 10;
  EXPECT_THROW(find_closest(MasterSurface(m.faces), m.positions, std::vector<Vector2d>{{0, 0}}, options,
                            std::vector<ContactPairing>{bad}),
               std::invalid_argument);
  options.search_radius = 0;
  EXPECT_THROW(find_closest(MasterSurface(m.faces), m.positions, std::vector<Vector2d>{{0, 0}}, options),
               std::invalid_argument);
}

TEST(ContactSearch, DeterministicUnderSegmentReordering) {
  const Mesh m = circle_master(50, 1.0, 3);
  std::vector<int> order(50);
  for (int i = 0; i < 50; ++i) order[i] = i;
  std::shuffle(order.begin(), order.end(), std::mt19937(3));
  Mesh shuffled = m;
  for (int i = 0; i < 50; ++i) shuffled.faces[i] = m.faces[order[i]];
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.2, 1.2);
  std::vector<Vector2d> slaves;
  for (int i = 0; i < 1000; ++i) slaves.emplace_back(u(rng), u(rng));
  SearchOptions options;
  options.search_radius = 0.2;
  const auto a = find_closest(MasterSurface(m.faces), m.positions, slaves, options);
  const auto again = find_closest(MasterSurface(m.faces), m.positions, slaves, options);
  const auto b = find_closest(MasterSurface(shuffled.faces), shuffled.positions, slaves, options);
  for (std::size_t i = 0; i < slaves.size(); ++i) {
    expect_same(a[i], again[i], "repeat");
    ASSERT_EQ(a[i].found(), b[i].found());
    if (!a[i].found()) continue;
    if (a[i].at_corner && std::abs(a[i].distance) < 1e-9) continue;
    EXPECT_EQ(a[i].segment, order[b[i].segment]);
    EXPECT_NEAR(a[i].gap, b[i].gap, 1e-12);
  }
}

TEST(ContactSearch, SmallSlidingKeepsTheFirstPairing) {
  const Mesh m = flat_master(10, 0.1);
  const MasterSurface surface(m.faces);
  SearchOptions options;
  options.search_radius = 0.2;
  options.keep_pairing = true;
  const auto first = find_closest(surface, m.positions, std::vector<Vector2d>{{0.25, 0.01}, {3.0, 0.0}}, options);
  ASSERT_EQ(first[0].segment, 2);
  ASSERT_FALSE(first[1].found());
  // Slide two segments: the pairing stays, ξ leaves [-1, 1], gap from the extended segment.
  const auto later = find_closest(surface, m.positions, std::vector<Vector2d>{{0.1, -0.02}, {0.5, 0.0}}, options, first);
  EXPECT_EQ(later[0].segment, 2);
  EXPECT_NEAR(later[0].xi, 3.0, 1e-12);
  EXPECT_NEAR(later[0].gap, -0.02, 1e-15);
  EXPECT_FALSE(later[1].found());  // unpaired at the start: stays unpaired
  options.keep_pairing = false;
  const auto finite = find_closest(surface, m.positions, std::vector<Vector2d>{{0.1, -0.02}}, options,
                                   std::span(first).first(1));
  EXPECT_EQ(finite[0].segment, 0);  // on node 1, shared by segments 0 and 1: the lower index, as a full search
}

TEST(ContactSearch, ProjectionsPerSlaveStayBoundedAsTheSurfaceGrows) {
  for (int n : {100, 1000, 10000, 100000}) {
    const double R = 1.0, h = 2 * std::numbers::pi * R / n;
    const Mesh m = circle_master(n, R, 2);
    const MasterSurface surface(m.faces);
    std::mt19937 rng(n);
    std::uniform_real_distribution<double> ut(0, 2 * std::numbers::pi), ug(-0.5 * h, 0.5 * h);
    const int n_slaves = n;
    std::vector<Vector2d> slaves;
    for (int i = 0; i < n_slaves; ++i) {
      const double t = ut(rng), r = R + ug(rng);
      slaves.emplace_back(r * std::cos(t), r * std::sin(t));
    }
    SearchOptions options;
    options.search_radius = 2 * h;
    SearchStatistics stats;
    const auto start = std::chrono::steady_clock::now();
    const auto full = find_closest(surface, m.positions, slaves, options, {}, &stats);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    for (const auto& p : full) ASSERT_TRUE(p.found());
    const double per_slave = double(stats.n_projections) / stats.n_slaves;
    EXPECT_LT(per_slave, 10.0) << n << " segments";
    EXPECT_LT(stats.n_bins, 8 * n) << "sparse bins grow linearly";
    // Incremental re-pairing after a small slide: neighbours only.
    std::vector<Vector2d> moved = slaves;
    const double c = std::cos(0.3 * h / R), sn = std::sin(0.3 * h / R);
    for (auto& y : moved) y = Vector2d(c * y.x() - sn * y.y(), sn * y.x() + c * y.y());
    SearchStatistics incremental;
    const auto t1 = std::chrono::steady_clock::now();
    find_closest(surface, m.positions, moved, options, full, &incremental);
    const double seconds_incremental = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
    EXPECT_EQ(incremental.n_broad_phase, 0);
    std::cout << "[ search ] " << n << " segments: " << per_slave << " projections/slave (full), "
              << double(incremental.n_projections) / incremental.n_slaves << " (incremental), " << stats.n_bins
              << " bins, " << 1e6 * seconds / n_slaves << " us/slave incl. bin build, " << 1e6 * seconds_incremental / n_slaves << " us/slave incremental\n";
  }
}

TEST(ContactSearch, ParallelSearchGivesTheSerialAnswer) {
  // 10^5 segments, 2·10^5 slave points: the loop over slaves runs on every
  // thread; pairings and work counters must equal the one-thread run exactly.
  const int n = 100000;
  const double R = 1.0, h = 2 * std::numbers::pi * R / n;
  const Mesh m = circle_master(n, R, 3);
  const MasterSurface surface(m.faces);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> ut(0, 2 * std::numbers::pi), ug(-0.5 * h, 0.5 * h);
  std::vector<Vector2d> slaves;
  for (int i = 0; i < 2 * n; ++i) {
    const double t = ut(rng), r = R + ug(rng);
    slaves.emplace_back(r * std::cos(t), r * std::sin(t));
  }
  SearchOptions options;
  options.search_radius = 2 * h;
  const int threads = omp_get_max_threads();
  auto run = [&](int t, std::span<const ContactPairing> previous, SearchStatistics& stats, double& seconds) {
    omp_set_num_threads(t);
    const auto start = std::chrono::steady_clock::now();
    auto out = find_closest(surface, m.positions, slaves, options, previous, &stats);
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
  };
  SearchStatistics s1, sn, i1, in;
  double t1 = 0, tn = 0, ti1 = 0, tin = 0;
  const auto serial = run(1, {}, s1, t1);
  const auto parallel = run(threads, {}, sn, tn);
  const auto serial_incremental = run(1, serial, i1, ti1);
  const auto parallel_incremental = run(threads, serial, in, tin);
  omp_set_num_threads(threads);
  for (std::size_t k = 0; k < slaves.size(); ++k) {
    ASSERT_EQ(serial[k].segment, parallel[k].segment) << k;
    ASSERT_EQ(serial[k].xi, parallel[k].xi) << k;
    ASSERT_EQ(serial[k].gap, parallel[k].gap) << k;
    ASSERT_EQ(serial_incremental[k].segment, parallel_incremental[k].segment) << k;
    ASSERT_EQ(serial_incremental[k].xi, parallel_incremental[k].xi) << k;
  }
  EXPECT_EQ(s1.n_projections, sn.n_projections);
  EXPECT_EQ(s1.n_broad_phase, sn.n_broad_phase);
  EXPECT_EQ(i1.n_local, in.n_local);
  std::cout << "[ search ] parallel, " << threads << " threads, " << slaves.size() << " slaves on " << n
            << " segments: full " << t1 << " s -> " << tn << " s (speed-up " << t1 / tn << "), incremental " << ti1
            << " s -> " << tin << " s (speed-up " << ti1 / tin << ")\n";
}
