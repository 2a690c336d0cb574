#include "tether/analysis/discretization.hpp"

#include "tether/analysis/constraint_builder.hpp"
#include "tether/analysis/contact_builder.hpp"
#include "tether/analysis/mortar_builder.hpp"
#include "tether/constraints/linear_constraint.hpp"
#include "tether/core/error.hpp"

namespace tether {

namespace {

std::vector<Eigen::Vector2d> coordinates_of(const Model& model, const std::vector<int>& nodes) {
  std::vector<Eigen::Vector2d> x;
  x.reserve(nodes.size());
  for (int n : nodes) x.push_back(model.coords[n]);
  return x;
}

PressureOverclosure::Law interaction_law(const Model& model, const ContactPairData& pair) {
  for (const SurfaceInteraction& i : model.interactions)
    if (i.name == pair.interaction) return i.behavior.law;
  return PressureOverclosure::Law::Hard;
}

/// CalculiX's LINEAR law on a SURFACE TO SURFACE pair is another law
/// (p = -K g at either sign, CalculiX's springforc_f2f), not modelled.
void refuse_calculix_linear_mortar(const Model& model, const ContactPairData& pair) {
  for (const SurfaceInteraction& i : model.interactions)
    if (i.name == pair.interaction && i.behavior.law == PressureOverclosure::Law::Linear &&
        i.behavior.meaning == Dialect::Calculix)
      throw ModelError("*CONTACT PAIR at " + pair.where.str() + " is surface-to-surface (mortar) with " + i.name +
                       "'s PRESSURE-OVERCLOSURE=LINEAR read in the calculix dialect (" + i.where.str() +
                       "): CalculiX's face-to-face LINEAR law (p = -K g, tension at open gaps too) is not modelled "
                       "for mortar pairs; use TYPE=NODE TO SURFACE, or --dialect abaqus for p = K h");
}

}  // namespace

Discretization::Discretization(const Model& model) : model_(model), dofs_(model.node_ids, model.instances) {
  materials_.reserve(model.materials.size());
  for (const auto& m : model.materials) materials_.push_back(make_constitutive_model(m));

  elements_.reserve(model.elements.size());
  for (const auto& e : model.elements) {
    if (e.section < 0) throw ModelError("element " + label_text(model.instances, e.id) + " has no section");
    const SolidSection& section = model.sections[e.section];
    // The element reads its nodes' reference coordinates from the model's
    // table (the model outlives the discretization and is not changed).
    elements_.push_back(std::make_unique<ContinuumElement>(e.id, e.type, e.nodes, model.coords,
                                                           *materials_[section.material], section.thickness, dofs_,
                                                           &model.materials[section.material]));
    elements_.back()->set_name(label_text(model.instances, e.id));
  }
  if (model.has_temperatures()) {
    temperatures_ = std::make_unique<StepTemperatures>(model);
    for (auto& element : elements_) element->set_temperatures(temperatures_.get());
  }

  if (!model.coords.empty()) {
    Eigen::Vector2d lo = model.coords.front(), hi = lo;
    for (const auto& x : model.coords) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
    // A model of one node (or nodes on a point) has no extent: fall back on
    // the distance from the origin, then on 1.
    double size = (hi - lo).norm();
    if (!(size > 0)) size = std::max(hi.cwiseAbs().maxCoeff(), 1.0);
    length_scale_ = size;
  }

  for (const ContactPairData& pair : model.contact_pairs) {
    // Two-pass HARD contact constrains each node against the other surface
    // and back: where nodes coincide the constraints repeat each other.
    for (const ContactPairData& other : model.contact_pairs)
      if (&other != &pair && other.slave == pair.master && other.master == pair.slave &&
          interaction_law(model, pair) == PressureOverclosure::Law::Hard &&
          interaction_law(model, other) == PressureOverclosure::Law::Hard)
        throw ModelError("the *CONTACT PAIRs at " + pair.where.str() + " and " + other.where.str() +
                         " make a two-pass HARD contact of " + pair.slave + " and " + pair.master +
                         ": exact constraints in both directions over-constrain the interface (repeated where "
                         "nodes coincide); use one pass (slave = the finer surface) or a soft law "
                         "(PRESSURE-OVERCLOSURE=LINEAR/EXPONENTIAL) for two-pass");
    if (pair.node_to_surface) {
      contact_order_.emplace_back(false, contact_pairs_.size());
      contact_pairs_.push_back(make_contact_pair(model, pair, model.coords, dofs_));
    } else {
      refuse_calculix_linear_mortar(model, pair);
      contact_order_.emplace_back(true, mortar_pairs_.size());
      mortar_pairs_.push_back(make_mortar_pair(model, pair, model.coords, dofs_));
    }
  }

  for (const ConstraintData& data : model.constraints) {
    if (data.kind == ConstraintData::Kind::User) {
      std::vector<int> labels;
      std::vector<Eigen::Vector2d> reference;
      for (int n : data.nodes) labels.push_back(model.node_ids[n]), reference.push_back(model.coords[n]);
      const int first = dofs_.add_multipliers(data.n_multipliers, "constraint " + data.name);
      user_constraints_.push_back(std::make_unique<UserConstraintElement>(
          data.library, data.symbol, static_cast<int>(user_constraints_.size() + 1), data.nodes, labels, reference,
          data.properties, data.n_multipliers, first, dofs_, data.name, data.flag));
      continue;
    }
    if (data.kind == ConstraintData::Kind::Beam) dofs_.add_rotation(data.nodes[1]);
    auto function = make_constraint_function(model, data, dofs_);
    if (data.enforcement.method == Enforcement::Method::Elimination) {
      const auto* linear = dynamic_cast<const LinearConstraint*>(function.get());
      if (!linear) throw ModelError(data.name + " (" + data.where.str() + "): ELIMINATION needs a linear constraint");
      EliminatedConstraint e{data.name, data.nodes_or_terms(), {}};
      const auto fd = linear->dofs();
      for (Eigen::Index r = 0; r < linear->gradient().rows(); ++r) {
        EliminationRow row{{}, linear->rhs()[r], data.name + " (" + data.where.str() + ")"};
        for (std::size_t j = 0; j < fd.size(); ++j)
          if (linear->gradient()(r, static_cast<Eigen::Index>(j)) != 0)
            row.terms.emplace_back(fd[j], linear->gradient()(r, static_cast<Eigen::Index>(j)));
        e.rows.push_back(std::move(row));
      }
      eliminated_.push_back(std::move(e));
      continue;
    }
    Enforcement enforcement = data.enforcement;
    if (enforcement.method == Enforcement::Method::Augmented && enforcement.tolerance == 0)
      enforcement.tolerance = 1e-8 * length_scale_;
    const int first = enforcement.method == Enforcement::Method::Lagrange
                          ? dofs_.add_multipliers(function->n_equations(), "constraint " + data.name)
                          : -1;
    constraints_.push_back(
        std::make_unique<ConstraintElement>(std::move(function), enforcement, first, data.name, data.nodes_or_terms()));
  }
}

std::vector<ContactPairValues> Discretization::contact_values(const EvaluationState& state) const {
  std::vector<ContactPairValues> out;
  out.reserve(contact_order_.size());
  for (const auto& [mortar, k] : contact_order_)
    out.push_back(mortar ? mortar_pairs_[k]->values(state) : contact_pairs_[k]->values(state));
  return out;
}

double Discretization::thickness(int element) const {
  const Element& e = model_.elements[element];
  if (e.type.family == Family::Axisymmetric) return 1.0;
  return model_.sections[e.section].thickness;
}

std::vector<std::unique_ptr<FacePressure>> Discretization::make_pressures(const std::vector<PressureLoad>& loads) const {
  std::vector<std::unique_ptr<FacePressure>> out;
  out.reserve(loads.size());
  for (const auto& load : loads) {
    const Element& e = model_.elements[load.face.element];
    out.push_back(std::make_unique<FacePressure>(e.id, e.type, e.nodes, coordinates_of(model_, e.nodes), load.face.face,
                                                 thickness(load.face.element),
                                                 *materials_[model_.sections[e.section].material], dofs_,
                                                 label_text(model_.instances, e.id)));
    out.back()->set_element(*elements_[static_cast<std::size_t>(load.face.element)]);  // plane-stress thickness
  }
  return out;
}

}  // namespace tether

namespace tether {

std::vector<EliminationRow> Discretization::elimination_rows() const {
  std::vector<EliminationRow> rows;
  for (const auto& e : eliminated_) rows.insert(rows.end(), e.rows.begin(), e.rows.end());
  return rows;
}

}  // namespace tether
