#pragma once
/// \file The declaration table of deck keywords: name, where it may appear,
/// its parameters (type, default, description) and its handler.
///
/// Adding a keyword is one entry in keyword_table.cpp plus one handler
/// (declared in keyword_handlers.hpp). The dispatcher validates parameters
/// and context from this table, and keyword_reference_markdown() renders it.

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "tether/io/line_reader.hpp"

namespace tether::deck {

struct DeckState;
class ParameterValues;

/// Reads one keyword block into the state. Parameters are already validated.
using Handler = void (*)(DeckState& state, const KeywordBlock& block, const ParameterValues& params);

/// How a parameter's value is written and checked.
enum class ParameterType {
  Flag,     ///< written without a value
  Name,     ///< a set/material/... name, compared upper case
  Text,     ///< free text kept as written (file names)
  Integer,  ///< an integer
  Real,     ///< a floating-point number
  Choice,   ///< one of `choices` (case-insensitive)
};

/// One declared parameter of a keyword.
struct ParameterSpec {
  std::string_view name;                  ///< upper case, e.g. "NSET"
  ParameterType type = ParameterType::Name;
  std::string_view default_value;         ///< used when the parameter is absent ("" = none)
  std::vector<std::string_view> choices;  ///< for Choice
  bool required = false;
  std::string_view flag_value;            ///< Choice that may also be written bare: its meaning then
  std::string_view description;           ///< one sentence
};

/// Where a keyword may appear (bit set).
enum Context : unsigned {
  kModelData = 1,     ///< model data: before the first *STEP
  kMaterial = 2,      ///< directly after *MATERIAL or another material option
  kStep = 4,          ///< inside *STEP ... *END STEP
  kBetweenSteps = 8,  ///< after an *END STEP, outside any step
  kInteraction = 16,  ///< directly after *SURFACE INTERACTION or another interaction option
};

/// One keyword of the table.
struct KeywordSpec {
  std::string_view name;         ///< upper case without '*', e.g. "SOLID SECTION"
  unsigned where = kModelData;   ///< Context bits
  std::string_view description;  ///< one sentence
  std::string_view data;         ///< what the data lines hold ("" = none)
  std::vector<ParameterSpec> parameters;
  Handler handler = nullptr;     ///< nullptr: recognised but not supported yet (or lexer-handled)
  std::string_view not_supported;  ///< non-empty: why/when it is not supported
};

/// The whole table, in documentation order.
const std::vector<KeywordSpec>& keyword_table();

/// The entry for `name` (upper case); throws std::out_of_range if unknown.
const KeywordSpec& find_keyword(std::string_view name);

/// The entry for `name` (upper case) or nullptr.
const KeywordSpec* lookup_keyword(std::string_view name);

/// Human-readable form of a Context bit set ("model data, inside a step").
std::string context_text(unsigned where);

/// The validated parameters of one keyword line. Construction checks every
/// written parameter against the spec (known, value present/absent, type,
/// choice, required, not repeated) and throws InputError at the keyword line.
class ParameterValues {
 public:
  ParameterValues(const KeywordSpec& spec, const KeywordBlock& block);

  /// True when the parameter was written on the line.
  [[nodiscard]] bool given(std::string_view name) const;
  /// Value as written, or the declared default.
  [[nodiscard]] std::string text(std::string_view name) const;
  /// Value upper-cased (names, choices), or the declared default.
  [[nodiscard]] std::string name(std::string_view name) const;
  /// Integer value or default (0 when neither).
  [[nodiscard]] int integer(std::string_view name) const;
  /// Real value or default (0 when neither).
  [[nodiscard]] double real(std::string_view name) const;

 private:
  std::map<std::string, std::string, std::less<>> values_;
  const KeywordSpec* spec_;
  SourceLocation where_;
};

}  // namespace tether::deck
