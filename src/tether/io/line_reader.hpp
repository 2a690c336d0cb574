#pragma once
/// \file Lexer for `.inp` decks: comments, blank lines, keyword continuation
/// lines, parameters and `*INCLUDE`.
///
/// The deck becomes a list of keyword blocks (a keyword line plus the data
/// lines below it). `*INCLUDE` is expanded transparently: an included file
/// may contain only data lines that continue the including block.

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "tether/core/error.hpp"

namespace tether::deck {

/// One `NAME[=value]` parameter of a keyword line.
struct Parameter {
  std::string name;        ///< upper case, inner blanks collapsed: "NEO HOOKE"
  std::string value;       ///< as written, trimmed, quotes removed; empty if absent
  bool has_value = false;  ///< an `=` was written
};

/// A data line: where it is and its raw text.
struct DataLine {
  std::shared_ptr<const std::string> file;  ///< file name for messages (shared by all its lines)
  int line = 0;                             ///< 1-based line number
  std::string text;                         ///< raw text, trailing CR removed

  /// file:line of this data line.
  [[nodiscard]] SourceLocation where() const { return {*file, line}; }
};

/// A keyword line (continuations joined) and the data lines that follow it.
struct KeywordBlock {
  std::string keyword;               ///< upper case without '*', inner blanks collapsed: "SOLID SECTION"; empty for a lone '*' line
  std::vector<Parameter> parameters; ///< in the order written
  SourceLocation where;              ///< the keyword line (its first line)
  std::vector<DataLine> data;
};

/// A data line split at commas: fields trimmed, quotes removed.
struct DataFields {
  std::vector<std::string> fields;  ///< empty strings for empty fields
  bool trailing_comma = false;      ///< the line ended with ',' (that last empty field is dropped)
};

/// Splits a data (or keyword) line at commas outside double quotes.
DataFields split_data_line(std::string_view text);

/// Upper-cases and collapses runs of blanks to one space, trimming the ends.
std::string normalize_name(std::string_view text);

/// Lexes deck text. `name` is the file name used in messages; `*INCLUDE`
/// paths are relative to `base_dir` (empty = current directory).
std::vector<KeywordBlock> lex_deck_text(const std::string& text, const std::string& name,
                                        const std::string& base_dir);

/// Lexes the deck file at `path`; includes are relative to its directory.
std::vector<KeywordBlock> lex_deck_file(const std::string& path);

}  // namespace tether::deck
