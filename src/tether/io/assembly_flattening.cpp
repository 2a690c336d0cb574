#include "tether/io/assembly_flattening.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <limits>
#include <set>

#include "tether/io/numbers.hpp"

namespace tether::deck {

namespace {

/// The value of parameter `name` (upper case) on a block, "" when absent.
std::string parameter(const KeywordBlock& b, std::string_view name) {
  for (const Parameter& p : b.parameters)
    if (p.name == name) return p.value;
  return "";
}

bool has_parameter(const KeywordBlock& b, std::string_view name) {
  for (const Parameter& p : b.parameters)
    if (p.name == name) return true;
  return false;
}

/// Translation, then rotation about z through `pivot` by `angle` [rad].
struct Placement {
  Eigen::Vector2d translation = Eigen::Vector2d::Zero();
  Eigen::Vector2d pivot = Eigen::Vector2d::Zero();
  double angle = 0;
  [[nodiscard]] Eigen::Vector2d apply(const Eigen::Vector2d& x) const {
    const Eigen::Vector2d t = x + translation - pivot;
    const double c = std::cos(angle), s = std::sin(angle);
    return pivot + Eigen::Vector2d(c * t.x() - s * t.y(), s * t.x() + c * t.y());
  }
};

std::vector<double> numbers(const DataLine& line, std::size_t count, std::string_view what) {
  std::vector<std::string> f = split_data_line(line.text).fields;
  while (f.size() > count && f.back().empty()) f.pop_back();
  if (f.size() > count)
    throw InputError(line.where(), "expected " + std::string(what) + " but found '" + line.text + "'");
  std::vector<double> v(count, 0.0);
  for (std::size_t i = 0; i < f.size(); ++i)
    if (!f[i].empty()) v[i] = parse_real(f[i], line.where(), std::string(what));
  return v;
}

Placement placement(const KeywordBlock& instance) {
  Placement p;
  if (instance.data.size() > 2)
    throw InputError(instance.data[2].where(), "*INSTANCE has at most two data lines: the translation `dx, dy, dz` "
                                               "and the rotation `ax, ay, az, bx, by, bz, angle`");
  if (!instance.data.empty()) {
    const auto t = numbers(instance.data[0], 3, "a translation `dx, dy, dz`");
    if (t[2] != 0)
      throw InputError(instance.data[0].where(), "*INSTANCE translation along z: a 2D model stays in its plane");
    p.translation = {t[0], t[1]};
  }
  if (instance.data.size() == 2) {
    const auto r = numbers(instance.data[1], 7, "a rotation `ax, ay, az, bx, by, bz, angle`");
    if (r[0] != r[3] || r[1] != r[4] || r[2] == r[5])
      throw InputError(instance.data[1].where(), "*INSTANCE rotation axis from (" + format_number(r[0]) + ", " +
                                                     format_number(r[1]) + ", " + format_number(r[2]) + ") to (" +
                                                     format_number(r[3]) + ", " + format_number(r[4]) + ", " +
                                                     format_number(r[5]) + ") is not along z: a 2D model can only "
                                                     "rotate in its plane");
    p.pivot = {r[0], r[1]};
    p.angle = (r[5] > r[2] ? 1 : -1) * r[6] * std::numbers::pi / 180;
  }
  return p;
}

/// `NAME` qualified by the instance, unless it already names one (`I.NAME`)
/// or is a label.
std::string qualified(const std::string& instance, const std::string& name) {
  if (name.empty() || is_integer_token(name) || name.find('.') != std::string::npos) return name;
  return instance + "." + name;
}

/// The data line rebuilt from its fields (a trailing ',' kept: it continues an *ELEMENT line).
std::string joined(const DataFields& d) {
  std::string text;
  for (std::size_t i = 0; i < d.fields.size(); ++i) text += (i ? ", " : "") + d.fields[i];
  return d.trailing_comma ? text + "," : text;
}

/// `label + offset` for an integer field; other fields unchanged.
void shift(std::string& field, int offset, const SourceLocation& at) {
  if (is_integer_token(field)) field = std::to_string(parse_label(field, at, "label") + offset);
}

/// The node and element labels of a part's block moved by `offset`: *NODE
/// labels, *ELEMENT labels and nodes, *NSET/*ELSET members (GENERATE: first
/// and last), element labels of *SURFACE lines.
void shift_labels(KeywordBlock& b, int offset) {
  const std::string& k = b.keyword;
  if (offset == 0 || (k != "NODE" && k != "ELEMENT" && k != "NSET" && k != "ELSET" && k != "SURFACE")) return;
  const bool generate = has_parameter(b, "GENERATE");
  for (DataLine& line : b.data) {
    DataFields d = split_data_line(line.text);
    std::size_t n = d.fields.size();
    if (k == "NODE" || k == "SURFACE") n = std::min<std::size_t>(n, 1);
    if (generate) n = std::min<std::size_t>(n, 2);
    for (std::size_t i = 0; i < n; ++i) shift(d.fields[i], offset, line.where());
    line.text = joined(d);
  }
}

/// Data fields that are names (not labels) qualified: *NSET/*ELSET members and
/// the first field of *SURFACE lines.
void qualify_data(KeywordBlock& b, const std::string& instance) {
  const bool sets = (b.keyword == "NSET" || b.keyword == "ELSET") && !has_parameter(b, "GENERATE");
  if (!sets && b.keyword != "SURFACE") return;
  for (DataLine& line : b.data) {
    std::vector<std::string> f = split_data_line(line.text).fields;
    const std::size_t n = sets ? f.size() : std::min<std::size_t>(1, f.size());
    for (std::size_t i = 0; i < n; ++i) f[i] = qualified(instance, f[i]);
    line.text = joined({f, split_data_line(line.text).trailing_comma});
  }
}

/// The blocks of one instance: the part's blocks with names qualified and nodes placed.
void emit_instance(const std::vector<KeywordBlock>& part, const std::string& instance, const Placement& place,
                   int offset, std::vector<KeywordBlock>& out) {
  for (KeywordBlock b : part) {
    shift_labels(b, offset);
    for (Parameter& p : b.parameters)
      if (p.name == "NSET" || p.name == "ELSET" || (p.name == "NAME" && b.keyword == "SURFACE"))
        p.value = qualified(instance, p.value);
    qualify_data(b, instance);
    if (b.keyword == "NODE")
      for (DataLine& line : b.data) {
        std::vector<std::string> f = split_data_line(line.text).fields;
        if (f.size() < 2) continue;  // the reader reports it
        Eigen::Vector2d x(f[1].empty() ? 0.0 : parse_real(f[1], line.where(), "x coordinate"),
                          f.size() < 3 || f[2].empty() ? 0.0 : parse_real(f[2], line.where(), "y coordinate"));
        x = place.apply(x);
        line.text = f[0] + ", " + format_number_exact(x.x()) + ", " + format_number_exact(x.y());
      }
    out.push_back(std::move(b));
  }
}

class Flattener {
 public:
  std::vector<KeywordBlock> run(std::vector<KeywordBlock> blocks) {
    for (KeywordBlock& b : blocks) step(std::move(b));
    if (part_) throw InputError(part_where_, "*PART " + part_name_ + " is not closed: expected *END PART");
    if (in_assembly_) throw InputError(assembly_where_, "*ASSEMBLY is not closed: expected *END ASSEMBLY");
    return std::move(out_);
  }

