#include "tether/constraints/user_mpc_constraint.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "tether/core/error.hpp"
#include "tether/dofs/dof_map.hpp"

namespace tether {

namespace {

constexpr int kMaxDof = TETHER_USER_MPC_MAXDOF;
static_assert(kMaxDof == kDofsPerNode, "user MPC dofs per node must match the DofMap");

std::string to_string(UserMpcMode mode) { return mode == UserMpcMode::Dof ? "MODE=DOF" : "MODE=NODE"; }

}  // namespace

/// f and the normalised gradient from one routine call.
struct UserMpcConstraint::Linearisation {
  std::vector<int> dependent;  ///< local dof of each dependent dof (one per equation)
  Eigen::VectorXd f;
  Eigen::MatrixXd gradient;    ///< m x n
};

UserMpcConstraint::UserMpcConstraint(std::string library_path, std::string symbol, UserMpcMode mode, int jtype,
                                     std::vector<int> node_indices, std::vector<int> node_labels,
                                     std::vector<Eigen::Vector2d> reference, const DofMap& dofs, std::string name,
                                     UserMpcOptions options)
    : symbol_(symbol.empty() ? std::string(TETHER_USER_MPC_DEFAULT_SYMBOL) : std::move(symbol)),
      mode_(mode),
      jtype_(jtype),
      labels_(std::move(node_labels)),
      name_(std::move(name)),
      options_(options) {
  const auto nn = node_indices.size();
  if (nn == 0 || labels_.size() != nn || reference.size() != nn)
    throw std::invalid_argument(name_ + ": user MPC needs >= 1 node and one label and coordinate pair per node");
  if (!(options_.relative_step > 0)) throw std::invalid_argument(name_ + ": relative_step must be > 0");
  std::vector<int> distinct;
  for (std::size_t k = 0; k < nn; ++k) {
    const int node = node_indices[k];
    if (node < 0 || node >= dofs.n_nodes())
      throw std::invalid_argument(name_ + ": node index " + std::to_string(node) + " out of range");
    auto it = std::find(distinct.begin(), distinct.end(), node);
    if (it == distinct.end()) {
      distinct.push_back(node);
      for (int c = 0; c < kMaxDof; ++c) dofs_.push_back(dofs.displacement(node, c));
      it = distinct.end() - 1;
    }
    slot_.push_back(static_cast<int>(it - distinct.begin()));
    x_.push_back(reference[k].x());
    x_.push_back(reference[k].y());
  }
  double size = 0, extent = 0;
  for (std::size_t k = 0; k < nn; ++k) {
    size = std::max(size, (reference[k] - reference[0]).norm());
    extent = std::max(extent, reference[k].norm());
  }
  length_scale_ = size > 0 ? size : std::max(1.0, extent);

  try {
    library_ = SharedLibrary::open(library_path);
  } catch (const ModelError& e) {
    throw ModelError("user MPC " + name_ + ": " + e.what() + " (looking for routine '" + symbol_ + "')");
  }
  std::string error;
  void* address = library_->symbol(symbol_, error);
  if (!address)
    throw ModelError("user MPC " + name_ + ": shared library '" + library_path + "' has no routine '" + symbol_ +
                     "': " + error + " (define it with C linkage, extern \"C\", and export it, or name it with SYMBOL=)");
  routine_ = reinterpret_cast<tether_user_mpc_fn>(address);

  // The reference call fixes the dependent dofs (and MDOF) for good.
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(dofs_.size()));
  try {
    dependent_ = call(zero, zero, 0, 0, false).dependent;
  } catch (const ModelError& e) {
    throw ModelError(std::string(e.what()) + " (in the reference configuration, when the constraint was built)");
  }
}

std::string UserMpcConstraint::who() const {
  return "user MPC " + name_ + " (" + to_string(mode_) + ", JTYPE " + std::to_string(jtype_) + ", routine '" +
         symbol_ + "' in '" + library_->path() + "')";
}

std::vector<int> UserMpcConstraint::dependent_dofs() const {
  std::vector<int> global;
  for (const int local : dependent_) global.push_back(dofs_[local]);
  return global;
}

