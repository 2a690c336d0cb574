#include "tether/solvers/dual_condensation.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "tether/core/error.hpp"

namespace tether {

namespace {

/// B is treated as singular (the full matrix goes to the inner solver) below
/// this reciprocal condition number estimate.
constexpr double kMinReciprocalCondition = 1e-14;

/// Sorted, unique.
std::vector<int> unique_sorted(std::vector<int> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

}  // namespace

MortarCondensation parse_mortar_condensation(const std::string& name) {
  std::string lower = name;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  if (lower == "dense") return MortarCondensation::Dense;
  if (lower == "kept") return MortarCondensation::Kept;
  if (lower == "sparse") return MortarCondensation::Sparse;
  throw std::invalid_argument("unknown mortar condensation '" + name + "' (dense, kept or sparse)");
}

DualElimination choose_dual_elimination(const SparseMatrix& a, const std::vector<DualNodeEquations>& nodes,
                                        const std::vector<int>* columns) {
  const auto n = static_cast<int>(a.rows());
  // Off-diagonal entries of each mortar multiplier's row and column.
  std::vector<int> node_of(static_cast<std::size_t>(n), -1);
  for (std::size_t k = 0; k < nodes.size(); ++k)
    if (nodes[k].multiplier >= 0) node_of[static_cast<std::size_t>(nodes[k].multiplier)] = static_cast<int>(k);
  std::vector<std::vector<std::pair<int, double>>> row(nodes.size());
  std::vector<double> diagonal(nodes.size(), 0.0);
  std::vector<bool> coupled(nodes.size(), false);
  const auto n_columns = columns ? static_cast<int>(columns->size()) : n;
  for (int c = 0; c < n_columns; ++c) {
    const int col = columns ? (*columns)[static_cast<std::size_t>(c)] : c;
    for (SparseMatrix::InnerIterator it(a, col); it; ++it) {
      if (it.value() == 0) continue;
      const int r = static_cast<int>(it.row());
      const int by_row = node_of[static_cast<std::size_t>(r)], by_col = node_of[static_cast<std::size_t>(col)];
      if (by_row >= 0 && r == col) diagonal[static_cast<std::size_t>(by_row)] = it.value();
      if (r == col) continue;
      if (by_row >= 0) row[static_cast<std::size_t>(by_row)].emplace_back(col, it.value()), coupled[static_cast<std::size_t>(by_row)] = true;
      if (by_col >= 0) coupled[static_cast<std::size_t>(by_col)] = true;
    }
  }
  DualElimination out;
  std::vector<bool> taken(static_cast<std::size_t>(n), false);
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    const DualNodeEquations& node = nodes[k];
    if (node.multiplier < 0) continue;
    if (diagonal[k] != 0 && !coupled[k]) {  // open: λ_j = b_j / a_jj, apart from B (its -1/c_j is tiny)
      out.apart.emplace_back(node.multiplier, diagonal[k]);
      ++out.diagonal;
      continue;
    }
    if (diagonal[k] != 0) {  // a soft law: the row solves for λ_j itself
      out.eliminated.push_back(node.multiplier);
      ++out.diagonal;
      continue;
    }
    if (!coupled[k]) continue;
    // Closed HARD: the pivot is the node's displacement equation with the largest |∂g̃_j/∂u|.
    int pivot = -1;
    double largest = 0;
    for (const auto& [col, value] : row[k])
      if ((col == node.displacement[0] || col == node.displacement[1]) && !taken[static_cast<std::size_t>(col)] &&
          std::abs(value) > largest)
        pivot = col, largest = std::abs(value);
    if (pivot < 0) continue;
    taken[static_cast<std::size_t>(pivot)] = true;
    out.eliminated.push_back(pivot);
    out.eliminated.push_back(node.multiplier);
    ++out.closed;
  }
  return out;
}

DualCondensedSolver::DualCondensedSolver(std::vector<DualNodeEquations> nodes, std::unique_ptr<LinearSolver> inner)
    : nodes_(std::move(nodes)), inner_(std::move(inner)) {}

void DualCondensedSolver::analyze(const SparseMatrix& /*a*/) {
  analysed_r_.clear();  // the inner solver analyses at the next factorize
  analysed_outer_.resize(0);
}

std::string DualCondensedSolver::name() const { return "dual condensation + " + inner_->name(); }

void DualCondensedSolver::choose_eliminated(const SparseMatrix& a) {
  DualElimination e = choose_dual_elimination(a, nodes_);
  z_ = std::move(e.eliminated);
  decoupled_ = std::move(e.apart);
  statistics_ = {};
  statistics_.closed = e.closed;
  statistics_.diagonal = e.diagonal;
}

void DualCondensedSolver::build_condensed(const SparseMatrix& a) {
  const auto n = static_cast<int>(a.rows());
  const auto nz = static_cast<Eigen::Index>(z_.size());
  std::vector<int> z_index(static_cast<std::size_t>(n), -1);
  for (std::size_t k = 0; k < z_.size(); ++k) z_index[static_cast<std::size_t>(z_[k])] = static_cast<int>(k);
  std::vector<bool> apart(static_cast<std::size_t>(n), false);
  for (const auto& [eq, d] : decoupled_) apart[static_cast<std::size_t>(eq)] = true;
  r_.clear();
  r_index_.assign(static_cast<std::size_t>(n), -1);
  for (int e = 0; e < n; ++e)
    if (z_index[static_cast<std::size_t>(e)] < 0 && !apart[static_cast<std::size_t>(e)]) {
      r_index_[static_cast<std::size_t>(e)] = static_cast<int>(r_.size());
      r_.push_back(e);
    }
  Eigen::MatrixXd b = Eigen::MatrixXd::Zero(nz, nz);
  std::vector<Eigen::Triplet<double, int>> triplets, rz, zr;
  triplets.reserve(static_cast<std::size_t>(a.nonZeros()));
  for (int col = 0; col < n; ++col)
    for (SparseMatrix::InnerIterator it(a, col); it; ++it) {
      const int r = static_cast<int>(it.row());
      const int zr_ = z_index[static_cast<std::size_t>(r)], zc = z_index[static_cast<std::size_t>(col)];
      if (apart[static_cast<std::size_t>(r)] || apart[static_cast<std::size_t>(col)]) continue;  // their diagonal only
      if (zr_ < 0 && zc < 0)
        triplets.emplace_back(r_index_[static_cast<std::size_t>(r)], r_index_[static_cast<std::size_t>(col)], it.value());
      else if (zr_ >= 0 && zc >= 0)
        b(zr_, zc) = it.value();
      else if (it.value() != 0 && zr_ < 0)
        rz.emplace_back(r_index_[static_cast<std::size_t>(r)], zc, it.value());
      else if (it.value() != 0)
        zr.emplace_back(zr_, r_index_[static_cast<std::size_t>(col)], it.value());
    }
  std::vector<int> rows, cols;
  for (const auto& t : rz) rows.push_back(t.row());
  for (const auto& t : zr) cols.push_back(t.col());
  rows_i_ = unique_sorted(std::move(rows));
  cols_i_ = unique_sorted(std::move(cols));
  const auto local = [](const std::vector<int>& sorted, int v) {
    return static_cast<Eigen::Index>(std::lower_bound(sorted.begin(), sorted.end(), v) - sorted.begin());
  };
  a_rz_ = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(rows_i_.size()), nz);
  a_zr_ = Eigen::MatrixXd::Zero(nz, static_cast<Eigen::Index>(cols_i_.size()));
  for (const auto& t : rz) a_rz_(local(rows_i_, t.row()), t.col()) += t.value();
  for (const auto& t : zr) a_zr_(t.row(), local(cols_i_, t.col())) += t.value();
  // B mixes stiffnesses with mortar weights (areas): equilibrated rows and
  // columns, B̃ = R B C, so that the condition test does not depend on the units.
  row_scale_ = Eigen::VectorXd::Ones(nz);
  column_scale_ = Eigen::VectorXd::Ones(nz);
  for (Eigen::Index i = 0; i < nz; ++i) {
    const double m = b.row(i).cwiseAbs().maxCoeff();
    if (m > 0) row_scale_[i] = 1 / m;
  }
  b = row_scale_.asDiagonal() * b;
  for (Eigen::Index j = 0; j < nz; ++j) {
    const double m = b.col(j).cwiseAbs().maxCoeff();
    if (m > 0) column_scale_[j] = 1 / m;
  }
  b = b * column_scale_.asDiagonal();
  b_lu_.compute(b);
  const double rcond = b_lu_.rcond();
  statistics_.full = !(rcond >= kMinReciprocalCondition);
  if (statistics_.full) return;
  // S = A_RR - A_RZ B⁻¹ A_ZR, the correction dense on rows_i_ × cols_i_.
  const Eigen::MatrixXd correction = a_rz_ * solve_b(a_zr_);
  for (std::size_t i = 0; i < rows_i_.size(); ++i)
    for (std::size_t j = 0; j < cols_i_.size(); ++j)
      triplets.emplace_back(rows_i_[i], cols_i_[j],
                            -correction(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)));
  const auto m = static_cast<int>(r_.size());
  s_.resize(m, m);
  s_.setFromTriplets(triplets.begin(), triplets.end());
  s_.makeCompressed();
  statistics_.coupled = static_cast<int>(std::max(rows_i_.size(), cols_i_.size()));
  statistics_.condensed_equations = m;
}

