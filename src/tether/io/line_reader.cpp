#include "tether/io/line_reader.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "tether/io/keyword_table.hpp"

namespace tether::deck {

namespace fs = std::filesystem;

namespace {

std::string_view trim(std::string_view s) {
  const auto not_blank = [](char c) { return !std::isspace(static_cast<unsigned char>(c)); };
  const auto b = std::find_if(s.begin(), s.end(), not_blank);
  const auto e = std::find_if(s.rbegin(), s.rend(), not_blank).base();
  return b < e ? std::string_view(&*b, static_cast<std::size_t>(e - b)) : std::string_view{};
}

std::string unquote(std::string_view s) {
  s = trim(s);
  if (s.size() >= 2 && s.front() == '"' && s.back() == '"') s = s.substr(1, s.size() - 2);
  return std::string(s);
}

bool is_comment(std::string_view line) { return line.size() >= 2 && line[0] == '*' && line[1] == '*'; }

bool is_blank(std::string_view line) { return trim(line).empty(); }

/// `name` without its blanks ("SOLID SECTION" -> "SOLIDSECTION").
std::string without_blanks(std::string_view name) {
  std::string out;
  for (char c : name)
    if (c != ' ') out += c;
  return out;
}

/// The table's spelling of a keyword or parameter name written without some
/// of its blanks (CalculiX removes every blank of a keyword line, so its
/// decks may write *SOLIDSECTION or *ENDSTEP): `name` itself when it is one
/// of `names` or when no name matches it blank for blank.
template <class Names, class NameOf>
std::string canonical_name(const std::string& name, const Names& names, NameOf name_of) {
  const std::string bare = without_blanks(name);
  for (const auto& n : names)
    if (name_of(n) == name) return name;
  for (const auto& n : names)
    if (without_blanks(name_of(n)) == bare) return std::string(name_of(n));
  return name;
}

/// A parameter's name and, for a choice, its value in the table's spelling
/// when written without some of its blanks (TYPE=NODETOSURFACE, as CalculiX
/// reads TYPE=NODE TO SURFACE).
void canonical_parameter(const KeywordSpec& spec, Parameter& p) {
  p.name = canonical_name(p.name, spec.parameters, [](const ParameterSpec& q) { return q.name; });
  const auto it = std::find_if(spec.parameters.begin(), spec.parameters.end(),
                               [&](const ParameterSpec& q) { return q.name == p.name; });
  if (it == spec.parameters.end() || it->type != ParameterType::Choice || !p.has_value) return;
  const std::string value = normalize_name(p.value);
  const std::string choice = canonical_name(value, it->choices, [](std::string_view c) { return c; });
  if (choice != value) p.value = choice;
}

/// Parses a complete keyword line ("*NAME, P1, P2=v").
KeywordBlock parse_keyword_line(std::string_view text, SourceLocation where) {
  const DataFields split = split_data_line(trim(text).substr(1));
  KeywordBlock block;
  block.where = std::move(where);
  if (split.fields.size() == 1 && split.fields[0].empty()) return block;  // a lone '*': the reader skips it
  if (split.fields.empty() || split.fields[0].empty())
    throw InputError(block.where, "empty keyword: expected a keyword name after '*', e.g. *NODE");
  block.keyword = canonical_name(normalize_name(split.fields[0]), keyword_table(),
                                 [](const KeywordSpec& k) { return k.name; });
  const KeywordSpec* spec = lookup_keyword(block.keyword);
  for (std::size_t i = 1; i < split.fields.size(); ++i) {
    const std::string& f = split.fields[i];
    if (f.empty()) continue;
    Parameter p;
    const auto eq = f.find('=');
    if (eq == std::string::npos) {
      p.name = normalize_name(f);
    } else {
      p.name = normalize_name(std::string_view(f).substr(0, eq));
      p.value = unquote(std::string_view(f).substr(eq + 1));
      p.has_value = true;
    }
    if (p.name.empty())
      throw InputError(block.where, "parameter without a name in '" + f + "' on *" + block.keyword);
    if (spec) canonical_parameter(*spec, p);
    block.parameters.push_back(std::move(p));
  }
  return block;
}

class Lexer {
 public:
  explicit Lexer(std::vector<KeywordBlock>& out) : out_(out) {}

