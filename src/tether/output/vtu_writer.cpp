#include "tether/output/vtu_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <map>
#include <bit>
#include <ostream>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

#include "tether/output/atomic_file.hpp"
#include "tether/output/base64_encoder.hpp"

namespace tether {

std::uint8_t vtk_cell_type(Shape shape) {
  switch (shape) {
    case Shape::Tri3: return 5;
    case Shape::Quad4: return 9;
    case Shape::Tri6: return 22;
    case Shape::Quad8: return 23;
  }
  throw std::invalid_argument("vtk_cell_type: unknown element shape");
}

namespace {

constexpr std::size_t kFlushBytes = std::size_t{1} << 20;

/// Text buffer in front of an ostream, flushed in ~1 MB pieces.
class Sink {
 public:
  explicit Sink(std::ostream& out) : out_(out) { buffer_.reserve(2 * kFlushBytes); }
  ~Sink() { flush(); }
  Sink(const Sink&) = delete;
  Sink& operator=(const Sink&) = delete;

  std::string& buffer() { return buffer_; }
  void append(std::string_view text) {
    buffer_.append(text);
    maybe_flush();
  }
  void maybe_flush() {
    if (buffer_.size() >= kFlushBytes) flush();
  }
  void flush() {
    out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    buffer_.clear();
  }

