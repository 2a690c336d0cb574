#pragma once
/// \file Exceptions used across tether.
///
/// User mistakes (bad decks, unsolvable models) are reported with always-on
/// exceptions carrying enough context to act on; programmer errors use
/// debug-only asserts.

#include <stdexcept>
#include <string>

namespace tether {

/// A place in an input deck: file name and 1-based line number (0 = unknown).
struct SourceLocation {
  std::string file;
  int line = 0;

  /// "file:line" or just "file" when the line is unknown.
  [[nodiscard]] std::string str() const {
    return line > 0 ? file + ":" + std::to_string(line) : file;
  }
};

/// `text` with every run of more than 200 non-blank characters cut to its
/// first 60 and a note of its length, so a message quoting a runaway token
/// (a 1 MB "number") stays readable.
inline std::string shorten_long_tokens(const std::string& text) {
  constexpr std::size_t kLong = 200, kKeep = 60;
  std::string out;
  std::size_t i = 0;
  while (i < text.size()) {
    std::size_t j = i;
    while (j < text.size() && text[j] != ' ') ++j;
    if (j - i > kLong)
      out.append(text, i, kKeep).append("...[" + std::to_string(j - i) + " characters]");
    else
      out.append(text, i, j - i);
    if (j < text.size()) out.push_back(' ');
    i = j + 1;
  }
  return out;
}

/// Error in the input deck: the message names the file and line.
class InputError : public std::runtime_error {
 public:
  InputError(SourceLocation where, const std::string& what)
      : std::runtime_error(where.str() + ": error: " + shorten_long_tokens(what)), where_(std::move(where)) {}
  [[nodiscard]] const SourceLocation& where() const { return where_; }

 private:
  SourceLocation where_;
};

/// The model is valid input but cannot be solved as posed (singular system,
/// unsupported combination, ...). The message names the node/dof/element.
class ModelError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The machine refused something the run needs that has nothing to do with
/// the model: a scratch directory that is missing or not writable, a full
/// disk. The message names the resource and what to change.
class ResourceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A linear solve failed (singular or numerically broken matrix).
class SolverError : public std::runtime_error {
 public:
  SolverError(const std::string& what, int equation = -1)
      : std::runtime_error(what), equation_(equation) {}
  /// Equation (reduced row) where the factorization broke down, or -1.
  [[nodiscard]] int equation() const { return equation_; }

 private:
  int equation_;
};

}  // namespace tether
