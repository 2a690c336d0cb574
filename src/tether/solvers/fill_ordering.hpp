#pragma once
/// \file Fill-reducing ordering of a sparse matrix with chosen equations
/// ordered last, for factorizations with a Schur complement.
///
/// MUMPS ignores the ordering asked for in ICNTL(7) when a Schur complement
/// is requested (ICNTL(19)) and uses AMD; a nested dissection given as
/// PERM_IN (ICNTL(7) = 1) keeps the Schur equations last and, on the 231k-dof
/// Hertz deck, leaves 21.2M factor entries instead of AMD's 24.0M.
///
/// The ordering is METIS's nested dissection (through CHOLMOD's Partition
/// module: no dependency beyond SuiteSparse) on the compressed graph:
/// consecutive equations with the same neighbours (a node's dofs) become one
/// vertex, so METIS orders nodes, not dofs, and the dofs of a node stay
/// together.
#include <vector>

#include "tether/solvers/linear_solver.hpp"

namespace tether {

/// Returns MUMPS's PERM_IN for `a`: entry e (0-based equation) holds the
/// 1-based position of e in the pivot order. The equations with
/// `last[e] != 0` come last, in ascending order; the others are ordered by
/// nested dissection of the graph of `a` without them. Reads only the pattern
/// of `a`, which may hold one triangle or both (it is symmetrized); the
/// diagonal is ignored. Cost on the 231k-dof Hertz deck: about 0.6 s CPU
/// (0.1 s the graph, 0.5 s METIS). Throws SolverError when METIS fails or
/// CHOLMOD was built without it (MumpsSchur then keeps MUMPS's AMD).
[[nodiscard]] std::vector<int> nested_dissection_last(const SparseMatrix& a, const std::vector<char>& last);

}  // namespace tether
