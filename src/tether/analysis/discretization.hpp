#pragma once
/// \file The model turned into contributions over global unknowns.
///
/// Owns the constitutive models and one ContinuumElement per mesh element, and
/// builds the per-step loads. Constraints and contact pairs add their
/// contributions and multiplier blocks here, through the same DofMap.

#include <algorithm>
#include <memory>
#include <vector>

#include "tether/analysis/step_temperatures.hpp"
#include "tether/assembly/contribution.hpp"
#include "tether/assembly/equation_map.hpp"
#include "tether/constraints/constraint_element.hpp"
#include "tether/constraints/user_constraint_element.hpp"
#include "tether/contact/contact_pair.hpp"
#include "tether/contact/mortar_pair.hpp"
#include "tether/dofs/dof_map.hpp"
#include "tether/elements/continuum_element.hpp"
#include "tether/elements/face_pressure.hpp"
#include "tether/materials/constitutive_model.hpp"
#include "tether/model/model.hpp"

namespace tether {

class Discretization {
 public:
  /// Throws ModelError for a model that cannot be discretized (e.g. a material
  /// without data, a constraint whose nodes coincide).
  explicit Discretization(const Model& model);

  [[nodiscard]] const Model& model() const { return model_; }
  [[nodiscard]] const DofMap& dofs() const { return dofs_; }
  [[nodiscard]] const std::vector<std::unique_ptr<ContinuumElement>>& elements() const { return elements_; }
  /// The largest number of user-material state variables (SDV) of the
  /// materials that sections use (ConstitutiveModel::n_user_state); 0
  /// without a UMAT.
  [[nodiscard]] int n_user_state() const {
    int n = 0;
    for (const auto& section : model_.sections)
      if (section.material >= 0) n = std::max(n, materials_[static_cast<std::size_t>(section.material)]->n_user_state());
    return n;
  }
  /// Constraints enforced as contributions (multipliers, penalty, augmented Lagrangian).
  [[nodiscard]] const std::vector<std::unique_ptr<ConstraintElement>>& constraints() const { return constraints_; }
  /// A linear constraint enforced by elimination (ENFORCEMENT=ELIMINATION).
  struct EliminatedConstraint {
    std::string name;
    std::vector<int> nodes;
    std::vector<EliminationRow> rows;
  };
  [[nodiscard]] const std::vector<EliminatedConstraint>& eliminated() const { return eliminated_; }
  /// All rows of the eliminated constraints, in order (for EquationMap).
  [[nodiscard]] std::vector<EliminationRow> elimination_rows() const;

  /// Constraints computed by user routines in shared libraries (*CONSTRAINT, TYPE=USER).
  [[nodiscard]] const std::vector<std::unique_ptr<UserConstraintElement>>& user_constraints() const {
    return user_constraints_;
  }

  /// One per *CONTACT PAIR; each is assembled before its nodes (ContactPair::nodes()).
  [[nodiscard]] const std::vector<std::unique_ptr<ContactPair>>& contact_pairs() const { return contact_pairs_; }
  /// One per *CONTACT PAIR of TYPE=SURFACE TO SURFACE (mortar); each is
  /// assembled before its nodes (MortarPair::nodes()).
  [[nodiscard]] const std::vector<std::unique_ptr<MortarPair>>& mortar_pairs() const { return mortar_pairs_; }
  /// Contact output of every *CONTACT PAIR at the state, in deck order.
  [[nodiscard]] std::vector<ContactPairValues> contact_values(const EvaluationState& state) const;

  /// One FacePressure per entry of `loads` (pressure set later with set_pressure).
  [[nodiscard]] std::vector<std::unique_ptr<FacePressure>> make_pressures(const std::vector<PressureLoad>& loads) const;

  /// Out-of-plane thickness of element e (1 for axisymmetric elements).
  [[nodiscard]] double thickness(int element) const;

  /// The nodal temperatures the elements read; nullptr when the deck gives none.
  [[nodiscard]] const StepTemperatures* temperatures() const { return temperatures_.get(); }

  /// Diagonal of the reference bounding box (a length scale for tolerances).
  [[nodiscard]] double length_scale() const { return length_scale_; }

 private:
  const Model& model_;
  DofMap dofs_;
  std::vector<std::unique_ptr<ConstitutiveModel>> materials_;
  std::unique_ptr<StepTemperatures> temperatures_;  ///< when the deck gives temperatures
  std::vector<std::unique_ptr<ContinuumElement>> elements_;
  std::vector<std::unique_ptr<ConstraintElement>> constraints_;
  std::vector<std::unique_ptr<UserConstraintElement>> user_constraints_;
  std::vector<EliminatedConstraint> eliminated_;
  std::vector<std::unique_ptr<ContactPair>> contact_pairs_;
  std::vector<std::unique_ptr<MortarPair>> mortar_pairs_;
  /// Per *CONTACT PAIR in deck order: (mortar, index into mortar_pairs_ or contact_pairs_).
  std::vector<std::pair<bool, std::size_t>> contact_order_;
  double length_scale_ = 1;
};

}  // namespace tether
