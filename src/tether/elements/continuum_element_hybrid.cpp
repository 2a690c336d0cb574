/// \file The hybrid (mean-dilatation, Q1P0) path of ContinuumElement: CPE4H
/// and CAX4H. Theory and the derivation of the tangent: docs/theory/elements.md.

#include <Eigen/LU>
#include <array>
#include <cassert>
#include <cmath>
#include <fmt/format.h>

#include "tether/elements/continuum_element.hpp"
#include "tether/elements/mean_dilatation.hpp"

namespace tether {

namespace {
constexpr int kMaxPoints = 9;  ///< integration points of any rule of a quadrilateral
}  // namespace

double ContinuumElement::element_mean(const double* ue, bool nlgeom) const {
  if (!type_->hybrid) return 0;
  const bool axisymmetric = type_->family == Family::Axisymmetric;
  PointGeometry g;
  double volume = 0, current = 0;  // V; v (finite) or the integral of tr eps (small)
  const NodeCoordinates X = reference_coords();
  for (int q = 0; q < n_points_; ++q) {
    point_geometry(q, X, g);
    const PointShape p{g.N, g.G, g.R, axisymmetric};
    volume += g.dV;
    if (nlgeom) {
      current += volume_point(p, ue).J * g.dV;
    } else {
      const ElementVector b = volumetric_row(p);
      current += b.dot(Eigen::Map<const ElementVector>(ue, 2 * n_nodes_)) * g.dV;
    }
  }
  return current / volume;
}

void ContinuumElement::hybrid_point(int q, const PointGeometry& g, const Eigen::Matrix2d& H, double hoop, double mean,
                                    const EvaluationState& s, MaterialPoint& mp, std::span<double> trial) const {
  const bool axisymmetric = type_->family == Family::Axisymmetric;
  if (s.nlgeom) {
    const Eigen::Matrix2d F = Eigen::Matrix2d::Identity() + H;
    const double F33 = axisymmetric ? 1 + hoop : 1.0;
    const double J = F.determinant() * F33;
    if (!(J > 0) || !(F33 > 0) || !(mean > 0))
      throw ModelError(fmt::format("the deformation gradient is not invertible (J = {:.3g}, F33 = {:.3g}, element "
                                   "volume ratio {:.3g}): the element is inverted",
                                   J, F33, mean));
    const double alpha = dilatation_scale(mean, J);
    finite_strain_point_at(*material_, type_->family, alpha * F, alpha * F33, committed_state(q), trial,
                           context(s, q, g), mp);
    return;
  }
  Vec6 strain;
  strain << H(0, 0), H(1, 1), axisymmetric ? hoop : 0.0, H(0, 1) + H(1, 0), 0, 0;
  small_strain_point_at(*material_, type_->family, mean_dilatation_strain(strain, mean), committed_state(q), trial,
                        context(s, q, g), mp);
}

void ContinuumElement::evaluate_hybrid_small(const double* ue, const EvaluationState& s, LocalSystem& out,
                                             bool need_tangent) const {
  // B_bar = B + m (b_bar - b_q)^T / 3, m = (1, 1, 1, 0): linear in u, so the
  // residual is sum B_bar^T sigma dV and the tangent sum B_bar^T D B_bar dV.
  assert(n_points_ <= kMaxPoints);
  const int nd = 2 * n_nodes_;
  const bool axisymmetric = type_->family == Family::Axisymmetric;
  std::array<PointGeometry, kMaxPoints> geo;
  double volume = 0;
  ElementVector b_bar = ElementVector::Zero(nd);
  const NodeCoordinates X = reference_coords();
  for (int q = 0; q < n_points_; ++q) {
    point_geometry(q, X, geo[q]);
    b_bar += volumetric_row(PointShape{geo[q].N, geo[q].G, geo[q].R, axisymmetric}) * geo[q].dV;
    volume += geo[q].dV;
  }
  b_bar /= volume;
  const double mean = element_mean(ue, false);
  MaterialPoint mp;
  std::vector<double> trial(static_cast<std::size_t>(n_state()));  // discarded: evaluate() commits nothing
  for (int q = 0; q < n_points_; ++q) {
    const PointGeometry& g = geo[q];
    const PointShape p{g.N, g.G, g.R, axisymmetric};
    material_point(q, g, ue, s, mp, trial, mean);
    auto B = strain_rows(p, Eigen::Matrix2d::Identity(), 1.0);
    const ElementVector shift = (b_bar - volumetric_row(p)) / 3;
    for (int i = 0; i < 3; ++i) B.row(i) += shift.transpose();
    out.residual += B.transpose() * (mp.stress.head<4>() * g.dV);
    if (need_tangent) out.tangent += B.transpose() * (mp.D.topLeftCorner<4, 4>() * g.dV) * B;
  }
}

void ContinuumElement::evaluate_hybrid_finite(const double* ue, const EvaluationState& s, LocalSystem& out,
                                              bool need_tangent) const {
  // Internal work sum S_bar : dE_bar dV, E_bar = (phi C - I)/2, phi = alpha^2 =
  // (theta/J)^(2/3). With h = (d ln theta - d ln J)/3: dE_bar = phi (B + c h^T) du,
  // c = (C11, C22, C33, 2 C12). The tangent is the exact second derivative
  // (docs/theory/elements.md, "Mean dilatation").
  assert(n_points_ <= kMaxPoints);
  const int nd = 2 * n_nodes_;
  const bool axisymmetric = type_->family == Family::Axisymmetric;
  std::array<PointGeometry, kMaxPoints> geo;
  std::array<VolumePoint, kMaxPoints> vol;
  double volume = 0, current = 0;
  ElementVector dv = ElementVector::Zero(nd);  // dv/du
  ElementMatrix d2v = ElementMatrix::Zero(need_tangent ? nd : 0, need_tangent ? nd : 0);  // d^2 v/du^2
  const NodeCoordinates X = reference_coords();
  for (int q = 0; q < n_points_; ++q) {
    point_geometry(q, X, geo[q]);
    const PointShape p{geo[q].N, geo[q].G, geo[q].R, axisymmetric};
    vol[q] = volume_point(p, ue);
    const double w = vol[q].J * geo[q].dV;
    volume += geo[q].dV;
    current += w;
    dv += w * vol[q].dlnJ;
    if (!need_tangent) continue;
    d2v += w * vol[q].dlnJ * vol[q].dlnJ.transpose();
    add_log_volume_hessian(p, vol[q], w, d2v);
  }
  const double theta = current / volume;
  const ElementVector dln_theta = dv / current;
  ElementMatrix d2ln_theta;
  if (need_tangent) d2ln_theta = d2v / current - dln_theta * dln_theta.transpose();
  MaterialPoint mp;
  std::vector<double> trial(static_cast<std::size_t>(n_state()));  // discarded: evaluate() commits nothing
  for (int q = 0; q < n_points_; ++q) {
    const PointGeometry& g = geo[q];
    const PointShape p{g.N, g.G, g.R, axisymmetric};
    const VolumePoint& v = vol[q];
    material_point(q, g, ue, s, mp, trial, theta);
    const double alpha = dilatation_scale(theta, v.J), phi = alpha * alpha;
    const auto B = strain_rows(p, v.F, v.F33);
    const Eigen::Matrix2d C = v.F.transpose() * v.F;
    const Eigen::Vector4d c(C(0, 0), C(1, 1), v.F33 * v.F33, 2 * C(0, 1));
    const ElementVector h = (dln_theta - v.dlnJ) / 3;
    const Eigen::Matrix<double, 4, Eigen::Dynamic, 0, 4, kMaxElementDofs> B_bar = phi * (B + c * h.transpose());
    const Eigen::Vector4d S = mp.stress.head<4>() * g.dV;
    out.residual += B_bar.transpose() * S;
    if (!need_tangent) continue;
    out.tangent += B_bar.transpose() * (mp.D.topLeftCorner<4, 4>() * g.dV) * B_bar;
    // S_bar : d^2 E_bar = phi [ (S:c)(2 h h^T + (d2 ln theta - d2 ln J)/3)
    //                          + 2 (s_B h^T + h s_B^T) + S : d^2 E ],  s_B = B^T S.
    const double sc = S.dot(c);
    const ElementVector sB = B.transpose() * S;
    ElementMatrix M = sc * (2 * h * h.transpose() + d2ln_theta / 3) + 2 * (sB * h.transpose() + h * sB.transpose());
    add_log_volume_hessian(p, v, -sc / 3, M);
    add_geometric_stiffness(p, S, M);
    out.tangent += phi * M;
  }
}

}  // namespace tether
