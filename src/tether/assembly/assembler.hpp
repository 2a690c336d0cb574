#pragma once
/// \file Loops over the contributions and scatters them into one sparse system.
///
/// The pattern is built from the contributions' dof lists once. When a
/// contribution reports a connectivity change (contact re-pairing), its
/// entries are first looked up in the existing pattern: if they are all
/// there (a reserved block, see the constructor), only that contribution's
/// positions change and it is assembled serially; otherwise the pattern is
/// rebuilt.
/// For every contribution the positions of its local entries in the
/// compressed-column value array are stored, so scattering is a plain add.
/// Contributions are coloured so that no two of one colour share an unknown;
/// each colour is assembled in parallel (OpenMP) without locks, and the result
/// does not depend on the number of threads.
///
/// Contributions declared linear in u (set_linear()) have their tangents
/// assembled once and kept in the tangent's values: later assemblies
/// evaluate them for the residual only and assemble anew just the entries a
/// nonlinear contribution (contact) touches, bit for bit as a full assembly.

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
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

/// Tangent assemblies since set_linear(), by kind (for logs and tests).
struct LinearReuseStatistics {
  int full = 0;    ///< every contribution's tangent evaluated (the linear ones' kept from then on)
  int reused = 0;  ///< the linear contributions' tangents kept; only nonlinear entries assembled
  /// Assemblies whose residual took the held linear contributions' part from
  /// the reference and the held tangent (enable_residual_updates()).
  int residual_updates = 0;
};

class Assembler {
 public:
  /// The contributions are borrowed and must outlive the assembler.
  /// `reserved_block`: free equations coupled all to all in the pattern
  /// whatever the contributions say (the contact equations), so that a
  /// re-pairing inside them never changes the pattern.
  /// `lower_triangle`: every contribution's tangent is symmetric (the
  /// caller's word, Contribution::symmetric_tangent) and the tangent is
  /// stored as its lower triangle only (rows >= columns): the entries above
  /// the diagonal are neither stored nor assembled (half the memory of the
  /// values and row indices), and the held tangent multiplies vectors as the
  /// symmetric matrix it stands for. The solvers must then read one triangle
  /// (LinearSolver::factorize with `symmetric`).
  /// `linear`, `keyed_on_dt`: as set_linear() right after construction, and
  /// the pattern is built knowing them (the held linear contributions' dof
  /// lists are never copied); empty: none held.
  Assembler(std::vector<Contribution*> contributions, EquationMap equations, std::vector<int> reserved_block = {},
            bool lower_triangle = false, std::vector<std::uint8_t> linear = {}, bool keyed_on_dt = false);

  /// Replaces the equation map (prescribed set changed between steps); rebuilds the pattern.
  void set_equations(EquationMap equations);

  /// Asks every contribution (after set_linear(), every one not declared
  /// linear: linear_in_u promises the same dofs all step) whether its
  /// connectivity changed; places the
  /// changed ones in the existing pattern, or rebuilds it when an entry is
  /// missing. Returns true on a rebuild (the solver must re-analyse).
  bool update_connectivity(const EvaluationState& state);

  /// Residual over all global dofs (prescribed ones included: that is where
  /// reactions are read) and, when `with_tangent`, the tangent over the free
  /// equations into tangent() (left unchanged otherwise). `residual` is
  /// resized to the number of global dofs. Exceptions thrown by a contribution
  /// (e.g. an inverted element) propagate.
  void assemble(const EvaluationState& state, Eigen::VectorXd& residual, bool with_tangent);

  /// As above; when `tangent` is not null it receives a copy of tangent()
  /// (for callers that want their own matrix: tests, benchmarks).
  void assemble(const EvaluationState& state, Eigen::VectorXd& residual, SparseMatrix* tangent);

