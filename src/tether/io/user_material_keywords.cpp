// *USER MATERIAL and *DEPVAR.
#include "tether/io/deck_state.hpp"
#include "tether/io/keyword_handlers.hpp"
#include "tether/io/numbers.hpp"

namespace tether::deck {

namespace {

MaterialData& material_of(DeckState& state) { return state.model.materials[static_cast<std::size_t>(state.material)]; }

}  // namespace

void handle_user_material(DeckState& state, const KeywordBlock& block, const ParameterValues& params) {
  MaterialData& m = material_of(state);
  if (m.user)
    throw InputError(block.where, "material " + m.name + " already has *USER MATERIAL (" + m.user->where.str() +
                                      "): expected one per material");
  const int n = params.integer("CONSTANTS");
  if (n < 0) throw InputError(block.where, "*USER MATERIAL, CONSTANTS=" + std::to_string(n) + ": expected >= 0");
  MaterialData::User u;
  u.where = block.where;
  u.library = params.text("LIBRARY");
  u.symbol = params.text("SYMBOL");
  for (const DataLine& line : block.data)
    for (const std::string& f : data_fields(line, 1, 8, "up to 8 constants per line")) {
      if (static_cast<int>(u.constants.size()) == n)
        throw InputError(line.where(), "*USER MATERIAL has more constants than CONSTANTS=" + std::to_string(n));
      u.constants.push_back(f.empty() ? 0.0 : parse_real(f, line.where(), "*USER MATERIAL constant"));
    }
  if (static_cast<int>(u.constants.size()) != n)
    throw InputError(block.data.empty() ? block.where : block.data.back().where(),
                     "*USER MATERIAL gives " + std::to_string(u.constants.size()) + " constants: expected CONSTANTS=" +
                         std::to_string(n));
  m.user = std::move(u);
}

void handle_depvar(DeckState& state, const KeywordBlock& block, const ParameterValues&) {
  MaterialData& m = material_of(state);
  require_data(block, "`number of state variables`");
  if (block.data.size() > 1)
    throw InputError(block.data[1].where(), "*DEPVAR has one data line: expected `number of state variables`");
  const auto f = data_fields(block.data[0], 1, 1, "`number of state variables`");
  const SourceLocation at = block.data[0].where();
  const double v = parse_real(f[0], at, "*DEPVAR number of state variables");
  if (!(v >= 0) || v != static_cast<double>(static_cast<int>(v)))
    throw InputError(at, "*DEPVAR " + f[0] + ": expected a whole number of state variables >= 0");
  if (m.depvar) throw InputError(block.where, "material " + m.name + " already has *DEPVAR");
  m.depvar = static_cast<int>(v);
  m.depvar_where = block.where;
}

}  // namespace tether::deck
