#include "tether/assembly/assembler.hpp"

#include <algorithm>
#include <atomic>
#include <bit>
#include <chrono>
#include <cstdint>
#include <exception>
#include <stdexcept>

namespace tether {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

Assembler::Assembler(std::vector<Contribution*> contributions, EquationMap equations,
                     std::vector<int> reserved_block, bool lower_triangle, std::vector<std::uint8_t> linear,
                     bool keyed_on_dt)
    : contributions_(std::move(contributions)), equations_(std::move(equations)),
      reserved_block_(std::move(reserved_block)), lower_(lower_triangle) {
  std::sort(reserved_block_.begin(), reserved_block_.end());
  reserved_block_.erase(std::unique(reserved_block_.begin(), reserved_block_.end()), reserved_block_.end());
  if (!linear.empty()) assign_linear(std::move(linear), keyed_on_dt);
  build_pattern();
}

void Assembler::set_equations(EquationMap equations) {
  equations_ = std::move(equations);
  build_pattern();
}

bool Assembler::update_connectivity(const EvaluationState& state) {
  bool changed = false;
  if (linear_.empty()) {
    for (Contribution* c : contributions_) changed = c->update_connectivity(state) || changed;
  } else {  // held linear contributions keep their dofs (Contribution::linear_in_u)
    for (int c : connecting_) changed = contributions_[static_cast<std::size_t>(c)]->update_connectivity(state) || changed;
  }
  if (!changed || relocate()) return false;
  build_pattern();
  return true;
}

int Assembler::find_position(int row, int col) const {
  const int* inner = tangent_.innerIndexPtr();
  const int* begin = inner + tangent_.outerIndexPtr()[col];
  const int* end = inner + tangent_.outerIndexPtr()[col + 1];
  const int* it = std::lower_bound(begin, end, row);
  return it != end && *it == row ? static_cast<int>(it - inner) : -1;
}

std::span<const int> Assembler::placed_dofs(std::size_t k) const {
  const auto c = static_cast<std::size_t>(built_contributions_[k]);
  if (relocated_slot_[c] >= 0) return relocated_dofs_[static_cast<std::size_t>(relocated_slot_[c])];
  return {built_dofs_.data() + built_offsets_[k], built_offsets_[k + 1] - built_offsets_[k]};
}

void Assembler::record_built_dofs() {
  built_contributions_.clear();
  std::size_t total = 0;
  for (std::size_t c = 0; c < contributions_.size(); ++c)
    if (linear_.empty() || !linear_[c])  // held linear ones keep their dofs all step
      built_contributions_.push_back(static_cast<int>(c)), total += contributions_[c]->dofs().size();
  built_contributions_.shrink_to_fit();
  built_offsets_.assign(1, 0);
  built_offsets_.reserve(built_contributions_.size() + 1);
  std::vector<int>().swap(built_dofs_);
  built_dofs_.reserve(total);
  for (int c : built_contributions_) {
    const auto dofs = contributions_[static_cast<std::size_t>(c)]->dofs();
    built_dofs_.insert(built_dofs_.end(), dofs.begin(), dofs.end());
    built_offsets_.push_back(built_dofs_.size());
  }
}

void Assembler::drop_linear_built_dofs() {
  std::vector<int> contributions, dofs;
  std::vector<std::size_t> offsets{0};
  std::size_t k = 0;  // walks built_contributions_ (ascending) beside c
  for (std::size_t c = 0; c < contributions_.size(); ++c) {
    while (k < built_contributions_.size() && built_contributions_[k] < static_cast<int>(c)) ++k;
    if (linear_[c]) continue;
    // One held linear before (set_linear() again) kept its dofs: its list now is the one placed.
    const bool built = k < built_contributions_.size() && built_contributions_[k] == static_cast<int>(c);
    const std::span<const int> list =
        built ? std::span<const int>(built_dofs_.data() + built_offsets_[k], built_offsets_[k + 1] - built_offsets_[k])
              : contributions_[c]->dofs();
    contributions.push_back(static_cast<int>(c));
    dofs.insert(dofs.end(), list.begin(), list.end());
    offsets.push_back(dofs.size());
  }
  built_contributions_ = std::move(contributions);
  built_dofs_ = std::move(dofs);
  built_offsets_ = std::move(offsets);
}

bool Assembler::relocate() {
  std::vector<int> changed;
  for (std::size_t k = 0; k < built_contributions_.size(); ++k) {
    const auto c = static_cast<std::size_t>(built_contributions_[k]);
    const auto now = contributions_[c]->dofs();
    const auto before = placed_dofs(k);
    if (!std::equal(now.begin(), now.end(), before.begin(), before.end())) changed.push_back(static_cast<int>(c));
  }
  std::vector<std::vector<int>> placed(changed.size());
  for (std::size_t k = 0; k < changed.size(); ++k) {
    const auto dofs = contributions_[static_cast<std::size_t>(changed[k])]->dofs();
    const std::size_t m = dofs.size();
    if (weighted_slot(changed[k]) >= 0) return false;
    std::vector<int>& pos = placed[k];
    pos.assign(m * m, -1);
    for (std::size_t b = 0; b < m; ++b) {
      if (equations_.is_dependent(dofs[b])) return false;
      const int ej = equations_.equation(dofs[b]);
      if (ej < 0) continue;
      for (std::size_t a = 0; a < m; ++a) {
        if (equations_.is_dependent(dofs[a])) return false;
        const int ei = equations_.equation(dofs[a]);
        if (ei < 0 || (lower_ && ei < ej)) continue;  // prescribed, or above the diagonal of a lower triangle
        pos[b * m + a] = find_position(ei, ej);
        if (pos[b * m + a] < 0) return false;
      }
    }
  }
  // All found: the contributions leave their colours (their new dofs may
  // collide there) and are assembled serially with their own positions.
  for (std::size_t k = 0; k < changed.size(); ++k) {
    const auto c = static_cast<std::size_t>(changed[k]);
    if (relocated_slot_[c] < 0) {
      for (auto& colour : colours_) {
        const auto it = std::find(colour.begin(), colour.end(), changed[k]);
        if (it != colour.end()) {
          colour.erase(it);
          break;
        }
      }
      relocated_slot_[c] = static_cast<int>(relocated_.size());
      relocated_.emplace_back();
      relocated_dofs_.emplace_back();
      relocated_order_.push_back(changed[k]);
    }
    const auto slot = static_cast<std::size_t>(relocated_slot_[c]);
    relocated_[slot] = std::move(placed[k]);
    const auto dofs = contributions_[c]->dofs();
    relocated_dofs_[slot].assign(dofs.begin(), dofs.end());
  }
  ++relocations_;
  nonlinear_moved_ = true;  // they scatter elsewhere now: hold_linear() adds those entries
  ++revision_;
  return true;
}

void Assembler::assemble(const EvaluationState& state, Eigen::VectorXd& residual, SparseMatrix* tangent) {
  assemble(state, residual, tangent != nullptr);
  if (tangent) *tangent = tangent_;
}

template <class F>
void Assembler::for_each_entry(int c, F&& f) const {
  const auto dofs = contributions_[static_cast<std::size_t>(c)]->dofs();
  const auto m = static_cast<Eigen::Index>(dofs.size());
  const int slot = relocated_slot_[static_cast<std::size_t>(c)];
  if (slot < 0 && weighted_slot(c) >= 0) {
    const WeightedScatter& w = weighted_[static_cast<std::size_t>(weighted_slot(c))];
    for (Eigen::Index e = 0; e < m * m; ++e)
      for (int k = w.start[e]; k < w.start[e + 1]; ++k) f(w.pos[k], e, w.weight[k]);
    return;
  }
  if (slot < 0 && blocked_[static_cast<std::size_t>(c)]) {
    const int* pos = positions_.data() + offsets_[static_cast<std::size_t>(c)];
    const int* outer = tangent_.outerIndexPtr();
    const Eigen::Index h = m / 2;
    for (Eigen::Index l = 0; l < h; ++l) {
      const Eigen::Index e0 = 2 * l * m;  // columns 2l and 2l + 1
      const Eigen::Index e1 = e0 + m;
      int len = -1, diagonal = -1;
      // Lower triangle: one position per pair of nodes, at packed_block(k, l):
      // l (l + 1) / 2 + k up to k = l, then k (k + 1) / 2 + l (steps of k).
      Eigen::Index at = lower_ ? l * (l + 1) / 2 : l * h;
      for (Eigen::Index k = 0; k < h; at += lower_ && k >= l ? k + 1 : 1, ++k) {
        const int p = pos[at];
        if (p < 0) continue;
        if (len < 0) {
          const int first = equations_.equation(dofs[static_cast<std::size_t>(2 * l)]);
          len = outer[first + 1] - outer[first];
          diagonal = outer[first];
        }
        // The pair's position is that of its block below the diagonal: in
        // column l only for that block; the other is skipped, as it was when
        // each block had a position of its own (-1).
        if (lower_ && static_cast<unsigned>(p - diagonal) >= static_cast<unsigned>(len)) continue;
        f(p, e0 + 2 * k, 1.0);
        f(p + 1, e0 + 2 * k + 1, 1.0);
        if (!lower_) {
          f(p + len, e1 + 2 * k, 1.0);
          f(p + len + 1, e1 + 2 * k + 1, 1.0);
          continue;
        }
        // Lower triangle: the second column lacks the first's diagonal row, so
        // its rows sit one place earlier; the diagonal block (p at the
        // column's diagonal) has no entry above the diagonal.
        if (p != diagonal) f(p + len - 1, e1 + 2 * k, 1.0);
        f(p + len, e1 + 2 * k + 1, 1.0);
      }
    }
    return;
  }
  const int* pos = slot >= 0 ? relocated_[static_cast<std::size_t>(slot)].data()
                             : positions_.data() + offsets_[static_cast<std::size_t>(c)];
  for (Eigen::Index e = 0; e < m * m; ++e)
    if (pos[e] >= 0) f(pos[e], e, 1.0);
}

void Assembler::assign_linear(std::vector<std::uint8_t> linear, bool keyed_on_dt) {
  if (linear.size() != contributions_.size())
    throw std::invalid_argument("Assembler::set_linear: one flag per contribution expected");
  linear_ = std::move(linear);
  connecting_.clear();
  for (std::size_t c = 0; c < linear_.size(); ++c)
    if (!linear_[c]) connecting_.push_back(static_cast<int>(c));
  keyed_on_dt_ = keyed_on_dt;
  any_nonlinear_ = std::find(linear_.begin(), linear_.end(), std::uint8_t{0}) != linear_.end();
}

void Assembler::set_linear(std::vector<std::uint8_t> linear, bool keyed_on_dt) {
  assign_linear(std::move(linear), keyed_on_dt);
  drop_linear_built_dofs();
  held_ = false;
  ++revision_, ++outer_revision_, ++hold_generation_;
}

bool Assembler::linear_held(const EvaluationState& state) const {
  return held_ && (!keyed_on_dt_ || state.dt == held_dt_);
}

void Assembler::hold_linear(const EvaluationState* state) {
  const auto n_contrib = static_cast<int>(contributions_.size());
  if (state) {  // after a full assembly: the nonlinear entries as they are now
    nonlinear_entry_.assign(static_cast<std::size_t>(tangent_.nonZeros()), false);
    nonlinear_entries_.clear();
    nonlinear_in_block_ = true;
  }  // else relocated: the entries they scattered into before stay nonlinear (they hold their values)
  std::vector<int> eqs;
  for (int c = 0; c < n_contrib && nonlinear_in_block_; ++c) {
    if (linear_[static_cast<std::size_t>(c)]) continue;
    equations_of(*contributions_[static_cast<std::size_t>(c)], eqs);
    for (int e : eqs)
      if (!std::binary_search(reserved_block_.begin(), reserved_block_.end(), e)) nonlinear_in_block_ = false;
  }
  const std::size_t first_new = nonlinear_entries_.size();  // all of them after a full assembly
  for (int c = 0; c < n_contrib; ++c)
    if (!linear_[static_cast<std::size_t>(c)])
      for_each_entry(c, [&](int p, Eigen::Index, double) {
        if (!nonlinear_entry_[static_cast<std::size_t>(p)])
          nonlinear_entry_[static_cast<std::size_t>(p)] = true, nonlinear_entries_.push_back(p);
      });
  if (!state && nonlinear_in_block_ && block_touchers_valid_) return add_relocated_entries(first_new);
  mixed_.assign(contributions_.size(), 0);
  if (!nonlinear_entries_.empty())
    for (int c = 0; c < n_contrib; ++c)
      if (linear_[static_cast<std::size_t>(c)])
        for_each_entry(c, [&](int p, Eigen::Index, double) {
          if (nonlinear_entry_[static_cast<std::size_t>(p)]) mixed_[static_cast<std::size_t>(c)] = 1;
        });
  if (state) held_ = true, held_dt_ = state->dt;
  nonlinear_moved_ = false;
  mark_direct();
  // The linear contributions with an equation in the reserved block: the
  // only ones a relocation inside the block can make mixed.
  block_touchers_.clear();
  block_touchers_valid_ = state != nullptr && nonlinear_in_block_;
  if (!block_touchers_valid_) return;
  std::vector<std::uint8_t> reserved(static_cast<std::size_t>(equations_.n_equations()), 0);
  for (int e : reserved_block_) reserved[static_cast<std::size_t>(e)] = 1;
  for (int c = 0; c < n_contrib; ++c) {
    if (!linear_[static_cast<std::size_t>(c)]) continue;
    bool touches = false;
    for (int d : contributions_[static_cast<std::size_t>(c)]->dofs())
      for (const EquationWeight& w : equations_.weights(d)) touches = touches || reserved[static_cast<std::size_t>(w.equation)];
    if (touches) block_touchers_.push_back(c);
  }
}

void Assembler::add_relocated_entries(std::size_t first_new) {
  // mixed_ and direct_ only grow: a contribution becomes mixed when it
  // touches one of the entries added since first_new, and those lie in the
  // reserved block, so only block_touchers_ can. The result is that of
  // recomputing both over every contribution (mark_direct()).
  ++hold_generation_;
  nonlinear_moved_ = false;
  if (first_new == nonlinear_entries_.size()) return;
  const int* outer = tangent_.outerIndexPtr();
  for (std::size_t k = first_new; k < nonlinear_entries_.size(); ++k)
    nonlinear_column_[static_cast<std::size_t>(
        std::upper_bound(outer, outer + tangent_.cols() + 1, nonlinear_entries_[k]) - outer - 1)] = 1;
  std::vector<bool> added(static_cast<std::size_t>(tangent_.nonZeros()), false);
  for (std::size_t k = first_new; k < nonlinear_entries_.size(); ++k)
    added[static_cast<std::size_t>(nonlinear_entries_[k])] = true;
  for (int c : block_touchers_) {
    if (mixed_[static_cast<std::size_t>(c)]) continue;
    for_each_entry(c, [&](int p, Eigen::Index, double) {
      if (added[static_cast<std::size_t>(p)]) mixed_[static_cast<std::size_t>(c)] = 1;
    });
    if (mixed_[static_cast<std::size_t>(c)]) direct_[static_cast<std::size_t>(c)] = 1;
  }
}

void Assembler::mark_direct() {
  ++hold_generation_;
  nonlinear_column_.assign(static_cast<std::size_t>(equations_.n_equations()), 0);
  for (int p : nonlinear_entries_)
    nonlinear_column_[static_cast<std::size_t>(
        std::upper_bound(tangent_.outerIndexPtr(), tangent_.outerIndexPtr() + tangent_.cols() + 1, p) -
        tangent_.outerIndexPtr() - 1)] = 1;
  direct_.assign(contributions_.size(), 0);
  timed_flag_.assign(contributions_.size(), 0);
  timed_.clear();
  for (std::size_t c = 0; c < contributions_.size(); ++c) {
    bool direct = !linear_[c] || mixed_[c];
    for (int d : contributions_[c]->dofs()) direct = direct || equations_.equation(d) < 0;
    direct_[c] = direct;
    if (!direct && contributions_[c]->residual_depends_on_time())
      timed_flag_[c] = 1, timed_.push_back(static_cast<int>(c));
  }
}

void Assembler::enable_residual_updates(bool on) {
  updates_enabled_ = on;
  if (on) timed_stale_ = true;  // the loads or the contributions' state may have changed
}

void Assembler::restart_point() {
  reference_valid_ = false;
  defer_record_ = true;
}

bool Assembler::reference_serves(const EvaluationState& state) const {
  if (!reference_valid_ || reference_generation_ != hold_generation_ || !linear_held(state) || nonlinear_moved_ ||
      state.u.size() != reference_u_.size())
    return false;
  // No prescribed dof is in L: other prescribed values than u_ref's change
  // only the residuals of the direct contributions, which are evaluated.
  return true;
}

bool Assembler::refresh_timed(const EvaluationState& state) {
  const EvaluationState at_reference{reference_u_, state.u_start, state.step_time, state.total_time, state.dt,
                                     state.nlgeom};
  if (!timed_.empty()) reference_timed_.setZero(equations_.n_dofs());
  LocalSystem local;
  try {
    for (int c : timed_) {
      if (direct_[static_cast<std::size_t>(c)]) continue;  // left L in a relocation
      const auto dofs = contributions_[static_cast<std::size_t>(c)]->dofs();
      local.reset(static_cast<Eigen::Index>(dofs.size()));
      contributions_[static_cast<std::size_t>(c)]->evaluate(at_reference, local, false);
      for (std::size_t a = 0; a < dofs.size(); ++a)
        reference_timed_[dofs[a]] += local.residual[static_cast<Eigen::Index>(a)];
    }
  } catch (...) {
    reference_valid_ = false;  // this assembly records a new reference
    return false;
  }
  reference_time_ = {state.step_time, state.total_time, state.dt};
  timed_stale_ = false;
  return true;
}

void Assembler::carry_reference(const EvaluationState& state, const std::vector<std::uint8_t>& before) {
  // The contributions that left L (now touching an entry a relocated
  // contribution scatters into) take their part of r_L(u_ref) with them.
  const EvaluationState at_reference{reference_u_, state.u_start, state.step_time, state.total_time, state.dt,
                                     state.nlgeom};
  LocalSystem local;
  try {
    for (std::size_t c = 0; c < contributions_.size(); ++c) {
      if (before[c] || !direct_[c]) continue;
      if (timed_flag_[c]) {  // r_T(u_ref) is evaluated anew without it
        timed_stale_ = true;
        continue;
      }
      const auto dofs = contributions_[c]->dofs();
      local.reset(static_cast<Eigen::Index>(dofs.size()));
      contributions_[c]->evaluate(at_reference, local, false);
      for (std::size_t a = 0; a < dofs.size(); ++a)
        reference_residual_[dofs[a]] -= local.residual[static_cast<Eigen::Index>(a)];
    }
  } catch (...) {
    reference_valid_ = false;  // the next assembly records a new reference
    return;
  }
  reference_generation_ = hold_generation_;
}

void Assembler::add_linear_update(const EvaluationState& state, Eigen::VectorXd& residual) const {
  residual += reference_residual_;
  if (reference_timed_.size() > 0) residual += reference_timed_;
  const int* outer = tangent_.outerIndexPtr();
  const int* inner = tangent_.innerIndexPtr();
  const double* value = tangent_.valuePtr();
  const int n = equations_.n_equations();
  Eigen::VectorXd product = Eigen::VectorXd::Zero(n);  // K_L (u - u_ref) by equations
  if (lower_) return add_symmetric_update(state, residual, product);
  for (int j = 0; j < n; ++j) {
    const int dof_j = equations_.dof(j);
    const double du = state.u[dof_j] - reference_u_[dof_j];
    if (du == 0.0) continue;
    if (!nonlinear_column_[static_cast<std::size_t>(j)]) {
      for (int p = outer[j]; p < outer[j + 1]; ++p) product[inner[p]] += value[p] * du;
      continue;
    }
    for (int p = outer[j]; p < outer[j + 1]; ++p)
      if (!nonlinear_entry_[static_cast<std::size_t>(p)]) product[inner[p]] += value[p] * du;
  }
  for (int i = 0; i < n; ++i) residual[equations_.dof(i)] += product[i];
}

void Assembler::add_symmetric_update(const EvaluationState& state, Eigen::VectorXd& residual,
                                     Eigen::VectorXd& product) const {
  // Each stored entry (i, j), i > j, stands for (j, i) too: column j adds to
  // row i and, with u_i, to row j. Row j receives nothing from later
  // columns, so adding its mirrored terms here, rows ascending, sums every
  // row in the order of the whole matrix's product (columns ascending).
  const int* outer = tangent_.outerIndexPtr();
  const int* inner = tangent_.innerIndexPtr();
  const double* value = tangent_.valuePtr();
  const int n = equations_.n_equations();
  Eigen::VectorXd du(n);
  for (int j = 0; j < n; ++j) {
    const int dof = equations_.dof(j);
    du[j] = state.u[dof] - reference_u_[dof];
  }
  // Row j's sum is kept in a register while column j is read (the rows i
  // of its other entries are all > j): the same additions in the same order.
  for (int j = 0; j < n; ++j) {
    const double dj = du[j];
    const bool check = nonlinear_column_[static_cast<std::size_t>(j)] != 0;
    double row_j = product[j];
    for (int p = outer[j]; p < outer[j + 1]; ++p) {
      if (check && nonlinear_entry_[static_cast<std::size_t>(p)]) continue;
      const int i = inner[p];
      if (i == j) {
        row_j += value[p] * dj;
        continue;
      }
      product[i] += value[p] * dj;
      row_j += value[p] * du[i];
    }
    product[j] = row_j;
  }
  for (int i = 0; i < n; ++i) residual[equations_.dof(i)] += product[i];
}

bool Assembler::prepare_updates(const EvaluationState& state, bool held, bool& record) {
  if (held && nonlinear_moved_) {
    const bool carried = reference_valid_ && reference_generation_ == hold_generation_;
    std::vector<std::uint8_t> before;
    if (carried) before = direct_;
    hold_linear(nullptr);
    if (carried) carry_reference(state, before);
  }
  const bool can_update = updates_enabled_ && held_ && !nonlinear_moved_ && linear_held(state) &&
                          !equations_.has_dependents();
  bool update = can_update && reference_serves(state);
  const std::array<double, 3> time{state.step_time, state.total_time, state.dt};
  if (update && (timed_stale_ || time != reference_time_)) update = refresh_timed(state);
  record = can_update && !update;
  if (updates_enabled_ && defer_record_) record = false, defer_record_ = false;  // as a resumed run
  if (record) {
    reference_time_ = time;
    timed_stale_ = false;
    reference_u_ = state.u;
    reference_residual_.setZero(equations_.n_dofs());
    if (timed_.empty())
      Eigen::VectorXd().swap(reference_timed_);
    else
      reference_timed_.setZero(equations_.n_dofs());
  }
  return update;
}

void Assembler::assemble(const EvaluationState& state, Eigen::VectorXd& residual, bool with_tangent) {
  const auto t0 = std::chrono::steady_clock::now();
  residual.setZero(equations_.n_dofs());
  // Held: only the entries of nonlinear contributions are assembled anew.
  const bool held = with_tangent && linear_held(state);
  // The values change unless every contribution is held (also when an assembly
  // fails); those outside the reserved block unless the nonlinear ones lie inside it.
  bool record = false;
  const bool update = prepare_updates(state, held, record);
  if (with_tangent && (!held || any_nonlinear_)) ++revision_;
  if (with_tangent && (!held || !nonlinear_in_block_)) ++outer_revision_;
  if (with_tangent) {
    if (held)
      for (int p : nonlinear_entries_) tangent_.valuePtr()[p] = 0.0;
    else
      std::fill_n(tangent_.valuePtr(), tangent_.nonZeros(), 0.0), held_ = false;
  }
  double* values = with_tangent ? tangent_.valuePtr() : nullptr;
  std::exception_ptr failure;
  std::atomic<bool> failed{false};

  // Evaluates contribution c and scatters it.
  const auto add = [&](int c, LocalSystem& local) {
    if (update && !direct_[static_cast<std::size_t>(c)]) return;  // in r_L(u_ref) + K_L (u - u_ref)
    const Contribution* contribution = contributions_[c];
    const auto dofs = contribution->dofs();
    const auto m = static_cast<Eigen::Index>(dofs.size());
    // Held linear contributions add to the nonlinear entries only (mixed) or not at all.
    const bool keep = held && linear_[static_cast<std::size_t>(c)];
    const bool mixed = keep && mixed_[static_cast<std::size_t>(c)];
    const bool tangent = values != nullptr && (!keep || mixed);
    // An update subtracts the held entries of the other linear contributions: their tangent.
    const bool subtract = update && linear_[static_cast<std::size_t>(c)];
    try {
      local.reset(m);
      contribution->evaluate(state, local, tangent || subtract);
    } catch (...) {
#pragma omp critical(tether_assembly_failure)
      if (!failure) failure = std::current_exception();
      failed = true;
      return;
    }
    for (Eigen::Index a = 0; a < m; ++a) residual[dofs[a]] += local.residual[a];
    if (record && !direct_[static_cast<std::size_t>(c)]) {
      Eigen::VectorXd& part = timed_flag_[static_cast<std::size_t>(c)] ? reference_timed_ : reference_residual_;
      for (Eigen::Index a = 0; a < m; ++a) part[dofs[a]] += local.residual[a];
    }
    const double* ke = local.tangent.data();  // column-major, like the positions
    if (subtract)
      for_each_entry(c, [&](int p, Eigen::Index e, double) {
        if (nonlinear_entry_[static_cast<std::size_t>(p)]) return;
        const int d = dofs[static_cast<std::size_t>(e / m)];
        const int row = dofs[static_cast<std::size_t>(e % m)];
        residual[row] -= ke[e] * (state.u[d] - reference_u_[d]);
        // A lower triangle holds this entry for its mirror too.
        if (lower_ && row != d) residual[d] -= ke[e] * (state.u[row] - reference_u_[row]);
      });
    if (!tangent) return;
    if (mixed)
      for_each_entry(c, [&](int p, Eigen::Index e, double w) {
        if (nonlinear_entry_[static_cast<std::size_t>(p)]) values[p] += w * ke[e];
      });
    else
      for_each_entry(c, [&](int p, Eigen::Index e, double w) { values[p] += w * ke[e]; });
  };

  for (std::size_t k = 0; k < colours_.size(); ++k) {
    const std::vector<int>& colour = colours_[k];
    const int count = static_cast<int>(colour.size());
    const bool serial = (last_colour_serial_ && k + 1 == colours_.size()) || count < kParallelThreshold;
#pragma omp parallel if (!serial)
    {
      LocalSystem local;
#pragma omp for schedule(dynamic, 64)
      for (int i = 0; i < count; ++i)
        if (!failed.load(std::memory_order_relaxed)) add(colour[i], local);
    }
    if (failure) std::rethrow_exception(failure);
  }
  LocalSystem local;
  for (int c : relocated_order_) {
    add(c, local);
    if (failure) std::rethrow_exception(failure);
  }
  if (update) add_linear_update(state, residual), ++reuse_statistics_.residual_updates;
  if (record) reference_valid_ = true, reference_generation_ = hold_generation_;
  if (with_tangent && !held && !linear_.empty()) hold_linear(&state), ++reuse_statistics_.full;
  if (held) ++reuse_statistics_.reused;
  timing_.evaluate = seconds_since(t0);
}

}  // namespace tether
