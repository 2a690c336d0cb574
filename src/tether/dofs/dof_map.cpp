#include "tether/dofs/dof_map.hpp"

#include <stdexcept>

namespace tether {

DofMap::DofMap(std::vector<int> node_labels, std::vector<PartInstance> instances)
    : node_labels_(std::move(node_labels)), instances_(std::move(instances)) {}

int DofMap::add_multipliers(int count, std::string owner) {
  if (count < 0) throw std::invalid_argument("DofMap::add_multipliers: negative count");
  const int first = n_dofs();
  blocks_.push_back({first, count, std::move(owner)});
  extra_node_.insert(extra_node_.end(), static_cast<std::size_t>(count), -1);
  n_multiplier_total_ += count;
  return first;
}

int DofMap::add_rotation(int node) {
  if (node < 0 || node >= n_nodes())
    throw std::invalid_argument("DofMap::add_rotation: node index " + std::to_string(node) + " outside the mesh");
  if (const int existing = rotation(node); existing >= 0) return existing;
  const int dof = n_dofs();
  extra_node_.push_back(node);
  rotations_.emplace_back(node, dof);
  return dof;
}

int DofMap::rotation(int node) const {
  for (const auto& [n, dof] : rotations_)
    if (n == node) return dof;
  return -1;
}

int DofMap::extra_node_of(int dof, const char* caller) const {
  if (dof < n_displacement_dofs() || dof >= n_dofs())
    throw std::invalid_argument(std::string("DofMap::") + caller + ": unknown " + std::to_string(dof) +
                                " is outside the map (" + std::to_string(n_dofs()) + " unknowns)");
  const int node = extra_node_[static_cast<std::size_t>(dof - n_displacement_dofs())];
  if (node < 0)
    throw std::invalid_argument(std::string("DofMap::") + caller + ": " + describe(dof) +
                                " is a multiplier, not a nodal unknown");
  return node;
}

std::string DofMap::describe(int dof) const {
  if (dof < 0 || dof >= n_dofs()) return "unknown " + std::to_string(dof);
  if (!is_multiplier(dof)) {
    const int component = component_of(dof);
    return "node " + node_name(node_of(dof)) + " dof " + std::to_string(component + 1) +
           (component == kRotationComponent ? " (rotation)" : "");
  }
  for (const auto& b : blocks_)
    if (dof >= b.first && dof < b.first + b.count)
      return "multiplier " + std::to_string(dof - b.first + 1) + " of " + b.owner;
  return "multiplier " + std::to_string(dof);
}

}  // namespace tether
