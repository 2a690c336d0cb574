#include "tether/analysis/results_builder.hpp"

namespace tether {

IncrementResults build_results(const Discretization& discretization, const EvaluationState& state,
                               const Eigen::VectorXd& residual, const EquationMap& equations) {
  const DofMap& dofs = discretization.dofs();
  const int n_nodes = dofs.n_nodes();
  IncrementResults r;
  r.displacement.resize(n_nodes);
  r.reaction.assign(n_nodes, Eigen::Vector2d::Zero());
  for (int i = 0; i < n_nodes; ++i) {
    for (int c = 0; c < kDofsPerNode; ++c) {
      const int d = dofs.displacement(i, c);
      r.displacement[i][c] = state.u[d];
      if (equations.is_prescribed(d)) r.reaction[i][c] = residual[d];
    }
  }

  const auto& elements = discretization.elements();
  const int n_elements = static_cast<int>(elements.size());
  r.points.resize(n_elements);
  std::vector<std::vector<Tensor4>> element_stress(n_elements), element_strain(n_elements);
#pragma omp parallel for schedule(dynamic, 256) if (n_elements >= 2048)
  for (int e = 0; e < n_elements; ++e) {
    elements[e]->point_values(state, r.points[e]);
    elements[e]->extrapolate_to_nodes(r.points[e], element_stress[e], element_strain[e]);
  }

  r.nodal_stress.assign(n_nodes, Tensor4{});
  r.nodal_strain.assign(n_nodes, Tensor4{});
  std::vector<int> count(n_nodes, 0);
  for (int e = 0; e < n_elements; ++e) {
    const auto& nodes = elements[e]->nodes();
    for (std::size_t a = 0; a < nodes.size(); ++a) {
      for (int k = 0; k < 4; ++k) {
        r.nodal_stress[nodes[a]][k] += element_stress[e][a][k];
        r.nodal_strain[nodes[a]][k] += element_strain[e][a][k];
      }
      ++count[nodes[a]];
    }
  }
  for (int i = 0; i < n_nodes; ++i)
    if (count[i] > 1)
      for (int k = 0; k < 4; ++k) r.nodal_stress[i][k] /= count[i], r.nodal_strain[i][k] /= count[i];
  for (const auto& c : discretization.constraints()) r.multipliers.push_back(c->values(state));
  for (const auto& c : discretization.user_constraints()) r.multipliers.push_back(c->values(state));
  return r;
}

}  // namespace tether
