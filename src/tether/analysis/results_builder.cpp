#include "tether/analysis/results_builder.hpp"

#include <Eigen/SparseLU>
#include <algorithm>
#include <stdexcept>

#include "tether/solvers/linear_solver.hpp"

namespace tether {

namespace {

/// Forces of the eliminated constraints: at convergence the residual at each
/// dependent dof is balanced by them, r[D_i] + sum_k c_k(D_i) lambda_k = 0.
Eigen::VectorXd eliminated_multipliers(const EquationMap& equations, const Eigen::VectorXd& residual) {
  const auto& rows = equations.rows();
  const int n = static_cast<int>(rows.size());
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(n);
  if (n == 0) return lambda;
  std::vector<int> row_of_dependent(equations.n_dofs(), -1);
  for (int k = 0; k < n; ++k) row_of_dependent[equations.dependent_of_row(k)] = k;
  std::vector<Eigen::Triplet<double>> t;
  Eigen::VectorXd rhs(n);
  for (int k = 0; k < n; ++k) {
    for (const auto& [dof, c] : rows[k].terms)
      if (const int i = row_of_dependent[dof]; i >= 0) t.emplace_back(i, k, c);
    rhs[k] = -residual[equations.dependent_of_row(k)];
  }
  SparseMatrix a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  a.makeCompressed();
  Eigen::SparseLU<SparseMatrix> lu(a);
  if (lu.info() == Eigen::Success) lambda = lu.solve(rhs);
  return lambda;
}

/// ALLPD: the elements' plastic dissipation summed.
double total_plastic_dissipation(const Discretization& discretization, const EvaluationState& state) {
  double dissipation = 0;
  for (const auto& e : discretization.elements()) dissipation += e->plastic_dissipation(state);
  return dissipation;
}

/// Sizes the plastic arrays of `r` (zeroed).
void start_plastic_results(const Discretization& discretization, IncrementResults& r) {
  const auto n_nodes = static_cast<std::size_t>(discretization.dofs().n_nodes());
  r.nodal_peeq.assign(n_nodes, 0.0);
  r.nodal_plastic_strain.assign(n_nodes, Tensor4{});
  r.element_peeq.assign(discretization.elements().size(), 0.0);
  r.nodal_ac_yield.assign(n_nodes, 0.0);
  r.element_ac_yield.assign(discretization.elements().size(), 0.0);
}

/// Adds element e's PEEQ and PE extrapolations to the nodal sums, sets its
/// mean PEEQ and its fraction of yielding points (AC YIELD), and adds that
/// fraction to the nodal sums of AC YIELD (not extrapolated).
void add_plastic_results(const ContinuumElement& element, int e, const std::vector<PointValues>& points,
                         std::vector<double>& peeq, std::vector<Tensor4>& pe, IncrementResults& r) {
  element.extrapolate_plastic_to_nodes(points, peeq, pe);
  double mean = 0, yielding = 0;
  for (const PointValues& p : points) {
    mean += p.peeq / static_cast<double>(points.size());
    yielding += p.ac_yield / static_cast<double>(points.size());
  }
  r.element_peeq[static_cast<std::size_t>(e)] = mean;
  r.element_ac_yield[static_cast<std::size_t>(e)] = yielding;
  const auto& nodes = element.nodes();
  for (std::size_t a = 0; a < nodes.size(); ++a) {
    r.nodal_ac_yield[nodes[a]] += yielding;
    r.nodal_peeq[nodes[a]] += peeq[a];
    for (int k = 0; k < 4; ++k) r.nodal_plastic_strain[nodes[a]][k] += pe[a][k];
  }
}

/// Element e's SDV: the mean over its points into element_sdv, the
/// extrapolation to its nodes added to the nodal sums of nodal_sdv.
void add_sdv_results(const ContinuumElement& element, int e, const std::vector<PointValues>& points,
                     std::vector<double>& nodal, IncrementResults& r) {
  const int n = r.n_sdv;
  double* mean = r.element_sdv.data() + static_cast<std::ptrdiff_t>(e) * n;
  for (const PointValues& p : points)
    for (int k = 0; k < std::min(n, static_cast<int>(p.sdv.size())); ++k)
      mean[k] += p.sdv[static_cast<std::size_t>(k)] / static_cast<double>(points.size());
  element.extrapolate_sdv_to_nodes(points, n, nodal);
  const auto& nodes = element.nodes();
  for (std::size_t a = 0; a < nodes.size(); ++a)
    for (int k = 0; k < n; ++k)
      r.nodal_sdv[static_cast<std::size_t>(nodes[a]) * n + k] += nodal[a * static_cast<std::size_t>(n) + k];
}

/// `full_residual` plus the forces of the eliminated constraints `lambda`
/// (so reactions at prescribed dofs they involve are complete).
Eigen::VectorXd with_eliminated_forces(const EquationMap& equations, const Eigen::VectorXd& full_residual,
                                       const Eigen::VectorXd& lambda) {
  Eigen::VectorXd residual = full_residual;
  for (std::size_t k = 0; k < equations.rows().size(); ++k)
    for (const auto& [dof, c] : equations.rows()[k].terms) residual[dof] += c * lambda[static_cast<Eigen::Index>(k)];
  return residual;
}

/// Displacements, reactions (read from `residual` at prescribed dofs) and temperatures per node.
void add_node_values(const Discretization& discretization, const EvaluationState& state,
                     const Eigen::VectorXd& residual, const EquationMap& equations, IncrementResults& r) {
  const DofMap& dofs = discretization.dofs();
  const int n_nodes = dofs.n_nodes();
  r.displacement.resize(n_nodes);
  r.reaction.assign(n_nodes, Eigen::Vector2d::Zero());
  for (int i = 0; i < n_nodes; ++i) {
    for (int c = 0; c < kDofsPerNode; ++c) {
      const int d = dofs.displacement(i, c);
      r.displacement[i][c] = state.u[d];
      if (equations.is_prescribed(d)) r.reaction[i][c] = residual[d];
    }
  }
  if (const StepTemperatures* t = discretization.temperatures()) r.temperature = t->all(state.step_time, state.total_time);
}

/// The multipliers and constraint values of the constraints, user
/// constraints and eliminated constraints (`lambda`: eliminated_multipliers()).
void add_multipliers(const Discretization& discretization, const EvaluationState& state, const Eigen::VectorXd& lambda,
                     IncrementResults& r) {
  const DofMap& dofs = discretization.dofs();
  for (const auto& c : discretization.constraints()) r.multipliers.push_back(c->values(state, dofs));
  for (const auto& c : discretization.user_constraints()) r.multipliers.push_back(c->values(state));
  std::size_t k = 0;
  for (const auto& e : discretization.eliminated()) {
    MultiplierValues v;
    v.owner = e.name;
    v.nodes = e.nodes;
    for (const auto& row : e.rows) {
      double f = -row.rhs;
      for (const auto& [dof, c] : row.terms) f += c * state.u[dof];
      v.constraint.push_back(f);
      const double l = lambda[static_cast<Eigen::Index>(k++)];
      v.value.push_back(l);
      // Force on dof i: -lambda * df/du_i, accumulated per node (on a rotation:
      // the moment).
      for (const auto& [dof, c] : row.terms) {
        const int node = dofs.node_of(dof), component = dofs.component_of(dof);
        auto it = std::find_if(v.nodal_force.begin(), v.nodal_force.end(),
                               [&](const NodalConstraintForce& n) { return n.node == node; });
        if (it == v.nodal_force.end()) it = v.nodal_force.insert(v.nodal_force.end(), NodalConstraintForce{node, Eigen::Vector2d::Zero(), std::nullopt});
        if (component < kDofsPerNode)
          it->force[component] -= l * c;
        else
          it->moment = it->moment.value_or(0.0) - l * c;
      }
    }
    r.multipliers.push_back(std::move(v));
  }
}

/// Node values (with the reactions of the eliminated constraints' forces),
/// ALLPD when an element keeps a material history, and the contact values.
IncrementResults node_results(const Discretization& discretization, const EvaluationState& state,
                              const Eigen::VectorXd& full_residual, const EquationMap& equations,
                              const Eigen::VectorXd& lambda) {
  IncrementResults r;
  add_node_values(discretization, state, with_eliminated_forces(equations, full_residual, lambda), equations, r);
  const auto& elements = discretization.elements();
  if (std::any_of(elements.begin(), elements.end(), [](const auto& e) { return e->has_history(); }))
    r.plastic_dissipation = total_plastic_dissipation(discretization, state);
  r.contact = discretization.contact_values(state);
  return r;
}

/// Elements whose points are alive at once when the results are streamed.
constexpr int kPointBlock = 8192;

/// Adds the element fields to `r` (see IncrementResults::element_fields):
/// the nodal averages of each element's extrapolation, per-element PEEQ and
/// SDV and, when streamed, the mean stresses; without `stream` every
/// element's points.
void add_element_fields(const Discretization& discretization, const EvaluationState& state,
                        const ElementPointSource* stream, IncrementResults& r) {
  const int n_nodes = discretization.dofs().n_nodes();
  const auto& elements = discretization.elements();
  const int n_elements = static_cast<int>(elements.size());
  const DiscretizationPoints own_source(discretization, state);
  const ElementPointSource& source = stream ? *stream : own_source;
  std::vector<std::vector<PointValues>> block;
  if (stream) {
    r.element_stress.resize(static_cast<std::size_t>(n_elements));
    block.resize(static_cast<std::size_t>(std::min(n_elements, kPointBlock)));
  } else {
    r.points.resize(static_cast<std::size_t>(n_elements));
  }

  // Nodal values: the average of each element's extrapolation, accumulated
  // element by element (one element's extrapolation alive at a time).
  r.nodal_stress.assign(n_nodes, Tensor4{});
  r.nodal_strain.assign(n_nodes, Tensor4{});
  const bool plastic = std::any_of(elements.begin(), elements.end(), [](const auto& e) { return e->has_history(); });
  if (plastic) start_plastic_results(discretization, r);
  const bool thermal = !r.temperature.empty();
  if (thermal) r.nodal_thermal_strain.assign(n_nodes, Tensor4{});
  if (r.n_sdv > 0) {
    r.element_sdv.assign(static_cast<std::size_t>(n_elements) * r.n_sdv, 0.0);
    r.nodal_sdv.assign(static_cast<std::size_t>(n_nodes) * r.n_sdv, 0.0);
  }
  std::vector<int> count(n_nodes, 0);
  std::vector<Tensor4> element_stress, element_strain, element_pe, element_the;
  std::vector<double> element_peeq, element_sdv;
  for (int first = 0; first < n_elements; first += kPointBlock) {
    const int last = std::min(n_elements, first + kPointBlock);
    const auto points_of = [&](int e) -> std::vector<PointValues>& {
      return stream ? block[static_cast<std::size_t>(e - first)] : r.points[static_cast<std::size_t>(e)];
    };
#pragma omp parallel for schedule(dynamic, 256) if (last - first >= 2048)
    for (int e = first; e < last; ++e) source.points(e, points_of(e));
    for (int e = first; e < last; ++e) {
      const std::vector<PointValues>& points = points_of(e);
      if (stream) r.element_stress[static_cast<std::size_t>(e)] = mean_stress(points);
      elements[e]->extrapolate_to_nodes(points, element_stress, element_strain);
      const auto& nodes = elements[e]->nodes();
      if (plastic) add_plastic_results(*elements[e], e, points, element_peeq, element_pe, r);
      if (r.n_sdv > 0) add_sdv_results(*elements[e], e, points, element_sdv, r);
      if (thermal) {
        elements[e]->extrapolate_thermal_to_nodes(points, element_the);
        for (std::size_t a = 0; a < nodes.size(); ++a)
          for (int k = 0; k < 4; ++k) r.nodal_thermal_strain[nodes[a]][k] += element_the[a][k];
      }
      for (std::size_t a = 0; a < nodes.size(); ++a) {
        for (int k = 0; k < 4; ++k) {
          r.nodal_stress[nodes[a]][k] += element_stress[a][k];
          r.nodal_strain[nodes[a]][k] += element_strain[a][k];
        }
        ++count[nodes[a]];
      }
    }
  }
  for (int i = 0; i < n_nodes; ++i)
    if (count[i] > 1) {
      for (int k = 0; k < 4; ++k) r.nodal_stress[i][k] /= count[i], r.nodal_strain[i][k] /= count[i];
      if (thermal)
        for (int k = 0; k < 4; ++k) r.nodal_thermal_strain[i][k] /= count[i];
      for (int k = 0; k < r.n_sdv; ++k) r.nodal_sdv[static_cast<std::size_t>(i) * r.n_sdv + k] /= count[i];
      if (!plastic) continue;
      r.nodal_peeq[i] /= count[i];
      r.nodal_ac_yield[i] /= count[i];
      for (int k = 0; k < 4; ++k) r.nodal_plastic_strain[i][k] /= count[i];
    }
}

}  // namespace

void DiscretizationPoints::points(int element, std::vector<PointValues>& out) const {
  discretization_.elements()[static_cast<std::size_t>(element)]->point_values(state_, out);
}

IncrementResults build_results(const Discretization& discretization, const EvaluationState& state,
                               const Eigen::VectorXd& full_residual, const EquationMap& equations,
                               const ElementPointSource* stream, bool element_fields) {
  if (!element_fields && !stream)
    throw std::logic_error("build_results: results without element fields must stream their points");
  const Eigen::VectorXd lambda = eliminated_multipliers(equations, full_residual);
  IncrementResults r = node_results(discretization, state, full_residual, equations, lambda);
  r.point_source = stream;
  r.element_fields = element_fields;
  r.n_sdv = discretization.n_user_state();
  if (element_fields) add_element_fields(discretization, state, stream, r);
  add_multipliers(discretization, state, lambda, r);
  return r;
}

IncrementResults build_node_results(const Discretization& discretization, const EvaluationState& state,
                                    const Eigen::VectorXd& full_residual, const EquationMap& equations) {
  IncrementResults r = node_results(discretization, state, full_residual, equations,
                                    eliminated_multipliers(equations, full_residual));
  r.element_fields = false;
  return r;
}

}  // namespace tether
