#pragma once
/// \file The equations of one step, as every procedure (static, dynamic) solves them.
///
/// A StepSystem gathers what a step sets up before its first increment: the
/// step's contributions (elements, constraints, user constraints, contact
/// pairs with their nodes, the step's pressure loads), the prescribed dofs
/// (the step's boundary conditions and the nodes no contribution uses), the
/// EquationMap, the Assembler over them and the LinearSolver (condensed onto
/// the contact equations when that pays). Each contribution declares whether
/// its tangent is symmetric and whether it is linear in u; the system combines
/// the declarations. Procedures borrow the system and decide when to assemble
/// and solve. See docs/theory/procedures.md.

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "tether/analysis/discretization.hpp"
#include "tether/analysis/increment_controller.hpp"
#include "tether/analysis/step_body_forces.hpp"
#include "tether/analysis/step_loads.hpp"
#include "tether/assembly/assembler.hpp"
#include "tether/elements/element_inertia.hpp"
#include "tether/solvers/dual_condensation.hpp"
#include "tether/solvers/linear_solver.hpp"

namespace tether {

class CondensedSolver;

/// How the step's linear systems are solved (AnalysisOptions' solver part).
struct SolverSettings {
  SolverKind solver = SolverKind::Auto;
  /// With the Auto solver and contact (not under NLGEOM): condense onto the
  /// contact equations while they are few (CondensedSolver).
  bool condense_contact = true;
  double memory_budget_mb = 0;  ///< [MB], 0 = no limit (see AnalysisOptions)
  /// When the bulk is linear (bulk_linear()): the assembler holds the linear
  /// contributions' tangents (Assembler::set_linear) and Newton reuses the
  /// factorization of an unchanged tangent. Off: every iteration assembles
  /// and factorizes everything (the results are the same bit for bit).
  bool reuse_linear_bulk = true;
  /// With mortar pairs: how their multipliers are treated (MortarCondensation).
  MortarCondensation mortar_condensation = MortarCondensation::Dense;
  /// Condense onto the contact equations however few the other equations
  /// are (the size limits of the choice are for speed only): for tests of
  /// the condensed paths on small decks.
  bool condense_any_size = false;
};

class StepSystem {
 public:
  /// Builds the system of `step` over `discretization` (both must outlive
  /// it), with `loads` from make_step_loads. `u` and `total_time` are the
  /// state at the start of the step (for the constraint checks). `message`
  /// receives notes while the system is built (nodes without dofs). Throws
  /// ModelError for a step that cannot be solved: redundant or conflicting
  /// constraints (EquationMap, check_constraints), or a solver that reads
  /// one triangle (MUMPS LDLT, CHOLMOD) for an unsymmetric tangent.
  StepSystem(const Discretization& discretization, const Step& step, StepLoads loads, const Eigen::VectorXd& u,
             double total_time, const SolverSettings& settings,
             const std::function<void(const std::string&)>& message = {});
  ~StepSystem();
  StepSystem(const StepSystem&) = delete;
  StepSystem& operator=(const StepSystem&) = delete;

  [[nodiscard]] const Discretization& discretization() const { return discretization_; }
  [[nodiscard]] const Step& step() const { return step_; }
  [[nodiscard]] const StepLoads& loads() const { return loads_; }
  /// One per loads().pressures, in that order (magnitudes set by the procedure).
  [[nodiscard]] const std::vector<std::unique_ptr<FacePressure>>& pressures() const { return pressures_; }
  /// The step's body loads (*DLOAD GRAV, CENTRIF; magnitudes set by the procedure with set_time).
  [[nodiscard]] StepBodyForces& body_forces() { return *body_forces_; }
  [[nodiscard]] const StepBodyForces& body_forces() const { return *body_forces_; }
  /// Everything assembled, in assembly order: elements, constraints, user
  /// constraints, each contact pair followed by its nodes, pressures, body forces, and in
  /// an implicit dynamic step the elements' inertia.
  [[nodiscard]] const std::vector<Contribution*>& contributions() const {
    return assembler_ ? assembler_->contributions() : contributions_;
  }
  /// The load contributions (pressures, body forces): they size Newton's force scale.
  [[nodiscard]] const std::vector<const Contribution*>& load_contributions() const { return load_contributions_; }

