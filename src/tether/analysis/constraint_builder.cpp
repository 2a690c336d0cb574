#include "tether/analysis/constraint_builder.hpp"

#include <stdexcept>

#include "tether/constraints/beam_constraint.hpp"
#include "tether/constraints/distance_constraint.hpp"
#include "tether/constraints/expression_constraint.hpp"
#include "tether/constraints/external_constraint_function.hpp"
#include "tether/constraints/linear_constraint.hpp"
#include "tether/constraints/user_mpc_constraint.hpp"

namespace tether {

std::unique_ptr<ConstraintFunction> make_constraint_function(const Model& model, const ConstraintData& data,
                                                             const DofMap& dofs) {
  const std::string what = data.name + " (" + data.where.str() + ")";
  auto dof = [&](int node, int c) { return dofs.displacement(node, c); };
  try {
    switch (data.kind) {
      case ConstraintData::Kind::Equation: {
        std::vector<LinearTerm> row;
        for (const auto& t : data.terms) row.push_back({dof(t.node, t.dof), t.coefficient});
        return std::make_unique<LinearConstraint>(std::vector<std::vector<LinearTerm>>{row}, what);
      }
      case ConstraintData::Kind::Tie: {
        const int a = data.nodes[0], b = data.nodes[1];
        return std::make_unique<LinearConstraint>(
            std::vector<std::vector<LinearTerm>>{{{dof(a, 0), 1.0}, {dof(b, 0), -1.0}},
                                                 {{dof(a, 1), 1.0}, {dof(b, 1), -1.0}}},
            what);
      }
      case ConstraintData::Kind::Link: {
        const int a = data.nodes[0], b = data.nodes[1];
        return std::make_unique<DistanceConstraint>(std::array<int, 4>{dof(a, 0), dof(a, 1), dof(b, 0), dof(b, 1)},
                                                    model.coords[a], model.coords[b], what);
      }
      case ConstraintData::Kind::Slider: {
        const int a = data.nodes[0], b = data.nodes[1], c = data.nodes[2];
        return std::make_unique<SliderConstraint>(
            std::array<int, 6>{dof(a, 0), dof(a, 1), dof(b, 0), dof(b, 1), dof(c, 0), dof(c, 1)}, model.coords[a],
            model.coords[b], model.coords[c], what);
      }
      case ConstraintData::Kind::Expression: {
        std::vector<ExpressionNode> nodes;
        for (int n : data.nodes) nodes.push_back({model.node_ids[n], model.coords[n], {dof(n, 0), dof(n, 1)}});
        return std::make_unique<ExpressionConstraint>(data.formulas, std::move(nodes), data.where, what,
                                                      data.formula_where);
      }
      case ConstraintData::Kind::Linear: {  // *TIE slave node, *PERIODIC pair: rows resolved by the reader
        std::vector<std::vector<LinearTerm>> rows;
        for (const auto& terms : data.rows) {
          std::vector<LinearTerm> row;
          for (const auto& t : terms) row.push_back({dof(t.node, t.dof), t.coefficient});
          rows.push_back(std::move(row));
        }
        return std::make_unique<LinearConstraint>(std::move(rows), what);
      }
      case ConstraintData::Kind::Beam: {
        const int a = data.nodes[0], b = data.nodes[1];
        const int theta = dofs.rotation(b);
        if (theta < 0) throw ModelError(what + ": the reference node has no rotation unknown");
        return std::make_unique<BeamConstraint>(std::array<int, 5>{dof(a, 0), dof(a, 1), dof(b, 0), dof(b, 1), theta},
                                                model.coords[a], model.coords[b], what);
      }
      case ConstraintData::Kind::UserMpc: {
        std::vector<int> labels;
        std::vector<Eigen::Vector2d> reference;
        for (int n : data.nodes) labels.push_back(model.node_ids[n]), reference.push_back(model.coords[n]);
        return std::make_unique<UserMpcConstraint>(data.library, data.symbol,
                                                   data.node_mode ? UserMpcMode::Node : UserMpcMode::Dof, data.flag,
                                                   data.nodes, labels, reference, dofs, what);
      }
      case ConstraintData::Kind::External: {
        std::vector<int> function_dofs;
        Eigen::VectorXd reference(2 * static_cast<Eigen::Index>(data.nodes.size()));
        for (std::size_t k = 0; k < data.nodes.size(); ++k) {
          const int n = data.nodes[k];
          function_dofs.push_back(dof(n, 0)), function_dofs.push_back(dof(n, 1));
          reference.segment<2>(2 * static_cast<Eigen::Index>(k)) = model.coords[n];
        }
        return std::make_unique<ExternalConstraintFunction>(data.external, std::move(function_dofs),
                                                            std::move(reference), what);
      }
      case ConstraintData::Kind::User: break;
    }
  } catch (const std::invalid_argument& e) {
    throw ModelError(e.what());
  }
  throw ModelError(what + ": this constraint type is not available in this build yet");
}

}  // namespace tether
