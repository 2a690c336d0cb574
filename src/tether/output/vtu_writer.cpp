#include "tether/output/vtu_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
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

template <class T>
void write_data_array(Sink& sink, VtuEncoding encoding, std::string_view indent, std::string_view name,
                      int n_components, std::span<const T> values) {
  auto out = std::back_inserter(sink.buffer());
  fmt::format_to(out, "{}<DataArray type=\"{}\" Name=\"{}\"", indent, vtk_type_name<T>(), name);
  if (n_components > 1) fmt::format_to(out, " NumberOfComponents=\"{}\"", n_components);
  if (encoding == VtuEncoding::Ascii) {
    sink.append(" format=\"ascii\">\n");
    const std::size_t per_line = static_cast<std::size_t>(std::max(n_components, 6));
    for (std::size_t i = 0; i < values.size(); ++i) {
      if constexpr (std::is_same_v<T, std::uint8_t>)
        fmt::format_to(std::back_inserter(sink.buffer()), "{}", static_cast<int>(values[i]));
      else
        fmt::format_to(std::back_inserter(sink.buffer()), "{}", values[i]);
      sink.buffer() += ((i + 1) % per_line == 0 || i + 1 == values.size()) ? '\n' : ' ';
      sink.maybe_flush();
    }
  } else {
    sink.append(" format=\"binary\">\n");
    // Header (byte count as UInt64) and data form one base64 stream.
    Base64Encoder encoder(sink.buffer());
    const std::uint64_t n_bytes = values.size() * sizeof(T);
    encoder.add(&n_bytes, sizeof n_bytes);
    constexpr std::size_t kChunk = 3 * 65536;  // multiple of 3 and of sizeof(T)
    const auto* bytes = reinterpret_cast<const unsigned char*>(values.data());
    for (std::size_t done = 0; done < n_bytes; done += kChunk) {
      encoder.add(bytes + done, std::min<std::size_t>(kChunk, n_bytes - done));
      sink.maybe_flush();
    }
    encoder.finish();
    sink.buffer() += '\n';
  }
  fmt::format_to(std::back_inserter(sink.buffer()), "{}</DataArray>\n", indent);
  sink.maybe_flush();
}

template <class T>
void write_data_array(Sink& sink, VtuEncoding encoding, std::string_view indent, std::string_view name,
                      int n_components, const std::vector<T>& values) {
  write_data_array(sink, encoding, indent, name, n_components, std::span<const T>(values));
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

std::vector<double> vectors3(const std::vector<Eigen::Vector2d>& v) {
  std::vector<double> out(3 * v.size());
  for (std::size_t i = 0; i < v.size(); ++i) {
    out[3 * i] = v[i].x();
    out[3 * i + 1] = v[i].y();
    out[3 * i + 2] = 0;
  }
  return out;
}

std::vector<double> tensors6(const std::vector<Tensor4>& t) {
  std::vector<double> out(6 * t.size());
  for (std::size_t i = 0; i < t.size(); ++i) put_tensor(&out[6 * i], t[i]);
  return out;
}

void check_size(std::size_t actual, std::size_t expected, const char* what) {
  if (actual != 0 && actual != expected)
    throw std::invalid_argument(fmt::format("VtuWriter: IncrementResults::{} has {} entries, the mesh needs {}",
                                            what, actual, expected));
}

/// CONTACT_* point data (see VtuWriter): several pairs on one node are
/// combined (sums; smallest gap; highest status).
void write_contact_point_data(Sink& sink, VtuEncoding enc, std::string_view indent,
                              const std::vector<ContactPairValues>& contact, std::size_t n_nodes) {
  std::vector<std::int64_t> slave(n_nodes, 0), status(n_nodes, -1);
  std::vector<double> pressure(n_nodes, 0.0), gap(n_nodes, 0.0), shear(n_nodes, 0.0), slip(n_nodes, 0.0);
  std::vector<Eigen::Vector2d> force(n_nodes, Eigen::Vector2d::Zero());
  for (const auto& pair : contact)
    for (const auto& v : pair.nodes) {
      if (v.node < 0 || static_cast<std::size_t>(v.node) >= n_nodes)
        throw std::invalid_argument(
            fmt::format("VtuWriter: contact pair '{}' names slave node index {} outside the mesh", pair.name, v.node));
      const auto i = static_cast<std::size_t>(v.node);
      const std::int64_t code = v.status == ContactNodeValues::Status::Open    ? 0
                                : v.status == ContactNodeValues::Status::Stick ? 1
                                                                               : 2;
      gap[i] = slave[i] != 0 ? std::min(gap[i], v.gap) : v.gap;
      slave[i] = 1;
      status[i] = std::max(status[i], code);
      pressure[i] += v.pressure;
      shear[i] += v.shear;
      slip[i] += v.total_slip;
      force[i] += v.force;
    }
  write_data_array(sink, enc, indent, "CONTACT_SLAVE", 1, slave);
  write_data_array(sink, enc, indent, "CONTACT_STATUS", 1, status);
  write_data_array(sink, enc, indent, "CONTACT_PRESSURE", 1, pressure);
  write_data_array(sink, enc, indent, "CONTACT_GAP", 1, gap);
  write_data_array(sink, enc, indent, "CONTACT_SHEAR", 1, shear);
  write_data_array(sink, enc, indent, "CONTACT_SLIP", 1, slip);
  write_data_array(sink, enc, indent, "CONTACT_FORCE", 3, vectors3(force));
}

}  // namespace

