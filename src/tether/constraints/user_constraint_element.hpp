#pragma once
/// \file A constraint whose residual and stiffness come from a user routine in
/// a shared library (the C plug-in interface of user_constraint.h).
///
/// Unknowns: the x, y displacements of the constraint's nodes in the order
/// given, then its m multipliers. tether gathers coordinates, displacements
/// and multipliers, calls the routine, checks the outputs and hands them to the
/// assembler unchanged, so the routine decides the formulation (Lagrange,
/// regularised f - eps*lambda, penalty with m = 0, ...).

#include <memory>
#include <string>
#include <vector>

#include "tether/assembly/contribution.hpp"
#include "tether/core/shared_library.hpp"
#include "tether/constraints/user_constraint.h"
#include "tether/model/results.hpp"

namespace tether {

class DofMap;

class UserConstraintElement final : public Contribution {
 public:
  /// Loads `library_path` (shared with other constraints naming the same
  /// library) and looks up `symbol` (a tether_user_constraint_fn; empty = the
  /// default TETHER_USER_CONSTRAINT_DEFAULT_SYMBOL).
  /// - `number`: 1-based constraint number passed to the routine;
  /// - `node_indices` / `node_labels` / `reference`: the nodes (index, user
  ///   label, reference coordinates), same length, in the order given;
  /// - `properties`: passed to the routine as is;
  /// - `n_multipliers` >= 0 unknowns starting at global index
  ///   `first_multiplier` (reserved by the caller with DofMap::add_multipliers;
  ///   ignored when n_multipliers is 0);
  /// - `name`: for messages and output; `flag`: the routine's `flag` input.
  /// Throws ModelError naming the path, the symbol and dlerror() when the
  /// library cannot be loaded or lacks the symbol; std::invalid_argument on
  /// inconsistent arguments (a programming error of the caller).
  UserConstraintElement(std::string library_path, std::string symbol, int number, std::vector<int> node_indices,
                        std::vector<int> node_labels, std::vector<Eigen::Vector2d> reference,
                        std::vector<double> properties, int n_multipliers, int first_multiplier, const DofMap& dofs,
                        std::string name, int flag = 0);

  [[nodiscard]] std::span<const int> dofs() const override { return dofs_; }

  /// Calls the routine. Throws ModelError naming the constraint, the routine
  /// and its message when it returns nonzero or produces NaN/Inf (Newton then
  /// cuts the increment back).
  void evaluate(const EvaluationState& state, LocalSystem& out, bool need_tangent) const override;

  [[nodiscard]] std::string describe() const override { return name_; }
  /// false: the routine's tangent is its own (often finite differences), and
  /// tether cannot vouch for its symmetry.
  [[nodiscard]] bool symmetric_tangent(bool /*nlgeom*/) const override { return false; }
  /// false: tether cannot know how the routine's residual depends on u.
  [[nodiscard]] bool linear_in_u(bool /*nlgeom*/) const override { return false; }

  /// For output: value = the multipliers lambda_k from the state; constraint =
  /// the routine's multiplier rows of the residual (f_k - eps*lambda_k in the
  /// Lagrange form). tether cannot separate f from the regularisation term, so
  /// this is f exactly only when the routine uses no regularisation; with
  /// m = 0 both lists are empty.
  [[nodiscard]] MultiplierValues values(const EvaluationState& state) const;

  [[nodiscard]] int n_nodes() const { return static_cast<int>(node_labels_.size()); }
  [[nodiscard]] int n_multipliers() const { return m_; }
  [[nodiscard]] const std::string& library_path() const { return library_->path(); }
  [[nodiscard]] const std::string& symbol() const { return symbol_; }

 private:
  /// Runs the routine at `state`; fills residual (n) and, if need_tangent, tangent.
  void call(const EvaluationState& state, Eigen::VectorXd& residual, Eigen::MatrixXd* tangent) const;
  [[nodiscard]] std::string who() const;

  std::shared_ptr<SharedLibrary> library_;
  std::string symbol_;
  tether_user_constraint_fn routine_ = nullptr;
  int number_ = 0, flag_ = 0;
  std::vector<int> node_indices_, node_labels_;
  std::vector<double> coordinates_;  ///< x0, y0, x1, y1, ...
  std::vector<double> properties_;
  int m_ = 0;
  std::vector<int> dofs_;            ///< 2 per node, then the multipliers
  std::string name_;
};

}  // namespace tether
