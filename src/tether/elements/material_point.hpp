#pragma once
/// \file Kinematics and constitutive response at one integration point of a 2D solid.
///
/// Pure functions of the displacement gradient: they know the element family
/// (plane strain, plane stress, axisymmetric) but not the mesh. Coordinates
/// are (x, y) or (r, z); the out-of-plane direction (index 2 in Voigt
/// vectors) is z for plane problems and the hoop direction for axisymmetry.

#include <Eigen/Core>
#include <span>

#include "tether/materials/constitutive_model.hpp"
#include "tether/model/element_type.hpp"

namespace tether {

/// State of one integration point.
struct MaterialPoint {
  Eigen::Matrix2d F = Eigen::Matrix2d::Identity();  ///< in-plane deformation gradient (identity for small strain)
  double F33 = 1;                ///< out-of-plane / hoop stretch (finite strain); 1 for small strain
  Eigen::Matrix3d C = Eigen::Matrix3d::Identity();  ///< right Cauchy-Green tensor (finite strain only)
  Vec6 strain = Vec6::Zero();    ///< small strain or Green-Lagrange strain, engineering shear
  Vec6 stress = Vec6::Zero();    ///< Cauchy (small strain) or PK2 (finite strain) stress [force/area]
  Mat6 D = Mat6::Zero();         ///< d stress / d strain; plane stress: condensed (row/column 2 zero)
  double elastic_energy = 0;     ///< elastic strain energy density [energy / reference volume]
  double dissipation = 0;        ///< plastic dissipation of the increment [energy / reference volume]
  /// Plane stress, finite strain: dE33/dE_k (k = 11, 22, 12) along S33 = 0
  /// (MaterialResponse::thickness_sensitivity); zero otherwise.
  Eigen::Vector3d thickness_sensitivity = Eigen::Vector3d::Zero();
};

/// Small strain from the displacement gradient H (H(i,j) = du_i/dx_j) and, for
/// axisymmetry, the hoop strain u_r / r (ignored otherwise), starting from the
/// committed history old_state; the trial history goes to new_state (both
/// material.n_state() values; empty for elastic materials); `where` is handed
/// to the material. Plane stress
/// solves eps_33 so that sigma_33 = 0. Throws ModelError if that fails.
void small_strain_point(const ConstitutiveModel& material, Family family, const Eigen::Matrix2d& H,
                        double hoop_strain, std::span<const double> old_state, std::span<double> new_state,
                        const PointContext& where, MaterialPoint& mp);

/// Small strain from the strain itself (11, 22, 33, engineering 12, then two
/// zeros): the point of a mean-dilatation element, whose volumetric part is
/// the element mean (plane strain then has eps_33 != 0). Histories and
/// errors as small_strain_point.
void small_strain_point_at(const ConstitutiveModel& material, Family family, const Vec6& strain,
                           std::span<const double> old_state, std::span<double> new_state,
                           const PointContext& where, MaterialPoint& mp);

/// Finite strain (total Lagrangian) from H = dU/dX and, for axisymmetry,
/// U_r / R (hoop stretch F33 = 1 + U_r/R); histories as in
/// small_strain_point. Plane strain has F33 = 1; plane stress solves F33 so
/// that S_33 = 0. Throws ModelError when det F <= 0 or the material has no
/// finite-strain form.
void finite_strain_point(const ConstitutiveModel& material, Family family, const Eigen::Matrix2d& H,
                         double hoop_strain, std::span<const double> old_state, std::span<double> new_state,
                         const PointContext& where, MaterialPoint& mp);

/// Finite strain from the deformation gradient itself: in-plane F and the
/// out-of-plane stretch F33 (used as given for plane strain too: a
/// mean-dilatation element scales F33 = 1 by (theta/J)^(1/3); ignored for
/// plane stress, which solves it). Histories and errors as finite_strain_point.
void finite_strain_point_at(const ConstitutiveModel& material, Family family, const Eigen::Matrix2d& F, double F33,
                            std::span<const double> old_state, std::span<double> new_state,
                            const PointContext& where, MaterialPoint& mp);

/// Plane stress under finite strain: the thickness stretch F33 = h/h0 at the
/// in-plane displacement gradient H = dU/dX (S_33 = 0 solved as in
/// finite_strain_point), and its derivative dF33/dH (2x2, entry (i,j) =
/// dF33/dH_ij), from the implicit function S_33(C) = 0. Used by loads that act
/// on the current area of a plane-stress face. Throws ModelError as
/// finite_strain_point does, and for a material that is not an ElasticModel
/// (a plastic point's thickness depends on its history, a thermal one's on
/// its temperature: ContinuumElement::thickness_stretch knows both).
double plane_stress_thickness_stretch(const ConstitutiveModel& material, const Eigen::Matrix2d& H,
                                      Eigen::Matrix2d& dF33_dH);

/// dF33/dH (2x2, entry (i,j) = dF33/dH_ij) of an evaluated plane-stress
/// finite-strain point, from its F, F33 and thickness_sensitivity.
Eigen::Matrix2d thickness_stretch_gradient(const MaterialPoint& mp);

/// Elastic strain energy density [energy / reference volume] of an evaluated point.
double strain_energy_density(const ConstitutiveModel& material, bool nlgeom, const MaterialPoint& mp);

/// Cauchy stress (xx, yy, zz, xy) of an evaluated point: sigma itself for small
/// strain, F S F^T / J for finite strain.
Eigen::Vector4d cauchy_stress(bool nlgeom, const MaterialPoint& mp);

}  // namespace tether
