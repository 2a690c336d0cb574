#pragma once
/// \file Geometry kernels of 2D node-to-segment contact: closest-point
/// projection of a slave point onto a 2- or 3-node master segment, normal gap,
/// tangent and normal, and the exact first and second derivatives of the gap
/// and of the projection coordinate (the consistent linearisation of finite
/// sliding). Pure functions of current positions; no model, no search.
/// Theory and derivations: docs/theory/contact_geometry.md.
///
/// Segment: y(ξ) = Σ_a N_a(ξ) y^a, ξ ∈ [-1,1], nodes in face_nodes() order
/// (first corner at ξ = -1, second corner at ξ = +1, mid-side node at ξ = 0),
/// N_a from face_shape_functions().
///
/// Sign convention: master faces run counter-clockwise around their element,
/// so the OUTWARD unit normal of the master body is
///     n = t × e3 = (t_y, -t_x)        (= -e3 × t),
/// and the normal gap g_n = (y_s - y(ξ*))·n is POSITIVE when the slave point is
/// outside the master body (open) and negative when it penetrates. (The lecture
/// writes n = e3 × t; with counter-clockwise faces that points into the body.)
///
/// Unknown ordering of every gradient/Hessian ("contact dofs"), 2(1 + m)
/// entries for an m-node segment: [y_s.x, y_s.y, y^1.x, y^1.y, y^2.x, y^2.y,
/// (y^3.x, y^3.y)].

#include <Eigen/Core>
#include <span>

namespace tether {

/// Largest number of nodes of a master segment.
inline constexpr int kMaxSegmentNodes = 3;
/// Largest number of contact dofs: slave node + segment nodes, 2 each.
inline constexpr int kMaxContactDofs = 2 * (1 + kMaxSegmentNodes);

/// Gradient with respect to the contact dofs (no heap allocation).
using ContactVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxContactDofs, 1>;
/// Hessian with respect to the contact dofs (symmetric).
using ContactMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxContactDofs, kMaxContactDofs>;

/// How much of the geometry to differentiate.
enum class ContactDerivatives { none, gradient, hessian };

/// Outcome of the closest-point search.
enum class ProjectionStatus {
  converged,        ///< orthogonality (y_s - y(ξ))·y'(ξ) = 0 met to tolerance
  not_converged,    ///< max_iterations reached; xi is the last iterate
  degenerate,       ///< zero-length segment or y'(ξ) = 0: no tangent, nothing else valid
};

/// Controls of the projection (Newton on 3-node segments).
struct ProjectionOptions {
  /// Converged when |Δξ| ≤ xi_tolerance (ξ is dimensionless, segment length 2)
  /// or |(y_s - y)·y'| ≤ 1e-15 |y'| (|y_s - y| + |y'|) (round-off level).
  double xi_tolerance = 1e-13;
  int max_iterations = 30;
  /// ξ* counts as inside when |ξ*| ≤ 1 + end_tolerance, so that a slave point
  /// exactly on a shared end node is inside both neighbours despite round-off.
  double end_tolerance = 1e-12;
};

/// Closest point ξ* of a slave point on the (extended) segment.
struct SegmentProjection {
  double xi = 0;              ///< ξ*, solution of (y_s - y(ξ))·y'(ξ) = 0 (NOT clamped; may leave [-1,1])
  bool inside = false;        ///< |ξ*| ≤ 1 + end_tolerance: the slave point projects onto this segment
  int iterations = 0;         ///< Newton iterations (0 for the closed form of 2-node segments)
  ProjectionStatus status = ProjectionStatus::converged;
  double clamped_xi = 0;      ///< ξ* clamped to [-1, 1] (the nearer end when outside)
  double clamped_distance = 0;  ///< |y_s - y(clamped_xi)| [length]: distance to the segment proper
};

/// Closest point of `slave` on the master segment `segment` (2 or 3 current
/// positions, face_nodes() order).
/// 2 nodes: closed form ξ* = (y_s - ȳ)·a / |a|², ȳ = (y^1+y^2)/2, a = (y^2-y^1)/2.
/// 3 nodes: Newton on f(ξ) = (y_s - y(ξ))·y'(ξ) = 0 started from the chord
/// projection, safeguarded: a Newton step is taken only where ½|y_s - y|² is
/// convex in ξ (otherwise the Gauss–Newton step f/|y'|²), steps are limited to
/// |Δξ| ≤ 1 and halved until the distance decreases. Finds the local
/// minimum of the distance nearest the chord projection on the extended
/// parabola; the hand-over to neighbour segments belongs to the search.
/// Throws std::invalid_argument unless segment.size() is 2 or 3.
SegmentProjection project(const Eigen::Vector2d& slave, std::span<const Eigen::Vector2d> segment,
                          const ProjectionOptions& options = {});

/// Contact kinematics at the closest point, with derivatives.
struct SegmentGeometry {
  SegmentProjection projection;       ///< ξ* and its status
  Eigen::Vector2d point{0, 0};        ///< y(ξ*) [length]
  Eigen::Vector2d tangent_vector{0, 0};  ///< y'(ξ*) = Σ N_a' y^a [length per unit ξ]
  double metric = 0;                  ///< |y'(ξ*)| (half the length of a straight segment)
  Eigen::Vector2d tangent{0, 0};      ///< t = y'/|y'|, from node 1 towards node 2
  Eigen::Vector2d normal{0, 0};       ///< n = t × e3 = (t_y, -t_x): outward from the master body
  double gap = 0;                     ///< g_n = (y_s - y(ξ*))·n [length]; > 0 open, < 0 penetration
  /// Signed curvature κ = -n·d²y/ds² at ξ* [1/length]: 1/R > 0 where the master
  /// body is convex (circle around the body), < 0 where concave, 0 for 2 nodes.
  double curvature = 0;
  /// 1 + g_n κ = -f_ξ/|y'|², f = (y_s - y)·y': > 0 when ξ* is a strict local
  /// minimum of the distance; → 0 when the slave point sits at the centre of
  /// curvature (|g_n| = R): the projection, and every derivative, is singular there.
  double projection_stiffness = 1;