void DualCondensedSolver::factorize(const SparseMatrix& a, bool symmetric) {
  choose_eliminated(a);
  if (!z_.empty()) build_condensed(a);
  if (z_.empty() || statistics_.full) {
    decoupled_.clear();
    statistics_.full = true;
    z_.clear();
    inner_->analyze(a);
    analysed_r_.clear();
    analysed_outer_.resize(0);
    inner_->factorize(a, symmetric);
    return;
  }
  const Eigen::Map<const Eigen::VectorXi> outer(s_.outerIndexPtr(), s_.outerSize() + 1);
  const Eigen::Map<const Eigen::VectorXi> inner(s_.innerIndexPtr(), s_.nonZeros());
  if (r_ != analysed_r_ || analysed_outer_.size() != outer.size() || analysed_outer_ != outer ||
      analysed_inner_.size() != inner.size() || analysed_inner_ != inner) {
    inner_->analyze(s_);
    analysed_r_ = r_;
    analysed_outer_ = outer;
    analysed_inner_ = inner;
  }
  a_ = a;
  try {
    inner_->factorize(s_, symmetric);
  } catch (const SolverError& e) {
    const int eq = e.equation();
    throw SolverError(e.what(), eq >= 0 && eq < static_cast<int>(r_.size()) ? r_[static_cast<std::size_t>(eq)] : -1);
  }
}

void DualCondensedSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  if (z_.empty()) return inner_->solve(b, x);
  solve_condensed(b, x);
  const Eigen::VectorXd residual = b - a_ * x;
  Eigen::VectorXd correction;
  solve_condensed(residual, correction);
  x += correction;
}

void DualCondensedSolver::solve_condensed(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  const auto nz = static_cast<Eigen::Index>(z_.size());
  Eigen::VectorXd b_z(nz), b_r(static_cast<Eigen::Index>(r_.size()));
  for (Eigen::Index k = 0; k < nz; ++k) b_z[k] = b[z_[static_cast<std::size_t>(k)]];
  for (std::size_t k = 0; k < r_.size(); ++k) b_r[static_cast<Eigen::Index>(k)] = b[r_[k]];
  const Eigen::VectorXd y = a_rz_ * solve_b(b_z);
  for (std::size_t i = 0; i < rows_i_.size(); ++i) b_r[rows_i_[i]] -= y[static_cast<Eigen::Index>(i)];
  Eigen::VectorXd x_r;
  inner_->solve(b_r, x_r);
  Eigen::VectorXd coupled(static_cast<Eigen::Index>(cols_i_.size()));
  for (std::size_t j = 0; j < cols_i_.size(); ++j) coupled[static_cast<Eigen::Index>(j)] = x_r[cols_i_[j]];
  const Eigen::VectorXd x_z = solve_b(b_z - a_zr_ * coupled);
  x.resize(b.size());
  for (std::size_t k = 0; k < r_.size(); ++k) x[r_[k]] = x_r[static_cast<Eigen::Index>(k)];
  for (Eigen::Index k = 0; k < nz; ++k) x[z_[static_cast<std::size_t>(k)]] = x_z[k];
  for (const auto& [eq, d] : decoupled_) x[eq] = b[eq] / d;
}

Eigen::MatrixXd DualCondensedSolver::solve_b(const Eigen::MatrixXd& y) const {
  return column_scale_.asDiagonal() * b_lu_.solve(row_scale_.asDiagonal() * y);
}

}  // namespace tether
