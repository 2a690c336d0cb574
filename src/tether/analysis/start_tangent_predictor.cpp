#include "tether/analysis/start_tangent_predictor.hpp"

#include "tether/solvers/linear_solver.hpp"

namespace tether {

bool start_tangent_predictor_applies(const StepSystem& system) {
  const Discretization& disc = system.discretization();
  return system.has_assembler() && !system.bulk_linear() && disc.contact_pairs().empty() &&
         disc.mortar_pairs().empty();
}

namespace {

/// K(u_start) du over all global dofs: each contribution's tangent at the
/// start state times its part of du (du zero on the free equations).
Eigen::VectorXd start_tangent_times(const StepSystem& system, const EvaluationState& start,
                                    const Eigen::VectorXd& du) {
  Eigen::VectorXd out = Eigen::VectorXd::Zero(du.size());
  LocalSystem local;
  Eigen::VectorXd du_local;
  for (const Contribution* c : system.contributions()) {
    const auto dofs = c->dofs();
    const auto n = static_cast<Eigen::Index>(dofs.size());
    du_local.resize(n);
    bool moves = false;
    for (Eigen::Index a = 0; a < n; ++a) moves |= (du_local(a) = du[dofs[static_cast<std::size_t>(a)]]) != 0;
    if (!moves) continue;
    local.reset(n);
    c->evaluate(start, local, true);
    const Eigen::VectorXd f = local.tangent * du_local;
    for (Eigen::Index a = 0; a < n; ++a) out[dofs[static_cast<std::size_t>(a)]] += f(a);
  }
  return out;
}

}  // namespace

bool apply_start_tangent_predictor(StepSystem& system, const IncrementTime& time, const Eigen::VectorXd& u_start,
                                   const Eigen::VectorXd& external, Eigen::VectorXd& u) {
  Assembler& assembler = system.assembler();
  const EquationMap& eqs = assembler.equations();
  Eigen::VectorXd du = u - u_start;
  for (int e = 0; e < eqs.n_equations(); ++e) du[eqs.dof(e)] = 0;  // the prescribed and dependent dofs' change
  if (du.cwiseAbs().maxCoeff() == 0) return false;

  const EvaluationState start{u_start, u_start, time.step_time, time.total_time, time.dt, time.nlgeom};
  assembler.update_connectivity(start);
  Eigen::VectorXd full;
  assembler.assemble(start, full, true);
  full += start_tangent_times(system, start, du) - external;
  Eigen::VectorXd rhs, correction;
  eqs.reduce(full, rhs);
  LinearSolver& solver = system.solver();
  try {
    solver.analyze(assembler.tangent());
    solver.factorize(assembler.tangent(), system.symmetric());
    solver.solve(-rhs, correction);
  } catch (const SolverError&) {
    return false;
  }
  if (!correction.allFinite()) return false;
  for (int e = 0; e < eqs.n_equations(); ++e) u[eqs.dof(e)] += correction[e];
  eqs.update_dependents(u);
  return true;
}

}  // namespace tether
