#include "tether/assembly/equation_map.hpp"

namespace tether {

EquationMap::EquationMap(const std::vector<bool>& prescribed) : equation_(prescribed.size(), -1) {
  for (int d = 0; d < static_cast<int>(prescribed.size()); ++d) {
    if (prescribed[d]) continue;
    equation_[d] = static_cast<int>(dof_.size());
    dof_.push_back(d);
  }
}

}  // namespace tether
