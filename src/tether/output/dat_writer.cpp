#include "tether/output/dat_writer.hpp"
#include "tether/output/pretension_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <iterator>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>

#include "tether/core/error.hpp"
#include "tether/fem/shape_functions.hpp"
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

bool is_contact_print(const OutputRequest& r) { return r.kind == OutputRequest::Kind::ContactPrint; }

constexpr std::array<std::string_view, 7> kContactPrintVariables = {"CSTR", "CDIS", "CSTRESS", "CDISP",
                                                                    "CFN",  "CFS",  "CELS"};

/// Node or element indices the request covers, and the set name to print.
struct Selection {
  std::string name;
  std::vector<int> indices;
  /// Subtracted from the labels printed: the offset of the ABAQUS/CAE instance
  /// holding every member of the set (its rows then carry the part's labels,
  /// as the user knows them), else 0.
  int label_offset = 0;
};

/// The offset of the one instance holding every label of `labels`, else 0.
template <class LabelOf>
int common_instance_offset(const Model& model, const std::vector<int>& indices, LabelOf label_of) {
  if (model.instances.empty() || indices.empty()) return 0;
  const PartInstance* first = instance_of(model.instances, label_of(indices.front()));
  for (const int i : indices)
    if (instance_of(model.instances, label_of(i)) != first) return 0;
  return first ? first->offset : 0;
}

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
  s.label_offset = nodal ? common_instance_offset(model, s.indices,
                                                  [&](int i) { return model.node_ids[static_cast<std::size_t>(i)]; })
                         : common_instance_offset(model, s.indices,
                                                  [&](int e) { return model.elements[static_cast<std::size_t>(e)].id; });
  return s;
}

/// The instance offset of the slave nodes of `pairs` (all of them in one
/// ABAQUS/CAE instance: its part's labels are printed), else 0.
int slave_label_offset(const Model& model, const std::vector<ContactPairValues>& pairs) {
  std::vector<int> nodes;
  for (const ContactPairValues& pair : pairs)
    for (const ContactNodeValues& v : pair.nodes)
      if (v.node >= 0 && v.node < model.n_nodes()) nodes.push_back(v.node);
  return common_instance_offset(model, nodes, [&](int i) { return model.node_ids[static_cast<std::size_t>(i)]; });
}

/// " and time  0.1000000E+01" (ccx: ' and time ',e14.7).
std::string time_suffix(double time) { return fmt::format(" and time {:>14}", fortran_e(time, 7)); }

void write_header(Out out, std::string_view what, const std::string& set, double time) {
  fmt::format_to(out, "\n {} for set {}{}\n\n", what, set, time_suffix(time));
}

/// CalculiX's .dat gives the forces of an axisymmetric model on the 2°
/// segment it expands the model to (1/180 of the full circle; measured with
/// ccx 2.20 on a CAX4 ring). In the calculix dialect, the forces `v` of the
/// nodes of axisymmetric elements are scaled so; in the abaqus dialect (and
/// for plane elements) `v` is returned as it is: totals over the full circle.
std::vector<Eigen::Vector2d> printed_forces(const Model& model, const std::vector<Eigen::Vector2d>& v) {
  if (model.dialect != Dialect::Calculix) return v;
  std::vector<Eigen::Vector2d> out = v;
  std::vector<char> scaled(v.size(), 0);
  for (const Element& e : model.elements)
    if (e.type.family == Family::Axisymmetric)
      for (int n : e.nodes)
        if (static_cast<std::size_t>(n) < out.size() && !scaled[static_cast<std::size_t>(n)]) {
          out[static_cast<std::size_t>(n)] /= kCalculixAxisymmetricSegments;
          scaled[static_cast<std::size_t>(n)] = 1;
        }
  return out;
}

