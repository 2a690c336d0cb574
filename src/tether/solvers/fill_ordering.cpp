#include "tether/solvers/fill_ordering.hpp"

#include <cholmod.h>

#include <algorithm>
#include <numeric>
#include <span>
#include <string>

#include "tether/core/error.hpp"

namespace tether {

namespace {

/// Symmetric adjacency of the equations that are not `last`, diagonal
/// excluded, as sorted unique lists in CSR form (`start` has n + 1 entries).
struct Graph {
  std::vector<int> start, neighbours;
  [[nodiscard]] std::span<const int> of(int e) const {
    return {neighbours.data() + start[static_cast<std::size_t>(e)],
            static_cast<std::size_t>(start[static_cast<std::size_t>(e) + 1] - start[static_cast<std::size_t>(e)])};
  }
};

Graph adjacency(const SparseMatrix& a, const std::vector<char>& last) {
  const auto n = static_cast<std::size_t>(a.cols());
  const auto kept = [&](int i, Eigen::Index j) {
    return i != j && !last[static_cast<std::size_t>(i)] && !last[static_cast<std::size_t>(j)];
  };
  std::vector<int> count(n + 1, 0);
  for (Eigen::Index j = 0; j < a.cols(); ++j)
    for (int k = a.outerIndexPtr()[j]; k < a.outerIndexPtr()[j + 1]; ++k)
      if (const int i = a.innerIndexPtr()[k]; kept(i, j)) ++count[static_cast<std::size_t>(i) + 1], ++count[static_cast<std::size_t>(j) + 1];
  std::partial_sum(count.begin(), count.end(), count.begin());
  std::vector<int> fill(count.begin(), count.end() - 1), neighbours(static_cast<std::size_t>(count[n]));
  for (Eigen::Index j = 0; j < a.cols(); ++j)
    for (int k = a.outerIndexPtr()[j]; k < a.outerIndexPtr()[j + 1]; ++k)
      if (const int i = a.innerIndexPtr()[k]; kept(i, j)) {
        neighbours[static_cast<std::size_t>(fill[static_cast<std::size_t>(i)]++)] = static_cast<int>(j);
        neighbours[static_cast<std::size_t>(fill[static_cast<std::size_t>(j)]++)] = i;
      }
  // Sort and compact in place: a matrix holding both triangles lists each edge twice.
  Graph g;
  g.start.assign(n + 1, 0);
  int out = 0;
  for (std::size_t e = 0; e < n; ++e) {
    const auto first = neighbours.begin() + count[e], end = neighbours.begin() + count[e + 1];
    std::sort(first, end);
    const auto unique_end = std::unique(first, end);
    out = static_cast<int>(std::copy(first, unique_end, neighbours.begin() + out) - neighbours.begin());
    g.start[e + 1] = out;
  }
  neighbours.resize(static_cast<std::size_t>(out));
  g.neighbours = std::move(neighbours);
  return g;
}

/// True when equations e - 1 and e have the same closed neighbourhood
/// (N(e) with e itself), as the dofs of one node have.
bool same_neighbourhood(const Graph& g, int e) {
  const auto p = g.of(e - 1), q = g.of(e);
  if (p.size() != q.size() || !std::binary_search(p.begin(), p.end(), e)) return false;
  // Then e - 1 is in N(e) too (symmetry): compare N(e-1) without e with N(e) without e - 1.
  std::size_t i = 0, j = 0;
  for (;;) {
    if (i < p.size() && p[i] == e) ++i;
    if (j < q.size() && q[j] == e - 1) ++j;
    if (i == p.size() || j == q.size()) return i == p.size() && j == q.size();
    if (p[i] != q[j]) return false;
    ++i, ++j;
  }
}

/// METIS nested dissection of the graph of groups (lower triangle given);
/// returns the groups in pivot order.
std::vector<int> metis_order(const std::vector<int>& start, std::vector<int>& rows) {
  const std::size_t n = start.size() - 1;
  cholmod_common common{};
  cholmod_start(&common);
  common.print = 0;
  common.error_handler = nullptr;
  cholmod_sparse g{};
  g.nrow = g.ncol = n;
  g.nzmax = rows.size();
  g.p = const_cast<int*>(start.data());
  g.i = rows.data();
  g.stype = -1;
  g.itype = CHOLMOD_INT;
  g.xtype = CHOLMOD_PATTERN;
  g.dtype = CHOLMOD_DOUBLE;
  g.sorted = 1;
  g.packed = 1;
  std::vector<int> order(n);
  const int ok = n == 0 ? 1 : cholmod_metis(&g, nullptr, 0, 0, order.data(), &common);
  const int status = common.status;
  cholmod_finish(&common);
  if (!ok || status < CHOLMOD_OK)
    throw SolverError("fill ordering: METIS nested dissection failed (CHOLMOD status " + std::to_string(status) + ")");
  return order;
}

}  // namespace

std::vector<int> nested_dissection_last(const SparseMatrix& a, const std::vector<char>& last) {
  const int n = static_cast<int>(a.cols());
  if (a.rows() != a.cols() || last.size() != static_cast<std::size_t>(n))
    throw SolverError("fill ordering: square matrix and one flag per equation expected");
  const Graph g = adjacency(a, last);
  // Groups: runs of consecutive kept equations with one closed neighbourhood.
  std::vector<int> group(static_cast<std::size_t>(n), -1), first;
  for (int e = 0; e < n; ++e) {
    if (last[static_cast<std::size_t>(e)]) continue;
    const bool joins = e > 0 && !last[static_cast<std::size_t>(e) - 1] && same_neighbourhood(g, e);
    if (!joins) first.push_back(e);
    group[static_cast<std::size_t>(e)] = static_cast<int>(first.size()) - 1;
  }
  // The graph of the groups, lower triangle, column by column.
  std::vector<int> start(first.size() + 1, 0), rows;
  for (std::size_t q = 0; q < first.size(); ++q) {
    for (const int e : g.of(first[q]))
      if (const int r = group[static_cast<std::size_t>(e)]; r > static_cast<int>(q) && (rows.size() == static_cast<std::size_t>(start[q]) || rows.back() != r))
        rows.push_back(r);  // neighbours are sorted, so groups are too
    start[q + 1] = static_cast<int>(rows.size());
  }
  const std::vector<int> order = metis_order(start, rows);
  std::vector<int> perm_in(static_cast<std::size_t>(n));
  int position = 0;
  for (const int q : order)
    for (int e = first[static_cast<std::size_t>(q)]; e < n && group[static_cast<std::size_t>(e)] == q; ++e)
      perm_in[static_cast<std::size_t>(e)] = ++position;
  for (int e = 0; e < n; ++e)
    if (last[static_cast<std::size_t>(e)]) perm_in[static_cast<std::size_t>(e)] = ++position;
  return perm_in;
}

}  // namespace tether
