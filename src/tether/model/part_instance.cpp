#include "tether/model/part_instance.hpp"

namespace tether {

const PartInstance* instance_of(const std::vector<PartInstance>& instances, int label) {
  for (const PartInstance& i : instances)
    if (label >= i.first && label <= i.last) return &i;
  return nullptr;
}

std::string label_text(const std::vector<PartInstance>& instances, int label) {
  const PartInstance* i = instance_of(instances, label);
  return i ? i->name + "." + std::to_string(label - i->offset) : std::to_string(label);
}

}  // namespace tether
