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

/// Error in the input deck: the message names the file and line.
class InputError : public std::runtime_error {
 public:
  InputError(SourceLocation where, const std::string& what)
      : std::runtime_error(where.str() + ": error: " + what), where_(std::move(where)) {}
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
