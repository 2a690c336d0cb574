#pragma once
/// \file Instances of ABAQUS/CAE parts and the labels the user knows them by.
///
/// The reader flattens an assembly into one mesh. An instance whose part's
/// labels are still free keeps them; otherwise its nodes and elements get
/// internal labels `part label + offset` (one offset for both, a round
/// number), so several instances of one part stay distinct. The label ranges
/// of different instances never overlap, so an internal label tells its
/// instance and the part's label back.

#include <string>
#include <vector>

namespace tether {

/// One `*INSTANCE` of a part, as flattened.
struct PartInstance {
  std::string name;  ///< instance name, upper case (as sets are qualified: `NAME.SET`)
  int offset = 0;    ///< internal label = part label + offset (nodes and elements alike)
  int first = 0;     ///< smallest internal label of its nodes and elements
  int last = 0;      ///< largest internal label of its nodes and elements
};

/// The instance whose label range holds internal label `label`, or nullptr.
const PartInstance* instance_of(const std::vector<PartInstance>& instances, int label);

/// A node or element label as the user knows it: `NAME.part_label` for a
/// label of an instance (`UPPER-1.3`), else the label itself.
std::string label_text(const std::vector<PartInstance>& instances, int label);

}  // namespace tether
