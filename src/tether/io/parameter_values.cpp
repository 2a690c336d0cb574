// Validation of keyword-line parameters against the declaration table.
#include <algorithm>

#include "tether/io/keyword_table.hpp"
#include "tether/io/numbers.hpp"

namespace tether::deck {

namespace {

std::string allowed_list(const KeywordSpec& spec) {
  if (spec.parameters.empty()) return "none";
  std::string out;
  for (const ParameterSpec& p : spec.parameters) out += (out.empty() ? "" : ", ") + std::string(p.name);
  return out;
}

std::string choices_list(const ParameterSpec& p) {
  std::string out;
  for (std::string_view c : p.choices) out += (out.empty() ? "" : ", ") + std::string(c);
  return out;
}

const ParameterSpec* find_parameter(const KeywordSpec& spec, std::string_view name) {
  for (const ParameterSpec& p : spec.parameters)
    if (p.name == name) return &p;
  return nullptr;
}

}  // namespace

ParameterValues::ParameterValues(const KeywordSpec& spec, const KeywordBlock& block)
    : spec_(&spec), where_(block.where) {
  // Appended, not "*" + std::string(...): GCC 12 -O2 reports a false -Wrestrict
  // on operator+(const char*, std::string&&) (it inlines to an insert at 0).
  std::string kw = "*";
  kw += spec.name;
  for (const Parameter& given : block.parameters) {
    const ParameterSpec* p = find_parameter(spec, given.name);
    if (!p)
      throw InputError(where_, "unknown parameter " + given.name + " on " + kw +
                                   ": expected one of: " + allowed_list(spec));
    if (values_.count(given.name))
      throw InputError(where_, "parameter " + given.name + " given twice on " + kw);
    std::string value = given.value;
    switch (p->type) {
      case ParameterType::Flag:
        if (given.has_value)
          throw InputError(where_, "parameter " + given.name + " on " + kw + " takes no value (found '=" +
                                       given.value + "')");
        break;
      case ParameterType::Choice:
        if (!given.has_value && !p->flag_value.empty()) {
          value = std::string(p->flag_value);
          break;
        }
        value = normalize_name(value);
        if (std::find(p->choices.begin(), p->choices.end(), value) == p->choices.end())
          throw InputError(where_, "bad value '" + given.value + "' for " + given.name + " on " + kw +
                                       ": expected one of: " + choices_list(*p));
        break;
      case ParameterType::Integer:
        if (!given.has_value) throw InputError(where_, given.name + " on " + kw + " needs a value: expected " +
                                                           given.name + "=<integer>");
        parse_int(value, where_, given.name + " on " + kw);
        break;
      case ParameterType::Real:
        if (!given.has_value) throw InputError(where_, given.name + " on " + kw + " needs a value: expected " +
                                                           given.name + "=<number>");
        parse_real(value, where_, given.name + " on " + kw);
        break;
      case ParameterType::Name:
      case ParameterType::Text:
        if (!given.has_value || value.empty())
          throw InputError(where_, given.name + " on " + kw + " needs a value: expected " + given.name +
                                       "=<name>");
        break;
    }
    values_.emplace(given.name, std::move(value));
  }
  for (const ParameterSpec& p : spec.parameters)
    if (p.required && !values_.count(p.name))
      throw InputError(where_, kw + " requires the parameter " + std::string(p.name) + " (" +
                                   std::string(p.description) + ")");
}

bool ParameterValues::given(std::string_view name) const { return values_.find(name) != values_.end(); }

std::string ParameterValues::text(std::string_view name) const {
  const auto it = values_.find(name);
  if (it != values_.end()) return it->second;
  const ParameterSpec* p = find_parameter(*spec_, name);
  return p ? std::string(p->default_value) : std::string();
}

std::string ParameterValues::name(std::string_view name) const { return to_upper(text(name)); }

int ParameterValues::integer(std::string_view name) const {
  const std::string t = text(name);
  return t.empty() ? 0 : parse_int(t, where_, name);
}

double ParameterValues::real(std::string_view name) const {
  const std::string t = text(name);
  return t.empty() ? 0.0 : parse_real(t, where_, name);
}

}  // namespace tether::deck
