#include "tether/io/reading_order.hpp"

#include <algorithm>
#include <string_view>

#include "tether/io/keyword_table.hpp"

namespace tether::deck {

namespace {

/// Reading group of a keyword: lower groups are read first (CalculiX's order).
int reading_group(std::string_view keyword) {
  struct Group {
    std::string_view keyword;
    int group;
  };
  static constexpr Group kGroups[] = {
      {"NODE", 1},      {"ELEMENT", 2},          {"NSET", 3},          {"ELSET", 4},
      {"SURFACE", 5},   {"MATERIAL", 6},         {"TIE", 7},           {"SURFACE INTERACTION", 8},
      {"INITIAL CONDITIONS", 9}, {"AMPLITUDE", 10}, {"CONTACT PAIR", 11},
  };
  constexpr int kEverythingElse = 12;
  for (const Group& g : kGroups)
    if (g.keyword == keyword) return g.group;
  // Options of a material or an interaction travel with the keyword that starts them.
  if (const KeywordSpec* spec = lookup_keyword(keyword)) {
    if (spec->where == kMaterial) return 6;
    if (spec->where == kInteraction) return 8;
  }
  return kEverythingElse;
}

}  // namespace

std::vector<std::size_t> reading_order(const std::vector<KeywordBlock>& blocks) {
  std::vector<int> group(blocks.size());
  for (std::size_t i = 0; i < blocks.size(); ++i) group[i] = reading_group(blocks[i].keyword);
  std::vector<std::size_t> order(blocks.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return group[a] < group[b]; });
  return order;
}

}  // namespace tether::deck
