#include "tether/solvers/linear_solver.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include "tether/core/error.hpp"
#include "tether/solvers/cholmod_solver.hpp"
#include "tether/solvers/mumps_solver.hpp"
#include "tether/solvers/sparse_lu_solver.hpp"
#include "tether/solvers/umfpack_solver.hpp"

namespace tether {

namespace {

/// True when some diagonal entry is absent or not positive (a multiplier
/// row of a saddle-point system): Cholesky cannot factor such a matrix.
bool has_nonpositive_diagonal(const SparseMatrix& a) {
  for (Eigen::Index j = 0; j < a.cols(); ++j) {
    const int* begin = a.innerIndexPtr() + a.outerIndexPtr()[j];
    const int* end = a.innerIndexPtr() + a.outerIndexPtr()[j + 1];
    const int* it = std::lower_bound(begin, end, static_cast<int>(j));
    if (it == end || *it != j || !(a.valuePtr()[it - a.innerIndexPtr()] > 0)) return true;
  }
  return false;
}

/// Symmetric systems: CHOLMOD while positive definite, MUMPS LDLT when
/// indefinite (multipliers, or once CHOLMOD has failed), UMFPACK when MUMPS
/// reports a zero pivot (it then also decides and names a singularity); each
/// choice sticks until the pattern changes. Unsymmetric systems: UMFPACK.
class AutoSolver final : public LinearSolver {
 public:
  explicit AutoSolver(double memory_budget_mb) { mumps_.set_memory_budget(memory_budget_mb); }
  void analyze(const SparseMatrix& a) override {
    cholmod_failed_ = mumps_failed_ = false;
    cholmod_ready_ = umfpack_ready_ = mumps_ready_ = false;
    (void)a;
  }
  void factorize(const SparseMatrix& a, bool symmetric) override {
    if (symmetric) {
      if (!cholmod_failed_ && !has_nonpositive_diagonal(a)) {
        try {
          if (!cholmod_ready_) cholmod_.analyze(a), cholmod_ready_ = true;
          cholmod_.factorize(a, true);
          active_ = &cholmod_;
          return;
        } catch (const SolverError&) {
          cholmod_failed_ = true;  // indefinite: LDLT, which also diagnoses singularity
        }
      }
      if (!mumps_failed_) {
        try {
          if (!mumps_ready_) mumps_.analyze(a), mumps_ready_ = true;
          mumps_.factorize(a, true);
          active_ = &mumps_;
          return;
        } catch (const SolverError&) {
          // MUMPS's null-pivot test can flag a tiny but regular pivot (an open
          // contact row -1/c against a very stiff body): LU with its own
          // condition estimate decides whether the matrix is singular.
          mumps_failed_ = true;
        }
      }
    }
    // UMFPACK reads both triangles: a lower triangle is mirrored for it.
    whole_ = symmetric && lower_triangle_only(a) ? mirror_lower(a) : SparseMatrix();
    const SparseMatrix& m = whole_.nonZeros() > 0 ? whole_ : a;
    if (!umfpack_ready_) umfpack_.analyze(m), umfpack_ready_ = true;
    umfpack_.factorize(m, symmetric);
    active_ = &umfpack_;
  }
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override {
    if (!active_) throw SolverError("solve before factorize");
    active_->solve(b, x);
  }
  [[nodiscard]] std::string name() const override { return active_ ? active_->name() : "auto"; }
  [[nodiscard]] int out_of_core_factorizations() const override { return mumps_.out_of_core_factorizations(); }

 private:
  CholmodSolver cholmod_;
  MumpsSolver mumps_;
  UmfpackSolver umfpack_;
  LinearSolver* active_ = nullptr;
  SparseMatrix whole_;  ///< both triangles of a symmetric matrix given as its lower one, for UMFPACK
  bool cholmod_ready_ = false, umfpack_ready_ = false, mumps_ready_ = false, cholmod_failed_ = false,
       mumps_failed_ = false;
};

}  // namespace

bool lower_triangle_only(const SparseMatrix& a) {
  for (Eigen::Index j = 0; j < a.outerSize(); ++j) {
    const int begin = a.outerIndexPtr()[j];
    const int end = a.isCompressed() ? a.outerIndexPtr()[j + 1] : begin + a.innerNonZeroPtr()[j];
    if (end > begin && a.innerIndexPtr()[begin] < j) return false;
  }
  return true;
}

SparseMatrix mirror_lower(const SparseMatrix& lower) {
  const SparseMatrix strict = lower.triangularView<Eigen::StrictlyLower>();
  SparseMatrix whole = lower + SparseMatrix(strict.transpose());  // disjoint patterns: values copied
  whole.makeCompressed();
  return whole;
}

SolverKind parse_solver_kind(const std::string& name) {
  std::string n = name;
  std::transform(n.begin(), n.end(), n.begin(), [](unsigned char c) { return std::tolower(c); });
  if (n == "auto") return SolverKind::Auto;
  if (n == "umfpack") return SolverKind::Umfpack;
  if (n == "cholmod") return SolverKind::Cholmod;
  if (n == "sparselu") return SolverKind::SparseLU;
  if (n == "mumps") return SolverKind::Mumps;
  throw std::invalid_argument("unknown linear solver '" + name +
                              "' (expected auto, umfpack, cholmod, mumps or sparselu)");
}

std::unique_ptr<LinearSolver> make_linear_solver(SolverKind kind, double memory_budget_mb) {
  switch (kind) {
    case SolverKind::Umfpack: return std::make_unique<UmfpackSolver>();
    case SolverKind::Cholmod: return std::make_unique<CholmodSolver>();
    case SolverKind::SparseLU: return std::make_unique<SparseLuSolver>();
    case SolverKind::Mumps: {
      auto mumps = std::make_unique<MumpsSolver>();
      mumps->set_memory_budget(memory_budget_mb);
      return mumps;
    }
    case SolverKind::Auto: break;
  }
  return std::make_unique<AutoSolver>(memory_budget_mb);
}

}  // namespace tether