VtuWriter::VtuWriter(const Model& model, VtuEncoding encoding) : model_(model), encoding_(encoding) {
  const auto n = static_cast<std::size_t>(model.n_nodes());
  points_.resize(3 * n);
  node_ids_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    points_[3 * i] = model.coords[i].x();
    points_[3 * i + 1] = model.coords[i].y();
    points_[3 * i + 2] = 0;
    node_ids_[i] = i < model.node_ids.size() ? model.node_ids[i] : static_cast<std::int64_t>(i + 1);
  }
  offsets_.reserve(model.elements.size());
  cell_types_.reserve(model.elements.size());
  element_ids_.reserve(model.elements.size());
  for (const auto& e : model.elements) {
    for (const int node : e.nodes) connectivity_.push_back(node);
    offsets_.push_back(static_cast<std::int64_t>(connectivity_.size()));
    cell_types_.push_back(vtk_cell_type(e.type.shape));
    element_ids_.push_back(e.id);
  }
  // Nodes outside every element (constraint-only nodes: a link's end, a
  // reference node) get a VTK_VERTEX cell each, so they are drawn and the file
  // has cells even without elements; ElementId 0, stress 0.
  std::vector<bool> used(n, false);
  for (const auto& e : model.elements)
    for (const int node : e.nodes) used[static_cast<std::size_t>(node)] = true;
  for (std::size_t i = 0; i < n; ++i) {
    if (used[i]) continue;
    connectivity_.push_back(static_cast<std::int64_t>(i));
    offsets_.push_back(static_cast<std::int64_t>(connectivity_.size()));
    cell_types_.push_back(1);  // VTK_VERTEX
    element_ids_.push_back(0);
  }
}

void VtuWriter::write(const IncrementResults& results, const std::filesystem::path& file) const {
  AtomicFile atomic(file);
  write(results, atomic.stream());
  atomic.commit();
}

