#pragma once
/// \file Kinematics of 2D mortar (segment-to-segment) contact: averaged slave
/// nodal normals, projection along the slave normal field, exact segmentation
/// of a slave segment by the projected master segments, the mortar integrals
/// D (diagonal, dual basis) and M, and the weighted gap of a slave node.
/// Pure functions of current positions, templated on the scalar: double for
/// values, Dual2 for exact first and second derivatives (the complete
/// linearisation, segmentation and normals included).
/// Theory and conventions: docs/theory/mortar.md.
///
/// Segments are 2- or 3-node faces in face_nodes() order (corners at ξ = -1
/// and +1, mid-side node at ξ = 0), counter-clockwise around their element,
/// so the outward unit normal of a face is n = (t_y, -t_x), t = x'(ξ)/|x'(ξ)|.
/// The gap is measured along the slave's outward normal field: positive when
/// the master surface lies outside the slave body (open).

#include <array>
#include <optional>
#include <span>
#include <vector>

#include "tether/contact/dual2.hpp"

namespace tether {

/// A 2D point or vector with a scalar T (double or Dual2).
template <class T>
struct Vec2T {
  T x{}, y{};
  friend Vec2T operator+(const Vec2T& a, const Vec2T& b) { return {a.x + b.x, a.y + b.y}; }
  friend Vec2T operator-(const Vec2T& a, const Vec2T& b) { return {a.x - b.x, a.y - b.y}; }
  friend Vec2T operator*(const T& s, const Vec2T& a) { return {s * a.x, s * a.y}; }
};
/// r += a b (r -= a b with `subtract`); for Dual2 without a temporary (the same bits).
inline void add_product(double& r, double a, double b, bool subtract = false) { r = subtract ? r - a * b : r + a * b; }
inline void add_product(Dual2& r, const Dual2& a, const Dual2& b, bool subtract = false) { r.add_product(a, b, subtract); }

template <class T>
T dot(const Vec2T<T>& a, const Vec2T<T>& b) {
  T r = a.x * b.x;
  add_product(r, a.y, b.y);
  return r;
}
/// z-component of a × b.
template <class T>
T cross(const Vec2T<T>& a, const Vec2T<T>& b) {
  T r = a.x * b.y;
  add_product(r, a.y, b.x, true);
  return r;
}

/// Largest number of nodes of a mortar segment (quadratic faces).
inline constexpr int kMaxMortarSegmentNodes = 3;

/// Shape functions N and dN/dξ of a 2- or 3-node segment at ξ (T may be Dual2).
template <class T>
void segment_shapes(int n_nodes, const T& xi, std::array<T, 3>& N, std::array<T, 3>& dN);

/// Outward unit normal of segment `x` (2 or 3 points) at ξ.
template <class T>
Vec2T<T> segment_normal(std::span<const Vec2T<T>> x, const T& xi);

/// Averaged nodal normal: the normalised sum of the outward unit normals at
/// that node of the segments that share it (`segments[k]` with the node at
/// local position `at[k]`). One segment at an end of the surface.
template <class T>
Vec2T<T> nodal_normal(std::span<const std::vector<Vec2T<T>>> segments, std::span<const int> at);

/// ξ on slave segment `x` with nodal normals `normals` whose normal ray
/// passes through point p: (p - x(ξ)) × n(ξ) = 0, n(ξ) = Σ N_a(ξ) n_a.
/// Newton from the closest-point guess; none when it does not converge
/// within |ξ| <= 3 (p far outside the segment's reach).
template <class T>
std::optional<T> project_along_slave_normals(const Vec2T<T>& p, std::span<const Vec2T<T>> x,
                                             std::span<const Vec2T<T>> normals);

/// η on master segment `y` where the ray from p along direction d meets it:
/// (y(η) - p) × d = 0. None when y'(η) is parallel to d (or no convergence).
template <class T>
std::optional<T> project_onto_master(const Vec2T<T>& p, const Vec2T<T>& d, std::span<const Vec2T<T>> y);

/// The mortar integrals of one slave segment against some master segments.
template <class T>
struct SegmentMortar {
  int n_slave = 2;  ///< nodes of the slave segment
  /// D_k [area]: the row sum Σ_l ∫ Φ_k N_l dA over the overlapped part of the
  /// segment, per slave node k (= ∫ Φ_k N_k dA, D diagonal, when the whole
  /// segment is overlapped: the dual basis is biorthogonal over it).
  std::array<T, 3> D{};
  /// M[f][k][a] = ∫ Φ_k N^f_a(η(ξ)) dA [area] over the overlap with master
  /// segment f, per slave node k and node a of f.
  std::vector<std::array<std::array<T, 3>, 3>> M;
  /// Overlap [ξ_lo, ξ_hi] of master segment f on the slave segment (values;
  /// ξ_lo >= ξ_hi: none).
  std::vector<std::array<double, 2>> overlap;
};

/// Integrates D and M of slave segment `x` (nodal normals `normals`, unit)
/// against each of `masters` (2- or 3-point segments, current positions):
/// segments at the projections of the master ends onto the slave along its
/// normal field, then `n_gauss` Gauss points per overlap, each projected onto
/// the master along the interpolated normal n(ξ). Φ is the dual basis of the
/// slave segment (biorthogonal to its N over the whole segment with the
/// current Jacobian). `thickness` multiplies every integral (dA = t ds).
/// Master segments with the slave's orientation (not facing it) are skipped.
/// `measure`: when given, the reference positions of the slave segment,
/// whose Jacobian then replaces the current one in dA and in the dual basis
/// (geometrically linear steps: λ conjugate to D is then a force per
/// reference area, like the loads); empty: the current Jacobian (NLGEOM:
/// λ is the Cauchy contact pressure).
template <class T>
SegmentMortar<T> integrate_segment(std::span<const Vec2T<T>> x, std::span<const Vec2T<T>> normals,
                                   std::span<const std::vector<Vec2T<T>>> masters, double thickness,
                                   int n_gauss = 6, std::span<const Vec2T<double>> measure = {});

/// Dual basis coefficients A (Φ_k = Σ_l A_kl N_l) of slave segment `x`
/// (the positions that define its Jacobian):
/// A = D_e M_e⁻¹ with D_e = diag ∫ N_k ds and M_e = ∫ N_k N_l ds over the
/// segment. For a straight 2-node segment A = [[2, -1], [-1, 2]].
template <class T>
std::array<std::array<T, 3>, 3> dual_coefficients(std::span<const Vec2T<T>> x);

}  // namespace tether
