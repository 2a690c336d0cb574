#include "tether/contact/master_segments.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace tether {

namespace {

/// How the faces meet at one node: the face ending there (corner 1) and the
/// face starting there (corner 0), and how many face ends touch it.
struct NodeUse {
  int ending = -1, starting = -1;
  int count = 0;
};

}  // namespace

MasterSegments::MasterSegments(std::span<const std::vector<int>> faces, double smoothing)
    : smoothing_(smoothing), surface_(build(faces, smoothing)) {}

std::vector<std::vector<int>> MasterSegments::build(std::span<const std::vector<int>> faces, double s) {
  if (!(s >= 0 && s <= kMaxSmoothing))
    throw std::invalid_argument("master surface smoothing " + std::to_string(s) + " outside [0, 0.5]");
  for (std::size_t f = 0; f < faces.size(); ++f) {
    for (int n : faces[f]) n_nodes_required_ = std::max(n_nodes_required_, n + 1);
    if (s > 0 && faces[f].size() != 2)
      throw std::invalid_argument("master face " + std::to_string(f) + " has " + std::to_string(faces[f].size()) +
                                  " nodes: only linear (2-node) master faces can be smoothed");
  }
  std::vector<std::vector<int>> points;  // per segment, its point indices (the search's "nodes")
  if (s == 0) {
    for (std::size_t f = 0; f < faces.size(); ++f) {
      MasterSegment m;
      m.n_nodes = static_cast<int>(faces[f].size());
      if (m.n_nodes != 2 && m.n_nodes != 3) break;  // MasterSurface names the bad face
      std::copy(faces[f].begin(), faces[f].end(), m.nodes.begin());
      m.face_before = m.face_after = static_cast<int>(f);
      segments_.push_back(m);
      points.push_back(faces[f]);
    }
    if (segments_.size() != faces.size()) return {faces.begin(), faces.end()};
    return points;
  }

  // Which nodes are rounded: one face ends there, one other face starts there, nothing else.
  std::vector<NodeUse> use(static_cast<std::size_t>(n_nodes_required_));
  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (faces[f][0] < 0 || faces[f][1] < 0) return {faces.begin(), faces.end()};  // MasterSurface refuses it
    NodeUse& first = use[static_cast<std::size_t>(faces[f][0])];
    NodeUse& last = use[static_cast<std::size_t>(faces[f][1])];
    first.starting = first.starting < 0 ? static_cast<int>(f) : -2;
    last.ending = last.ending < 0 ? static_cast<int>(f) : -2;
    ++first.count;
    ++last.count;
  }
  auto rounded = [&](int node) {
    const NodeUse& u = use[static_cast<std::size_t>(node)];
    if (u.count != 2 || u.ending < 0 || u.starting < 0 || u.ending == u.starting) return false;
    // A - B - C with A = C (two faces folded onto each other) has no corner to round.
    return faces[static_cast<std::size_t>(u.ending)][0] != faces[static_cast<std::size_t>(u.starting)][1];
  };

  // Point indices: real nodes keep theirs; cut points and mid nodes follow.
  auto add_point = [&](Combination c) {
    extra_points_.push_back(c);
    return n_nodes_required_ + static_cast<int>(extra_points_.size()) - 1;
  };
  // Cut point of each face at its start and end (the real node where not rounded).
  std::vector<int> start_point(faces.size()), end_point(faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const int a = faces[f][0], b = faces[f][1];
    const bool round_a = rounded(a), round_b = rounded(b);
    start_point[f] = round_a ? add_point({{a, b, -1}, {1 - s, s, 0}, 2}) : a;
    if (round_a && round_b && s == kMaxSmoothing)
      end_point[f] = start_point[f];  // both cuts at the middle: no straight piece
    else
      end_point[f] = round_b ? add_point({{a, b, -1}, {s, 1 - s, 0}, 2}) : b;
  }
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const int a = faces[f][0], b = faces[f][1];
    const int face = static_cast<int>(f);
    // Straight piece of face f.
    if (start_point[f] != end_point[f]) {
      MasterSegment m;
      m.n_nodes = 2;
      m.nodes = {a, b, -1};
      m.weights.setZero();
      m.weights.topLeftCorner<2, 2>() << (rounded(a) ? 1 - s : 1.0), (rounded(a) ? s : 0.0),
          (rounded(b) ? s : 0.0), (rounded(b) ? 1 - s : 1.0);
      m.identity = !rounded(a) && !rounded(b);
      if (m.identity) m.weights = Eigen::Matrix3d::Identity();
      m.face_before = m.face_after = face;
      segments_.push_back(m);
      points.push_back({start_point[f], end_point[f]});
    }
    // Corner piece at the end node b of face f, towards the face starting at b.
    if (!rounded(b)) continue;
    const int next = use[static_cast<std::size_t>(b)].starting;
    const int c = faces[static_cast<std::size_t>(next)][1];
    MasterSegment m;
    m.n_nodes = 3;
    m.nodes = {a, b, c};
    m.weights << s, 1 - s, 0,           // P0 = B + s (A - B)   (ξ = -1)
        0, 1 - s, s,                     // P2 = B + s (C - B)   (ξ = +1)
        s / 4, 1 - s / 2, s / 4;         // (P0 + 2B + P2) / 4   (ξ = 0)
    m.identity = false;
    m.face_before = face;
    m.face_after = next;
    segments_.push_back(m);
    const int mid = add_point({{a, b, c}, {s / 4, 1 - s / 2, s / 4}, 3});
    points.push_back({end_point[f], start_point[static_cast<std::size_t>(next)], mid});
    ++n_rounded_;
  }
  return points;
}