  /// Dynamic steps: one per element, in the order of the discretization's
  /// elements (lumped for EXPLICIT and MASS=LUMPED); empty in static steps.
  /// Assembled only in implicit steps.
  [[nodiscard]] const std::vector<std::unique_ptr<ElementInertia>>& inertia() const { return inertia_; }
  /// The Newmark data the inertia reads: set by the dynamic procedure before each attempt.
  [[nodiscard]] NewmarkIncrement& newmark() { return newmark_; }

  /// Sets the prescribed values in `u` (and the dependent dofs), the nodal
  /// forces `forces` (over all dofs) and the pressures to their magnitudes at
  /// the time `t` of the step (step_time, period and total_time are used).
  void apply_loads(const IncrementTimes& t, Eigen::VectorXd& u, Eigen::VectorXd& forces);

  /// The assembler of an implicit (static or dynamic) step; an explicit step
  /// has none (has_assembler() false; std::logic_error).
  [[nodiscard]] Assembler& assembler();
  [[nodiscard]] const Assembler& assembler() const;
  [[nodiscard]] bool has_assembler() const { return assembler_ != nullptr; }
  [[nodiscard]] const EquationMap& equations() const;
  [[nodiscard]] LinearSolver& solver() { return *solver_; }
  [[nodiscard]] const LinearSolver& solver() const { return *solver_; }
  /// The condensed solver when the system condenses onto the contact equations, else null.
  [[nodiscard]] const CondensedSolver* condensed() const { return condensed_; }

  /// Nodes that no contribution uses: their displacements are prescribed to zero.
  [[nodiscard]] int n_unused_nodes() const { return unused_nodes_; }
  /// Every contribution declares a symmetric tangent under the step's NLGEOM.
  [[nodiscard]] bool symmetric() const { return symmetric_; }
  /// Every contribution outside contact (elements, constraints, loads and
  /// in dynamic steps the inertia) is linear in u under the step's NLGEOM:
  /// with SolverSettings::reuse_linear_bulk the assembler then holds their
  /// tangents, assembled again only at a pattern change or, in an implicit
  /// dynamic step, at another increment size (the inertia's tangent is
  /// M / (beta dt^2) + ...), and an unchanged tangent is not factorized again.
  [[nodiscard]] bool bulk_linear() const { return bulk_linear_; }

 private:
  /// Fills inertia_ in dynamic steps (ModelError: a material without *DENSITY).
  void make_inertia();
  /// Fills contributions_, load_contributions_ and bulk_linear_.
  void gather_contributions();
  /// The step's prescribed dofs, and the dofs of nodes no contribution uses.
  std::vector<bool> prescribed_dofs();
  /// The contact equations to condense onto (empty: no condensation).
  [[nodiscard]] std::vector<int> condensation_interface(const EquationMap& equations) const;
  /// True when the tangent is stored as its lower triangle (Assembler):
  /// symmetric, and every solver the step may use reads one triangle.
  [[nodiscard]] bool lower_triangle() const;
  void make_solver(std::vector<int> interface);
  /// Per contribution (of contributions_, before the assembler takes them):
  /// linear in u under the step's NLGEOM, for Assembler's `linear`
  /// (bulk_linear() steps only).
  [[nodiscard]] std::vector<std::uint8_t> linear_flags() const;

  const Discretization& discretization_;
  const Step& step_;
  SolverSettings settings_;
  StepLoads loads_;
  std::vector<std::unique_ptr<FacePressure>> pressures_;
  NewmarkIncrement newmark_;
  std::vector<std::unique_ptr<ElementInertia>> inertia_;
  std::unique_ptr<StepBodyForces> body_forces_;
  std::vector<Contribution*> contributions_;  ///< until the assembler takes them (explicit steps: for good)
  std::vector<const Contribution*> load_contributions_;
  std::unique_ptr<Assembler> assembler_;
  std::unique_ptr<EquationMap> explicit_equations_;  ///< explicit steps' equations (no assembler_)
  std::unique_ptr<LinearSolver> solver_;
  const CondensedSolver* condensed_ = nullptr;
  int unused_nodes_ = 0;
  bool symmetric_ = true;
  bool bulk_linear_ = true;
};

}  // namespace tether