  /// Declares the contributions whose tangent is the same matrix at every
  /// state (Contribution::linear_in_u under the step's NLGEOM): `linear` has
  /// one flag per contribution, in the constructor's order. `keyed_on_dt`:
  /// their tangents depend on the increment size EvaluationState::dt
  /// (inertia, M / (beta dt^2) + ...), so they are kept only at the same dt.
  /// From then on an assembly with the tangent evaluates the linear
  /// contributions' tangents only when they are not held: the first time,
  /// after a pattern rebuild, after a full assembly that failed, and at
  /// another dt when keyed. Otherwise the linear contributions are evaluated
  /// for the residual only, and the entries that a nonlinear contribution
  /// scatters (or, before a relocation, scattered) into are zeroed and
  /// assembled again from every contribution touching them, in the usual
  /// order: the tangent is bit for bit that of a full assembly. Throws std::invalid_argument when the size
  /// of `linear` is not the number of contributions.
  void set_linear(std::vector<std::uint8_t> linear, bool keyed_on_dt);
  /// Changes whenever an assembly may have changed the tangent's values or
  /// structure; equal values mean the same matrix (a factorization of it can be reused).
  [[nodiscard]] std::uint64_t tangent_revision() const { return revision_; }
  /// Changes whenever an assembly may have changed an entry of the tangent
  /// with a row or a column outside the reserved block (or its structure);
  /// equal values mean those entries are bitwise the same. Held assemblies
  /// whose nonlinear contributions all lie inside the reserved block (contact
  /// condensed onto its equations) leave it unchanged.
  [[nodiscard]] std::uint64_t outer_revision() const { return outer_revision_; }
  [[nodiscard]] const LinearReuseStatistics& linear_reuse() const { return reuse_statistics_; }

  /// Residual updates from the held tangent. While enabled (and the linear
  /// tangents are held, at the same dt when keyed, with no dependent dofs),
  /// the first assembly evaluates everything and records the residual of
  /// the held linear contributions that touch neither a nonlinear entry nor
  /// a prescribed dof (set L) at its u, u_ref; each later one evaluates only
  /// the other contributions and adds r_L(u_ref) + K_L (u - u_ref), K_L from
  /// the held tangent's values (the held entries minus the local tangents of
  /// the other linear contributions): a sparse product instead of element
  /// loops. Exact for affine contributions up to round-off (not bit for bit:
  /// the sums are taken in another order); the rows of prescribed dofs
  /// (reactions) are bit for bit those of a full assembly.
  /// The reference lasts for the step, across increments and Newton
  /// solves: r_L(u_ref) is kept in two parts. That of the contributions
  /// whose residual is a function of u alone
  /// (Contribution::residual_depends_on_time() false: small-strain elastic
  /// elements) is recorded once; that of the others in L (loads, inertia,
  /// constraints with Uzawa multipliers) is evaluated again at u_ref (only
  /// they) whenever the time, total time or dt differs from the last
  /// assembly's and at every enable_residual_updates(true) (new loads,
  /// state stored by on_converged() or commit()). L holds no prescribed
  /// dof, so changed prescribed values need nothing (their K_fp (u_p -
  /// u_p,ref) is in the direct contributions' evaluated residual). A new
  /// reference is recorded after a pattern change or a full tangent
  /// assembly (held_ anew); a relocation (re-pairing inside the reserved
  /// block) moves the linear contributions that touch its new entries out
  /// of L and their part out of the reference. Off: every assembly
  /// evaluates every contribution (the reference is kept for a later on).
  void enable_residual_updates(bool on);
  /// A restart state has been saved after the last assembly. A run resumed
  /// from it starts with a new assembler, whose first assembly evaluates
  /// everything and whose second records the reference; this one does the
  /// same from here (drops its reference, records none at the next
  /// assembly with updates enabled), so that both runs take the same sums
  /// and continue bit for bit alike.
  void restart_point();

  /// The tangent over the free equations, owned by the assembler: its
  /// structure is the pattern (built by the constructor, set_equations() and
  /// update_connectivity() on a rebuild), its values those of the last
  /// assemble() with the tangent (zero before). The assembler keeps no other
  /// copy of the structure. With lower_triangle(), the lower triangle
  /// (diagonal included) of the symmetric tangent only.
  [[nodiscard]] const SparseMatrix& tangent() const { return tangent_; }
  /// The tangent is stored as its lower triangle (see the constructor).
  [[nodiscard]] bool lower_triangle() const { return lower_; }

