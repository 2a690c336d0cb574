#pragma once
/// \file A direct solver for systems whose matrix changes, from one Newton
/// iteration to the next, only in a small block of "interface" equations —
/// the contact unknowns of a contact problem with a linear-elastic bulk.
///
/// With the free equations split into the interface I and the rest R,
///     [A_RR A_RI] [x_R]   [b_R]
///     [A_IR A_II] [x_I] = [b_I],
/// the solver factorizes A_RR once with the Schur complement
/// C = -A_IR A_RR⁻¹ A_RI (MumpsSchur). While the entries of A with a row or
/// column in R stay bitwise unchanged (checked at every factorize(), O(nnz)),
/// a new matrix costs only the dense LU of A_II + C (|I| × |I|) and a solve
/// one forward and one backward sweep plus that dense solve. The answer is
/// that of the full system to round-off; nothing is approximated.
///
/// When those entries change (finite strain, plasticity), A_RR is factorized
/// again; after two such changes in a row the solver gives up condensing and
/// hands every further call to the fallback solver. The fallback also takes a
/// single call when A_RR is singular (a body not held through I) or the dense
/// interface matrix is (a floating body, an overconstrained contact): it then
/// decides and names the singular equation as it would have without
/// condensation.
///
/// With mortar pairs or node-to-segment pairs with a HARD law
/// (eliminate_dual_multipliers()), the dense interface system is not
/// factorized as it is: its closed normal multipliers (dual mortar, or
/// node-to-segment: a closed row of slave node s holds ∂g/∂u_s = n, a unit
/// vector) are eliminated exactly with a pivot displacement of their own
/// node and the open ones solved apart (DenseDualCondensation), and the
/// remaining system — the interface displacements only, for frictionless
/// HARD contact — factorized by Cholesky (LU with friction or regularised
/// rows). The bulk factorization is the same; the answer is the same to
/// round-off (one step of iterative refinement on the dense system).

#include <memory>
#include <vector>

#include "tether/solvers/dense_dual_condensation.hpp"
#include "tether/solvers/dense_factor.hpp"
#include "tether/solvers/dual_condensation.hpp"
#include "tether/solvers/linear_solver.hpp"
#include "tether/solvers/mumps_schur.hpp"

namespace tether {

/// What the solver did, for logs and tests.
struct CondensationStatistics {
  int interface_equations = 0;  ///< |I|
  int sparse_factorizations = 0;  ///< of A_RR with its Schur complement
  int reuses = 0;                 ///< factorize() calls served by the dense interface system alone
  int promised = 0;               ///< of those, taken on the caller's word (note_outer_unchanged)
  int fallbacks = 0;              ///< factorize() calls handed to the fallback solver
  int interface_only_solves = 0;  ///< solve() calls whose bulk right-hand side was negligible (no full forward sweep)
  bool gave_up = false;           ///< stopped condensing (R entries changed twice in a row)
  double factor_entries = 0;      ///< entries of the last sparse factors (MUMPS INFOG(29))
  int factor_memory_mb = 0;       ///< MUMPS' memory for the last factorization [MB] (INFOG(22))
  bool out_of_core = false;       ///< the last sparse factors were kept on disk (memory budget)
  int out_of_core_factorizations = 0;  ///< sparse factorizations whose factors were kept on disk
  int dense_equations = 0;        ///< size of the last dense system factorized: |I|, or |K| after the dual elimination
  bool dense_cholesky = false;    ///< the last one was factorized by Cholesky (else LU)
  /// Reciprocal condition number estimate (1-norm, equilibrated) of the
  /// last dense system factorized, and the smallest since construction.
  double dense_rcond = 0;
  double smallest_dense_rcond = 0;
  int dual_eliminations = 0;      ///< factorize() calls whose dense system was condensed by the dual elimination
  int dual_closed = 0;            ///< closed multipliers eliminated with a pivot in the last one
};

class CondensedSolver final : public LinearSolver {
 public:
  /// `interface`: free equations (any order, duplicates allowed) that hold all
  /// the entries expected to change between factorizations. `fallback`:
  /// the solver used when condensation does not apply.
  /// `memory_budget_mb`: memory the process may use [MB], 0 for no limit;
  /// the bulk factors go out of core when they would not fit (MumpsSchur::set_memory_budget).
  CondensedSolver(std::vector<int> interface, std::unique_ptr<LinearSolver> fallback, double memory_budget_mb = 0);
  ~CondensedSolver() override;