void MasterSegments::point_positions(std::span<const Eigen::Vector2d> nodes,
                                     std::vector<Eigen::Vector2d>& points) const {
  points.assign(nodes.begin(), nodes.begin() + n_nodes_required_);
  for (const Combination& c : extra_points_) {
    Eigen::Vector2d p(0, 0);
    for (int k = 0; k < c.n; ++k) p += c.weight[static_cast<std::size_t>(k)] * nodes[static_cast<std::size_t>(c.node[static_cast<std::size_t>(k)])];
    points.push_back(p);
  }
}

void MasterSegments::virtual_positions(int k, std::span<const Eigen::Vector2d> real,
                                       std::span<Eigen::Vector2d> out) const {
  const MasterSegment& m = segment(k);
  for (int p = 0; p < m.n_nodes; ++p) {
    Eigen::Vector2d z(0, 0);
    for (int a = 0; a < m.n_nodes; ++a) z += m.weights(p, a) * real[static_cast<std::size_t>(a)];
    out[static_cast<std::size_t>(p)] = z;
  }
}

void map_to_real_nodes(const MasterSegment& segment, Eigen::VectorXd& v) {
  if (segment.identity) return;
  const int m = segment.n_nodes;
  Eigen::VectorXd mapped = Eigen::VectorXd::Zero(2 * m);
  for (int a = 0; a < m; ++a)
    for (int p = 0; p < m; ++p) mapped.segment<2>(2 * a) += segment.weights(p, a) * v.segment<2>(2 + 2 * p);
  v.segment(2, 2 * m) = mapped;
}

void map_to_real_nodes(const MasterSegment& segment, Eigen::MatrixXd& K) {
  if (segment.identity) return;
  const int m = segment.n_nodes;
  const Eigen::Index n = K.rows();
  // T = I₂ ⊕ (W⊗I₂) ⊕ I, applied as K ← Tᵀ K T.
  Eigen::MatrixXd T = Eigen::MatrixXd::Identity(n, n);
  for (int p = 0; p < m; ++p)
    for (int a = 0; a < m; ++a) T.block<2, 2>(2 + 2 * p, 2 + 2 * a) = segment.weights(p, a) * Eigen::Matrix2d::Identity();
  K = (T.transpose() * K * T).eval();
}

}  // namespace tether
