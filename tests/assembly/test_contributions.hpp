#pragma once
// Test contributions for the assembler tests: a linear spring, a spring that
// re-pairs, a linear block with a dense matrix of distinct entries, and a
// grid of such blocks.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "tether/assembly/contribution.hpp"

namespace tether::testing {

/// Linear spring of stiffness k between two scalar unknowns.
class Spring final : public Contribution {
 public:
  Spring(int a, int b, double k) : dofs_{a, b}, k_(k) {}
  std::span<const int> dofs() const override { return dofs_; }
  void evaluate(const EvaluationState& s, LocalSystem& out, bool need_tangent) const override {
    const double f = k_ * (s.u[dofs_[0]] - s.u[dofs_[1]]);
    out.residual << f, -f;
    if (need_tangent) out.tangent << k_, -k_, -k_, k_;
  }
  std::string describe() const override { return "spring"; }
  bool symmetric_tangent(bool) const override { return true; }
  bool linear_in_u(bool) const override { return true; }

 private:
  std::vector<int> dofs_;
  double k_;
};

/// A spring whose second end jumps to another unknown on update_connectivity()
/// (a re-paired contact node): same number of entries, different positions.
class Rewiring final : public Contribution {
 public:
  Rewiring(int a, int b, int later) : dofs_{a, b}, later_(later) {}
  std::span<const int> dofs() const override { return dofs_; }
  void evaluate(const EvaluationState& s, LocalSystem& out, bool need_tangent) const override {
    const double f = s.u[dofs_[0]] - s.u[dofs_[1]];
    out.residual << f, -f;
    if (need_tangent) out.tangent << 1, -1, -1, 1;
  }
  bool update_connectivity(const EvaluationState&) override {
    if (dofs_[1] == later_) return false;
    dofs_[1] = later_;
    return true;
  }
  std::string describe() const override { return "rewiring spring"; }
  bool symmetric_tangent(bool) const override { return true; }
  bool linear_in_u(bool) const override { return false; }  // its connectivity changes

 private:
  std::vector<int> dofs_;
  int later_;
};


/// Linear contribution over any dof list with a dense, unsymmetric matrix of
/// distinct entries (a misplaced entry changes the assembled matrix).
class DenseBlock final : public Contribution {
 public:
  /// `symmetric`: k + kᵀ instead of k (still distinct entries on each side of the diagonal).
  DenseBlock(std::vector<int> dofs, double seed, bool symmetric = false) : dofs_(std::move(dofs)), symmetric_(symmetric) {
    const auto m = static_cast<Eigen::Index>(dofs_.size());
    k_.resize(m, m);
    for (Eigen::Index j = 0; j < m; ++j)
      for (Eigen::Index i = 0; i < m; ++i) k_(i, j) = seed + 0.37 * static_cast<double>(i) + 1.13 * static_cast<double>(j * j);
    if (symmetric) k_ = Eigen::MatrixXd(k_ + k_.transpose());
  }
  std::span<const int> dofs() const override { return dofs_; }
  void evaluate(const EvaluationState& s, LocalSystem& out, bool need_tangent) const override {
    ++evaluations;
    Eigen::VectorXd ue(k_.rows());
    for (Eigen::Index a = 0; a < ue.size(); ++a) ue[a] = s.u[dofs_[static_cast<std::size_t>(a)]];
    out.residual = k_ * ue;
    if (need_tangent) out.tangent = k_;
  }
  std::string describe() const override { return "dense block"; }
  bool symmetric_tangent(bool) const override { return symmetric_; }
  bool linear_in_u(bool) const override { return true; }
  bool residual_depends_on_time() const override { return timed; }
  const Eigen::MatrixXd& matrix() const { return k_; }
  mutable int evaluations = 0;  ///< evaluate() calls
  /// What residual_depends_on_time() says: the default true, or false (also
  /// right, K u reads no time) to have the assembler keep the residual for the step.
  bool timed = true;

 private:
  std::vector<int> dofs_;
  bool symmetric_ = false;
  Eigen::MatrixXd k_;
};

/// The 4 x 2 "quads" of 8 dofs of an nx x ny grid of nodes (dofs 2i, 2i+1;
/// node = nx row + column), each with its own matrix; the fourth quad of the
/// first row lists its first node's y before x (so it keeps full positions).
inline std::vector<DenseBlock> grid_quads(int nx, int ny) {
  std::vector<DenseBlock> quads;
  quads.reserve(static_cast<std::size_t>((nx - 1) * (ny - 1)));
  for (int j = 0; j + 1 < ny; ++j)
    for (int i = 0; i + 1 < nx; ++i) {
      const int a = j * nx + i, b = a + 1, c = a + nx + 1, d = a + nx;
      std::vector<int> dofs{2 * a, 2 * a + 1, 2 * b, 2 * b + 1, 2 * c, 2 * c + 1, 2 * d, 2 * d + 1};
      if (i == 3 && j == 0) std::swap(dofs[0], dofs[1]);
      quads.emplace_back(dofs, 1.0 + static_cast<double>(quads.size()));
    }
  return quads;
}

/// The contribution list of the grid tests: every quad, then the spring
/// (pointers into `quads`: do not resize it afterwards).
inline std::vector<Contribution*> grid_list(std::vector<DenseBlock>& quads, Spring& spring) {
  std::vector<Contribution*> list;
  for (auto& q : quads) list.push_back(&q);
  list.push_back(&spring);
  return list;
}

/// The grid tests' prescribed dofs: node 0 in x and y, node 10 in x only.
inline std::vector<bool> grid_prescribed(int n_dofs) {
  std::vector<bool> prescribed(static_cast<std::size_t>(n_dofs), false);
  prescribed[0] = prescribed[1] = true;
  prescribed[2 * 10] = true;
  return prescribed;
}

}  // namespace tether::testing