  [[nodiscard]] const EquationMap& equations() const { return equations_; }
  /// The contributions, in the constructor's order.
  [[nodiscard]] const std::vector<Contribution*>& contributions() const { return contributions_; }
  /// The tangent's structure (tangent()).
  [[nodiscard]] const SparseMatrix& pattern() const { return tangent_; }
  [[nodiscard]] int n_colours() const { return static_cast<int>(colours_.size()); }
  [[nodiscard]] const AssemblyTiming& timing() const { return timing_; }
  /// Pattern builds so far (the first included) and connectivity changes
  /// placed in the existing pattern.
  [[nodiscard]] int pattern_builds() const { return pattern_builds_; }
  /// Contributions scattered by 2x2 node blocks (one position per block; see build_pattern).
  [[nodiscard]] int n_blocked() const { return static_cast<int>(std::count(blocked_.begin(), blocked_.end(), 1)); }
  [[nodiscard]] int relocations() const { return relocations_; }
  /// Scatter positions stored for the contributions placed at the last
  /// pattern build (their memory: 4 bytes each), and the dof lists kept to
  /// find re-paired contributions (ints; none for held linear ones).
  [[nodiscard]] std::size_t n_positions() const { return positions_.size(); }
  [[nodiscard]] std::size_t n_kept_dofs() const { return built_dofs_.size(); }

 private:
  /// Below this many contributions a colour is assembled (and the scatter
  /// positions are built) on one thread: thread start-up costs more than it saves.
  static constexpr int kParallelThreshold = 2048;
  void build_pattern();
  /// Positions, in the current pattern, of the contributions whose dof list
  /// differs from the one last placed; false (nothing changed) when an entry
  /// is missing or a contribution is weighted.
  bool relocate();
  /// set_linear() without its bookkeeping of a built pattern.
  void assign_linear(std::vector<std::uint8_t> linear, bool keyed_on_dt);
  /// The dof list contribution built_contributions_[k] was last placed with.
  [[nodiscard]] std::span<const int> placed_dofs(std::size_t k) const;
  /// At a pattern build: the dof lists of the contributions whose lists may
  /// change (all; after set_linear() those not linear).
  void record_built_dofs();
  /// set_linear(): forgets the lists of the contributions now held linear.
  void drop_linear_built_dofs();
  /// Value-array index of entry (row, col), -1 when not in the pattern.
  [[nodiscard]] int find_position(int row, int col) const;
  /// Index of the position of nodes k and l (either order) of a blocked
  /// contribution in a lower triangle: the pairs k <= l packed by columns.
  [[nodiscard]] static std::size_t packed_block(std::size_t k, std::size_t l) {
    return k <= l ? l * (l + 1) / 2 + k : k * (k + 1) / 2 + l;
  }
  /// Fills the packed positions `pos` of a blocked contribution over `dofs`
  /// in a lower triangle; position(row, col) is the value index of an entry.
  template <class Position>
  void place_packed_blocks(std::span<const int> dofs, int* pos, const Position& position) const;
  /// Index into weighted_ of contribution c, -1 when it scatters by positions.
  [[nodiscard]] int weighted_slot(int c) const {
    return weighted_index_.empty() ? -1 : weighted_index_[static_cast<std::size_t>(c)];
  }
  /// Free equations a contribution's entries land in (through T), sorted, unique.
  void equations_of(const Contribution& c, std::vector<int>& out) const;
  /// Calls f(p, e, w) for every value-array index p that local tangent entry
  /// e (column-major, b * n + a) of contribution c adds to, with weight w
  /// (1 except through T): the one definition of where a contribution's
  /// tangent goes, for the scatter and for the held entries' bookkeeping.
  template <class F>
  void for_each_entry(int c, F&& f) const;
  /// True when an assembly with the tangent at `state` may keep the linear
  /// contributions' tangents (set_linear()).
  [[nodiscard]] bool linear_held(const EvaluationState& state) const;
  /// After a full assembly at `state`: the entries nonlinear contributions
  /// scatter into and the linear contributions that touch one of them. With
  /// null, after a relocation: adds the entries the relocated contributions
  /// scatter into now (those they left keep being assembled anew) and finds
  /// the linear contributions touching them again.
  void hold_linear(const EvaluationState* state);
  /// direct_ after hold_linear(): the contributions evaluated at every residual update.
  void mark_direct();
  /// hold_linear(nullptr) when every nonlinear contribution lies in the
  /// reserved block: marks mixed (and direct) the linear contributions that
  /// touch the nonlinear entries from index `first_new` of
  /// nonlinear_entries_ on, looking at block_touchers_ only, instead of
  /// every contribution. The same mixed_, direct_ and nonlinear_column_ as
  /// the full recomputation.
  void add_relocated_entries(std::size_t first_new);
  /// After a relocation (hold_linear(nullptr)) that kept a valid reference:
  /// removes from r_L(u_ref) the contributions that left L (`before`: direct_
  /// before the relocation), evaluated at u_ref, so that the reference serves on.
  void carry_reference(const EvaluationState& state, const std::vector<std::uint8_t>& before);
  /// Before an assembly at `state` (`held`: with the tangent, the linear
  /// tangents held): places the entries of a relocation (hold_linear(nullptr),
  /// carrying the reference), and returns true when the assembly updates the
  /// residual from the reference; `record`: it records a new one instead.
  bool prepare_updates(const EvaluationState& state, bool held, bool& record);
  /// True when the reference of enable_residual_updates() serves `state`
  /// (its time-dependent part perhaps after refresh_timed()).
  [[nodiscard]] bool reference_serves(const EvaluationState& state) const;
  /// Evaluates the time-dependent part of the reference, r_T(u_ref), anew
  /// at the times and dt of `state` (the contributions of timed_ still in
  /// L). False, and the reference dropped, when an evaluation throws.
  bool refresh_timed(const EvaluationState& state);
  /// Adds r_L(u_ref) + K_L (u - u_ref) with K_L from the held values (all of
  /// it but the nonlinear entries; the other linear contributions are
  /// subtracted as they are evaluated) to `residual`.
  void add_linear_update(const EvaluationState& state, Eigen::VectorXd& residual) const;
  /// add_linear_update() for a tangent stored as its lower triangle: each
  /// entry below the diagonal multiplies for itself and its mirror.
  /// `product`: zero, n_equations() long (work space).
  void add_symmetric_update(const EvaluationState& state, Eigen::VectorXd& residual, Eigen::VectorXd& product) const;

