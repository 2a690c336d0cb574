#include "tether/io/deck_survey.hpp"

#include <algorithm>

#include "tether/io/assembly_flattening.hpp"
#include "tether/io/keyword_table.hpp"
#include "tether/io/line_reader.hpp"
#include "tether/model/element_type.hpp"

namespace tether {

namespace {

using deck::KeywordBlock;
using deck::KeywordSpec;
using deck::ParameterSpec;

const ParameterSpec* find_parameter(const KeywordSpec& spec, std::string_view name) {
  for (const ParameterSpec& p : spec.parameters)
    if (p.name == name) return &p;
  return nullptr;
}

/// A keyword tether recognises but does not support is a procedure when its
/// table entry describes one (and it stands in a step).
bool is_procedure(const KeywordSpec& spec) {
  return (spec.where & deck::kStep) && spec.description.find("procedure") != std::string_view::npos;
}

void survey_block(const KeywordBlock& block, std::vector<Refusal>& out) {
  const std::string kw = "*" + block.keyword;
  const KeywordSpec* spec = deck::lookup_keyword(block.keyword);
  if (!spec) {
    out.push_back({Refusal::Kind::Keyword, kw, block.where});
    return;
  }
  if (!spec->handler && spec->name != "INCLUDE" && !deck::is_assembly_keyword(spec->name)) {
    out.push_back({is_procedure(*spec) ? Refusal::Kind::Procedure : Refusal::Kind::Keyword, kw, block.where});
    return;
  }
  for (const deck::Parameter& given : block.parameters) {
    const ParameterSpec* p = find_parameter(*spec, given.name);
    if (!p) {
      out.push_back({Refusal::Kind::Parameter, kw + ", " + given.name, block.where});
      continue;
    }
    if (p->type != deck::ParameterType::Choice || (!given.has_value && !p->flag_value.empty())) continue;
    const std::string value = deck::normalize_name(given.value);
    if (std::find(p->choices.begin(), p->choices.end(), value) == p->choices.end())
      out.push_back({Refusal::Kind::ParameterValue, kw + ", " + given.name + "=" + value, block.where});
  }
  if (block.keyword == "ELEMENT")
    for (const deck::Parameter& given : block.parameters) {
      if (given.name != "TYPE") continue;
      const std::string type = deck::normalize_name(given.value);
      if (line_element_nodes(type) > 0) continue;  // line elements only name faces
      const auto t = find_element_type(type);
      if (!t || !unsupported_reason(*t).empty()) out.push_back({Refusal::Kind::ElementType, type, block.where});
    }
}

}  // namespace

std::string_view refusal_kind_name(Refusal::Kind kind) {
  switch (kind) {
    case Refusal::Kind::Keyword: return "keyword";
    case Refusal::Kind::Procedure: return "procedure";
    case Refusal::Kind::Parameter: return "parameter";
    case Refusal::Kind::ParameterValue: return "parameter value";
    case Refusal::Kind::ElementType: return "element type";
    case Refusal::Kind::Unreadable: return "unreadable";
  }
  return "";
}

std::vector<Refusal> survey_deck(const std::string& path) {
  std::vector<KeywordBlock> blocks;
  try {
    blocks = deck::lex_deck_file(path);
  } catch (const InputError& e) {
    return {{Refusal::Kind::Unreadable, e.what(), e.where()}};
  }
  std::vector<Refusal> out;
  for (const KeywordBlock& block : blocks)
    if (!block.keyword.empty()) survey_block(block, out);
  return out;
}

}  // namespace tether
