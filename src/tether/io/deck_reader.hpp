#pragma once
/// \file Reader for ABAQUS/CalculiX `.inp` decks (the subset tether supports).
///
/// The reader lexes the deck (comments, continuation lines, `*INCLUDE`),
/// dispatches every keyword to its handler through one declaration table
/// (keyword_table.hpp), resolves the step-by-step boundary-condition and load
/// lists, and validates the model. Every user mistake is an InputError whose
/// message starts with `file:line: error:` and says what was expected.

#include <string>
#include <vector>

#include "tether/core/error.hpp"
#include "tether/model/model.hpp"

namespace tether {

/// Something the reader accepted but ignored or reinterpreted, where ABAQUS
/// itself would also carry on (e.g. an out-of-plane dof 3 boundary condition).
struct DeckWarning {
  SourceLocation where;  ///< deck line the warning is about
  std::string message;   ///< one sentence, no file:line prefix
};

/// Reads and validates the deck at `path` (includes resolved relative to the
/// including file) with the meanings of `dialect` where ABAQUS and CalculiX
/// differ (Model::dialect records it). Throws InputError (file:line + what was
/// expected) on any error. Warnings are appended to `*warnings` when it is given.
Model read_deck(const std::string& path, std::vector<DeckWarning>* warnings = nullptr,
                Dialect dialect = Dialect::Abaqus);

/// Same as read_deck(), from a string; `name` is the file name used in
/// messages and `*INCLUDE` paths are relative to the current directory.
Model read_deck_string(const std::string& text, const std::string& name,
                       std::vector<DeckWarning>* warnings = nullptr, Dialect dialect = Dialect::Abaqus);

/// Markdown reference of every keyword and parameter the reader knows,
/// generated from the reader's own declaration table (docs/keywords.md).
std::string keyword_reference_markdown();

}  // namespace tether
