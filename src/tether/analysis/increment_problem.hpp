#pragma once
/// \file The equations of one increment, as Newton sees them.

#include <memory>
#include <vector>

#include "tether/analysis/newton.hpp"
#include "tether/assembly/assembler.hpp"
#include "tether/dofs/dof_map.hpp"

namespace tether {

/// Time data of the increment being solved.
struct IncrementTime {
  double step_time = 0;
  double total_time = 0;
  double dt = 0;
  bool nlgeom = false;
};

class ContactPair;
class MortarPair;

class IncrementProblem final : public NewtonProblem {
 public:
  /// `u` holds the current iterate (prescribed values already set) and is
  /// updated in place; `u_start` the converged state; `external` the applied
  /// nodal forces over all dofs; `loads` the load contributions (pressures),
  /// also assembled by `assembler`, used only to size the force scale;
  /// `contact` the contact pairs among the assembler's contributions, whose
  /// search statistics evaluate() reports in the norms (contact_*), and
  /// `mortar` the mortar pairs likewise.
  IncrementProblem(Assembler& assembler, const DofMap& dofs, Eigen::VectorXd& u, const Eigen::VectorXd& u_start,
                   const Eigen::VectorXd& external, std::vector<const Contribution*> loads, IncrementTime time,
                   bool symmetric, const std::vector<std::unique_ptr<ContactPair>>* contact = nullptr,
                   const std::vector<std::unique_ptr<MortarPair>>* mortar = nullptr);
  /// Turns the assembler's residual updates off again.
  ~IncrementProblem() override;
  IncrementProblem(const IncrementProblem&) = delete;
  IncrementProblem& operator=(const IncrementProblem&) = delete;

  /// Enables the assembler's residual updates with a new reference
  /// (Assembler::enable_residual_updates): within one Newton solve the loads
  /// and the contributions' state change with u only. Not with an
  /// unsymmetric tangent (friction): whether a node that slipped still
  /// slips is decided on the cone's edge, |t| = mu p, by round-off, so the
  /// updates' other round-off would change the iterations, not only the
  /// last bits of the answer.
  void begin_solve() override { assembler_.enable_residual_updates(symmetric_); }

  bool evaluate(Eigen::VectorXd& residual, bool with_tangent, IterationNorms& norms, double& force_scale) override;
  [[nodiscard]] const SparseMatrix& tangent() const override { return assembler_.tangent(); }
  void apply_correction(const Eigen::VectorXd& correction, double alpha) override;
  [[nodiscard]] double displacement_norm(const Eigen::VectorXd& correction) const override;
  [[nodiscard]] bool symmetric() const override { return symmetric_; }
  [[nodiscard]] std::string describe_equation(int eq) const override;
  [[nodiscard]] bool is_multiplier_equation(int eq) const override;
  [[nodiscard]] std::uint64_t tangent_revision() const override { return assembler_.tangent_revision(); }
  [[nodiscard]] std::uint64_t outer_revision() const override { return assembler_.outer_revision(); }
  void add_evaluation_time(SolveTiming& timing) const override {
    timing.contact_search += search_seconds_;
    timing.assembly += assembly_seconds_;
  }

  /// Residual over all global dofs from the last evaluate (reactions at prescribed dofs).
  [[nodiscard]] const Eigen::VectorXd& full_residual() const { return full_; }
  [[nodiscard]] EvaluationState state() const;

 private:
  Assembler& assembler_;
  const DofMap& dofs_;
  Eigen::VectorXd& u_;
  const Eigen::VectorXd& u_start_;
  const Eigen::VectorXd& external_;
  std::vector<const Contribution*> loads_;
  IncrementTime time_;
  bool symmetric_;
  const std::vector<std::unique_ptr<ContactPair>>* contact_;
  const std::vector<std::unique_ptr<MortarPair>>* mortar_;
  /// Force scale q of the state `s` from full_ (see evaluate()); `n_disp`: displacement dofs.
  [[nodiscard]] double force_scale_of(const EvaluationState& s, int n_disp) const;

  Eigen::VectorXd full_;
  double search_seconds_ = 0, assembly_seconds_ = 0;  ///< of the last evaluate()
};

}  // namespace tether
