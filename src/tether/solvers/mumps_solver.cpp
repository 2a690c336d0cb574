#include "tether/solvers/mumps_solver.hpp"

#include <string>

#include "tether/solvers/mumps_instance.hpp"

namespace tether {

namespace {
constexpr Eigen::Index kMetisThreshold = 100000;
}  // namespace

struct MumpsSolver::Instance : detail::MumpsInstance {
  Instance() : MumpsInstance(2) {}  // general symmetric: LDLT with 2x2 pivots (indefinite allowed)
};

std::string check_out_of_core_directory() { return detail::MumpsInstance::scratch_directory(); }

MumpsSolver::MumpsSolver() : mumps_(std::make_unique<Instance>()) {}
MumpsSolver::~MumpsSolver() = default;

void MumpsSolver::analyze(const SparseMatrix& a) {
  if (!a.isCompressed()) throw SolverError("MUMPS: matrix must be compressed");
  if (a.rows() != a.cols()) throw SolverError("MUMPS: matrix must be square");
  rows_.clear(), cols_.clear(), source_.clear();
  for (Eigen::Index j = 0; j < a.cols(); ++j)
    for (int k = a.outerIndexPtr()[j]; k < a.outerIndexPtr()[j + 1]; ++k) {
      const int i = a.innerIndexPtr()[k];
      if (i < j) continue;  // lower triangle only
      rows_.push_back(i + 1);
      cols_.push_back(static_cast<int>(j) + 1);
      source_.push_back(k);
    }
  values_.assign(source_.size(), 0.0);
  n_ = a.cols();
  nnz_ = a.nonZeros();
  DMUMPS_STRUC_C& id = mumps_->id;
  id.n = static_cast<int>(n_);
  id.nnz = static_cast<MUMPS_INT8>(rows_.size());
  id.irn = rows_.data();
  id.jcn = cols_.data();
  id.a = values_.data();
  mumps_->icntl(7) = n_ > kMetisThreshold ? 5 : 0;  // METIS, else AMD
  mumps_->run(1);
  factorized_ = false;
}

void MumpsSolver::factorize(const SparseMatrix& a, bool /*symmetric*/) {
  if (a.cols() != n_ || a.nonZeros() != nnz_) analyze(a);
  const double* v = a.valuePtr();
  for (std::size_t e = 0; e < source_.size(); ++e) values_[e] = v[source_[e]];
  DMUMPS_STRUC_C& id = mumps_->id;
  id.a = values_.data();
  factorized_ = false;
  mumps_->plan_memory(memory_budget_mb_);
  mumps_->run(2);
  if (mumps_->icntl(22) == 1) ++out_of_core_factorizations_;
  mumps_->throw_if_null_pivots();
  factorized_ = true;
}

void MumpsSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  if (!factorized_) throw SolverError("MUMPS: solve before factorize");
  x = b;
  DMUMPS_STRUC_C& id = mumps_->id;
  id.rhs = x.data();
  id.nrhs = 1;
  id.lrhs = static_cast<int>(n_);
  mumps_->run(3);
}

}  // namespace tether