  /// The instances placed, with their label offsets.
  [[nodiscard]] const std::vector<PartInstance>& instances() const { return instances_; }

 private:
  void step(KeywordBlock b) {
    const std::string& k = b.keyword;
    if (k == "PART") return open_part(b);
    if (k == "END PART") return close_part(b);
    if (part_) return parts_[part_name_].push_back(std::move(b));
    if (k == "ASSEMBLY") {
      in_assembly_ = true;
      assembly_where_ = b.where;
      return;
    }
    if (k == "END ASSEMBLY") {
      in_assembly_ = false;
      return;
    }
    if (k == "INSTANCE") return instance(b);
    if (k == "END INSTANCE") return;
    if (in_assembly_ && (k == "NSET" || k == "ELSET") && has_parameter(b, "INSTANCE")) {
      const std::string instance = normalize_name(parameter(b, "INSTANCE"));
      const PartInstance* placed = find_instance(instance);
      if (!placed)
        throw InputError(b.where, "INSTANCE=" + instance + " on *" + k + " names no *INSTANCE placed before it");
      std::erase_if(b.parameters, [](const Parameter& p) { return p.name == "INSTANCE"; });
      shift_labels(b, placed->offset);
      qualify_data(b, instance);
    } else {
      resolve_qualified_labels(b);
    }
    out_.push_back(std::move(b));
  }

