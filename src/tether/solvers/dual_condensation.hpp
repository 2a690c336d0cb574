#pragma once
/// \file Exact condensation of the mortar contact multipliers (dual basis),
/// as a LinearSolver in front of another one.
///
/// With dual multipliers the weighted gap g̃_j of slave node j depends on its
/// own position through -D_j n_j (D diagonal), so each closed multiplier λ_j
/// pairs with one displacement equation of its own node, the pivot p(j): the
/// component along which |∂g̃_j/∂u| is largest. Once the normals and the
/// segmentation are linearised, g̃_j also depends (by small terms: gaps and
/// tangential parts of the weighted gap vector times the variation of the
/// normals, of D and of M) on the neighbouring slave nodes, so the block
///
///     B = A_ZZ,   Z = {p(j), λ_j: j closed} ∪ {λ_j: j with a diagonal}
///
/// is banded, not block-diagonal. It is eliminated exactly:
///
///     S = A_RR - A_RZ B⁻¹ A_ZR,    S x_R = b_R - A_RZ B⁻¹ b_Z,
///     x_Z = B⁻¹ (b_Z - A_ZR x_R),
///
/// B by a dense LU (|Z| = 2 × closed + open nodes: a few hundred in 2D), the
/// fill of S confined to the equations coupled to Z (the slave nodes'
/// element neighbours and the master nodes). For a frictionless HARD pair S
/// holds no contact multiplier: symmetric positive definite when the
/// problem is, so the inner Auto solver takes Cholesky. Nothing is
/// approximated: x is that of the full system to round-off. A λ_j row with
/// a diagonal (an open node, a soft law) is eliminated alone. Friction
/// multipliers stay in S. The elimination mixes stiffnesses (force/length)
/// with the mortar weights (area) in B, so solve() follows the condensed
/// solve by one step of iterative refinement on the full matrix
/// (x += Â⁻¹(b - A x)), which brings the residual to that of a direct solve
/// of A. Theory: docs/theory/mortar.md ("Condensation").

#include <array>
#include <string>
#include <utility>
#include <memory>
#include <vector>

#include <Eigen/Dense>

#include "tether/solvers/linear_solver.hpp"

namespace tether {

/// How the linear solver treats the multipliers of mortar pairs
/// (`tether run --mortar-condensation`; docs/theory/mortar.md,
/// "Condensation of the multipliers") and, in the dense interface system of
/// CondensedSolver, the normal multipliers of node-to-segment HARD pairs.
/// Every choice gives the answer of the full system to round-off.
enum class MortarCondensation {
  /// Where the solver condenses onto the contact equations (CondensedSolver),
  /// the mortar and node-to-segment normal multipliers are eliminated from
  /// its dense interface system and the rest factorized by Cholesky when it
  /// can be; elsewhere they stay in the matrix.
  Dense,
  /// The multipliers stay in the dense interface system (or the matrix),
  /// factorized by LU.
  Kept,
  /// The mortar multipliers are eliminated from the whole sparse matrix
  /// (DualCondensedSolver), whose condensed matrix the inner solver
  /// factorizes at every iteration (no condensation onto the contact
  /// equations). Without mortar pairs, as Kept.
  Sparse,
};

/// "dense", "kept", "sparse" (any case); throws std::invalid_argument otherwise.
[[nodiscard]] MortarCondensation parse_mortar_condensation(const std::string& name);

/// The reduced equations of one slave node whose closed normal multiplier
/// row couples to its own displacement by a diagonal weight (dual mortar:
/// -D_j n_j) or a unit vector (node-to-segment: n): its normal multiplier
/// and its two displacement components (-1 where the dof is not a free
/// equation of weight 1, e.g. prescribed or eliminated by *EQUATION: never
/// a pivot).
struct DualNodeEquations {
  int multiplier = -1;
  std::array<int, 2> displacement{-1, -1};
};

/// The equations a dual elimination takes out of a matrix
/// (choose_dual_elimination): what DualCondensedSolver eliminates from the
/// whole sparse matrix and CondensedSolver from its dense interface system.
struct DualElimination {
  /// The block B, in order: (pivot, multiplier) for each closed HARD node,
  /// the multiplier alone for each node whose row has a diagonal and
  /// off-diagonal entries (a soft law).
  std::vector<int> eliminated;
  /// Open multipliers (a diagonal and nothing else in row and column):
  /// equation and diagonal, solved apart as λ_j = b_j / a_jj.
  std::vector<std::pair<int, double>> apart;
  int closed = 0;    ///< nodes eliminated with a pivot
  int diagonal = 0;  ///< nodes eliminated alone (apart, or in B with their diagonal)
};

/// Classifies the multiplier rows of `nodes` in `a` (every nonzero entry read;
/// explicit zeros, such as a reserved block's, count as absent) and pairs
/// each closed multiplier (a row with no diagonal) with its pivot: the
/// displacement equation of its own node with the largest |a_jk|, not yet
/// taken by another node. A node whose row and column are empty (no
/// segment overlaps it) or whose displacements are no free equations of
/// weight 1 is left alone (its equations stay in the kept part).
/// `columns`: the columns of `a` to read, all when null; otherwise they must
/// hold the multipliers' columns and every column with an entry in a
/// multiplier's row (CondensedSolver passes its interface: the rest of a
/// 230k-dof matrix need not be read at every iteration).
[[nodiscard]] DualElimination choose_dual_elimination(const SparseMatrix& a, const std::vector<DualNodeEquations>& nodes,
                                                      const std::vector<int>* columns = nullptr);

/// Work of the last factorize().
struct DualCondensationStatistics {
  int closed = 0;     ///< multipliers eliminated with a pivot (closed HARD rows)
  int diagonal = 0;   ///< multipliers eliminated alone (open rows, solved apart; soft laws, in B)
  int coupled = 0;    ///< equations of S that the elimination filled
  int condensed_equations = 0;  ///< size of S
  bool full = false;  ///< B was (numerically) singular: the full matrix went to the inner solver
};

class DualCondensedSolver final : public LinearSolver {
 public:
  DualCondensedSolver(std::vector<DualNodeEquations> nodes, std::unique_ptr<LinearSolver> inner);

