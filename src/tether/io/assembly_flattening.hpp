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
/// to that instance's labels and names. Node and element labels are kept as
/// the part numbers them, so two instances whose labels overlap are refused
/// (instance-qualified labels in messages and results are not there yet).

#include <string_view>
#include <vector>

#include "tether/io/line_reader.hpp"

namespace tether::deck {

/// The blocks of a deck with parts, assembly and instances replaced by the
/// flat blocks they stand for; a deck without `*PART` is returned unchanged.
/// Throws InputError (file:line) for a part without `*END PART`, an instance
/// of an undefined part, a rotation about an axis that is not along z, bad
/// transformation data, or instances whose node or element labels overlap.
std::vector<KeywordBlock> flatten_assembly(std::vector<KeywordBlock> blocks);

/// *PART, *END PART, *ASSEMBLY, *END ASSEMBLY, *INSTANCE, *END INSTANCE:
/// consumed by flatten_assembly() (no handler in the keyword table).
bool is_assembly_keyword(std::string_view keyword);

}  // namespace tether::deck
