#pragma once
/// \file An ABAQUS-style user MPC routine (tether/constraints/user_mpc.h) as a
/// constraint function f(u) = 0, enforced like any other by ConstraintElement.
///
/// The routine gives, for the current displacements, the value UE that the
/// dependent dof(s) of the first node must take and the coefficients A of the
/// linearised constraint (ABAQUS's meaning: sum_k A(k) du_k = 0, A(1) on the
/// dependent dof). tether does not eliminate the dependent dof; it enforces
///
///   MODE=DOF:  f   = u_dep   - UE(u)      (1 equation)
///   MODE=NODE: f_i = u_dep,i - UE_i(u)    (MDOF equations, MDOF = 1 or 2)
///
/// Gradient G = df/du: A normalised so that df/du_dep = 1, i.e.
///   DOF:  G(0, dof of entry k) += A(k) / A(1)
///   NODE: G = B^-1 [A(.,.,1) | A(.,.,2) | ...] with B = A(.,.,1) (MDOF x MDOF),
/// each column scattered to the dof JDOF of its node entry (entries naming the
/// same global dof add up). This is the exact derivative of f when A is the
/// exact linearisation of UE (A(k)/A(1) = -dUE/du_k).
///
/// Hessians: the interface gives no second derivatives, so they are central
/// differences of that normalised gradient — the one place tether
/// differentiates numerically:
///   H_i(:, j) = (G_i(u + h_j e_j) - G_i(u - h_j e_j)) / (2 h_j),  then
///   H_i <- (H_i + H_i^T) / 2,
///   h_j = relative_step * max(L, |u_j|),
/// where L is the constraint's size (largest distance of its nodes from the
/// first node in the reference configuration; max(1, largest |X|) when all
/// nodes coincide). With relative_step = 1e-6 the error is about 1e-10
/// relative to the curvature. That costs 2n + 1 routine calls per tangent (n =
/// number of dofs); switch it off (numerical_hessian = false, Hessians zero)
/// for MPCs that are linear, where it is exact and cheaper.
///
/// Dofs: the x and y dofs of every distinct node in the node list, in order of
/// first appearance (a fixed list, so the sparsity pattern is stable).

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "tether/constraints/constraint_function.hpp"
#include "tether/core/shared_library.hpp"
#include "tether/constraints/user_mpc.h"

namespace tether {

class DofMap;

/// MODE= of `*MPC, USER`.
enum class UserMpcMode { Dof = TETHER_USER_MPC_MODE_DOF, Node = TETHER_USER_MPC_MODE_NODE };

/// Numerical choices of a user MPC (deck parameters later).
struct UserMpcOptions {
  /// true: Hessians by central differences of the routine's A (nonlinear MPCs);
  /// false: Hessians are zero (exact for linear MPCs, one routine call per evaluation).
  bool numerical_hessian = true;
  /// h_j = relative_step * max(L, |u_j|) (see the file comment); > 0.
  double relative_step = 1e-6;
};

class UserMpcConstraint final : public ConstraintFunction {
 public:
  /// Loads `library_path` (shared with other constraints naming the same
  /// library, via SharedLibrary) and looks up `symbol` (a tether_user_mpc_fn;
  /// empty = TETHER_USER_MPC_DEFAULT_SYMBOL).
  /// - `mode`: MODE=DOF or MODE=NODE; `jtype`: JTYPE from the data line;
  /// - `node_indices` / `node_labels` / `reference`: the node entries in deck
  ///   order (a node may appear more than once), same length >= 1: node index
  ///   in `dofs`, user label, reference coordinates;
  /// - `name`: for messages and describe(), e.g. "*MPC USER 3" or NAME=.
  /// Calls the routine once in the reference configuration (U = UINIT = 0,
  /// times 0) to learn the dependent dof(s) and MDOF, which later calls must
  /// keep. Throws ModelError naming the constraint when the library or symbol
  /// is missing or that call fails (see evaluate()); std::invalid_argument on
  /// inconsistent arguments (a programming error of the caller).
  UserMpcConstraint(std::string library_path, std::string symbol, UserMpcMode mode, int jtype,
                    std::vector<int> node_indices, std::vector<int> node_labels,
                    std::vector<Eigen::Vector2d> reference, const DofMap& dofs, std::string name,
                    UserMpcOptions options = {});

  /// x, y of each distinct node, in order of first appearance.
  [[nodiscard]] std::span<const int> dofs() const override { return dofs_; }
  /// 1 (DOF mode) or MDOF (NODE mode, fixed by the reference call).
  [[nodiscard]] int n_equations() const override { return static_cast<int>(dependent_.size()); }

  /// Calls the routine at `in` (and, for the Hessians, at 2n perturbed states).
  /// Throws ModelError naming the constraint, routine and library when the
  /// routine returns nonzero, sets LMPC = 0, returns NaN/Inf, a JDOF out of
  /// range, a zero A(1) / singular A(.,.,1), changes its dependent dofs or
  /// MDOF, or (DOF mode) changes MDOF.
  void evaluate(const ConstraintInput& in, ConstraintOutput& out, bool need_hessian) const override;

  /// false: tether cannot know (even with numerical_hessian off, the gradient
  /// may vary), so the constraint is never eliminated as a linear one.
  [[nodiscard]] bool linear() const override { return false; }
  /// false, conservatively: the Hessians are central differences of the
  /// routine's A, symmetrised in evaluate(), so the tangent is in fact
  /// symmetric; but decks with user MPCs have always been solved as
  /// unsymmetric (LU), and declaring them symmetric would change the
  /// factorization (and the results in their last digits).
  [[nodiscard]] bool symmetric_hessian() const override { return false; }
  [[nodiscard]] std::string describe() const override { return name_; }

  /// Global dofs of the dependent dof(s), one per equation.
  [[nodiscard]] std::vector<int> dependent_dofs() const;
  [[nodiscard]] UserMpcMode mode() const { return mode_; }
  [[nodiscard]] int jtype() const { return jtype_; }
  [[nodiscard]] const UserMpcOptions& options() const { return options_; }
  [[nodiscard]] const std::string& library_path() const { return library_->path(); }
  [[nodiscard]] const std::string& symbol() const { return symbol_; }

 private:
  struct Linearisation;

  /// One routine call at local displacements `u` (size n, order of dofs()),
  /// checked and turned into f and the normalised gradient.
  Linearisation call(const Eigen::VectorXd& u, const Eigen::VectorXd& u_start, double step_time, double total_time,
                     bool perturbed) const;
  [[nodiscard]] std::string who() const;

  std::shared_ptr<SharedLibrary> library_;
  std::string symbol_;
  tether_user_mpc_fn routine_ = nullptr;
  UserMpcMode mode_;
  int jtype_;
  std::vector<int> labels_;        ///< per node entry
  std::vector<int> slot_;          ///< per node entry: index of its node among the distinct nodes
  std::vector<double> x_;          ///< X(2,N), per node entry
  std::vector<int> dofs_;          ///< 2 per distinct node
  std::vector<int> dependent_;     ///< local dof index of each dependent dof (empty until the reference call)
  double length_scale_ = 1;        ///< L of the finite-difference step
  std::string name_;
  UserMpcOptions options_;
};

}  // namespace tether
