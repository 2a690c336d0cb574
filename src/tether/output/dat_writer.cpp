#include "tether/output/dat_writer.hpp"

#include <fmt/format.h>

#include <cctype>
#include <iterator>
#include <numeric>
#include <stdexcept>
#include <string>

#include "tether/core/error.hpp"
#include "tether/output/fortran_format.hpp"
#include "tether/output/output_schedule.hpp"

namespace tether {

namespace {

using Out = std::back_insert_iterator<std::string>;

/// -0.0 prints as 0.0 (x + 0.0 is +0.0 for x = -0.0 under round-to-nearest).
double unsigned_zero(double x) { return x + 0.0; }

bool is_print(const OutputRequest& r) {
  return r.kind == OutputRequest::Kind::NodePrint || r.kind == OutputRequest::Kind::ElementPrint;
}

/// Node or element indices the request covers, and the set name to print.
struct Selection {
  std::string name;
  std::vector<int> indices;
};

Selection select(const Model& model, const OutputRequest& r) {
  const bool nodal = r.kind == OutputRequest::Kind::NodePrint;
  Selection s;
  if (r.set.empty()) {
    s.name = nodal ? "NALL" : "EALL";
    s.indices.resize(static_cast<std::size_t>(nodal ? model.n_nodes() : model.n_elements()));
    std::iota(s.indices.begin(), s.indices.end(), 0);
    return s;
  }
  const auto& sets = nodal ? model.node_sets : model.element_sets;
  s.name = r.set;
  s.indices = sets.at(r.set);
  return s;
}

/// " and time  0.1000000E+01" (ccx: ' and time ',e14.7).
std::string time_suffix(double time) { return fmt::format(" and time {:>14}", fortran_e(time, 7)); }

void write_header(Out out, std::string_view what, const std::string& set, double time) {
  fmt::format_to(out, "\n {} for set {}{}\n\n", what, set, time_suffix(time));
}

void write_nodal(Out out, const Model& model, const Selection& sel, const std::vector<Eigen::Vector2d>& v,
                 std::string_view what, bool rows, bool totals, double time) {
  if (v.size() != static_cast<std::size_t>(model.n_nodes()))
    throw std::invalid_argument(fmt::format("DatWriter: {} needs {} nodal values, results have {}", what,
                                            model.n_nodes(), v.size()));
  if (rows) {
    write_header(out, what, sel.name, time);
    for (const int i : sel.indices)
      fmt::format_to(out, "{:10d} {:13.6E} {:13.6E} {:13.6E}\n", model.node_ids[static_cast<std::size_t>(i)],
                     unsigned_zero(v[static_cast<std::size_t>(i)].x()),
                     unsigned_zero(v[static_cast<std::size_t>(i)].y()), 0.0);
  }
  if (totals) {
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    for (const int i : sel.indices) sum += v[static_cast<std::size_t>(i)];
    write_header(out, "total force (fx,fy,fz)", sel.name, time);
    fmt::format_to(out, "       {:13.6E} {:13.6E} {:13.6E}\n", unsigned_zero(sum.x()), unsigned_zero(sum.y()), 0.0);
  }
}

void write_points(Out out, const Model& model, const Selection& sel, const IncrementResults& r, bool stress) {
  if (r.points.size() != static_cast<std::size_t>(model.n_elements()))
    throw std::invalid_argument(fmt::format("DatWriter: EL PRINT needs integration-point values for {} elements, "
                                            "results have {}",
                                            model.n_elements(), r.points.size()));
  write_header(out,
               stress ? "stresses (elem, integ.pnt.,sxx,syy,szz,sxy,sxz,syz)"
                      : "strains (elem, integ.pnt.,exx,eyy,ezz,exy,exz,eyz)",
               sel.name, r.total_time);
  for (const int e : sel.indices) {
    const auto& points = r.points[static_cast<std::size_t>(e)];
    const int label = model.elements[static_cast<std::size_t>(e)].id;
    for (std::size_t k = 0; k < points.size(); ++k) {
      const Tensor4& t = stress ? points[k].stress : points[k].strain;
      fmt::format_to(out, "{:10d}{:4d} {:13.6E} {:13.6E} {:13.6E} {:13.6E} {:13.6E} {:13.6E}\n", label, k + 1,
                     unsigned_zero(t[0]), unsigned_zero(t[1]), unsigned_zero(t[2]), unsigned_zero(t[3]), 0.0, 0.0);
    }
  }
}

}  // namespace

std::string multiplier_set_name(const std::string& owner, int number) {
  std::string name;
  for (const char c : owner) name += std::isspace(static_cast<unsigned char>(c)) ? '_' : c;
  return name.empty() ? fmt::format("C{}", number) : name;
}

void write_multiplier_blocks(std::string& text, const std::vector<MultiplierValues>& multipliers, double time) {
  const auto out = std::back_inserter(text);
  for (std::size_t c = 0; c < multipliers.size(); ++c) {
    const MultiplierValues& m = multipliers[c];
    if (m.value.empty()) continue;
    if (m.constraint.size() != m.value.size())
      throw std::invalid_argument(fmt::format("DatWriter: constraint '{}' has {} multipliers but {} values of f",
                                              m.owner, m.value.size(), m.constraint.size()));
    const int number = static_cast<int>(c) + 1;
    write_header(out, kMultiplierTitle, multiplier_set_name(m.owner, number), time);
    for (std::size_t k = 0; k < m.value.size(); ++k)
      fmt::format_to(out, "{:10d}{:5d} {:13.6E} {:13.6E}\n", number, k + 1, unsigned_zero(m.constraint[k]),
                     unsigned_zero(m.value[k]));
  }
}

DatWriter::DatWriter(const Model& model, std::filesystem::path file)
    : model_(model), file_(std::move(file)), out_(file_, std::ios::binary | std::ios::trunc) {
  if (!out_) throw std::runtime_error("cannot create '" + file_.string() + "'");
}

void DatWriter::check(const Model& model, const OutputRequest& r) {
  if (!is_print(r)) return;
  const bool nodal = r.kind == OutputRequest::Kind::NodePrint;
  const char* keyword = nodal ? "*NODE PRINT" : "*EL PRINT";
  if (!r.set.empty()) {
    const auto& sets = nodal ? model.node_sets : model.element_sets;
    if (sets.find(r.set) == sets.end())
      throw InputError(r.where, fmt::format("{}: {} set '{}' is not defined", keyword, nodal ? "node" : "element",
                                            r.set));
  }
  for (const auto& v : r.variables) {
    const bool ok = nodal ? (v == "U" || v == "RF") : (v == "S" || v == "E");
    if (!ok)
      throw InputError(r.where, fmt::format("{}: variable '{}' cannot be printed (tether prints {})", keyword, v,
                                            nodal ? "U and RF" : "S and E"));
  }
}

void DatWriter::write_increment(const IncrementResults& results, const std::vector<OutputRequest>& requests,
                                bool last_in_step) {
  for (const auto& r : requests) check(model_, r);
  std::string text;
  const auto out = std::back_inserter(text);
  for (const auto& r : requests) {
    if (!is_print(r) || !is_due(r, results.increment, last_in_step)) continue;
    const Selection sel = select(model_, r);
    for (const auto& v : r.variables) {
      if (v == "U")
        write_nodal(out, model_, sel, results.displacement, "displacements (vx,vy,vz)", true, false,
                    results.total_time);
      else if (v == "RF")
        write_nodal(out, model_, sel, results.reaction, "forces (fx,fy,fz)", !r.totals_only,
                    r.totals || r.totals_only, results.total_time);
      else if (v == "S" || v == "E")
        write_points(out, model_, sel, results, v == "S");
    }
  }
  write_multiplier_blocks(text, results.multipliers, results.total_time);
  out_ << text;
  out_.flush();
  if (!out_) throw std::runtime_error("error while writing '" + file_.string() + "' (disk full?)");
}

}  // namespace tether
