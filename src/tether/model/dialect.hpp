#pragma once
/// \file Which program's meaning a deck is read with, where ABAQUS and
/// CalculiX give the same data different meanings (docs/keywords.md,
/// section "Dialects").

#include <optional>
#include <string_view>

namespace tether {

/// The dialect a deck is read in (`tether run|check --dialect`).
enum class Dialect {
  Abaqus,    ///< ABAQUS's meaning (the default)
  Calculix,  ///< CalculiX's meaning
};

/// "abaqus" or "calculix".
constexpr std::string_view dialect_name(Dialect d) { return d == Dialect::Calculix ? "calculix" : "abaqus"; }

/// The dialect called `name` (lower case), nullopt for another name.
constexpr std::optional<Dialect> parse_dialect(std::string_view name) {
  if (name == "abaqus") return Dialect::Abaqus;
  if (name == "calculix") return Dialect::Calculix;
  return std::nullopt;
}

/// CalculiX expands an axisymmetric model to a 2° segment (a wedge of 2π/180
/// about the y axis) and prints its forces for that segment: full-circle
/// totals / 180 (dialect calculix: DatWriter, and the areas of node-based
/// slave nodes in contact_builder.cpp).
inline constexpr double kCalculixAxisymmetricSegments = 180;

}  // namespace tether
