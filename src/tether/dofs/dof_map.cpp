#include "tether/dofs/dof_map.hpp"

#include <stdexcept>

namespace tether {

DofMap::DofMap(std::vector<int> node_labels) : node_labels_(std::move(node_labels)) {}

int DofMap::add_multipliers(int count, std::string owner) {
  if (count < 0) throw std::invalid_argument("DofMap::add_multipliers: negative count");
  const int first = n_dofs();
  blocks_.push_back({first, count, std::move(owner)});
  is_multiplier_.insert(is_multiplier_.end(), static_cast<std::size_t>(count), true);
  n_multiplier_total_ += count;
  return first;
}

int DofMap::add_rotation(int node) {
  if (const int existing = rotation(node); existing >= 0) return existing;
  const int dof = n_dofs();
  is_multiplier_.push_back(false);
  rotations_.emplace_back(node, dof);
  return dof;
}

int DofMap::rotation(int node) const {
  for (const auto& [n, dof] : rotations_)
    if (n == node) return dof;
  return -1;
}

std::string DofMap::describe(int dof) const {
  if (dof < 0 || dof >= n_dofs()) return "unknown " + std::to_string(dof);
  if (!is_multiplier(dof)) {
    return "node " + std::to_string(node_labels_[node_of(dof)]) + " dof " +
           std::to_string(dof % kDofsPerNode + 1);
  }
  for (const auto& [node, rot] : rotations_)
    if (rot == dof) return "node " + std::to_string(node_labels_[node]) + " dof 6 (rotation)";
  for (const auto& b : blocks_)
    if (dof >= b.first && dof < b.first + b.count)
      return "multiplier " + std::to_string(dof - b.first + 1) + " of " + b.owner;
  return "multiplier " + std::to_string(dof);
}

}  // namespace tether