  void lex(std::istream& in, const std::string& name, const fs::path& base_dir) {
    auto file = std::make_shared<const std::string>(name);
    std::string line;
    std::string keyword_text;  // keyword line being assembled over continuation lines
    int keyword_line = 0;
    int line_no = 0;
    while (std::getline(in, line)) {
      ++line_no;
      if (!line.empty() && line.back() == '\r') line.pop_back();
      if (is_comment(line) || is_blank(line)) continue;
      const std::string_view t = trim(line);
      if (!keyword_text.empty()) {  // continuation of a keyword line
        keyword_text += ',';
        keyword_text += t;
      } else if (t.front() == '*') {
        keyword_text = std::string(t);
        keyword_line = line_no;
      } else {
        if (out_.empty())
          throw InputError({name, line_no},
                           "data line before any keyword: expected a keyword line starting with '*' "
                           "(e.g. *HEADING or *NODE)");
        out_.back().data.push_back({file, line_no, line});
        continue;
      }
      if (keyword_text.back() == ',') {  // continues on the next line
        keyword_text.pop_back();
        continue;
      }
      finish_keyword(keyword_text, {name, keyword_line}, base_dir);
      keyword_text.clear();
    }
    if (!keyword_text.empty())
      throw InputError({name, keyword_line},
                       "keyword line ends with ',' but the file ends: expected a continuation line");
  }

  std::vector<fs::path> stack_;  ///< canonical paths of the files being read

 private:
  void finish_keyword(const std::string& text, SourceLocation where, const fs::path& base_dir) {
    KeywordBlock block = parse_keyword_line(text, std::move(where));
    if (block.keyword != "INCLUDE") {
      out_.push_back(std::move(block));
      return;
    }
    const ParameterValues params(find_keyword("INCLUDE"), block);
    const fs::path input = params.text("INPUT");
    const fs::path resolved = input.is_absolute() ? input : base_dir / input;
    std::ifstream in(resolved);
    if (!in)
      throw InputError(block.where, "cannot open *INCLUDE file '" + input.string() + "' (looked for '" +
                                        resolved.string() + "')");
    const fs::path canonical = fs::weakly_canonical(resolved);
    if (std::find(stack_.begin(), stack_.end(), canonical) != stack_.end())
      throw InputError(block.where, "recursive *INCLUDE: '" + resolved.string() +
                                        "' is already being read (an included file includes itself)");
    stack_.push_back(canonical);
    lex(in, resolved.string(), resolved.parent_path());
    stack_.pop_back();
  }

  std::vector<KeywordBlock>& out_;
};

}  // namespace

DataFields split_data_line(std::string_view text) {
  DataFields result;
  std::string field;
  bool quoted = false;
  for (char c : text) {
    if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      result.fields.emplace_back(trim(field));
      field.clear();
    } else {
      field += c;
    }
  }
  const std::string_view last = trim(field);
  if (last.empty() && !result.fields.empty())
    result.trailing_comma = true;
  else
    result.fields.emplace_back(last);
  return result;
}

std::string normalize_name(std::string_view text) {
  std::string out;
  bool blank = false;
  for (char c : trim(text)) {
    if (std::isspace(static_cast<unsigned char>(c))) {
      blank = true;
      continue;
    }
    if (blank) out += ' ';
    blank = false;
    out += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  }
  return out;
}

std::vector<KeywordBlock> lex_deck_text(const std::string& text, const std::string& name,
                                        const std::string& base_dir) {
  std::vector<KeywordBlock> blocks;
  Lexer lexer(blocks);
  std::istringstream in(text);
  lexer.lex(in, name, fs::path(base_dir));
  return blocks;
}

std::vector<KeywordBlock> lex_deck_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError({path, 0}, "cannot open deck file '" + path + "'");
  std::vector<KeywordBlock> blocks;
  Lexer lexer(blocks);
  lexer.stack_.push_back(fs::weakly_canonical(path));
  lexer.lex(in, path, fs::path(path).parent_path());
  return blocks;
}

}  // namespace tether::deck