  /// Nothing to do before the values are known (the closed set is read from them).
  void analyze(const SparseMatrix& a) override;
  /// Classifies the mortar rows of `a`, eliminates Z and factorizes S with
  /// the inner solver (re-analysed when S's pattern changed). A SolverError
  /// of the inner solver names the equation of `a`.
  void factorize(const SparseMatrix& a, bool symmetric) override;
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override;
  [[nodiscard]] std::string name() const override;
  [[nodiscard]] const DualCondensationStatistics& statistics() const { return statistics_; }

 private:
  void choose_eliminated(const SparseMatrix& a);
  void solve_condensed(const Eigen::VectorXd& b, Eigen::VectorXd& x);
  /// B⁻¹ y through the equilibrated factors.
  [[nodiscard]] Eigen::MatrixXd solve_b(const Eigen::MatrixXd& y) const;
  void build_condensed(const SparseMatrix& a);

  std::vector<DualNodeEquations> nodes_;
  std::unique_ptr<LinearSolver> inner_;
  std::vector<int> z_;          ///< eliminated equations, in B's order
  std::vector<int> r_;          ///< kept equations, in S's order
  std::vector<int> r_index_;    ///< by equation: index in r_, or -1 (in Z)
  std::vector<int> rows_i_;     ///< S indices of the rows of A_RZ with entries
  std::vector<int> cols_i_;     ///< S indices of the columns of A_ZR with entries
  Eigen::MatrixXd a_rz_, a_zr_;  ///< dense: rows_i_ × Z and Z × cols_i_
  Eigen::PartialPivLU<Eigen::MatrixXd> b_lu_;  ///< of R B C (equilibrated)
  Eigen::VectorXd row_scale_, column_scale_;   ///< R, C
  std::vector<std::pair<int, double>> decoupled_;  ///< open multipliers: equation, diagonal
  SparseMatrix s_;
  SparseMatrix a_;  ///< the full matrix of the last factorize (refinement)
  std::vector<int> analysed_r_;  ///< r_ when the inner solver last analysed
  Eigen::VectorXi analysed_outer_, analysed_inner_;  ///< S's pattern then
  DualCondensationStatistics statistics_;
};

}  // namespace tether
