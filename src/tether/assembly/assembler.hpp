#pragma once
/// \file Loops over the contributions and scatters them into one sparse system.
///
/// The pattern is built from the contributions' dof lists once, and again only
/// when a contribution reports a connectivity change (contact re-pairing).
/// For every contribution the positions of its local entries in the
/// compressed-column value array are stored, so scattering is a plain add.
/// Contributions are coloured so that no two of one colour share an unknown;
/// each colour is assembled in parallel (OpenMP) without locks, and the result
/// does not depend on the number of threads.

#include <Eigen/Core>
#include <vector>

#include "tether/assembly/contribution.hpp"
#include "tether/assembly/equation_map.hpp"
#include "tether/solvers/linear_solver.hpp"

namespace tether {

/// Wall-clock seconds spent in the parts of one assembly (for benchmarks).
struct AssemblyTiming {
  double pattern = 0;   ///< last pattern build
  double evaluate = 0;  ///< last assemble() call
};

class Assembler {
 public:
  /// The contributions are borrowed and must outlive the assembler.
  Assembler(std::vector<Contribution*> contributions, EquationMap equations);

  /// Replaces the equation map (prescribed set changed between steps); rebuilds the pattern.
  void set_equations(EquationMap equations);

  /// Asks every contribution whether its connectivity changed; rebuilds the
  /// pattern if any did. Returns true on a rebuild (the solver must re-analyse).
  bool update_connectivity(const EvaluationState& state);

  /// Residual over all global dofs (prescribed ones included: that is where
  /// reactions are read) and, when `tangent` is not null, the tangent over the
  /// free equations. `residual` is resized to the number of global dofs.
  /// Exceptions thrown by a contribution (e.g. an inverted element) propagate.
  void assemble(const EvaluationState& state, Eigen::VectorXd& residual, SparseMatrix* tangent);

  [[nodiscard]] const EquationMap& equations() const { return equations_; }
  [[nodiscard]] const SparseMatrix& pattern() const { return pattern_; }
  [[nodiscard]] int n_colours() const { return static_cast<int>(colours_.size()); }
  [[nodiscard]] const AssemblyTiming& timing() const { return timing_; }

 private:
  void build_pattern();
  /// Free equations a contribution's entries land in (through T), sorted, unique.
  void equations_of(const Contribution& c, std::vector<int>& out) const;

  std::vector<Contribution*> contributions_;
  EquationMap equations_;
  SparseMatrix pattern_;                 ///< values zero; copied into the tangent
  /// Value-array index of local entry (a, b) of contribution c, column-major:
  /// positions_[offsets_[c] + b * n + a]; -1 where a row or column is prescribed.
  std::vector<int> positions_;
  std::vector<std::size_t> offsets_;
  /// Contributions touching a dependent (eliminated) dof scatter through the
  /// map T: local entry e = b * n + a adds weight[k] * k_e to values[pos[k]]
  /// for k in [start[e], start[e + 1]).
  struct WeightedScatter {
    std::vector<int> start;
    std::vector<int> pos;
    std::vector<double> weight;
  };
  std::vector<int> weighted_index_;  ///< per contribution: index into weighted_ or -1 (plain positions)
  std::vector<WeightedScatter> weighted_;
  /// Contribution indices per colour; the last colour may hold contributions
  /// that found no free colour and is then assembled serially.
  std::vector<std::vector<int>> colours_;
  bool last_colour_serial_ = false;
  AssemblyTiming timing_;
};

}  // namespace tether
