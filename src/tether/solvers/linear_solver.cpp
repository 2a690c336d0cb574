#include "tether/solvers/linear_solver.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include "tether/core/error.hpp"
#include "tether/solvers/cholmod_solver.hpp"
#include "tether/solvers/sparse_lu_solver.hpp"
#include "tether/solvers/umfpack_solver.hpp"

namespace tether {

namespace {

/// CHOLMOD while the system is symmetric positive definite, UMFPACK otherwise.
/// Once CHOLMOD has failed (indefinite system) the choice sticks to UMFPACK
/// until the pattern changes.
class AutoSolver final : public LinearSolver {
 public:
  void analyze(const SparseMatrix& a) override {
    cholmod_failed_ = false;
    cholmod_ready_ = umfpack_ready_ = false;
    (void)a;
  }
  void factorize(const SparseMatrix& a, bool symmetric) override {
    if (symmetric && !cholmod_failed_) {
      try {
        if (!cholmod_ready_) cholmod_.analyze(a), cholmod_ready_ = true;
        cholmod_.factorize(a, true);
        active_ = &cholmod_;
        return;
      } catch (const SolverError&) {
        cholmod_failed_ = true;  // indefinite: retry with LU, which also diagnoses singularity
      }
    }
    if (!umfpack_ready_) umfpack_.analyze(a), umfpack_ready_ = true;
    umfpack_.factorize(a, symmetric);
    active_ = &umfpack_;
  }
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override {
    if (!active_) throw SolverError("solve before factorize");
    active_->solve(b, x);
  }
  [[nodiscard]] std::string name() const override { return active_ ? active_->name() : "auto"; }

 private:
  CholmodSolver cholmod_;
  UmfpackSolver umfpack_;
  LinearSolver* active_ = nullptr;
  bool cholmod_ready_ = false, umfpack_ready_ = false, cholmod_failed_ = false;
};

}  // namespace

SolverKind parse_solver_kind(const std::string& name) {
  std::string n = name;
  std::transform(n.begin(), n.end(), n.begin(), [](unsigned char c) { return std::tolower(c); });
  if (n == "auto") return SolverKind::Auto;
  if (n == "umfpack") return SolverKind::Umfpack;
  if (n == "cholmod") return SolverKind::Cholmod;
  if (n == "sparselu") return SolverKind::SparseLU;
  throw std::invalid_argument("unknown linear solver '" + name + "' (expected auto, umfpack, cholmod or sparselu)");
}

std::unique_ptr<LinearSolver> make_linear_solver(SolverKind kind) {
  switch (kind) {
    case SolverKind::Umfpack: return std::make_unique<UmfpackSolver>();
    case SolverKind::Cholmod: return std::make_unique<CholmodSolver>();
    case SolverKind::SparseLU: return std::make_unique<SparseLuSolver>();
    case SolverKind::Auto: break;
  }
  return std::make_unique<AutoSolver>();
}

}  // namespace tether
