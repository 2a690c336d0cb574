#pragma once
/// \file `*USER MATERIAL`: an ABAQUS UMAT from a shared library (see user_material.h).

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "tether/materials/constitutive_model.hpp"
#include "tether/materials/user_material.h"

namespace tether {

class SharedLibrary;

/// A constitutive model computed by a user routine with ABAQUS's UMAT
/// argument list, small strain and finite strain (NLGEOM; the kinematics are
/// in docs/theory/user_material.md). The state of a point is the UMAT's view
/// of the start of an increment: stress, total strain, SSE, SPD, SCD, the
/// right stretch less the identity U - I (Voigt, tensor shear; the small
/// strain itself after a small-strain update, so that an NLGEOM step after a
/// small-strain one starts from U = I + eps), then the NSTATV state variables. Under NLGEOM the stress
/// and strain are stored in the polar-rotated frame (R^T sigma R).
class UserMaterial final : public ConstitutiveModel {
 public:
  static constexpr int kHeader = 21;  ///< stress (6), strain (6), SSE, SPD, SCD, U - I (6)

  /// Loads `symbol` (empty: umat_) from `library`, and calls it once at zero
  /// strain for the initial shear stiffness. name: the material name (CMNAME);
  /// props: PROPS; n_statev: NSTATV >= 0. Throws ModelError when the library
  /// or the routine cannot be found or the zero-strain call returns NaN.
  UserMaterial(std::string name, const std::string& library, std::string symbol, std::vector<double> props,
               int n_statev);

  [[nodiscard]] int n_state() const override { return kHeader + n_statev_; }
  /// Calls the routine once from old_state. Throws ModelError naming the
  /// material, the element and the point when an output is NaN or infinite,
  /// or when the routine sets PNEWDT < 1 (the increment is then cut back).
  void update_small_strain(Vec6& eps, bool plane_stress, std::span<const double> old_state,
                           std::span<double> new_state, const PointContext& where,
                           MaterialResponse& out) const override;
  /// Finite strain (NLGEOM): calls the routine in the frame rotated by the
  /// polar rotation R of F = R U, with STRESS = the corotational Cauchy stress
  /// at the start rotated by DROT, DSTRAN and DROT from the Hughes-Winget
  /// midpoint increment (U1 - U0)((U0 + U1)/2)^-1, DFGRD0/1 = U0, U1; returns
  /// PK2 S = J U^-1 sigma U^-1 and dS/dE with DDSDDE taken as d STRESS / d
  /// DSTRAN at a fixed rotated start stress. Plane stress: throws ModelError
  /// (the thickness stretch of a user material is not known). Errors as in
  /// update_small_strain.
  void update_finite_strain(Eigen::Matrix3d& C, bool plane_stress, std::span<const double> old_state,
                            std::span<double> new_state, const PointContext& where,
                            MaterialResponse& out) const override;
  [[nodiscard]] int n_user_state() const override { return n_statev_; }
  /// STATEV: the last NSTATV values of a state.
  [[nodiscard]] std::span<const double> user_state(std::span<const double> state) const override {
    return state.subspan(kHeader, static_cast<std::size_t>(n_statev_));
  }
  [[nodiscard]] bool linear_small_strain() const override { return false; }
  /// False: tether cannot vouch for a user routine's DDSDDE.
  [[nodiscard]] bool symmetric_tangent(bool /*nlgeom*/) const override { return false; }
  /// DDSDDE(4,4) of the zero-strain call (plane strain) [stress].
  [[nodiscard]] double shear_modulus() const override { return mu_; }
  [[nodiscard]] std::string describe() const override;

 private:
  /// One call's arrays in ABAQUS's order (NTENS = ntens <= 4), in and out.
  struct UmatCall {
    int ntens = 4;
    double stress[4] = {}, stran[4] = {}, dstran[4] = {}, ddsdde[16] = {};
    double sse = 0, spd = 0, scd = 0;
    std::array<double, 9> drot{1, 0, 0, 0, 1, 0, 0, 0, 1}, dfgrd0{}, dfgrd1{};  ///< column-major 3x3
  };
  /// Calls the routine with c's arrays and the context's times, temperature
  /// and point; SSE, SPD, SCD from old_state, STATEV copied into new_state
  /// and updated there, with new_state's SSE, SPD, SCD. Throws ModelError on
  /// a NaN or infinite output or PNEWDT < 1.
  void call_routine(UmatCall& c, std::span<const double> old_state, std::span<double> new_state,
                    const PointContext& where) const;

  std::string name_;
  std::string symbol_;
  std::shared_ptr<SharedLibrary> library_;
  tether_umat_fn routine_ = nullptr;
  std::array<char, 80> cmname_{};
  std::vector<double> props_;
  int n_statev_;
  double mu_ = 0;
};

}  // namespace tether
