// *PLASTIC.
#include "tether/io/deck_state.hpp"
#include "tether/io/keyword_handlers.hpp"
#include "tether/io/numbers.hpp"

#include <fmt/format.h>
#include <optional>

namespace tether::deck {

namespace {

/// The rows of *PLASTIC or *CYCLIC HARDENING (`keyword`, for messages).
struct HardeningRows {
  std::vector<double>& y;  ///< yield stress [stress]
  std::vector<double>& e;  ///< plastic strain [-]
  std::vector<double>& t;  ///< temperature [temperature]; stays empty without the column
};

/// Checks one row's plastic strain and temperature against the previous row
/// (none when rows.e is empty): the first row of each temperature group at
/// plastic strain 0, strains increasing within a group, temperatures
/// increasing between groups, the temperature column on all rows or none.
void check_hardening_row(const DataLine& line, const std::string& keyword, const std::vector<std::string>& f,
                         double strain, std::optional<double> temperature, const HardeningRows& rows) {
  const std::string strain_text = f.size() > 1 && !f[1].empty() ? f[1] : std::string("0");
  if (!rows.e.empty() && temperature.has_value() != !rows.t.empty())
    throw InputError(line.where(), keyword + (temperature ? " gives a temperature (" + f[2] + ") on this line but "
                                                            "not on the first: expected it on every line or none"
                                                          : " gives no temperature on this line but one on the "
                                                            "first: expected it on every line or none"));
  const bool new_group = rows.e.empty() || (temperature && *temperature != rows.t.back());
  if (!rows.e.empty() && temperature && *temperature < rows.t.back())
    throw InputError(line.where(), keyword + " temperature " + f[2] + ": expected the temperatures to increase "
                                   "from one group of lines to the next (the previous is " +
                                   fmt::format("{:g}", rows.t.back()) + ")");
  if (new_group && strain != 0)
    throw InputError(line.where(), keyword + " plastic strain " + strain_text + " on the first line" +
                                       (temperature ? " of temperature " + f[2] : std::string()) +
                                       ": expected 0 (the initial yield stress)");
  if (!new_group && !(strain > rows.e.back()))
    throw InputError(line.where(), keyword + " plastic strain " + strain_text +
                                       ": expected a plastic strain greater than the previous line's (" +
                                       fmt::format("{:g}", rows.e.back()) + ")");
}

/// Reads `yield stress, plastic strain[, temperature]` rows (keyword:
/// "*PLASTIC" or "*CYCLIC HARDENING"), grouped by temperature as ABAQUS
/// does, into rows.
void read_hardening_rows(const KeywordBlock& block, const std::string& keyword, const HardeningRows& rows) {
  require_data(block, "`yield stress, plastic strain[, temperature]` lines");
  for (const DataLine& line : block.data) {
    const auto f = data_fields(line, 1, 3, "`yield stress, plastic strain[, temperature]`");
    const double stress = parse_real(f[0], line.where(), keyword + " yield stress");
    const double strain = f.size() > 1 && !f[1].empty() ? parse_real(f[1], line.where(), keyword + " plastic strain") : 0.0;
    std::optional<double> temperature;
    if (f.size() == 3 && !f[2].empty()) temperature = parse_real(f[2], line.where(), keyword + " temperature");
    if (!(stress > 0)) throw InputError(line.where(), keyword + " yield stress " + f[0] + ": expected a yield stress > 0");
    check_hardening_row(line, keyword, f, strain, temperature, rows);
    rows.y.push_back(stress);
    rows.e.push_back(strain);
    if (temperature) rows.t.push_back(*temperature);
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
  read_hardening_rows(block, "*PLASTIC", {p.yield_stress, p.plastic_strain, p.temperature});
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
  read_hardening_rows(block, "*CYCLIC HARDENING",
                      {m.plastic->cyclic_yield_stress, m.plastic->cyclic_plastic_strain, m.plastic->cyclic_temperature});
}

}  // namespace tether::deck
