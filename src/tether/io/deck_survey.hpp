#pragma once
/// \file What a deck needs that tether refuses: every unknown or unsupported
/// keyword, procedure, parameter, parameter value and element type of a deck,
/// found in one scan of the whole deck (`tether check` over several decks).

#include <string>
#include <string_view>
#include <vector>

#include "tether/core/error.hpp"

namespace tether {

/// One thing a deck uses that tether refuses.
struct Refusal {
  enum class Kind {
    Keyword,         ///< unknown, or recognised but not supported
    Procedure,       ///< a step procedure tether does not have (*DYNAMIC, *FREQUENCY, ...)
    Parameter,       ///< a parameter the keyword does not take
    ParameterValue,  ///< a value not among the parameter's choices
    ElementType,     ///< an *ELEMENT TYPE tether does not have
    Unreadable,      ///< the deck (or an *INCLUDE) cannot be lexed: the message says why
  };
  Kind kind = Kind::Keyword;
  std::string what;  ///< "*DYNAMIC", "*STEP, PERTURBATION", "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TIED", "C3D8"
  SourceLocation where;
};

/// "keyword", "procedure", "parameter", "parameter value", "element type", "unreadable".
std::string_view refusal_kind_name(Refusal::Kind kind);

/// Every refusal of the deck at `path`, in deck order, one per occurrence.
/// Only what the keyword table decides is surveyed (names, parameters,
/// choices, element types); data lines and the model are not checked here,
/// so an empty list does not mean the deck reads: read_deck() says that.
/// A deck that cannot be lexed gives one Unreadable refusal.
std::vector<Refusal> survey_deck(const std::string& path);

}  // namespace tether
