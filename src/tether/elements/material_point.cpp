#include "tether/elements/material_point.hpp"

#include <Eigen/LU>
#include <cmath>
#include <fmt/format.h>

#include "tether/materials/plane_stress.hpp"

namespace tether {

namespace {

void take_response(const MaterialResponse& r, MaterialPoint& mp) {
  mp.stress = r.stress;
  mp.D = r.tangent;
  mp.elastic_energy = r.elastic_energy;
  mp.dissipation = r.dissipation;
  mp.thickness_sensitivity = r.thickness_sensitivity;
}

}  // namespace

void small_strain_point(const ConstitutiveModel& material, Family family, const Eigen::Matrix2d& H,
                        double hoop_strain, std::span<const double> old_state, std::span<double> new_state,
                        const PointContext& where, MaterialPoint& mp) {
  Vec6 strain;
  strain << H(0, 0), H(1, 1), family == Family::Axisymmetric ? hoop_strain : 0.0, H(0, 1) + H(1, 0), 0, 0;
  small_strain_point_at(material, family, strain, old_state, new_state, where, mp);
}

void small_strain_point_at(const ConstitutiveModel& material, Family family, const Vec6& strain,
                           std::span<const double> old_state, std::span<double> new_state,
                           const PointContext& where, MaterialPoint& mp) {
  mp.strain = strain;
  MaterialResponse r;
  material.update_small_strain(mp.strain, family == Family::PlaneStress, old_state, new_state, where, r);
  take_response(r, mp);
}

void finite_strain_point(const ConstitutiveModel& material, Family family, const Eigen::Matrix2d& H,
                         double hoop_strain, std::span<const double> old_state, std::span<double> new_state,
                         const PointContext& where, MaterialPoint& mp) {
  finite_strain_point_at(material, family, Eigen::Matrix2d::Identity() + H,
                         family == Family::Axisymmetric ? 1 + hoop_strain : 1.0, old_state, new_state, where, mp);
}

void finite_strain_point_at(const ConstitutiveModel& material, Family family, const Eigen::Matrix2d& F, double F33,
                            std::span<const double> old_state, std::span<double> new_state,
                            const PointContext& where, MaterialPoint& mp) {
  mp.F = F;
  const double det2 = mp.F.determinant();
  mp.F33 = family == Family::PlaneStress ? 1.0 : F33;
  if (!(det2 > 0) || !(mp.F33 > 0))
    throw ModelError(fmt::format("the deformation gradient is not invertible (in-plane det F = {:.3g}, "
                                 "F33 = {:.3g}): the element is inverted",
                                 det2, mp.F33));
  mp.C.setZero();
  mp.C.topLeftCorner<2, 2>().noalias() = mp.F.transpose() * mp.F;
  mp.C(2, 2) = mp.F33 * mp.F33;
  MaterialResponse r;
  material.update_finite_strain(mp.C, family == Family::PlaneStress, old_state, new_state, where, r);
  take_response(r, mp);
  if (family == Family::PlaneStress) mp.F33 = std::sqrt(mp.C(2, 2));
  mp.strain << 0.5 * (mp.C(0, 0) - 1), 0.5 * (mp.C(1, 1) - 1), 0.5 * (mp.C(2, 2) - 1), mp.C(0, 1), 0, 0;
}

double plane_stress_thickness_stretch(const ConstitutiveModel& material, const Eigen::Matrix2d& H,
                                      Eigen::Matrix2d& dF33_dH) {
  if (dynamic_cast<const ElasticModel*>(&material) == nullptr)
    throw ModelError("a load on the current area of a plane-stress face needs its element for the thickness of " +
                     material.describe());
  MaterialPoint mp;
  finite_strain_point(material, Family::PlaneStress, H, 0, {}, {}, PointContext{}, mp);
  dF33_dH = thickness_stretch_gradient(mp);
  return mp.F33;
}

Eigen::Matrix2d thickness_stretch_gradient(const MaterialPoint& mp) {
  // S_33(E) = 0 holds for every in-plane E: dE33 = s_k dE_k over k = 11, 22,
  // 12 (engineering shear), s = -D_3k / D_33 of the uncondensed tangent.
  // E11 = (F_i1 F_i1 - 1)/2, E22 = (F_i2 F_i2 - 1)/2, G12 = F_i1 F_i2, F = I + H;
  // E33 = (F33^2 - 1)/2, so dF33 = dE33 / F33.
  const Eigen::Vector3d& s = mp.thickness_sensitivity;
  const Eigen::Matrix2d& F = mp.F;
  Eigen::Matrix2d d;
  for (int i = 0; i < 2; ++i) {
    d(i, 0) = s(0) * F(i, 0) + s(2) * F(i, 1);
    d(i, 1) = s(1) * F(i, 1) + s(2) * F(i, 0);
  }
  return d / mp.F33;
}

double strain_energy_density(const ConstitutiveModel& /*material*/, bool /*nlgeom*/, const MaterialPoint& mp) {
  return mp.elastic_energy;
}

Eigen::Vector4d cauchy_stress(bool nlgeom, const MaterialPoint& mp) {
  if (!nlgeom) return mp.stress.head<4>();
  Eigen::Matrix2d S;
  S << mp.stress(0), mp.stress(3), mp.stress(3), mp.stress(1);
  const double J = mp.F.determinant() * mp.F33;
  const Eigen::Matrix2d sigma = mp.F * S * mp.F.transpose() / J;
  return {sigma(0, 0), sigma(1, 1), mp.F33 * mp.F33 * mp.stress(2) / J, sigma(0, 1)};
}

}  // namespace tether
