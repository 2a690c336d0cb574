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
/// argument list, small strain. The state of a point is the UMAT's view of
/// the start of an increment: stress, total strain, SSE, SPD, SCD, then the
/// NSTATV state variables.
class UserMaterial final : public ConstitutiveModel {
 public:
  static constexpr int kHeader = 15;  ///< stress (6), strain (6), SSE, SPD, SCD

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
  /// Throws ModelError: user materials are small strain only in tether.
  void update_finite_strain(Eigen::Matrix3d& C, bool plane_stress, std::span<const double> old_state,
                            std::span<double> new_state, const PointContext& where,
                            MaterialResponse& out) const override;
  [[nodiscard]] bool linear_small_strain() const override { return false; }
  /// False: tether cannot vouch for a user routine's DDSDDE.
  [[nodiscard]] bool symmetric_tangent(bool /*nlgeom*/) const override { return false; }
  /// DDSDDE(4,4) of the zero-strain call (plane strain) [stress].
  [[nodiscard]] double shear_modulus() const override { return mu_; }
  [[nodiscard]] std::string describe() const override;

 private:
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