  int n_dofs = 0;                     ///< 2 (1 + segment nodes)
  /// ∂g_n/∂(contact dofs), incl. the variation of ξ* and n. Since ∂g_n/∂ξ = 0 at ξ*
  /// this equals [n; -N_1 n; ...; -N_m n] (N_a at ξ*).
  ContactVector gap_gradient;
  /// ∂²g_n/∂(contact dofs)² = Eᵀ g_zz E, z = (ξ, x), E = [∂ξ*/∂xᵀ; I] (implicit function
  /// theorem on the projection condition; see the theory page). Filled for ContactDerivatives::hessian.
  ContactMatrix gap_hessian;
  ContactVector xi_gradient;          ///< ∂ξ*/∂(contact dofs)
  ContactMatrix xi_hessian;           ///< ∂²ξ*/∂(contact dofs)² (filled for ContactDerivatives::hessian)
  ContactVector metric_gradient;      ///< ∂|y'(ξ*)|/∂(contact dofs), for the slip increment
};

/// Projects `slave` onto `segment` and evaluates the kinematics at ξ* with
/// the derivatives asked for. Derivatives are those of the smooth extended
/// segment at ξ* even when ξ* ∉ [-1,1] (check projection.inside). When the
/// projection is degenerate, only `projection` is meaningful and derivatives
/// are zero. Throws std::invalid_argument unless segment.size() is 2 or 3.
SegmentGeometry segment_geometry(const Eigen::Vector2d& slave, std::span<const Eigen::Vector2d> segment,
                                 ContactDerivatives derivatives = ContactDerivatives::hessian,
                                 const ProjectionOptions& options = {});

/// Largest number of unknowns of the slip increment: the slave node, the
/// current segment and the segment of the last converged increment, 2 each.
inline constexpr int kMaxSlipDofs = 2 * (1 + 2 * kMaxSegmentNodes);
/// Gradient of the slip increment (no heap allocation).
using SlipVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxSlipDofs, 1>;

/// Tangential slip increment since the last converged increment, in the
/// current configuration,
///     Δs = (y_s - ȳ_c)·t(ξ*),   ȳ_c = Σ_a N_a(ξ_c) z_c^a     [length],
/// positive along t: the motion of the slave relative to the master point it
/// was paired with at the last converged increment (ξ_c on the committed
/// segment z_c, at the committed segment's CURRENT node positions), resolved
/// along the current tangent. Since y_s - y(ξ*) = g n, Δs = (y(ξ*) - ȳ_c)·t,
/// the form evaluated (exactly 0 when ξ* = ξ_c on the same segment, so that
/// round-off does not decide stick or slip at the start of an increment);
/// on a straight segment this is |y'| (ξ* - ξ_c), on curved ones it agrees
/// with the arc length to second order in the slip. The committed segment may
/// be the current one (then pass the same points) or another one (after a
/// hand-over); nothing else about it is assumed.
struct SlipIncrement {
  double value = 0;  ///< Δs [length]
  /// ∂Δs/∂[y_s, y^1..y^m, z_c^1..z_c^{m_c}] (2 (1 + m + m_c) entries), with
  /// the variation of ξ* and t; filled unless ContactDerivatives::none is asked for.
  SlipVector gradient;
};

/// Δs and its gradient for the slave at `slave`, whose closest point on
/// `segment` is described by `geometry` (segment_geometry() of the same
/// points, with at least ContactDerivatives::gradient when a gradient is
/// asked for; ContactDerivatives::hessian is treated as gradient), and the
/// committed point at ξ_c = `committed_xi` on `committed_segment` (2 or 3
/// points). Gradient: δΔs = (δy_s - δȳ_c)·t + w·δy'(ξ*), w = ((y_s - ȳ_c)·n / |y'|) n,
/// δy'(ξ*) = y''(ξ*) δξ* + Σ N_a'(ξ*) δy^a. Zero value and gradient on a degenerate segment.
/// Throws std::invalid_argument unless both segments have 2 or 3 points.
SlipIncrement slip_increment(const Eigen::Vector2d& slave, std::span<const Eigen::Vector2d> segment,
                             const SegmentGeometry& geometry, std::span<const Eigen::Vector2d> committed_segment,
                             double committed_xi, ContactDerivatives derivatives = ContactDerivatives::gradient);

}  // namespace tether
