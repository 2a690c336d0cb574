// *PLASTIC.
#include "tether/io/deck_state.hpp"
#include "tether/io/keyword_handlers.hpp"
#include "tether/io/numbers.hpp"

namespace tether::deck {

namespace {

/// Reads `yield stress, plastic strain` rows (keyword: "*PLASTIC" or "*CYCLIC HARDENING") into y and e.
void read_hardening_rows(const KeywordBlock& block, const std::string& keyword, std::vector<double>& y,
                         std::vector<double>& e) {
  require_data(block, "`yield stress, plastic strain` lines");
  for (const DataLine& line : block.data) {
    const auto f = data_fields(line, 1, 3, "`yield stress, plastic strain`");
    if (f.size() == 3 && !f[2].empty())
      throw InputError(line.where(), keyword + " gives a temperature (" + f[2] +
                                         "): temperature-dependent plasticity is not supported");
    const double stress = parse_real(f[0], line.where(), keyword + " yield stress");
    const double strain = f.size() > 1 && !f[1].empty() ? parse_real(f[1], line.where(), keyword + " plastic strain") : 0.0;
    if (!(stress > 0)) throw InputError(line.where(), keyword + " yield stress " + f[0] + ": expected a yield stress > 0");
    if (e.empty() && strain != 0)
      throw InputError(line.where(), keyword + " plastic strain " + f[1] + " on the first line: expected 0 (the "
                                     "initial yield stress)");
    if (!e.empty() && !(strain > e.back()))
      throw InputError(line.where(), keyword + " plastic strain " + (f.size() > 1 ? f[1] : std::string("0")) +
                                         ": expected a plastic strain greater than the previous line's (" +
                                         std::to_string(e.back()) + ")");
    y.push_back(stress);
    e.push_back(strain);
  }
}

}  // namespace

void handle_plastic(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  MaterialData& m = state.model.materials[static_cast<std::size_t>(state.material)];
  if (m.plastic)
    throw InputError(block.where, "material " + m.name + " already has *PLASTIC (" + m.plastic->where.str() +
                                      "): expected one per material");
  MaterialData::Plastic p;
  p.where = block.where;
  const std::string hardening = params.name("HARDENING");
  using Kind = MaterialData::Plastic::Hardening;
  p.hardening = hardening == "KINEMATIC" ? Kind::Kinematic : hardening == "COMBINED" ? Kind::Combined : Kind::Isotropic;
  read_hardening_rows(block, "*PLASTIC", p.yield_stress, p.plastic_strain);
  m.plastic = std::move(p);
}

void handle_cyclic_hardening(DeckState& state, const KeywordBlock& block, const ParameterValues&) {
  MaterialData& m = state.model.materials[static_cast<std::size_t>(state.material)];
  if (!m.plastic || m.plastic->hardening != MaterialData::Plastic::Hardening::Combined)
    throw InputError(block.where, "*CYCLIC HARDENING in material " + m.name +
                                      " needs a *PLASTIC, HARDENING=COMBINED before it");
  if (!m.plastic->cyclic_yield_stress.empty())
    throw InputError(block.where, "material " + m.name + " already has *CYCLIC HARDENING (" +
                                      m.plastic->cyclic_where.str() + "): expected one per material");
  m.plastic->cyclic_where = block.where;
  read_hardening_rows(block, "*CYCLIC HARDENING", m.plastic->cyclic_yield_stress, m.plastic->cyclic_plastic_strain);
}

}  // namespace tether::deck
