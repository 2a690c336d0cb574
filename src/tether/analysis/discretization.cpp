#include "tether/analysis/discretization.hpp"

#include "tether/core/error.hpp"

namespace tether {

namespace {

std::vector<Eigen::Vector2d> coordinates_of(const Model& model, const std::vector<int>& nodes) {
  std::vector<Eigen::Vector2d> x;
  x.reserve(nodes.size());
  for (int n : nodes) x.push_back(model.coords[n]);
  return x;
}

}  // namespace

Discretization::Discretization(const Model& model) : model_(model), dofs_(model.node_ids) {
  materials_.reserve(model.materials.size());
  for (const auto& m : model.materials) materials_.push_back(make_constitutive_model(m));

  elements_.reserve(model.elements.size());
  for (const auto& e : model.elements) {
    if (e.section < 0) throw ModelError("element " + std::to_string(e.id) + " has no section");
    const SolidSection& section = model.sections[e.section];
    elements_.push_back(std::make_unique<ContinuumElement>(e.id, e.type, e.nodes, coordinates_of(model, e.nodes),
                                                           *materials_[section.material], section.thickness, dofs_));
  }

  if (!model.coords.empty()) {
    Eigen::Vector2d lo = model.coords.front(), hi = lo;
    for (const auto& x : model.coords) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
    length_scale_ = std::max((hi - lo).norm(), 1e-30);
  }
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
                                                 thickness(load.face.element), dofs_));
  }
  return out;
}

}  // namespace tether
