#pragma once
/// \file Collects the results of a converged increment from the elements.

#include "tether/analysis/discretization.hpp"
#include "tether/assembly/equation_map.hpp"
#include "tether/model/results.hpp"

namespace tether {

/// The integration-point values of the discretization's elements in one
/// state: the source of streamed results (IncrementResults::point_source).
/// Borrows both. The values are the converged trial state of the state's
/// displacements whether they are asked for before or after the elements
/// commit it (see ContinuumElement::point_values).
class DiscretizationPoints final : public ElementPointSource {
 public:
  DiscretizationPoints(const Discretization& discretization, const EvaluationState& state)
      : discretization_(discretization), state_(state) {}
  void points(int element, std::vector<PointValues>& out) const override;

 private:
  const Discretization& discretization_;
  EvaluationState state_;
};

/// Displacements and reactions per node, integration-point values per element
/// and nodal averages of the values extrapolated from each element.
/// `residual` is the full residual (reactions are read at prescribed dofs).
/// With `stream` (normally a DiscretizationPoints of the same discretization
/// and state, which must outlive the use of the results) the results are
/// streamed: no `points`, but `element_stress` and `point_source = stream`
/// (see IncrementResults). Element values are computed in blocks of elements,
/// so streaming never holds more than one block's points.
/// Without `element_fields` (streamed results only, else std::logic_error)
/// no element value is computed here: the nodal averages and element means
/// are left empty (IncrementResults::element_fields false) and the `.dat`'s
/// element prints take their elements' points from `stream`. The rule of
/// when to ask for them is the caller's (see StaticProcedure::complete).
IncrementResults build_results(const Discretization& discretization, const EvaluationState& state,
                               const Eigen::VectorXd& residual, const EquationMap& equations,
                               const ElementPointSource* stream = nullptr, bool element_fields = true);

/// The nodal part of build_results() alone: displacements, reactions and
/// temperatures per node, ALLPD (when an element keeps a material history)
/// and the contact values; no element values and no multipliers (for the
/// explicit reports where no output request is due; element_fields false).
IncrementResults build_node_results(const Discretization& discretization, const EvaluationState& state,
                                    const Eigen::VectorXd& residual, const EquationMap& equations);

}  // namespace tether
