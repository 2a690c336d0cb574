// The dispatcher: lexed keyword blocks -> context and parameter checks from
// the table -> one handler per keyword -> whole-model checks.
#include "tether/io/deck_reader.hpp"

#include "tether/io/deck_state.hpp"
#include "tether/io/keyword_table.hpp"
#include "tether/io/line_reader.hpp"
#include "tether/io/model_checks.hpp"

namespace tether {

namespace {

using deck::DeckState;
using deck::KeywordBlock;
using deck::KeywordSpec;

bool allowed_here(const DeckState& s, unsigned where) {
  return ((where & deck::kMaterial) && s.material >= 0) || ((where & deck::kInteraction) && s.interaction >= 0) ||
         ((where & deck::kModelData) && !s.seen_step) ||
         ((where & deck::kStep) && s.in_step) || ((where & deck::kBetweenSteps) && s.seen_step && !s.in_step);
}

std::string position_text(DeckState& s) {
  if (s.in_step) return "inside step " + s.step().name + " (started at " + s.step().where.str() + ")";
  if (s.seen_step) return "between steps";
  if (s.material >= 0) return "in model data after *MATERIAL";
  return "in model data";
}

[[noreturn]] void unknown_keyword(const DeckState& s, const KeywordBlock& block) {
  std::string allowed;
  for (const KeywordSpec& k : deck::keyword_table())
    if (k.handler && allowed_here(s, k.where)) allowed += (allowed.empty() ? "*" : ", *") + std::string(k.name);
  throw InputError(block.where, "unknown keyword *" + block.keyword + ": expected one of the keywords allowed here: " +
                                    allowed + " (docs/keywords.md lists all)");
}

void check_position(DeckState& s, const KeywordSpec& spec, const KeywordBlock& block) {
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

Model read_blocks(const std::vector<KeywordBlock>& blocks, const std::string& deck_path,
                  std::vector<DeckWarning>* warnings) {
  if (blocks.empty()) throw InputError({deck_path, 0}, "the deck is empty: expected keyword lines such as *NODE");
  DeckState state;
  state.warnings = warnings;
  state.model.deck_path = deck_path;
  for (const KeywordBlock& block : blocks) {
    const KeywordSpec* spec = deck::lookup_keyword(block.keyword);
    if (!spec) unknown_keyword(state, block);
    if (!spec->handler)
      throw InputError(block.where, "*" + block.keyword + " is not supported yet: " + std::string(spec->not_supported));
    check_position(state, *spec, block);
    const deck::ParameterValues params(*spec, block);
    if (!(spec->where & deck::kMaterial)) state.material = -1;
    if (!(spec->where & deck::kInteraction)) state.interaction = -1;
    spec->handler(state, block, params);
  }
  if (state.in_step)
    throw InputError(state.step().where, "step " + state.step().name +
                                             " is not closed: expected *END STEP before the end of the deck");
  if (state.model.steps.empty())
    state.warn({deck_path, 0}, "the deck has no *STEP: nothing will be solved");
  deck::check_model(state);
  deck::apply_contact_adjustments(state);
  deck::warn_about_stiff_slaves(state);
  return std::move(state.model);
}

}  // namespace

Model read_deck(const std::string& path, std::vector<DeckWarning>* warnings) {
  return read_blocks(deck::lex_deck_file(path), path, warnings);
}

Model read_deck_string(const std::string& text, const std::string& name, std::vector<DeckWarning>* warnings) {
  return read_blocks(deck::lex_deck_text(text, name, ""), name, warnings);
}

}  // namespace tether
