#pragma once
/// \file ABAQUS/CAE decks: `*PART ... *END PART` and `*ASSEMBLY` with
/// `*INSTANCE ... *END INSTANCE`, flattened into the plain keyword blocks of
/// an ordinary deck before anything else reads them.
///
/// Each instance gets a copy of its part's blocks: node coordinates moved by
/// the instance's translation, then rotated (about an axis along z; a 2D
/// model cannot rotate out of its plane), and every set and surface name of
/// the part qualified by the instance, `INSTANCE.NAME` (as ABAQUS names them:
/// `Part-1-1.Set-1`). Assembly-level `*NSET`/`*ELSET` with `INSTANCE=` refer
/// to that instance's labels and names, and a data field `INSTANCE.label`
/// outside the parts to that node or element. An instance keeps its part's
/// labels when they are still free, else all of them are moved by one round
/// offset (part_instance.hpp), so several instances of one part coexist.

#include <string_view>
#include <vector>

#include "tether/io/line_reader.hpp"
#include "tether/model/part_instance.hpp"

namespace tether::deck {

/// The blocks of a deck with parts, assembly and instances replaced by the
/// flat blocks they stand for; a deck without `*PART` is returned unchanged.
/// The instances placed (with their label offsets) go to `instances` when given.
/// Throws InputError (file:line) for a part without `*END PART`, an instance
/// of an undefined part or defined twice, a rotation about an axis that is not
/// along z, bad transformation data, or INSTANCE= naming no placed instance.
std::vector<KeywordBlock> flatten_assembly(std::vector<KeywordBlock> blocks,
                                           std::vector<PartInstance>* instances = nullptr);

/// *PART, *END PART, *ASSEMBLY, *END ASSEMBLY, *INSTANCE, *END INSTANCE:
/// consumed by flatten_assembly() (no handler in the keyword table).
bool is_assembly_keyword(std::string_view keyword);

}  // namespace tether::deck
