#pragma once
/// \file Strict number parsing for deck fields, with file:line errors that
/// name the offending token.

#include <string>
#include <string_view>

#include "tether/core/error.hpp"

namespace tether::deck {

/// Parses a real number ("1", "-2.5e3", "1.D0", "+.5"). The whole token must
/// be a finite number; otherwise InputError "bad number 'tok' for <what>".
double parse_real(std::string_view token, const SourceLocation& where, std::string_view what);

/// Parses an integer that fits `int`; otherwise InputError naming the token.
int parse_int(std::string_view token, const SourceLocation& where, std::string_view what);

/// Parses a node or element label: an integer in [1, INT_MAX].
int parse_label(std::string_view token, const SourceLocation& where, std::string_view what);

/// True when the token is written as an integer (optional sign, digits only):
/// distinguishes labels from set names in data lines.
bool is_integer_token(std::string_view token);

/// Upper-case copy.
std::string to_upper(std::string_view text);

/// "%g"-like text of a number (6 significant digits) for messages.
std::string format_number(double v);

/// `v` with 17 significant digits: reads back as the same double.
std::string format_number_exact(double v);

}  // namespace tether::deck