 private:
  std::ostream& out_;
  std::string buffer_;
};

template <class T>
constexpr std::string_view vtk_type_name() {
  if constexpr (std::is_same_v<T, double>) return "Float64";
  else if constexpr (std::is_same_v<T, std::int64_t>) return "Int64";
  else if constexpr (std::is_same_v<T, std::uint8_t>) return "UInt8";
}

/// Values produced per piece: arrays are generated and encoded piece by
/// piece, so writing a file needs no mesh-sized buffer.
constexpr std::size_t kPieceValues = 3 * 8192;

/// Writes one DataArray of `n_values` values, produced in order by
/// `produce(std::span<T> piece)`, which fills the next piece.size() values.
template <class T, class Produce>
void write_data_array(Sink& sink, VtuEncoding encoding, std::string_view indent, std::string_view name,
                      int n_components, std::size_t n_values, Produce&& produce) {
  auto out = std::back_inserter(sink.buffer());
  fmt::format_to(out, "{}<DataArray type=\"{}\" Name=\"{}\"", indent, vtk_type_name<T>(), name);
  if (n_components > 1) fmt::format_to(out, " NumberOfComponents=\"{}\"", n_components);
  std::vector<T> piece(std::min(n_values, kPieceValues));
  if (encoding == VtuEncoding::Ascii) {
    sink.append(" format=\"ascii\">\n");
    const std::size_t per_line = static_cast<std::size_t>(std::max(n_components, 6));
    for (std::size_t done = 0; done < n_values; done += piece.size()) {
      const std::span<T> values(piece.data(), std::min(piece.size(), n_values - done));
      produce(values);
      for (std::size_t k = 0; k < values.size(); ++k) {
        const std::size_t i = done + k;
        if constexpr (std::is_same_v<T, std::uint8_t>)
          fmt::format_to(std::back_inserter(sink.buffer()), "{}", static_cast<int>(values[k]));
        else
          fmt::format_to(std::back_inserter(sink.buffer()), "{}", values[k]);
        sink.buffer() += ((i + 1) % per_line == 0 || i + 1 == n_values) ? '\n' : ' ';
        sink.maybe_flush();
      }
    }
  } else {
    sink.append(" format=\"binary\">\n");
    // Header (byte count as UInt64) and data form one base64 stream.
    Base64Encoder encoder(sink.buffer());
    const std::uint64_t n_bytes = n_values * sizeof(T);
    encoder.add(&n_bytes, sizeof n_bytes);
    for (std::size_t done = 0; done < n_values; done += piece.size()) {
      const std::span<T> values(piece.data(), std::min(piece.size(), n_values - done));
      produce(values);
      encoder.add(values.data(), values.size() * sizeof(T));
      sink.maybe_flush();
    }
    encoder.finish();
    sink.buffer() += '\n';
  }
  fmt::format_to(std::back_inserter(sink.buffer()), "{}</DataArray>\n", indent);
  sink.maybe_flush();
}

/// Producer of the values `value(i)`, i = 0, 1, ... in order.
template <class Value>
auto indexed(Value value) {
  return [value = std::move(value), i = std::size_t{0}](auto piece) mutable {
    for (auto& v : piece) v = value(i++);
  };
}

/// Producer of tuples of `width` values per item: `fill(item, double* tuple)`
/// writes item `item`'s tuple (called once per item).
template <class Fill>
auto tuples(int width, Fill fill) {
  return [fill = std::move(fill), width = static_cast<std::size_t>(width), tuple = std::array<double, 6>{},
          i = std::size_t{0}](std::span<double> piece) mutable {
    for (double& v : piece) {
      const std::size_t c = i % width;
      if (c == 0) fill(i / width, tuple.data());
      v = tuple[c];
      ++i;
    }
  };
}

/// (xx, yy, zz, xy) -> VTK order (XX, YY, ZZ, XY, YZ, XZ).
void put_tensor(double* dst, const Tensor4& t) {
  dst[0] = t[0];
  dst[1] = t[1];
  dst[2] = t[2];
  dst[3] = t[3];
  dst[4] = 0;
  dst[5] = 0;
}

void put_vector(double* dst, const Eigen::Vector2d& v) {
  dst[0] = v.x();
  dst[1] = v.y();
  dst[2] = 0;
}

void write_vectors3(Sink& sink, VtuEncoding enc, std::string_view indent, std::string_view name,
                    const std::vector<Eigen::Vector2d>& v) {
  write_data_array<double>(sink, enc, indent, name, 3, 3 * v.size(),
                           tuples(3, [&](std::size_t i, double* t) { put_vector(t, v[i]); }));
}

void write_tensors6(Sink& sink, VtuEncoding enc, std::string_view indent, std::string_view name,
                    const std::vector<Tensor4>& v) {
  write_data_array<double>(sink, enc, indent, name, 6, 6 * v.size(),
                           tuples(6, [&](std::size_t i, double* t) { put_tensor(t, v[i]); }));
}

/// Point data that is nonzero on few nodes (constraint and contact nodes):
/// kept per node in a map, written as full arrays piece by piece.
template <class Combined>
using SparseNodal = std::map<std::size_t, Combined>;

/// Producer of get(value of node i), or get(absent) for a node without one,
/// for i = 0, 1, ... asked in increasing order (a cursor walks the map).
template <class Combined, class Get>
auto sparse_nodal(const SparseNodal<Combined>& values, Combined absent, Get get) {
  return [&values, absent = std::move(absent), get = std::move(get), it = values.begin()](std::size_t node) mutable {
    while (it != values.end() && it->first < node) ++it;
    return get(it != values.end() && it->first == node ? it->second : absent);
  };
}

void check_size(std::size_t actual, std::size_t expected, const char* what) {
  if (actual != 0 && actual != expected)
    throw std::invalid_argument(fmt::format("VtuWriter: IncrementResults::{} has {} entries, the mesh needs {}",
                                            what, actual, expected));
}

/// CONTACT_* values of one node (see VtuWriter): several pairs on one node
/// are combined (sums; smallest gap; highest status).
struct ContactNodal {
  std::int64_t slave = 0, status = -1;
  double pressure = 0, gap = 0, shear = 0, slip = 0;
  Eigen::Vector2d force{0, 0};
};

void write_contact_point_data(Sink& sink, VtuEncoding enc, std::string_view indent,
                              const std::vector<ContactPairValues>& contact, std::size_t n_nodes) {
  SparseNodal<ContactNodal> nodal;
  for (const auto& pair : contact)
    for (const auto& v : pair.nodes) {
      if (v.node < 0 || static_cast<std::size_t>(v.node) >= n_nodes)
        throw std::invalid_argument(
            fmt::format("VtuWriter: contact pair '{}' names slave node index {} outside the mesh", pair.name, v.node));
      ContactNodal& n = nodal[static_cast<std::size_t>(v.node)];
      const std::int64_t code = v.status == ContactNodeValues::Status::Open    ? 0
                                : v.status == ContactNodeValues::Status::Stick ? 1
                                                                               : 2;
      n.gap = n.slave != 0 ? std::min(n.gap, v.gap) : v.gap;
      n.slave = 1;
      n.status = std::max(n.status, code);
      n.pressure += v.pressure;
      n.shear += v.shear;
      n.slip += v.total_slip;
      n.force += v.force;
    }
  const ContactNodal none;
  const auto int_field = [&](std::string_view name, auto get) {
    write_data_array<std::int64_t>(sink, enc, indent, name, 1, n_nodes, indexed(sparse_nodal(nodal, none, get)));
  };
  const auto real_field = [&](std::string_view name, auto get) {
    write_data_array<double>(sink, enc, indent, name, 1, n_nodes, indexed(sparse_nodal(nodal, none, get)));
  };
  int_field("CONTACT_SLAVE", [](const ContactNodal& n) { return n.slave; });
  int_field("CONTACT_STATUS", [](const ContactNodal& n) { return n.status; });
  real_field("CONTACT_PRESSURE", [](const ContactNodal& n) { return n.pressure; });
  real_field("CONTACT_GAP", [](const ContactNodal& n) { return n.gap; });
  real_field("CONTACT_SHEAR", [](const ContactNodal& n) { return n.shear; });
  real_field("CONTACT_SLIP", [](const ContactNodal& n) { return n.slip; });
  auto force = sparse_nodal(nodal, none, [](const ContactNodal& n) { return n.force; });
  write_data_array<double>(sink, enc, indent, "CONTACT_FORCE", 3, 3 * n_nodes,
                           tuples(3, [&](std::size_t i, double* t) { put_vector(t, force(i)); }));
}

/// 1-based position in `instances` of the instance that holds internal
/// label `label`, 0 for a label of no instance.
std::int64_t instance_number(const std::vector<PartInstance>& instances, int label) {
  const PartInstance* i = instance_of(instances, label);
  return i ? static_cast<std::int64_t>(i - instances.data()) + 1 : 0;
}

/// The label the user wrote in the part: the internal one less its instance's offset.
std::int64_t part_label(const std::vector<PartInstance>& instances, int label) {
  const PartInstance* i = instance_of(instances, label);
  return i ? label - i->offset : label;
}

/// FieldData `INSTANCE_NAMES`: a VTK string array (ascii: each name as its
/// character codes and a 0), entry k - 1 names instance number k.
void write_instance_names(std::string& buffer, const std::vector<PartInstance>& instances) {
  const auto out = std::back_inserter(buffer);
  fmt::format_to(out, "      <DataArray type=\"String\" Name=\"INSTANCE_NAMES\" NumberOfTuples=\"{}\" format=\"ascii\">",
                 instances.size());
  for (const PartInstance& i : instances) {
    for (const char c : i.name) fmt::format_to(out, "{} ", static_cast<int>(static_cast<unsigned char>(c)));
    fmt::format_to(out, "0 ");
  }
  buffer += "</DataArray>\n";
}

}  // namespace

VtuWriter::VtuWriter(const Model& model, VtuEncoding encoding) : model_(model), encoding_(encoding) {
  // Nodes outside every element (constraint-only nodes: a link's end, a
  // reference node) get a VTK_VERTEX cell each, so they are drawn and the file
  // has cells even without elements; ElementId 0, stress 0. The mesh arrays
  // themselves are generated from the Model while a file is written.
  const auto n = static_cast<std::size_t>(model.n_nodes());
  std::vector<bool> used(n, false);
  for (const auto& e : model.elements) {
    for (const int node : e.nodes) used[static_cast<std::size_t>(node)] = true;
    n_element_connectivity_ += e.nodes.size();
  }
  for (std::size_t i = 0; i < n; ++i)
    if (!used[i]) lonely_nodes_.push_back(static_cast<int>(i));
}

void VtuWriter::write(const IncrementResults& results, const std::filesystem::path& file) const {
  AtomicFile atomic(file);
  write(results, atomic.stream());
  atomic.commit();
}

void VtuWriter::write(const IncrementResults& r, std::ostream& out) const {
  const Model& model = model_;
  const std::size_t n_nodes = static_cast<std::size_t>(model.n_nodes());
  const std::size_t n_elements = model.elements.size();
  const std::size_t n_cells = n_elements + lonely_nodes_.size();  // elements, then vertex cells
  if (r.displacement.size() != n_nodes)
    throw std::invalid_argument(fmt::format("VtuWriter: IncrementResults::displacement has {} entries, the mesh needs {}",
                                            r.displacement.size(), n_nodes));
  if (!r.element_fields)
    throw std::invalid_argument(fmt::format(
        "VtuWriter: the results of step {} increment {} were built without element fields", r.step, r.increment));
  check_size(r.reaction.size(), n_nodes, "reaction");
  check_size(r.nodal_stress.size(), n_nodes, "nodal_stress");
  check_size(r.nodal_strain.size(), n_nodes, "nodal_strain");
  check_size(r.points.size(), n_elements, "points");
  check_size(r.element_stress.size(), n_elements, "element_stress");
  check_size(r.nodal_peeq.size(), n_nodes, "nodal_peeq");
  check_size(r.nodal_plastic_strain.size(), n_nodes, "nodal_plastic_strain");
  check_size(r.nodal_thermal_strain.size(), n_nodes, "nodal_thermal_strain");
  check_size(r.element_peeq.size(), n_elements, "element_peeq");
  check_size(r.nodal_ac_yield.size(), n_nodes, "nodal_ac_yield");
  check_size(r.element_ac_yield.size(), n_elements, "element_ac_yield");

  Sink sink(out);
  const auto enc = encoding_;
  const std::string_view byte_order = std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";
  fmt::format_to(std::back_inserter(sink.buffer()),
                 "<?xml version=\"1.0\"?>\n"
                 "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"{}\" header_type=\"UInt64\">\n"
                 "  <UnstructuredGrid>\n"
                 "    <FieldData>\n",
                 byte_order);
  const auto out_it = std::back_inserter(sink.buffer());
  fmt::format_to(out_it, "      <DataArray type=\"Float64\" Name=\"TIME\" NumberOfTuples=\"1\" format=\"ascii\">{}</DataArray>\n",
                 r.total_time);
  fmt::format_to(out_it, "      <DataArray type=\"Int64\" Name=\"STEP\" NumberOfTuples=\"1\" format=\"ascii\">{}</DataArray>\n",
                 r.step);
  fmt::format_to(out_it, "      <DataArray type=\"Int64\" Name=\"INCREMENT\" NumberOfTuples=\"1\" format=\"ascii\">{}</DataArray>\n",
                 r.increment);
  if (r.plastic_dissipation)
    fmt::format_to(out_it, "      <DataArray type=\"Float64\" Name=\"ALLPD\" NumberOfTuples=\"1\" format=\"ascii\">{}</DataArray>\n",
                   *r.plastic_dissipation);
  if (!model.instances.empty()) write_instance_names(sink.buffer(), model.instances);
  fmt::format_to(std::back_inserter(sink.buffer()),
                 "    </FieldData>\n"
                 "    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n"
                 "      <PointData Vectors=\"U\"{}>\n",
                 n_nodes, n_cells, r.nodal_stress.empty() ? "" : " Scalars=\"S_Mises\" Tensors=\"S\"");

  constexpr std::string_view kIndent = "        ";
  write_data_array<std::int64_t>(sink, enc, kIndent, "NodeId", 1, n_nodes, indexed([&](std::size_t i) {
    return i < model.node_ids.size() ? static_cast<std::int64_t>(model.node_ids[i]) : static_cast<std::int64_t>(i + 1);
  }));
  if (!model.instances.empty()) {  // an ABAQUS/CAE deck: the instance and the part's label of each node
    write_data_array<std::int64_t>(sink, enc, kIndent, "INSTANCE", 1, n_nodes, indexed([&](std::size_t i) {
      return instance_number(model.instances, model.node_ids[i]);
    }));
    write_data_array<std::int64_t>(sink, enc, kIndent, "PART_NODE_ID", 1, n_nodes, indexed([&](std::size_t i) {
      return part_label(model.instances, model.node_ids[i]);
    }));
  }
  write_vectors3(sink, enc, kIndent, "U", r.displacement);
  if (!r.reaction.empty()) write_vectors3(sink, enc, kIndent, "RF", r.reaction);
  if (!r.velocity.empty()) write_vectors3(sink, enc, kIndent, "V", r.velocity);
  if (!r.acceleration.empty()) write_vectors3(sink, enc, kIndent, "A", r.acceleration);
  if (!r.temperature.empty())
    write_data_array<double>(sink, enc, kIndent, "NT", 1, n_nodes, indexed([&](std::size_t i) { return r.temperature[i]; }));
  if (!r.nodal_stress.empty()) {
    write_tensors6(sink, enc, kIndent, "S", r.nodal_stress);
    write_data_array<double>(sink, enc, kIndent, "S_Mises", 1, n_nodes,
                             indexed([&](std::size_t i) { return von_mises(r.nodal_stress[i]); }));
  }
  if (!r.nodal_strain.empty()) write_tensors6(sink, enc, kIndent, "E", r.nodal_strain);
  if (!r.nodal_thermal_strain.empty()) write_tensors6(sink, enc, kIndent, "THE", r.nodal_thermal_strain);
  if (!r.nodal_peeq.empty())
    write_data_array<double>(sink, enc, kIndent, "PEEQ", 1, n_nodes, indexed([&](std::size_t i) { return r.nodal_peeq[i]; }));
  if (!r.nodal_plastic_strain.empty()) write_tensors6(sink, enc, kIndent, "PE", r.nodal_plastic_strain);
  if (!r.nodal_ac_yield.empty())  // the fraction of yielding points around the node (see IncrementResults)
    write_data_array<double>(sink, enc, kIndent, "AC_YIELD", 1, n_nodes,
                             indexed([&](std::size_t i) { return r.nodal_ac_yield[i]; }));
  for (int k = 0; k < r.n_sdv && !r.nodal_sdv.empty(); ++k)  // SDV1, SDV2, ...: one array each
    write_data_array<double>(sink, enc, kIndent, "SDV" + std::to_string(k + 1), 1, n_nodes, indexed([&](std::size_t i) {
                               return r.nodal_sdv[i * static_cast<std::size_t>(r.n_sdv) + static_cast<std::size_t>(k)];
                             }));
  if (!r.multipliers.empty()) {
    SparseNodal<double> lambda;
    SparseNodal<Eigen::Vector3d> lambdas;  // constraints of 2 or 3 equations, at their first node
    bool scalar = false;
    SparseNodal<Eigen::Vector2d> force;
    SparseNodal<double> moment;
    const auto checked = [&](const MultiplierValues& m, int node) {
      if (node < 0 || static_cast<std::size_t>(node) >= n_nodes)
        throw std::invalid_argument(fmt::format("VtuWriter: multiplier owner '{}' names node index {} outside the mesh",
                                                m.owner, node));
      return static_cast<std::size_t>(node);
    };
    for (const auto& m : r.multipliers) {
      if ((m.value.size() == 2 || m.value.size() == 3) && !m.nodes.empty()) {
        Eigen::Vector3d l = Eigen::Vector3d::Zero();
        for (std::size_t k = 0; k < m.value.size(); ++k) l[static_cast<Eigen::Index>(k)] = m.value[k];
        lambdas.try_emplace(checked(m, m.nodes.front()), Eigen::Vector3d::Zero()).first->second += l;
      }
      scalar = scalar || m.value.size() == 1;
      std::vector<std::size_t> seen;  // a node listed twice gets the owner's lambda once
      for (const int node : m.nodes) {
        const std::size_t i = checked(m, node);
        if (m.value.size() != 1 || std::find(seen.begin(), seen.end(), i) != seen.end()) continue;
        seen.push_back(i);
        lambda.try_emplace(i, 0.0).first->second += m.value.front();
      }
      for (const auto& f : m.nodal_force) {
        force.try_emplace(checked(m, f.node), Eigen::Vector2d::Zero()).first->second += f.force;
        if (f.moment) moment.try_emplace(checked(m, f.node), 0.0).first->second += *f.moment;
      }
    }
    if (scalar)
      write_data_array<double>(sink, enc, kIndent, "LAGRANGE_MULTIPLIER", 1, n_nodes,
                               indexed(sparse_nodal(lambda, 0.0, [](double v) { return v; })));
    if (!lambdas.empty()) {
      auto nodal = sparse_nodal(lambdas, Eigen::Vector3d(Eigen::Vector3d::Zero()),
                                [](const Eigen::Vector3d& v) { return v; });
      write_data_array<double>(sink, enc, kIndent, "LAGRANGE_MULTIPLIERS", 3, 3 * n_nodes,
                               tuples(3, [&](std::size_t i, double* t) {
                                 const Eigen::Vector3d v = nodal(i);
                                 t[0] = v.x(), t[1] = v.y(), t[2] = v.z();
                               }));
    }
    auto nodal_force =
        sparse_nodal(force, Eigen::Vector2d(Eigen::Vector2d::Zero()), [](const Eigen::Vector2d& v) { return v; });
    write_data_array<double>(sink, enc, kIndent, "CONSTRAINT_FORCE", 3, 3 * n_nodes,
                             tuples(3, [&](std::size_t i, double* t) { put_vector(t, nodal_force(i)); }));
    if (!moment.empty())
      write_data_array<double>(sink, enc, kIndent, "CONSTRAINT_MOMENT", 1, n_nodes,
                               indexed(sparse_nodal(moment, 0.0, [](double v) { return v; })));
  }
  if (!r.contact.empty()) write_contact_point_data(sink, enc, kIndent, r.contact, n_nodes);
  sink.append("      </PointData>\n      <CellData Scalars=\"ElementId\">\n");
  write_data_array<std::int64_t>(sink, enc, kIndent, "ElementId", 1, n_cells, indexed([&](std::size_t c) {
    return c < n_elements ? static_cast<std::int64_t>(model.elements[c].id) : std::int64_t{0};
  }));
  if (!model.instances.empty()) {  // vertex cells: their node's instance, element label 0
    write_data_array<std::int64_t>(sink, enc, kIndent, "INSTANCE", 1, n_cells, indexed([&](std::size_t c) {
      return instance_number(model.instances,
                             c < n_elements ? model.elements[c].id
                                            : model.node_ids[static_cast<std::size_t>(lonely_nodes_[c - n_elements])]);
    }));
    write_data_array<std::int64_t>(sink, enc, kIndent, "PART_ELEMENT_ID", 1, n_cells, indexed([&](std::size_t c) {
      return c < n_elements ? part_label(model.instances, model.elements[c].id) : std::int64_t{0};
    }));
  }
  if (!r.points.empty() || !r.element_stress.empty()) {
    // Arithmetic mean of the integration-point stresses (zero for vertex cells).
    const auto cell_stress = [&](std::size_t c) {
      if (c >= n_elements) return Tensor4{};
      return r.points.empty() ? r.element_stress[c] : mean_stress(r.points[c]);
    };
    write_data_array<double>(sink, enc, kIndent, "S", 6, 6 * n_cells,
                             tuples(6, [&](std::size_t c, double* t) { put_tensor(t, cell_stress(c)); }));
    write_data_array<double>(sink, enc, kIndent, "S_Mises", 1, n_cells,
                             indexed([&](std::size_t c) { return von_mises(cell_stress(c)); }));
  }
  if (!r.element_peeq.empty())
    write_data_array<double>(sink, enc, kIndent, "PEEQ", 1, n_cells, indexed([&](std::size_t c) {
                               return c < n_elements ? r.element_peeq[c] : 0.0;
                             }));
  if (!r.element_ac_yield.empty())  // the fraction of the element's points that yield
    write_data_array<double>(sink, enc, kIndent, "AC_YIELD", 1, n_cells, indexed([&](std::size_t c) {
                               return c < n_elements ? r.element_ac_yield[c] : 0.0;
                             }));
  for (int k = 0; k < r.n_sdv && !r.element_sdv.empty(); ++k)  // the mean over the element's points
    write_data_array<double>(sink, enc, kIndent, "SDV" + std::to_string(k + 1), 1, n_cells, indexed([&](std::size_t c) {
                               return c < n_elements ? r.element_sdv[c * static_cast<std::size_t>(r.n_sdv) +
                                                                     static_cast<std::size_t>(k)]
                                                     : 0.0;
                             }));
  sink.append("      </CellData>\n      <Points>\n");
  write_data_array<double>(sink, enc, kIndent, "Points", 3, 3 * n_nodes,
                           tuples(3, [&](std::size_t i, double* t) { put_vector(t, model.coords[i]); }));
  sink.append("      </Points>\n      <Cells>\n");
  // Connectivity: element nodes in order, then one node per vertex cell.
  write_data_array<std::int64_t>(
      sink, enc, kIndent, "connectivity", 1, n_element_connectivity_ + lonely_nodes_.size(),
      [&, e = std::size_t{0}, a = std::size_t{0}, lonely = std::size_t{0}](std::span<std::int64_t> piece) mutable {
        for (auto& v : piece) {
          while (e < n_elements && a == model.elements[e].nodes.size()) ++e, a = 0;
          v = e < n_elements ? model.elements[e].nodes[a++] : lonely_nodes_[lonely++];
        }
      });
  write_data_array<std::int64_t>(sink, enc, kIndent, "offsets", 1, n_cells,
                                 [&, c = std::size_t{0}, end = std::int64_t{0}](std::span<std::int64_t> piece) mutable {
                                   for (auto& v : piece) {
                                     end += c < n_elements ? static_cast<std::int64_t>(model.elements[c].nodes.size()) : 1;
                                     v = end;
                                     ++c;
                                   }
                                 });
  write_data_array<std::uint8_t>(sink, enc, kIndent, "types", 1, n_cells, indexed([&](std::size_t c) {
    return c < n_elements ? vtk_cell_type(model.elements[c].type.shape) : std::uint8_t{1};  // 1: VTK_VERTEX
  }));
  sink.append("      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n");
  sink.flush();
  if (!out) throw std::runtime_error("VtuWriter: error while writing the .vtu stream");
}

}  // namespace tether