  void open_part(const KeywordBlock& b) {
    if (part_) throw InputError(b.where, "*PART inside *PART " + part_name_ + ": expected *END PART first");
    part_name_ = normalize_name(parameter(b, "NAME"));
    if (part_name_.empty()) throw InputError(b.where, "*PART needs NAME=");
    if (parts_.count(part_name_)) throw InputError(b.where, "*PART " + part_name_ + " is defined twice");
    parts_[part_name_];
    part_ = true;
    part_where_ = b.where;
  }

  void close_part(const KeywordBlock& b) {
    if (!part_) throw InputError(b.where, "*END PART without *PART");
    part_ = false;
  }

  void instance(const KeywordBlock& b) {
    const std::string name = normalize_name(parameter(b, "NAME")), part = normalize_name(parameter(b, "PART"));
    if (name.empty() || part.empty())
      throw InputError(b.where, "*INSTANCE needs NAME= and PART= (an instance of a part defined by *PART)");
    const auto it = parts_.find(part);
    if (it == parts_.end())
      throw InputError(b.where, "*INSTANCE " + name + " of undefined part " + part + ": expected a *PART, NAME=" +
                                    part + " before the assembly");
    if (find_instance(name)) throw InputError(b.where, "*INSTANCE " + name + " is defined twice");
    const auto [low, high] = label_range(it->second);
    PartInstance placed{name, label_offset(low, high), 0, 0};
    placed.first = low + placed.offset;
    placed.last = high + placed.offset;
    if (placed.offset != 0) refuse_unmovable_labels(it->second, name);
    if (low <= high) instances_.push_back(placed);
    emit_instance(it->second, name, placement(b), placed.offset, out_);
  }

  /// A moved instance may only copy part blocks whose labels shift_labels() moves (or that hold none).
  static void refuse_unmovable_labels(const std::vector<KeywordBlock>& part, const std::string& instance) {
    for (const KeywordBlock& b : part) {
      const std::string& k = b.keyword;
      if (k == "NODE" || k == "ELEMENT" || k == "NSET" || k == "ELSET" || k == "SURFACE" || k == "SOLID SECTION")
        continue;
      throw InputError(b.where, "*" + k + " inside a *PART instanced more than once: instance " + instance +
                                    " gets new labels, and tether moves the labels of *NODE, *ELEMENT, *NSET, "
                                    "*ELSET and *SURFACE only; expected *" + k + " in the assembly or the model "
                                    "data, naming nodes as Instance.label or by instance-qualified sets");
    }
  }

  const PartInstance* find_instance(const std::string& name) const {
    for (const PartInstance& i : instances_)
      if (i.name == name) return &i;
    return nullptr;
  }