UserMpcConstraint::Linearisation UserMpcConstraint::call(const Eigen::VectorXd& u, const Eigen::VectorXd& u_start,
                                                         double step_time, double total_time, bool perturbed) const {
  const int nn = static_cast<int>(labels_.size());
  const auto n = static_cast<Eigen::Index>(dofs_.size());
  std::vector<double> total(kMaxDof * nn), initial(kMaxDof * nn);
  for (int k = 0; k < nn; ++k)
    for (int i = 0; i < kMaxDof; ++i) {
      total[i + kMaxDof * k] = u[kMaxDof * slot_[k] + i];
      initial[i + kMaxDof * k] = u_start[kMaxDof * slot_[k] + i];
    }

  tether_user_mpc_input in{};
  in.version = TETHER_USER_MPC_VERSION;
  in.mode = static_cast<int>(mode_);
  in.jtype = jtype_;
  in.n = nn;
  in.maxdof = kMaxDof;
  in.node_labels = labels_.data();
  in.x = x_.data();
  in.u = total.data();
  in.uinit = initial.data();
  in.kstep = 0;  // not known through ConstraintInput (documented in user_mpc.h)
  in.kinc = 0;
  in.time[0] = step_time;
  in.time[1] = total_time;
  in.name = name_.c_str();
  in.perturbed = perturbed ? 1 : 0;

  std::vector<double> a(kMaxDof * kMaxDof * nn, 0.0);
  std::vector<int> jdof(kMaxDof * nn, 0);
  RoutineMessage message{};
  tether_user_mpc_output out{};
  out.mdof = mode_ == UserMpcMode::Dof ? 1 : kMaxDof;
  out.lmpc = 1;
  out.a = a.data();
  out.jdof = jdof.data();
  out.message = message.data();
  out.message_capacity = message.size();

  const int status = routine_(&in, &out);
  check_routine_status(status, message, who());
  if (out.lmpc != 1)
    throw ModelError(who() + " set LMPC = " + std::to_string(out.lmpc) +
                     ": switching a user MPC off is not supported (its multipliers stay unknowns of the step)");
  if (mode_ == UserMpcMode::Dof && out.mdof != 1)
    throw ModelError(who() + " changed MDOF to " + std::to_string(out.mdof) + " (MODE=DOF eliminates one dof)");
  if (mode_ == UserMpcMode::Node && (out.mdof < 1 || out.mdof > kMaxDof))
    throw ModelError(who() + " returned MDOF = " + std::to_string(out.mdof) + " (1 or 2 in 2D)");

  const int m = out.mdof;
  const bool dof_mode = mode_ == UserMpcMode::Dof;
  auto entry = [&](int k) {
    return "node entry " + std::to_string(k + 1) + " (node " + std::to_string(labels_[k]) + ")";
  };
  // Storage index of A(i, j, k) and JDOF(j, k), 0-based; DOF mode: A(k), JDOF(k).
  auto ai = [&](int i, int j, int k) { return dof_mode ? k : i + kMaxDof * j + kMaxDof * kMaxDof * k; };
  auto ji = [&](int j, int k) { return dof_mode ? k : j + kMaxDof * k; };
  auto a_name = [&](int i, int j, int k) {
    return dof_mode ? "A(" + std::to_string(k + 1) + ")"
                    : "A(" + std::to_string(i + 1) + "," + std::to_string(j + 1) + "," + std::to_string(k + 1) + ")";
  };
  auto j_name = [&](int j, int k) {
    return dof_mode ? "JDOF(" + std::to_string(k + 1) + ")"
                    : "JDOF(" + std::to_string(j + 1) + "," + std::to_string(k + 1) + ")";
  };

  Linearisation lin;
  lin.f.resize(m);
  for (int i = 0; i < m; ++i)
    if (!std::isfinite(out.ue[i]))
      throw ModelError(who() + " returned a non-finite UE(" + std::to_string(i + 1) + ") = " +
                       std::to_string(out.ue[i]));
  for (int k = 0; k < nn; ++k)
    for (int j = 0; j < m; ++j) {
      const int d = jdof[ji(j, k)];
      const bool allowed = k == 0 ? (d == 1 || d == 2) : (d >= 0 && d <= kMaxDof);
      if (!allowed)
        throw ModelError(who() + " returned " + j_name(j, k) + " = " + std::to_string(d) + " for " + entry(k) +
                         (k == 0 ? " (the dependent dof must be 1 or 2)" : " (must be 0, 1 or 2 in 2D)"));
      for (int i = 0; i < m; ++i) {
        const double v = a[ai(i, j, k)];
        if (!std::isfinite(v))
          throw ModelError(who() + " returned a non-finite " + a_name(i, j, k) + " = " + std::to_string(v) + " for " +
                           entry(k));
        if (d == 0 && v != 0)
          throw ModelError(who() + " returned " + a_name(i, j, k) + " = " + std::to_string(v) + " for " + entry(k) +
                           " whose " + j_name(j, k) + " is 0 (no dof)");
      }
    }
  for (int j = 0; j < m; ++j) {
    lin.dependent.push_back(kMaxDof * slot_[0] + jdof[ji(j, 0)] - 1);
    for (int l = 0; l < j; ++l)
      if (lin.dependent[l] == lin.dependent[j])
        throw ModelError(who() + " names the same dependent dof twice (" + j_name(l, 0) + " = " + j_name(j, 0) + ")");
  }
  if (!dependent_.empty() && lin.dependent != dependent_)
    throw ModelError(who() + " changed its dependent dof(s) or MDOF since the reference call (JDOF(1) / JDOF(.,1) "
                     "and MDOF must not change)");

  // Raw coefficients scattered to the local dofs, then normalised by the dependent block B.
  Eigen::MatrixXd raw = Eigen::MatrixXd::Zero(m, n);
  Eigen::MatrixXd block(m, m);
  for (int k = 0; k < nn; ++k)
    for (int j = 0; j < m; ++j) {
      const int d = jdof[ji(j, k)];
      for (int i = 0; i < m; ++i) {
        if (k == 0) block(i, j) = a[ai(i, j, 0)];
        if (d != 0) raw(i, kMaxDof * slot_[k] + d - 1) += a[ai(i, j, k)];
      }
    }
  if (m == 1) {
    if (block(0, 0) == 0)
      throw ModelError(who() + " returned " + a_name(0, 0, 0) +
                       " = 0: the coefficient of the dependent dof must be nonzero");
    lin.gradient = raw / block(0, 0);
  } else {
    const double scale = block.cwiseAbs().maxCoeff();
    const double det = block.determinant();
    if (!(std::abs(det) > 1e-13 * scale * scale))
      throw ModelError(who() + " returned a singular block A(.,.,1) of the dependent dofs (determinant " +
                       std::to_string(det) + ")");
    lin.gradient = block.partialPivLu().solve(raw);
  }
  for (int i = 0; i < m; ++i) lin.f[i] = u[lin.dependent[i]] - out.ue[i];
  return lin;
}

