/// \file The assembler's sparsity pattern: which equations each
/// contribution couples, the compressed-column pattern (whole, or its lower
/// triangle for a symmetric tangent stored as one), and each contribution's
/// scatter positions in it. The rest of Assembler is in assembler.cpp.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <limits>
#include <stdexcept>

#include "tether/assembly/assembler.hpp"

namespace tether {

namespace {

/// Drops the entries above the diagonal of a compressed-column pattern
/// (rows sorted in each column), in place.
void keep_lower(std::vector<int>& outer, std::vector<int>& inner) {
  int kept = 0, begin = outer[0];
  for (std::size_t j = 0; j + 1 < outer.size(); ++j) {
    const int end = outer[j + 1];
    for (int p = begin; p < end; ++p)
      if (inner[static_cast<std::size_t>(p)] >= static_cast<int>(j)) inner[static_cast<std::size_t>(kept++)] = inner[static_cast<std::size_t>(p)];
    begin = end;
    outer[j + 1] = kept;
  }
  inner.resize(static_cast<std::size_t>(kept));
  inner.shrink_to_fit();
}

}  // namespace

void Assembler::equations_of(const Contribution& c, std::vector<int>& out) const {
  out.clear();
  if (!equations_.has_dependents()) {  // T is the identity on the free dofs
    for (int d : c.dofs())
      if (const int e = equations_.equation(d); e >= 0) out.push_back(e);
  } else {
    for (int d : c.dofs())
      for (const EquationWeight& w : equations_.weights(d)) out.push_back(w.equation);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

template <class Position>
void Assembler::place_packed_blocks(std::span<const int> dofs, int* pos, const Position& position) const {
  // Of the blocks (row k, column l) and (row l, column k) of two nodes, the
  // one whose first equation of the row is the larger lies below the
  // diagonal (the pairs' equations are disjoint); a node's own block is on it.
  const std::size_t h = dofs.size() / 2;
  for (std::size_t l = 0; l < h; ++l) {
    const int el = equations_.equation(dofs[2 * l]);
    if (el < 0) continue;
    for (std::size_t k = 0; k <= l; ++k) {
      const int ek = equations_.equation(dofs[2 * k]);
      if (ek >= 0) pos[packed_block(k, l)] = ek >= el ? position(ek, el) : position(el, ek);
    }
  }
}

void Assembler::build_pattern() {
  const auto t0 = std::chrono::steady_clock::now();
  const int n = equations_.n_equations();
  const int n_contrib = static_cast<int>(contributions_.size());
  std::vector<int> eqs;
  if (!reserved_block_.empty() && (reserved_block_.front() < 0 || reserved_block_.back() >= n))
    throw std::invalid_argument("Assembler: a reserved equation is outside the system");
  ++pattern_builds_;
  held_ = false;
  ++revision_, ++outer_revision_, ++hold_generation_;
  relocated_slot_.assign(static_cast<std::size_t>(n_contrib), -1);
  relocated_.clear();
  relocated_dofs_.clear();
  relocated_order_.clear();
  record_built_dofs();

  // 1. Rows per column, with duplicates, then sorted and unique.
  std::vector<std::int64_t> count(n + 1, 0);
  for (const Contribution* c : contributions_) {
    equations_of(*c, eqs);
    for (int e : eqs) count[e + 1] += static_cast<std::int64_t>(eqs.size());
  }
  for (int e : reserved_block_) count[e + 1] += static_cast<std::int64_t>(reserved_block_.size());
  for (int j = 0; j < n; ++j) count[j + 1] += count[j];
  std::vector<int> rows(static_cast<std::size_t>(count[n]));
  std::vector<std::int64_t> fill(count.begin(), count.end() - 1);
  for (const Contribution* c : contributions_) {
    equations_of(*c, eqs);
    for (int ej : eqs)
      for (int ei : eqs) rows[fill[ej]++] = ei;
  }
  for (int ej : reserved_block_)
    for (int ei : reserved_block_) rows[fill[ej]++] = ei;
  // The previous tangent is dropped first; the new one gets the structure
  // with zero values.
  SparseMatrix().swap(tangent_);
  std::vector<int> outer(static_cast<std::size_t>(n) + 1, 0);
  std::vector<int> inner;
  inner.reserve(rows.size() / 2);
  for (int j = 0; j < n; ++j) {
    auto b = rows.begin() + count[j], e = rows.begin() + count[j + 1];
    std::sort(b, e);
    e = std::unique(b, e);
    inner.insert(inner.end(), b, e);
    outer[j + 1] = static_cast<int>(inner.size());
  }
  rows.clear();
  rows.shrink_to_fit();

  auto position = [&](int row, int col) {
    return static_cast<int>(std::lower_bound(inner.data() + outer[col], inner.data() + outer[col + 1], row) -
                            inner.data());
  };

  // 2. Value positions of each contribution's local entries: plain for
  //    contributions on free/prescribed dofs only, weighted through T otherwise.
  //    A plain contribution whose dofs come in node pairs (2k, 2k+1) with
  //    consecutive equations (or both prescribed), each pair's second column
  //    having the rows of its first, stores one position per 2x2 block: the
  //    block's other entries sit at p + 1 (next row), p + len and p + len + 1
  //    (next column, len = length of the block's first column).
  std::vector<bool> same_rows_as_previous(static_cast<std::size_t>(n), false);
  for (int j = 1; j < n; ++j)
    same_rows_as_previous[j] = outer[j + 1] - outer[j] == outer[j] - outer[j - 1] &&
                               std::equal(inner.begin() + outer[j], inner.begin() + outer[j + 1],
                                          inner.begin() + outer[j - 1]);
  if (lower_) keep_lower(outer, inner);
  const auto in_blocks = [&](std::span<const int> dofs) {
    if (dofs.size() % 2 != 0) return false;
    for (std::size_t k = 0; k < dofs.size(); k += 2) {
      const int e0 = equations_.equation(dofs[k]), e1 = equations_.equation(dofs[k + 1]);
      if (e0 < 0 && e1 < 0) continue;
      if (e0 < 0 || e1 != e0 + 1 || !same_rows_as_previous[static_cast<std::size_t>(e1)]) return false;
    }
    return true;
  };
  offsets_.assign(n_contrib + 1, 0);
  std::vector<int>().swap(weighted_index_);
  if (equations_.has_dependents()) weighted_index_.assign(n_contrib, -1);
  weighted_.clear();
  blocked_.assign(static_cast<std::size_t>(n_contrib), 0);
  std::size_t n_positions = 0;
  for (int c = 0; c < n_contrib; ++c) {
    const auto dofs = contributions_[c]->dofs();
    const auto m = dofs.size();
    const bool weighted =
        equations_.has_dependents() && std::any_of(dofs.begin(), dofs.end(), [&](int d) { return equations_.is_dependent(d); });
    if (weighted) {
      weighted_index_[c] = static_cast<int>(weighted_.size());
      weighted_.emplace_back();
    } else {
      blocked_[c] = in_blocks(dofs);
    }
    // Blocked: one position per 2x2 block, or in a lower triangle per pair of nodes (packed_block).
    const std::size_t h = m / 2;
    n_positions += weighted ? 0 : !blocked_[c] ? m * m : lower_ ? h * (h + 1) / 2 : h * h;
    if (n_positions > std::numeric_limits<std::uint32_t>::max())
      throw std::length_error("Assembler: more than 2^32 scatter positions");
    offsets_[c + 1] = static_cast<std::uint32_t>(n_positions);
  }
  positions_.assign(n_positions, -1);
  positions_.shrink_to_fit();
#pragma omp parallel for schedule(dynamic, 256) if (n_contrib >= kParallelThreshold)
  for (int c = 0; c < n_contrib; ++c) {
    const auto dofs = contributions_[c]->dofs();
    const std::size_t m = dofs.size();
    if (weighted_slot(c) >= 0) {
      WeightedScatter& w = weighted_[weighted_index_[c]];
      w.start.assign(m * m + 1, 0);
      for (std::size_t b = 0; b < m; ++b)
        for (std::size_t a = 0; a < m; ++a) {
          for (const EquationWeight& wb : equations_.weights(dofs[b]))
            for (const EquationWeight& wa : equations_.weights(dofs[a])) {
              if (lower_ && wa.equation < wb.equation) continue;  // above the diagonal: not stored
              w.pos.push_back(position(wa.equation, wb.equation));
              w.weight.push_back(wa.weight * wb.weight);
            }
          w.start[b * m + a + 1] = static_cast<int>(w.pos.size());
        }
      continue;
    }
    if (blocked_[c] && lower_) {
      place_packed_blocks(dofs, positions_.data() + offsets_[c], position);
      continue;
    }
    const std::size_t step = blocked_[c] ? 2 : 1, h = m / step;
    for (std::size_t b = 0; b < m; b += step) {
      const int ej = equations_.equation(dofs[b]);
      if (ej < 0) continue;
      for (std::size_t a = 0; a < m; a += step) {
        const int ei = equations_.equation(dofs[a]);
        // Lower triangle: a 2x2 block above the diagonal holds no entry (the
        // pairs' equations are disjoint, so ei < ej puts all four there).
        if (ei >= 0 && (!lower_ || ei >= ej)) positions_[offsets_[c] + (b / step) * h + a / step] = position(ei, ej);
      }
    }
  }

  tangent_.resize(n, n);
  tangent_.resizeNonZeros(static_cast<Eigen::Index>(inner.size()));
  std::copy(outer.begin(), outer.end(), tangent_.outerIndexPtr());
  std::copy(inner.begin(), inner.end(), tangent_.innerIndexPtr());
  std::fill_n(tangent_.valuePtr(), inner.size(), 0.0);
  inner.clear();
  inner.shrink_to_fit();

  // 3. Greedy colouring: no two contributions of a colour share a global dof
  //    or (through T) a free equation, so their scatters never collide.
  std::vector<std::uint64_t> used(equations_.n_dofs(), 0);
  colours_.assign(1, {});
  std::vector<int> overflow;
  std::vector<int> touched;
  for (int c = 0; c < n_contrib; ++c) {
    const auto dofs = contributions_[c]->dofs();
    touched.assign(dofs.begin(), dofs.end());
    if (weighted_slot(c) >= 0) {
      equations_of(*contributions_[c], eqs);
      for (int e : eqs) touched.push_back(equations_.dof(e));
    }
    std::uint64_t mask = 0;
    for (int d : touched) mask |= used[d];
    if (mask == ~std::uint64_t{0}) {
      overflow.push_back(c);
      continue;
    }
    const int colour = std::countr_one(mask);
    for (int d : touched) used[d] |= std::uint64_t{1} << colour;
    if (colour >= static_cast<int>(colours_.size())) colours_.resize(colour + 1);
    colours_[colour].push_back(c);
  }
  last_colour_serial_ = !overflow.empty();
  if (last_colour_serial_) colours_.push_back(std::move(overflow));
  timing_.pattern = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace tether
