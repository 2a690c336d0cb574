#pragma once
/// \file The segments a slave node is projected onto: the master faces
/// themselves, or (`*CONTACT PAIR, SMOOTH=s`) a C¹ surface made of rounded
/// corners and shortened straight pieces.
///
/// Every segment k is a 2- or 3-node segment of segment_geometry.hpp whose
/// "virtual" nodes are fixed linear combinations of the same number of real
/// master nodes,
///     z^p = Σ_a W_k(p, a) y^a,       p, a = 1..m_k,  m_k = 2 or 3,
/// with a constant weight matrix W_k. Kinematics are computed on z and mapped
/// back to the real nodes by the chain rule: gradients by (I ⊕ W_k⊗I₂)ᵀ,
/// Hessians by (I ⊕ W_k⊗I₂)ᵀ (·) (I ⊕ W_k⊗I₂) — exact, W_k being constant.
/// Without smoothing W_k = I and the segments are the faces, in order.
///
/// Smoothing of linear (2-node) faces, 0 < s ≤ 0.5: at a master node B that
/// ends face A–B and starts face B–C (and no other face touches B), the two
/// faces are cut at P0 = B + s(A − B) and P2 = B + s(C − B); the corner piece
/// is the quadratic Bézier curve with control points P0, B, P2, written as a
/// 3-node segment with end nodes P0, P2 and mid node (P0 + 2B + P2)/4. Its
/// tangent at P0 is B − P0 (along A→B) and at P2 is P2 − B (along B→C), so
/// position and tangent are continuous at both joints. The rest of each face
/// is a straight 2-node piece from A + s(B − A) (or A when A is not rounded)
/// to B + s(A − B) (or B); with s = 0.5 and both ends rounded it has zero
/// length and is left out. Nodes of open ends, nodes shared by three or more
/// faces, and nodes where the two faces do not run head to tail are not
/// rounded. Theory: docs/theory/contact_geometry.md, "Smoothed master surface".

#include <Eigen/Core>
#include <array>
#include <span>
#include <vector>

#include "tether/contact/contact_search.hpp"

namespace tether {

/// Largest SMOOTH fraction (the corner pieces of a face then meet in its middle).
inline constexpr double kMaxSmoothing = 0.5;

/// One segment seen by the contact element.
struct MasterSegment {
  std::array<int, 3> nodes{-1, -1, -1};  ///< real master node indices (global), first n_nodes used
  int n_nodes = 0;                       ///< 2 or 3: also the number of virtual nodes
  /// W: virtual node p = Σ_a weights(p, a) × real node a (top-left n_nodes block).
  Eigen::Matrix3d weights = Eigen::Matrix3d::Identity();
  bool identity = true;  ///< W = I: the segment is a master face itself
  /// Master face (index into the faces given) the segment lies on for ξ < 0
  /// and for ξ ≥ 0: the same face except for a corner piece (face before and
  /// after the corner).
  int face_before = -1, face_after = -1;
  /// The face a point at ξ on this segment belongs to (for output labels).
  [[nodiscard]] int face_at(double xi) const { return xi < 0 ? face_before : face_after; }
};

/// The segments of one master surface, with the topology for the search.
class MasterSegments {
 public:
  /// `faces`: master faces as in ContactPairSetup::master_faces (2 or 3 node
  /// indices each, face_nodes() order). `smoothing`: the SMOOTH fraction s,
  /// 0 (none) or 0 < s ≤ kMaxSmoothing. Throws std::invalid_argument for s
  /// outside [0, kMaxSmoothing], for s > 0 with any 3-node face (quadratic
  /// masters are already curved and are not smoothed), and for faces
  /// MasterSurface refuses.
  MasterSegments(std::span<const std::vector<int>> faces, double smoothing);

  [[nodiscard]] int n_segments() const { return static_cast<int>(segments_.size()); }
  [[nodiscard]] const MasterSegment& segment(int k) const { return segments_[static_cast<std::size_t>(k)]; }
  [[nodiscard]] double smoothing() const { return smoothing_; }
  [[nodiscard]] bool smoothed() const { return smoothing_ > 0; }
  /// Number of corners rounded (0 without smoothing).
  [[nodiscard]] int n_rounded() const { return n_rounded_; }

  /// Topology for find_closest(): segment k of it is segment k here, its
  /// "nodes" are point indices (see point_positions()).
  [[nodiscard]] const MasterSurface& surface() const { return surface_; }

  /// Largest real node index + 1 (the real positions passed below must hold this many).
  [[nodiscard]] int n_nodes_required() const { return n_nodes_required_; }

  /// Positions of the surface's points from the real node positions (indexed
  /// by node): without smoothing the same vector; with smoothing the real
  /// positions followed by the cut points and corner mid nodes.
  void point_positions(std::span<const Eigen::Vector2d> nodes, std::vector<Eigen::Vector2d>& points) const;

  /// Virtual node positions z of segment k from the positions of its real
  /// nodes (`real`, n_nodes of them, in segment order); writes n_nodes points.
  void virtual_positions(int k, std::span<const Eigen::Vector2d> real, std::span<Eigen::Vector2d> out) const;

 private:
  /// A surface point that is not a real node: Σ weight × node, ≤ 3 terms.
  struct Combination {
    std::array<int, 3> node{-1, -1, -1};
    std::array<double, 3> weight{0, 0, 0};
    int n = 0;
  };

  /// Fills the members above from the faces; returns the segments' point
  /// indices (the faces of surface_, which is built from them).
  std::vector<std::vector<int>> build(std::span<const std::vector<int>> faces, double s);

  double smoothing_ = 0;
  int n_rounded_ = 0;
  int n_nodes_required_ = 0;
  std::vector<MasterSegment> segments_;
  std::vector<Combination> extra_points_;  ///< point index n_nodes_required_ + i
  MasterSurface surface_;
};

/// Maps a gradient over [slave (2), virtual nodes (2m), others] to the real
/// nodes in place: v ← Tᵀ v, T = I₂ ⊕ (W⊗I₂) ⊕ I. No-op for identity segments.
void map_to_real_nodes(const MasterSegment& segment, Eigen::VectorXd& v);
/// The same for a matrix over the same unknowns: K ← Tᵀ K T.
void map_to_real_nodes(const MasterSegment& segment, Eigen::MatrixXd& K);

}  // namespace tether