  void analyze(const SparseMatrix& a) override;
  void factorize(const SparseMatrix& a, bool symmetric) override;
  /// The next factorize() takes the entries outside the interface as those of
  /// the previous call without comparing them (statistics().promised).
  void note_outer_unchanged() override { outer_unchanged_ = true; }
  /// The slave nodes' equations (mortar_dual_equations,
  /// contact_dual_equations: one normal multiplier per node, no node twice):
  /// from the next factorize() on, their multipliers are eliminated from the
  /// dense interface system (DenseDualCondensation); where that elimination
  /// finds its block singular, the dense system is factorized as it is.
  /// Every equation named must be in the interface, else nothing is
  /// eliminated.
  void eliminate_dual_multipliers(std::vector<DualNodeEquations> nodes) { dual_nodes_ = std::move(nodes); }
  /// One forward and one backward sweep over the bulk factors and the dense
  /// interface solve. When every entry of b outside the interface (b_R) is at
  /// most 1e-10 times the largest such entry of the solves since the bulk
  /// factorization (all zero included), b_R is taken as zero: the reduced
  /// right-hand side is b_I alone and x_R = -A_RR⁻¹ A_RI x_I, whose forward
  /// sweep visits only the fronts above the equations coupled to I
  /// (MumpsSchur::expand_interface; statistics().interface_only_solves). In
  /// Newton on a linear bulk that is every iteration after an increment's
  /// first: the bulk rows of the residual are round-off (measured at 2–4e-12
  /// of the increment's load at 230k dofs). A b_R so dropped that was not
  /// round-off stays in the next residual, so a convergence tolerance below
  /// 1e-10 of the largest bulk load would not be reached. Only after a
  /// factorize() of a matrix declared symmetric: with friction the
  /// stick/slip decisions rest on round-off, and dropping it changes the
  /// path (measured: one more iteration in a Cattaneo–Mindlin increment).
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override;
  [[nodiscard]] std::string name() const override;
  /// Those of the bulk (statistics().out_of_core_factorizations) and of the fallback.
  [[nodiscard]] int out_of_core_factorizations() const override {
    return statistics_.out_of_core_factorizations + fallback_->out_of_core_factorizations();
  }

  [[nodiscard]] const CondensationStatistics& statistics() const { return statistics_; }

 private:
  /// True when the entries of `a` outside the interface block are symmetric.
  [[nodiscard]] bool outer_symmetric(const SparseMatrix& a) const;
  void use_fallback(const SparseMatrix& a, bool symmetric);
  /// Factorizes the dense interface system `s` = A_II + C, with the dual
  /// elimination when it applies; false when it is (numerically) singular.
  [[nodiscard]] bool factorize_interface(Eigen::MatrixXd s, const SparseMatrix& a, bool symmetric);
  /// choose_dual_elimination on the interface columns of `a`, in interface
  /// positions; empty when a named equation is outside the interface.
  [[nodiscard]] DualElimination interface_elimination(const SparseMatrix& a) const;

  std::vector<int> interface_;      ///< ascending, unique
  std::vector<char> in_interface_;  ///< per equation (sized at the first factorize)
  std::unique_ptr<LinearSolver> fallback_;
  std::unique_ptr<MumpsSchur> bulk_;
  bool bulk_valid_ = false;       ///< bulk_ holds a factorization (of the R entries it compares against)
  bool bulk_symmetric_ = false;   ///< bulk_ is an LDLT
  int changes_in_row_ = 0;        ///< consecutive factorize() calls whose R entries changed
  bool fallback_active_ = false;  ///< the last factorize() went to the fallback
  bool fallback_analysed_ = false;
  bool outer_unchanged_ = false;  ///< note_outer_unchanged() before this factorize()
  bool system_symmetric_ = false;  ///< the last factorize() was of a matrix declared symmetric
  double bulk_scale_ = 0;         ///< largest |b_i| outside the interface in the solves since the bulk factorization
  // Dense interface system (A_II + C), equilibrated and factorized by LAPACK
  // (DenseFactor), or, with dual nodes, D (A_II + C) D condensed by the dual elimination.
  DenseFactor interface_factor_;
  std::vector<DualNodeEquations> dual_nodes_;
  DenseDualCondensation dual_;
  Eigen::VectorXd dual_scale_;  ///< D of D (A_II + C) D for dual_
  bool dual_active_ = false;    ///< the last factorize() went through dual_
  bool dual_scaled_ = false;    ///< the last dense system was D (A_II + C) D (dual_scale_), whichever factorized it
  CondensationStatistics statistics_;
};

}  // namespace tether
