// *PLASTIC.
#include "tether/io/deck_state.hpp"
#include "tether/io/keyword_handlers.hpp"
#include "tether/io/numbers.hpp"

namespace tether::deck {

void handle_plastic(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  MaterialData& m = state.model.materials[static_cast<std::size_t>(state.material)];
  if (m.plastic)
    throw InputError(block.where, "material " + m.name + " already has *PLASTIC (" + m.plastic->where.str() +
                                      "): expected one per material");
  MaterialData::Plastic p;
  p.where = block.where;
  const std::string hardening = params.name("HARDENING");
  if (hardening == "COMBINED")
    throw InputError(block.where, "*PLASTIC, HARDENING=COMBINED (with *CYCLIC HARDENING) is not supported yet: "
                                  "expected ISOTROPIC or KINEMATIC");
  p.hardening = hardening == "KINEMATIC" ? MaterialData::Plastic::Hardening::Kinematic
                                         : MaterialData::Plastic::Hardening::Isotropic;
  require_data(block, "`yield stress, plastic strain` lines");
  for (const DataLine& line : block.data) {
    const auto f = data_fields(line, 1, 3, "`yield stress, plastic strain`");
    if (f.size() == 3 && !f[2].empty())
      throw InputError(line.where(), "*PLASTIC gives a temperature (" + f[2] +
                                         "): temperature-dependent plasticity is not supported");
    const double y = parse_real(f[0], line.where(), "*PLASTIC yield stress");
    const double e = f.size() > 1 && !f[1].empty() ? parse_real(f[1], line.where(), "*PLASTIC plastic strain") : 0.0;
    if (!(y > 0)) throw InputError(line.where(), "*PLASTIC yield stress " + f[0] + ": expected a yield stress > 0");
    if (p.plastic_strain.empty() && e != 0)
      throw InputError(line.where(), "*PLASTIC plastic strain " + f[1] + " on the first line: expected 0 (the "
                                     "initial yield stress)");
    if (!p.plastic_strain.empty() && !(e > p.plastic_strain.back()))
      throw InputError(line.where(), "*PLASTIC plastic strain " + (f.size() > 1 ? f[1] : std::string("0")) +
                                         ": expected a plastic strain greater than the previous line's (" +
                                         std::to_string(p.plastic_strain.back()) + ")");
    p.yield_stress.push_back(y);
    p.plastic_strain.push_back(e);
  }
  m.plastic = std::move(p);
}

}  // namespace tether::deck
