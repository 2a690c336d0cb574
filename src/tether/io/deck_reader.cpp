// The dispatcher: lexed keyword blocks -> context and parameter checks from
// the table -> one handler per keyword -> whole-model checks.
#include "tether/io/deck_reader.hpp"
#include "tether/io/keyword_handlers.hpp"

#include "tether/io/assembly_flattening.hpp"
#include "tether/io/deck_state.hpp"
#include "tether/io/keyword_handlers.hpp"
#include "tether/io/keyword_table.hpp"
#include "tether/io/line_reader.hpp"
#include "tether/io/model_checks.hpp"
#include "tether/io/reading_order.hpp"

namespace tether {

namespace {

using deck::DeckState;
using deck::KeywordBlock;
using deck::KeywordSpec;

/// Where the reader stands in the deck, in deck order: what decides whether a
/// keyword may appear where it is written (the handlers run later, in
/// reading order, see reading_order.hpp).
struct DeckPosition {
  bool material = false;     ///< directly after *MATERIAL or a material option
  bool interaction = false;  ///< directly after *SURFACE INTERACTION or one of its options
  bool in_step = false;
  bool seen_step = false;
  std::string step_name;
  SourceLocation step_where;
  int n_steps = 0;

  /// Moves past `block` (already checked).
  void advance(const KeywordSpec& spec, const KeywordBlock& block, const deck::ParameterValues& params) {
    material = block.keyword == "MATERIAL" || (material && (spec.where & deck::kMaterial));
    interaction = block.keyword == "SURFACE INTERACTION" || (interaction && (spec.where & deck::kInteraction));
    if (block.keyword == "STEP") {
      in_step = seen_step = true;
      ++n_steps;
      step_name = params.given("NAME") ? params.text("NAME") : "Step-" + std::to_string(n_steps);
      step_where = block.where;
    }
    if (block.keyword == "END STEP") in_step = false;
  }
};

bool allowed_here(const DeckPosition& s, unsigned where) {
  return ((where & deck::kMaterial) && s.material) || ((where & deck::kInteraction) && s.interaction) ||
         ((where & deck::kModelData) && !s.seen_step) ||
         ((where & deck::kStep) && s.in_step) || ((where & deck::kBetweenSteps) && s.seen_step && !s.in_step);
}

std::string position_text(const DeckPosition& s) {
  if (s.in_step) return "inside step " + s.step_name + " (started at " + s.step_where.str() + ")";
  if (s.seen_step) return "between steps";
  if (s.material) return "in model data after *MATERIAL";
  return "in model data";
}

[[noreturn]] void unknown_keyword(const DeckPosition& s, const KeywordBlock& block) {
  std::string allowed;
  for (const KeywordSpec& k : deck::keyword_table())
    if (k.handler && allowed_here(s, k.where)) allowed += (allowed.empty() ? "*" : ", *") + std::string(k.name);
  throw InputError(block.where, "unknown keyword *" + block.keyword + ": expected one of the keywords allowed here: " +
                                    allowed + " (docs/keywords.md lists all)");
}

void check_position(const DeckPosition& s, const KeywordSpec& spec, const KeywordBlock& block) {
  if (allowed_here(s, spec.where)) return;
  std::string hint;
  if (s.in_step && !(spec.where & deck::kStep)) hint = "; is *END STEP missing?";
  if (!s.in_step && (spec.where & deck::kStep) && !(spec.where & deck::kModelData)) hint = "; expected a *STEP first";
  if (spec.where == deck::kMaterial) hint = "; expected it directly after *MATERIAL or another material option";
  if (spec.where == deck::kInteraction)
    hint = "; expected it directly after *SURFACE INTERACTION or another interaction option";
  throw InputError(block.where, "*" + std::string(spec.name) + " is not allowed " + position_text(s) +
                                    ": it belongs to " + deck::context_text(spec.where) + hint);
}

/// A lone `*` line: CalculiX skips it with a warning, and so does tether; data
/// lines under it would be dropped, so they are an error.
bool skip_lone_star(const DeckState& state, const KeywordBlock& block) {
  if (!block.keyword.empty()) return false;
  if (!block.data.empty())
    throw InputError(block.data.front().where(), "data line under a lone '*' line: expected a keyword name after "
                                                 "the '*' (e.g. *NODE) or no data lines");
  state.warn(block.where, "a lone '*' line is ignored (as CalculiX does)");
  return true;
}

/// Every keyword known, supported, allowed where it is written and with valid
/// parameters, checked in deck order; returns the specs (nullptr: skipped).
std::vector<const KeywordSpec*> check_blocks(const DeckState& state, const std::vector<KeywordBlock>& blocks) {
  std::vector<const KeywordSpec*> specs;
  DeckPosition position;
  for (const KeywordBlock& block : blocks) {
    if (skip_lone_star(state, block)) {
      specs.push_back(nullptr);
      continue;
    }
    const KeywordSpec* spec = deck::lookup_keyword(block.keyword);
    if (!spec) unknown_keyword(position, block);
    if (!spec->handler)
      throw InputError(block.where, "*" + block.keyword + " is not supported yet: " + std::string(spec->not_supported));
    check_position(position, *spec, block);
    position.advance(*spec, block, deck::ParameterValues(*spec, block));
    specs.push_back(spec);
  }
  if (position.in_step)
    throw InputError(position.step_where, "step " + position.step_name +
                                              " is not closed: expected *END STEP before the end of the deck");
  return specs;
}

/// The mesh tables grow by doubling while the deck is read; their spare
/// capacity (up to half of each: 1.5 MiB of the element table of the 230k-dof
/// Hertz deck) is given back once the model is complete. The elements of the
/// analysis keep a pointer into `coords`: this runs before any is built.
void trim_mesh_tables(Model& m) {
  m.elements.shrink_to_fit();
  m.coords.shrink_to_fit();
  m.node_ids.shrink_to_fit();
}

Model read_blocks(const std::vector<KeywordBlock>& blocks, const std::string& deck_path,
                  std::vector<DeckWarning>* warnings, Dialect dialect, std::vector<PartInstance> instances) {
  if (blocks.empty()) throw InputError({deck_path, 0}, "the deck is empty: expected keyword lines such as *NODE");
  DeckState state;
  state.warnings = warnings;
  state.model.deck_path = deck_path;
  state.model.dialect = dialect;
  state.model.instances = std::move(instances);
  const std::vector<const KeywordSpec*> specs = check_blocks(state, blocks);
  for (const std::size_t i : deck::reading_order(blocks)) {
    const KeywordSpec* spec = specs[i];
    if (!spec) continue;
    const KeywordBlock& block = blocks[i];
    const deck::ParameterValues params(*spec, block);
    if (!(spec->where & deck::kMaterial)) state.material = -1;
    if (!(spec->where & deck::kInteraction)) state.interaction = -1;
    spec->handler(state, block, params);
  }
  if (state.model.steps.empty())
    state.warn({deck_path, 0}, "the deck has no *STEP: nothing will be solved");
  deck::check_model(state);
  deck::apply_temperature_table_dialect(state);
  deck::check_pretension_loads(state);
  deck::apply_contact_adjustments(state);
  deck::warn_about_stiff_slaves(state);
  trim_mesh_tables(state.model);
  return std::move(state.model);
}

}  // namespace

Model read_deck(const std::string& path, std::vector<DeckWarning>* warnings, Dialect dialect) {
  std::vector<PartInstance> instances;
  auto blocks = deck::flatten_assembly(deck::lex_deck_file(path), &instances);
  return read_blocks(blocks, path, warnings, dialect, std::move(instances));
}

Model read_deck_string(const std::string& text, const std::string& name, std::vector<DeckWarning>* warnings,
                       Dialect dialect) {
  std::vector<PartInstance> instances;
  auto blocks = deck::flatten_assembly(deck::lex_deck_text(text, name, ""), &instances);
  return read_blocks(blocks, name, warnings, dialect, std::move(instances));
}

}  // namespace tether