void write_nodal(Out out, const Model& model, const Selection& sel, const std::vector<Eigen::Vector2d>& v,
                 std::string_view what, bool rows, bool totals, double time) {
  if (v.size() != static_cast<std::size_t>(model.n_nodes()))
    throw std::invalid_argument(fmt::format("DatWriter: {} needs {} nodal values, results have {}", what,
                                            model.n_nodes(), v.size()));
  if (rows) {
    write_header(out, what, sel.name, time);
    for (const int i : sel.indices)
      fmt::format_to(out, "{:10d} {:13.6E} {:13.6E} {:13.6E}\n", model.node_ids[static_cast<std::size_t>(i)] - sel.label_offset,
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

/// NT: `temperatures for set ...`, one row per node (0 for every node when
/// the deck gives no temperatures).
void write_temperatures(Out out, const Model& model, const Selection& sel, const std::vector<double>& t, double time) {
  write_header(out, "temperatures", sel.name, time);
  for (const int i : sel.indices)
    fmt::format_to(out, "{:10d} {:13.6E}\n", model.node_ids[static_cast<std::size_t>(i)] - sel.label_offset,
                   t.empty() ? 0.0 : unsigned_zero(t[static_cast<std::size_t>(i)]));
}

/// Which tensor of the integration points a block of write_points prints.
enum class PointTensor { Stress, Strain, ThermalStrain };

void write_points(Out out, const Model& model, const Selection& sel, const IncrementResults& r, PointTensor what) {
  if (r.points.size() != static_cast<std::size_t>(model.n_elements()) && !(r.points.empty() && r.point_source))
    throw std::invalid_argument(fmt::format("DatWriter: EL PRINT needs integration-point values for {} elements, "
                                            "results have {}",
                                            model.n_elements(), r.points.size()));
  // THE: tether's block (ccx prints no thermal strains), laid out as the strains.
  write_header(out,
               what == PointTensor::Stress   ? "stresses (elem, integ.pnt.,sxx,syy,szz,sxy,sxz,syz)"
               : what == PointTensor::Strain ? "strains (elem, integ.pnt.,exx,eyy,ezz,exy,exz,eyz)"
                                             : "thermal strains (elem, integ.pnt.,exx,eyy,ezz,exy,exz,eyz)",
               sel.name, r.total_time);
  std::vector<PointValues> buffer;
  for (const int e : sel.indices) {
    const auto& points = element_points(r, static_cast<std::size_t>(e), buffer);
    const int label = model.elements[static_cast<std::size_t>(e)].id - sel.label_offset;
    for (std::size_t k = 0; k < points.size(); ++k) {
      const Tensor4& t = what == PointTensor::Stress   ? points[k].stress
                         : what == PointTensor::Strain ? points[k].strain
                                                       : points[k].thermal_strain;
      fmt::format_to(out, "{:10d}{:4d} {:13.6E} {:13.6E} {:13.6E} {:13.6E} {:13.6E} {:13.6E}\n", label, k + 1,
                     unsigned_zero(t[0]), unsigned_zero(t[1]), unsigned_zero(t[2]), unsigned_zero(t[3]), 0.0, 0.0);
    }
  }
}

/// PEEQ (ccx's block: no blank before "for set") or PE (tether's block, tensor shear like strains).
void write_plastic_points(Out out, const Model& model, const Selection& sel, const IncrementResults& r, bool peeq) {
  if (peeq)
    fmt::format_to(out, "\n equivalent plastic strain (elem, integ.pnt.,pe)for set {}{}\n\n", sel.name,
                   time_suffix(r.total_time));
  else
    write_header(out, "plastic strains (elem, integ.pnt.,pexx,peyy,pezz,pexy,pexz,peyz)", sel.name, r.total_time);
  std::vector<PointValues> buffer;
  for (const int e : sel.indices) {
    const auto& points = element_points(r, static_cast<std::size_t>(e), buffer);
    const int label = model.elements[static_cast<std::size_t>(e)].id - sel.label_offset;
    for (std::size_t k = 0; k < points.size(); ++k) {
      if (peeq) {
        fmt::format_to(out, "{:10d}{:4d} {:13.6E}\n", label, k + 1, unsigned_zero(points[k].peeq));
        continue;
      }
      const Tensor4& t = points[k].plastic_strain;
      fmt::format_to(out, "{:10d}{:4d} {:13.6E} {:13.6E} {:13.6E} {:13.6E} {:13.6E} {:13.6E}\n", label, k + 1,
                     unsigned_zero(t[0]), unsigned_zero(t[1]), unsigned_zero(t[2]), unsigned_zero(t[3]), 0.0, 0.0);
    }
  }
}

/// AC YIELD (tether's block; ccx prints none): 1 at a point that flowed
/// plastically in the increment, 0 elsewhere, in the number format of PEEQ.
void write_yield_flags(Out out, const Model& model, const Selection& sel, const IncrementResults& r) {
  write_header(out, "actively yielding (elem, integ.pnt.,ac yield)", sel.name, r.total_time);
  std::vector<PointValues> buffer;
  for (const int e : sel.indices) {
    const auto& points = element_points(r, static_cast<std::size_t>(e), buffer);
    const int label = model.elements[static_cast<std::size_t>(e)].id - sel.label_offset;
    for (std::size_t k = 0; k < points.size(); ++k)
      fmt::format_to(out, "{:10d}{:4d} {:13.6E}\n", label, k + 1, static_cast<double>(points[k].ac_yield));
  }
}

/// SDV: a user material's state variables, CalculiX's block and line layout
/// (all n_sdv values of a point on its line; zeros beyond a point's own).
void write_state_variables(Out out, const Model& model, const Selection& sel, const IncrementResults& r) {
  write_header(out, "internal state variables (elem, integ.pnt.,values)", sel.name, r.total_time);
  std::vector<PointValues> buffer;
  for (const int e : sel.indices) {
    const auto& points = element_points(r, static_cast<std::size_t>(e), buffer);
    const int label = model.elements[static_cast<std::size_t>(e)].id - sel.label_offset;
    for (std::size_t k = 0; k < points.size(); ++k) {
      fmt::format_to(out, "{:10d}{:4d}", label, k + 1);
      const std::vector<double>& sdv = points[k].sdv;
      for (std::size_t i = 0; i < static_cast<std::size_t>(r.n_sdv); ++i)
        fmt::format_to(out, " {:13.6E}", i < sdv.size() ? unsigned_zero(sdv[i]) : 0.0);
      fmt::format_to(out, "\n");
    }
  }
}

// ---------------------------------------------------------------- contact

bool closed(const ContactNodeValues& v) { return v.status != ContactNodeValues::Status::Open; }

int status_code(ContactNodeValues::Status s) {
  switch (s) {
    case ContactNodeValues::Status::Open: return 0;
    case ContactNodeValues::Status::Stick: return 1;
    case ContactNodeValues::Status::Slip: return 2;
  }
  return 0;
}

/// Unit tangent t (face node 1 -> 2) and outward normal n = (t_y, -t_x) of the
/// current master face at ξ*.
struct MasterFrame {
  Eigen::Vector2d t{1, 0};
  Eigen::Vector2d n{0, -1};
};

/// The frame of the face a slave node is paired with; nullopt when it is not
/// paired or the face cannot be evaluated (unknown element or face number,
/// zero-length face). `u` may be empty (reference configuration).
std::optional<MasterFrame> master_frame(const Model& model, const std::vector<Eigen::Vector2d>& u,
                                        const ContactNodeValues& v) {
  if (v.master_element == 0) return std::nullopt;
  const auto it = model.element_index.find(v.master_element);
  if (it == model.element_index.end()) return std::nullopt;
  const Element& e = model.elements[static_cast<std::size_t>(it->second)];
  const int face = v.master_face - 1;
  if (face < 0 || face >= n_faces(e.type.shape)) return std::nullopt;
  const auto local = face_nodes(e.type.shape, face);
  const int nf = n_face_nodes(e.type.shape);
  Eigen::Vector3d N, dN;
  face_shape_functions(nf, v.xi, N, dN);
  Eigen::Vector2d dy = Eigen::Vector2d::Zero();
  for (int a = 0; a < nf; ++a) {
    const auto node = static_cast<std::size_t>(e.nodes[static_cast<std::size_t>(local[static_cast<std::size_t>(a)])]);
    Eigen::Vector2d x = model.coords[node];
    if (node < u.size()) x += u[node];
    dy += dN[a] * x;
  }
  const double length = dy.norm();
  if (!(length > 0) || !std::isfinite(length)) return std::nullopt;
  MasterFrame f;
  f.t = dy / length;
  f.n = Eigen::Vector2d(f.t.y(), -f.t.x());
  return f;
}

/// ccx's in-plane tangent direction (springforc_n2f) relative to tether's t:
/// not vertical -> tang1 = sign(t_x) t, tang2 out of plane; vertical
/// (1 - |n_x| < 1.5231e-6) -> tang1 = e3, tang2 = n x e3 = -t.
struct CcxTangent {
  double factor = 1;      ///< value along ccx's in-plane tangent = factor * value along t
  bool vertical = false;  ///< true: the in-plane value goes to tang2
};

CcxTangent ccx_tangent(const std::optional<MasterFrame>& frame) {
  CcxTangent c;
  if (!frame) return c;
  if (1.0 - std::abs(frame->n.x()) < 1.5231e-6) {
    c.vertical = true;
    c.factor = -1;
  } else {
    c.factor = frame->t.x() >= 0 ? 1.0 : -1.0;
  }
  return c;
}

std::size_t checked_node(const Model& model, const ContactPairValues& pair, int node) {
  if (node < 0 || node >= model.n_nodes())
    throw std::invalid_argument(fmt::format("DatWriter: contact pair '{}' names slave node index {} outside the mesh",
                                            pair.name, node));
  return static_cast<std::size_t>(node);
}

/// "... for all contact elements and time 0.1000000E+01" (ccx: 'time',e14.7).
void write_contact_header(Out out, std::string_view what, double time) {
  fmt::format_to(out, "\n {} for all contact elements and time{:>14}\n\n", what, fortran_e(time, 7));
}

/// CSTR (stress = true) or CDIS rows of every closed slave node of every pair.
void write_contact_rows(Out out, const Model& model, const IncrementResults& r, const RelativeSlip& relative_slip,
                        bool stress) {
  write_contact_header(out,
                       stress ? "contact stress (slave node,press,tang1,tang2)"
                              : "relative contact displacement (slave node,normal,tang1,tang2)",
                       r.total_time);
  const int offset = slave_label_offset(model, r.contact);
  for (std::size_t p = 0; p < r.contact.size(); ++p) {
    const ContactPairValues& pair = r.contact[p];
    for (const ContactNodeValues& v : pair.nodes) {
      const std::size_t node = checked_node(model, pair, v.node);
      if (!closed(v)) continue;
      const CcxTangent c = ccx_tangent(master_frame(model, r.displacement, v));
      const double in_plane = stress ? c.factor * v.shear : relative_slip[p].at(v.node);
      const double tang1 = c.vertical ? 0.0 : in_plane;
      const double tang2 = c.vertical ? in_plane : 0.0;
      fmt::format_to(out, "{:10d} {:13.6E} {:13.6E} {:13.6E}\n", model.node_ids[node] - offset,
                     unsigned_zero(stress ? v.pressure : v.gap), unsigned_zero(tang1), unsigned_zero(tang2));
    }
  }
}

/// CFN (normal = true: sum of N n) or CFS (sum of -T t) blocks, one per pair.
void write_contact_forces(Out out, const Model& model, const IncrementResults& r, bool normal) {
  for (std::size_t p = 0; p < r.contact.size(); ++p) {
    const ContactPairValues& pair = r.contact[p];
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    for (const ContactNodeValues& v : pair.nodes) {
      checked_node(model, pair, v.node);
      if (v.normal_force == 0 && v.tangential_force == 0) continue;
      const auto frame = master_frame(model, r.displacement, v);
      if (!frame)
        throw std::invalid_argument(fmt::format(
            "DatWriter: contact pair '{}': slave node {} carries a force but its master face (element {}, face {}) "
            "cannot be evaluated",
            pair.name, label_text(model.instances, model.node_ids[static_cast<std::size_t>(v.node)]),
            label_text(model.instances, v.master_element), v.master_face));
      sum += normal ? Eigen::Vector2d(v.normal_force * frame->n) : Eigen::Vector2d(-v.tangential_force * frame->t);
    }
    fmt::format_to(out, "\n {} for pair {}{}\n\n",
                   normal ? "total normal contact force (fx,fy,fz)" : "total shear contact force (fx,fy,fz)",
                   contact_pair_set_name(model, r.contact, p), time_suffix(r.total_time));
    fmt::format_to(out, "       {:13.6E} {:13.6E} {:13.6E}\n", unsigned_zero(sum.x()), unsigned_zero(sum.y()), 0.0);
  }
}

/// `slip` advanced by this increment: + Δs along ccx's in-plane tangent for
/// every closed node. Pairs and nodes not seen before start at 0.
RelativeSlip advanced_slip(const Model& model, const IncrementResults& r, RelativeSlip slip) {
  slip.resize(r.contact.size());
  for (std::size_t p = 0; p < r.contact.size(); ++p)
    for (const ContactNodeValues& v : r.contact[p].nodes) {
      double& sum = slip[p][v.node];
      if (closed(v) && std::isfinite(v.slip))
        sum += ccx_tangent(master_frame(model, r.displacement, v)).factor * v.slip;
    }
  return slip;
}

}  // namespace

std::string multiplier_set_name(const std::string& owner, int number) {
  std::string name;
  for (const char c : owner) name += std::isspace(static_cast<unsigned char>(c)) ? '_' : c;
  return name.empty() ? fmt::format("C{}", number) : name;
}

/// The whole model's energies of a dynamic increment (one line, ABAQUS's names).
void write_energy_block(std::string& text, const EnergyTotals& e, double time) {
  const auto out = std::back_inserter(text);
  fmt::format_to(out, "\n energies (ALLKE,ALLSE,ALLWK,ALLFD,ALLVD,ALLPD,numerical,ETOTAL) for time {:14.7E}\n\n",
                 time);
  fmt::format_to(out, " {:13.6E} {:13.6E} {:13.6E} {:13.6E} {:13.6E} {:13.6E} {:13.6E} {:13.6E}\n",
                 unsigned_zero(e.kinetic), unsigned_zero(e.strain), unsigned_zero(e.work), unsigned_zero(e.friction),
                 unsigned_zero(e.viscous), unsigned_zero(e.plastic), unsigned_zero(e.numerical), unsigned_zero(e.total));
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

std::string contact_pair_set_name(const Model& model, const std::vector<ContactPairValues>& contact,
                                  std::size_t k) {
  if (k < model.contact_pairs.size()) {
    const ContactPairData& data = model.contact_pairs[k];
    if (!data.slave.empty() && !data.master.empty()) return multiplier_set_name(data.slave + "-" + data.master, 0);
  }
  const std::string name = k < contact.size() ? contact[k].name : std::string();
  return name.empty() ? fmt::format("P{}", k + 1) : multiplier_set_name(name, 0);
}

void write_contact_state_blocks(std::string& text, const Model& model, const std::vector<ContactPairValues>& contact,
                                double time) {
  const auto out = std::back_inserter(text);
  for (std::size_t p = 0; p < contact.size(); ++p) {
    fmt::format_to(out, "\n {} for pair {}{}\n\n",
                   contact[p].node_based ? kNodeBasedContactStateTitle : kContactStateTitle,
                   contact_pair_set_name(model, contact, p),
                   time_suffix(time));
    // Within one ABAQUS/CAE instance each, slave nodes and master elements carry their part's labels.
    const int node_offset = slave_label_offset(model, {contact[p]});
    std::vector<int> masters;
    for (const ContactNodeValues& v : contact[p].nodes)
      if (v.master_element > 0) masters.push_back(v.master_element);
    const int element_offset = common_instance_offset(model, masters, [](int label) { return label; });
    for (const ContactNodeValues& v : contact[p].nodes) {
      const std::size_t node = checked_node(model, contact[p], v.node);
      fmt::format_to(out, "{:10d}{:5d} {:13.6E} {:13.6E} {:13.6E} {:13.6E} {:13.6E}{:10d}{:5d} {:13.6E}\n",
                     model.node_ids[node] - node_offset, status_code(v.status), unsigned_zero(v.gap),
                     unsigned_zero(v.pressure), unsigned_zero(v.shear), unsigned_zero(v.slip),
                     unsigned_zero(v.total_slip), v.master_element > 0 ? v.master_element - element_offset : 0,
                     v.master_face, unsigned_zero(v.xi));
    }
  }
}

DatWriter::DatWriter(const Model& model, std::filesystem::path file)
    : model_(model), file_(std::move(file)), out_(file_, std::ios::binary | std::ios::trunc) {
  if (!out_) throw std::runtime_error("cannot create '" + file_.string() + "'");
}

void DatWriter::check(const Model& model, const OutputRequest& r) {
  if (is_contact_print(r)) {
    for (const auto& v : r.variables)
      if (std::find(kContactPrintVariables.begin(), kContactPrintVariables.end(), v) == kContactPrintVariables.end())
        throw InputError(r.where, fmt::format("*CONTACT PRINT: variable '{}' cannot be printed (tether prints CSTR, "
                                              "CDIS, CSTRESS, CDISP, CFN, CFS; CELS is accepted)",
                                              v));
    return;
  }
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
    const bool ok = nodal ? (v == "U" || v == "RF" || v == "V" || v == "A" || v == "NT")
                          : (v == "S" || v == "E" || v == "THE" || v == "PEEQ" || v == "PE" || v == "AC YIELD" ||
                             v == "SDV");
    if (!ok)
      throw InputError(r.where, fmt::format("{}: variable '{}' cannot be printed (tether prints {})", keyword, v,
                                            nodal ? "U, RF, V, A and NT" : "S, E, THE, PEEQ, PE, AC YIELD and SDV"));
  }
}

void DatWriter::save_state(std::vector<double>& out) const {
  out.push_back(static_cast<double>(relative_slip_.size()));
  for (const auto& pair : relative_slip_) {
    out.push_back(static_cast<double>(pair.size()));
    for (const auto& [node, slip] : pair) out.push_back(node), out.push_back(slip);
  }
}

void DatWriter::load_state(std::span<const double> in) {
  const auto take = [&]() {
    if (in.empty()) throw std::runtime_error("the .dat writer's saved state is too short");
    const double v = in.front();
    in = in.subspan(1);
    return v;
  };
  const auto count = [&](double hi, const char* what) {
    const double v = take();
    if (!(v >= 0 && v <= hi) || std::floor(v) != v)
      throw std::runtime_error(fmt::format("bad {} in the .dat writer's saved state: {}", what, v));
    return static_cast<int>(v);
  };
  RelativeSlip slip(static_cast<std::size_t>(count(static_cast<double>(in.size()), "number of contact pairs")));
  for (auto& pair : slip) {
    const int n = count(static_cast<double>(in.size()) / 2, "number of slave nodes");
    for (int k = 0; k < n; ++k) {
      const int node = count(model_.n_nodes() - 1, "slave node");
      pair[node] = take();
    }
  }
  if (!in.empty()) throw std::runtime_error("the .dat writer's saved state is too long");
  relative_slip_ = std::move(slip);
}

void DatWriter::write_increment(const IncrementResults& results, const std::vector<OutputRequest>& requests,
                                bool last_in_step) {
  for (const auto& r : requests) check(model_, r);
  const auto relative_slip = advanced_slip(model_, results, relative_slip_);
  std::string text;
  const auto out = std::back_inserter(text);
  bool contact_due = false, any_due = false;
  for (const auto& r : requests) {
    if (!is_due(r, results, last_in_step)) continue;
    any_due = any_due || is_print(r) || is_contact_print(r);
    if (is_contact_print(r)) {
      contact_due = true;
      for (const auto& v : r.variables) {
        if (v == "CSTR" || v == "CSTRESS")
          write_contact_rows(out, model_, results, relative_slip, true);
        else if (v == "CDIS" || v == "CDISP")
          write_contact_rows(out, model_, results, relative_slip, false);
        else if (v == "CFN" || v == "CFS")
          write_contact_forces(out, model_, results, v == "CFN");
        // CELS: no contact energy in the results (see DatWriter).
      }
      continue;
    }
    if (!is_print(r)) continue;
    const Selection sel = select(model_, r);
    for (const auto& v : r.variables) {
      if (v == "U")
        write_nodal(out, model_, sel, results.displacement, "displacements (vx,vy,vz)", true, false,
                    results.total_time);
      else if (v == "RF")
        write_nodal(out, model_, sel, printed_forces(model_, results.reaction), "forces (fx,fy,fz)", !r.totals_only,
                    r.totals || r.totals_only, results.total_time);
      else if (v == "V")
        write_nodal(out, model_, sel, results.velocity, "velocities (vx,vy,vz)", true, false, results.total_time);
      else if (v == "A")
        write_nodal(out, model_, sel, results.acceleration, "accelerations (ax,ay,az)", true, false,
                    results.total_time);
      else if (v == "NT")
        write_temperatures(out, model_, sel, results.temperature, results.total_time);
      else if (v == "S" || v == "E" || v == "THE")
        write_points(out, model_, sel, results,
                     v == "S" ? PointTensor::Stress : v == "E" ? PointTensor::Strain : PointTensor::ThermalStrain);
      else if (v == "PEEQ" || v == "PE")
        write_plastic_points(out, model_, sel, results, v == "PEEQ");
      else if (v == "AC YIELD")
        write_yield_flags(out, model_, sel, results);
      else if (v == "SDV" && results.n_sdv > 0)  // without a user material: nothing (the reader warned)
        write_state_variables(out, model_, sel, results);
    }
  }
  if (contact_due) write_contact_state_blocks(text, model_, results.contact, results.total_time);
  write_multiplier_blocks(text, results.multipliers, results.total_time);
  write_pretension_blocks(text, model_, results);
  if (results.energy && (any_due || last_in_step)) write_energy_block(text, *results.energy, results.total_time);
  out_ << text;
  out_.flush();
  if (!out_) throw std::runtime_error("error while writing '" + file_.string() + "' (disk full?)");
  relative_slip_ = relative_slip;
}

}  // namespace tether
