#pragma once
/// \file Plane-stress condensation of a 3D elastic model.
///
/// The out-of-plane normal stress is driven to zero by a local Newton
/// iteration on the out-of-plane strain; the tangent returned is the
/// condensed one, D_ab - D_a3 D_3b / D_33, so that in-plane strain increments
/// map to stress increments with sigma_33 = 0 kept. Shear components 23 and 13
/// are zero in 2D and left alone.

#include "tether/materials/constitutive_model.hpp"

namespace tether {

/// Small strain. In: eps with the in-plane components 11, 22, 12 (index 0, 1,
/// 3); eps(2) is the starting guess for eps_33 (0 is fine). Out: eps(2) such
/// that sigma_33 = 0 to round-off, the stress (sigma(2) ~ 0) and the condensed
/// tangent D (row and column 2 zero). Throws ModelError when the iteration does
/// not converge in 50 steps.
void plane_stress_small_strain(const ElasticModel& model, Vec6& eps, Vec6& sigma, Mat6& D);

/// Finite strain. In: C with the in-plane block set; C(2,2) is the starting
/// guess for the squared out-of-plane stretch (1 is fine), C(0,2), C(1,2) must
/// be zero. Out: C(2,2) with S_33 = 0 to round-off, S and the condensed tangent
/// dS/dE (row and column 2 zero); `sensitivity` (if given): dE33/dE_k
/// (k = 11, 22, 12) as thickness_sensitivity() gives it. Throws ModelError
/// when the iteration fails.
void plane_stress_finite_strain(const ElasticModel& model, Eigen::Matrix3d& C, Vec6& S, Mat6& D,
                                Eigen::Vector3d* sensitivity = nullptr);

/// Removes row and column 2 (the 33 direction) by static condensation, in place.
void condense_out_of_plane(Mat6& D);

/// The out-of-plane strain's change with the in-plane strains that keeps the
/// out-of-plane stress at zero: dE33/dE_k = -D(2, k) / D(2, 2) for k = 11,
/// 22, 12 (engineering shear), from the uncondensed tangent D (D(2, 2) > 0).
Eigen::Vector3d thickness_sensitivity(const Mat6& D);

}  // namespace tether