void VtuWriter::write(const IncrementResults& r, std::ostream& out) const {
  const std::size_t n_nodes = node_ids_.size();
  const std::size_t n_cells = element_ids_.size();           // elements, then vertex cells
  const std::size_t n_elements = model_.elements.size();
  if (r.displacement.size() != n_nodes)
    throw std::invalid_argument(fmt::format("VtuWriter: IncrementResults::displacement has {} entries, the mesh needs {}",
                                            r.displacement.size(), n_nodes));
  check_size(r.reaction.size(), n_nodes, "reaction");
  check_size(r.nodal_stress.size(), n_nodes, "nodal_stress");
  check_size(r.nodal_strain.size(), n_nodes, "nodal_strain");
  check_size(r.points.size(), n_elements, "points");

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
  fmt::format_to(std::back_inserter(sink.buffer()),
                 "    </FieldData>\n"
                 "    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n"
                 "      <PointData Vectors=\"U\"{}>\n",
                 n_nodes, n_cells, r.nodal_stress.empty() ? "" : " Scalars=\"S_Mises\" Tensors=\"S\"");

  constexpr std::string_view kIndent = "        ";
  write_data_array(sink, enc, kIndent, "NodeId", 1, node_ids_);
  write_data_array(sink, enc, kIndent, "U", 3, vectors3(r.displacement));
  if (!r.reaction.empty()) write_data_array(sink, enc, kIndent, "RF", 3, vectors3(r.reaction));
  if (!r.nodal_stress.empty()) {
    write_data_array(sink, enc, kIndent, "S", 6, tensors6(r.nodal_stress));
    std::vector<double> mises(n_nodes);
    for (std::size_t i = 0; i < n_nodes; ++i) mises[i] = von_mises(r.nodal_stress[i]);
    write_data_array(sink, enc, kIndent, "S_Mises", 1, mises);
  }
  if (!r.nodal_strain.empty()) write_data_array(sink, enc, kIndent, "E", 6, tensors6(r.nodal_strain));
  if (!r.multipliers.empty()) {
    std::vector<double> lambda(n_nodes, 0.0);
    std::vector<Eigen::Vector2d> force(n_nodes, Eigen::Vector2d::Zero());
    const auto checked = [&](const MultiplierValues& m, int node) {
      if (node < 0 || static_cast<std::size_t>(node) >= n_nodes)
        throw std::invalid_argument(fmt::format("VtuWriter: multiplier owner '{}' names node index {} outside the mesh",
                                                m.owner, node));
      return static_cast<std::size_t>(node);
    };
    for (const auto& m : r.multipliers) {
      std::vector<std::size_t> seen;  // a node listed twice gets the owner's lambda once
      for (const int node : m.nodes) {
        const std::size_t i = checked(m, node);
        if (m.value.size() != 1 || std::find(seen.begin(), seen.end(), i) != seen.end()) continue;
        seen.push_back(i);
        lambda[i] += m.value.front();
      }
      for (const auto& f : m.nodal_force) force[checked(m, f.node)] += f.force;
    }
    write_data_array(sink, enc, kIndent, "LAGRANGE_MULTIPLIER", 1, lambda);
    write_data_array(sink, enc, kIndent, "CONSTRAINT_FORCE", 3, vectors3(force));
  }
  if (!r.contact.empty()) write_contact_point_data(sink, enc, kIndent, r.contact, n_nodes);
  sink.append("      </PointData>\n      <CellData Scalars=\"ElementId\">\n");
  write_data_array(sink, enc, kIndent, "ElementId", 1, element_ids_);
  if (!r.points.empty()) {
    std::vector<double> average(6 * n_cells, 0.0), mises(n_cells, 0.0);
    for (std::size_t e = 0; e < n_elements; ++e) {
      const auto& points = r.points[e];
      if (points.empty()) continue;
      Tensor4 mean{};
      for (const auto& p : points)
        for (int c = 0; c < 4; ++c) mean[c] += p.stress[c];
      for (double& c : mean) c /= static_cast<double>(points.size());
      put_tensor(&average[6 * e], mean);
      mises[e] = von_mises(mean);
    }
    write_data_array(sink, enc, kIndent, "S", 6, average);
    write_data_array(sink, enc, kIndent, "S_Mises", 1, mises);
  }
  sink.append("      </CellData>\n      <Points>\n");
  write_data_array(sink, enc, kIndent, "Points", 3, points_);
  sink.append("      </Points>\n      <Cells>\n");
  write_data_array(sink, enc, kIndent, "connectivity", 1, connectivity_);
  write_data_array(sink, enc, kIndent, "offsets", 1, offsets_);
  write_data_array(sink, enc, kIndent, "types", 1, cell_types_);
  sink.append("      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n");
  sink.flush();
  if (!out) throw std::runtime_error("VtuWriter: error while writing the .vtu stream");
}

}  // namespace tether