void UserMpcConstraint::evaluate(const ConstraintInput& in, ConstraintOutput& out, bool need_hessian) const {
  const Linearisation lin = call(in.u, in.u_start, in.step_time, in.total_time, false);
  out.f = lin.f;
  out.gradient = lin.gradient;
  if (!need_hessian || !options_.numerical_hessian) return;
  const auto n = static_cast<Eigen::Index>(dofs_.size());
  const int m = n_equations();
  out.hessian.assign(m, Eigen::MatrixXd::Zero(n, n));
  for (Eigen::Index j = 0; j < n; ++j) {
    Eigen::VectorXd plus = in.u, minus = in.u;
    const double step = options_.relative_step * std::max(length_scale_, std::abs(in.u[j]));
    plus[j] += step;
    minus[j] -= step;
    const double width = plus[j] - minus[j];  // the step actually taken, after rounding
    const Linearisation p = call(plus, in.u_start, in.step_time, in.total_time, true);
    const Linearisation q = call(minus, in.u_start, in.step_time, in.total_time, true);
    for (int i = 0; i < m; ++i) out.hessian[i].col(j) = (p.gradient.row(i) - q.gradient.row(i)).transpose() / width;
  }
  for (auto& h : out.hessian) h = (0.5 * (h + h.transpose())).eval();
}

}  // namespace tether