  std::vector<Contribution*> contributions_;
  EquationMap equations_;
  SparseMatrix tangent_;                 ///< the pattern, with the last assembled values
  /// Value-array index of local entry (a, b) of contribution c, column-major:
  /// positions_[offsets_[c] + b * n + a]; -1 where a row or column is prescribed.
  /// A blocked contribution (blocked_[c], dofs in node pairs) stores one index
  /// per 2x2 block, positions_[offsets_[c] + (b/2) * (n/2) + a/2] for even a, b
  /// (see build_pattern): a quarter of the memory. With lower_, -1 for the
  /// entries above the diagonal, and a blocked contribution stores one index
  /// per pair of nodes (packed_block), that of the pair's block below the
  /// diagonal: 10 instead of 16 for a CPE4.
  std::vector<int> positions_;
  std::vector<std::uint32_t> offsets_;  ///< per contribution, into positions_ (size + 1)
  std::vector<std::uint8_t> blocked_;
  /// Contributions touching a dependent (eliminated) dof scatter through the
  /// map T: local entry e = b * n + a adds weight[k] * k_e to values[pos[k]]
  /// for k in [start[e], start[e + 1]).
  struct WeightedScatter {
    std::vector<int> start;
    std::vector<int> pos;
    std::vector<double> weight;
  };
  /// Per contribution: index into weighted_ or -1 (plain positions); empty
  /// when no dof is dependent (weighted_slot()).
  std::vector<int> weighted_index_;
  std::vector<WeightedScatter> weighted_;
  /// Contribution indices per colour; the last colour may hold contributions
  /// that found no free colour and is then assembled serially.
  std::vector<std::vector<int>> colours_;
  bool last_colour_serial_ = false;
  /// Contributions placed by relocate(): their own positions, assembled
  /// serially after the colours (they left their colour).
  std::vector<int> relocated_slot_;               ///< per contribution: index into relocated_, -1
  std::vector<std::vector<int>> relocated_;
  std::vector<std::vector<int>> relocated_dofs_;  ///< the dof lists they were placed with
  /// Dof lists at the last pattern build (a coordinating contribution such as
  /// a contact pair reports the change for the contributions it re-pairs, so
  /// the assembler finds the changed ones by comparison), of the
  /// contributions built_contributions_ (ascending): all of them, or after
  /// set_linear() those not linear (a linear one keeps its dofs all step, see
  /// Contribution::linear_in_u; the elements' lists are not copied then).
  std::vector<int> built_contributions_;
  std::vector<int> built_dofs_;
  std::vector<std::size_t> built_offsets_;  ///< per built_contributions_ entry, into built_dofs_ (size + 1)
  std::vector<int> relocated_order_;              ///< contribution indices, assembled in this order
  std::vector<int> reserved_block_;
  bool lower_ = false;  ///< the tangent is stored as its lower triangle
  int pattern_builds_ = 0, relocations_ = 0;
  AssemblyTiming timing_;
  // Held linear tangents (set_linear()).
  std::vector<std::uint8_t> linear_;    ///< per contribution; empty: nothing held
  std::vector<int> connecting_;         ///< the contributions not linear_ (asked by update_connectivity())
  bool keyed_on_dt_ = false;
  bool held_ = false;                   ///< the values hold the linear tangents of the last full assembly
  bool nonlinear_moved_ = false;        ///< a relocation since hold_linear()
  double held_dt_ = 0;                  ///< the dt they were assembled at
  std::vector<int> nonlinear_entries_;  ///< value indices nonlinear contributions scatter into
  std::vector<std::uint8_t> mixed_;     ///< per contribution: linear and touching one of those entries
  std::vector<bool> nonlinear_entry_;   ///< per value index: one of nonlinear_entries_
  bool any_nonlinear_ = false;
  bool nonlinear_in_block_ = false;     ///< every nonlinear contribution's equations are reserved ones
  /// Linear contributions with an equation in the reserved block, found by
  /// the last hold_linear() after a full assembly (valid when the nonlinear
  /// ones lay in the block then).
  std::vector<int> block_touchers_;
  bool block_touchers_valid_ = false;
  std::uint64_t revision_ = 0, outer_revision_ = 0;
  LinearReuseStatistics reuse_statistics_;
  // Residual updates (enable_residual_updates()).
  bool updates_enabled_ = false;
  bool reference_valid_ = false;
  std::uint64_t hold_generation_ = 0;       ///< changes at every hold_linear(), pattern build, set_linear()
  std::uint64_t reference_generation_ = 0;  ///< hold_generation_ when the reference was recorded
  std::vector<std::uint8_t> direct_;        ///< per contribution: not in L (evaluated at every update)
  std::vector<std::uint8_t> nonlinear_column_;  ///< per equation: its column holds a nonlinear entry
  /// Contributions of L whose residual depends on more than u
  /// (Contribution::residual_depends_on_time), by mark_direct(); timed_flag_ per contribution.
  std::vector<int> timed_;
  std::vector<std::uint8_t> timed_flag_;
  bool defer_record_ = false;  ///< restart_point(): the next assembly with updates enabled records nothing
  bool timed_stale_ = true;                 ///< enable_residual_updates(true) since the last refresh_timed()
  Eigen::VectorXd reference_u_;             ///< u_ref over all dofs
  std::array<double, 3> reference_time_{};  ///< step time, total time and dt of reference_timed_
  Eigen::VectorXd reference_residual_;      ///< r_L(u_ref) of L minus timed_, over all dofs
  Eigen::VectorXd reference_timed_;         ///< r_T(u_ref) of timed_ at reference_time_ (empty: none)
};

}  // namespace tether