  /// Smallest and largest node or element label of a part (low > high when it has none).
  static std::pair<int, int> label_range(const std::vector<KeywordBlock>& part) {
    int low = std::numeric_limits<int>::max(), high = std::numeric_limits<int>::min();
    for (const KeywordBlock& b : part) {
      if (b.keyword != "NODE" && b.keyword != "ELEMENT") continue;
      bool continuation = false;  // an *ELEMENT line continued from the previous one starts with a node
      for (const DataLine& line : b.data) {
        const DataFields split = split_data_line(line.text);
        const bool skip = continuation;
        continuation = b.keyword == "ELEMENT" && split.trailing_comma;
        if (skip || split.fields.empty() || !is_integer_token(split.fields[0])) continue;
        const int label = parse_label(split.fields[0], line.where(), b.keyword == "NODE" ? "node label" : "element label");
        low = std::min(low, label), high = std::max(high, label);
      }
    }
    return {low, high};
  }

  /// 0 when [low, high] is free of earlier instances' labels; else the smallest
  /// multiple of 10^d (10^d > high) that moves the range past every label used.
  int label_offset(int low, int high) const {
    if (low > high) return 0;
    int used = 0;
    bool overlap = false;
    for (const PartInstance& i : instances_) {
      used = std::max(used, i.last);
      overlap = overlap || (low <= i.last && i.first <= high);
    }
    if (!overlap) return 0;
    long long round = 10;
    while (round <= high) round *= 10;
    const long long offset = (static_cast<long long>(used) - low + round) / round * round;
    if (offset + high > std::numeric_limits<int>::max())
      throw InputError(part_where_, "node and element labels of the instances do not fit in an int");
    return static_cast<int>(offset);
  }

  /// Data fields `INSTANCE.label` (a node or element of a placed instance, as
  /// ABAQUS writes them in assembly and history data) replaced by the internal label.
  void resolve_qualified_labels(KeywordBlock& b) const {
    if (instances_.empty()) return;
    for (DataLine& line : b.data) {
      DataFields d = split_data_line(line.text);
      bool changed = false;
      for (std::string& f : d.fields) {
        const auto dot = f.rfind('.');
        if (dot == std::string::npos || dot + 1 == f.size() || !is_integer_token(f.substr(dot + 1))) continue;
        const PartInstance* i = find_instance(normalize_name(f.substr(0, dot)));
        if (!i) continue;
        const int label = parse_label(f.substr(dot + 1), line.where(), "label");
        if (label + i->offset < i->first || label + i->offset > i->last)
          throw InputError(line.where(), "undefined node or element " + i->name + "." + std::to_string(label) +
                                             ": instance " + i->name + " has the labels " +
                                             std::to_string(i->first - i->offset) + "-" +
                                             std::to_string(i->last - i->offset) + " of its part");
        f = std::to_string(label + i->offset);
        changed = true;
      }
      if (changed) line.text = joined(d);
    }
  }

  std::map<std::string, std::vector<KeywordBlock>> parts_;
  std::vector<PartInstance> instances_;
  std::vector<KeywordBlock> out_;
  bool part_ = false, in_assembly_ = false;
  std::string part_name_;
  SourceLocation part_where_, assembly_where_;
};

}  // namespace

bool is_assembly_keyword(std::string_view keyword) {
  return keyword == "PART" || keyword == "END PART" || keyword == "ASSEMBLY" || keyword == "END ASSEMBLY" ||
         keyword == "INSTANCE" || keyword == "END INSTANCE";
}

std::vector<KeywordBlock> flatten_assembly(std::vector<KeywordBlock> blocks, std::vector<PartInstance>* instances) {
  const bool cae =
      std::any_of(blocks.begin(), blocks.end(), [](const KeywordBlock& b) { return is_assembly_keyword(b.keyword); });
  if (!cae) return blocks;
  Flattener flattener;
  blocks = flattener.run(std::move(blocks));
  if (instances) *instances = flattener.instances();
  return blocks;
}

}  // namespace tether::deck
