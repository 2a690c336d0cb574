#include "tether/solvers/mumps_solver.hpp"

#include <dmumps_c.h>

#include <string>

#include "tether/core/error.hpp"

namespace tether {

namespace {

constexpr int kUseCommWorld = -987654;      ///< MUMPS' Fortran communicator for the sequential library
constexpr Eigen::Index kMetisThreshold = 100000;

/// ICNTL(i) / INFOG(i) with MUMPS' 1-based numbering.
int& icntl(DMUMPS_STRUC_C& id, int i) { return id.icntl[i - 1]; }
int infog(const DMUMPS_STRUC_C& id, int i) { return id.infog[i - 1]; }

}  // namespace

struct MumpsSolver::Instance {
  DMUMPS_STRUC_C id{};
  Instance() {
    id.comm_fortran = kUseCommWorld;
    id.par = 1;  // the host works
    id.sym = 2;  // general symmetric: LDLT with 2x2 pivots (indefinite allowed)
    id.job = -1;
    dmumps_c(&id);
    icntl(id, 1) = -1;  // no error, diagnostic or global output streams
    icntl(id, 2) = -1;
    icntl(id, 3) = -1;
    icntl(id, 4) = 0;
    icntl(id, 14) = 40;  // working space relaxation [%]
    icntl(id, 24) = 1;   // detect null pivots (report the singular equation instead of failing)
  }
  ~Instance() {
    id.job = -2;
    dmumps_c(&id);
  }
  /// Runs `job`; throws SolverError on a MUMPS error. Retries a factorization
  /// with more working space when MUMPS asks for it (INFOG(1) = -9, -8).
  void run(int job) {
    id.job = job;
    dmumps_c(&id);
    for (int retry = 0; retry < 3 && job == 2 && (infog(id, 1) == -9 || infog(id, 1) == -8); ++retry) {
      icntl(id, 14) *= 2;
      id.job = job;
      dmumps_c(&id);
    }
    if (infog(id, 1) < 0)
      throw SolverError("MUMPS " + std::string(job == 1 ? "analysis" : job == 2 ? "factorization" : "solve") +
                        " failed (INFOG(1) = " + std::to_string(infog(id, 1)) + ", INFOG(2) = " +
                        std::to_string(infog(id, 2)) + ")");
  }
};

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
  icntl(id, 7) = n_ > kMetisThreshold ? 5 : 0;  // METIS, else AMD
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
  mumps_->run(2);
  if (infog(id, 28) > 0) {
    const int eq = id.pivnul_list ? id.pivnul_list[0] - 1 : -1;
    throw SolverError("the stiffness matrix is singular (MUMPS found " + std::to_string(infog(id, 28)) +
                          " zero pivot(s))",
                      eq);
  }
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
