#pragma once
/// \file ParaView output: one VTK XML UnstructuredGrid (`.vtu`) per increment.

#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <vector>

#include "tether/model/model.hpp"
#include "tether/model/results.hpp"

namespace tether {

/// How the DataArrays of a `.vtu` are stored.
enum class VtuEncoding {
  Base64,  ///< format="binary": Float64/Int64 little- or big-endian (native), base64, UInt64 headers
  Ascii,   ///< format="ascii": shortest round-trip decimal text; slow, for debugging
};

/// VTK cell type of an element shape: Tri3 -> 5 (VTK_TRIANGLE), Quad4 -> 9
/// (VTK_QUAD), Tri6 -> 22 (VTK_QUADRATIC_TRIANGLE), Quad8 -> 23
/// (VTK_QUADRATIC_QUAD). ABAQUS and VTK order the nodes of all four the same
/// way (corners counter-clockwise, then the mid-side nodes of edges 1-2, 2-3,
/// ...), so connectivity is copied unchanged.
std::uint8_t vtk_cell_type(Shape shape);

/// Writes the mesh and the results of one increment as a `.vtu` file.
///
/// Geometry is the *reference* configuration in 3D with z = 0; the
/// displacement is a point vector `U` so ParaView's "Warp By Vector" shows the
/// deformed shape. Content:
/// - FieldData `TIME` (total time), `STEP`, `INCREMENT`;
/// - PointData `NodeId` (node labels), `U`, `RF` (3 components, z = 0),
///   `S`, `E` (6 components in VTK's symmetric-tensor order XX, YY, ZZ, XY,
///   YZ, XZ; tensor shear strains), `S_Mises`, and `LAGRANGE_MULTIPLIER` when
///   the increment has multipliers (see below);
/// - CellData `ElementId` (element labels), `S` and `S_Mises`: the arithmetic
///   mean of the integration-point stresses and its von Mises value.
/// A field whose vector in IncrementResults is empty is left out.
///
/// `LAGRANGE_MULTIPLIER`: for each MultiplierValues with as many values as
/// nodes, value i is put on node i; otherwise its first value is put on every
/// node it lists. Contributions meeting at a node are summed; nodes without a
/// multiplier get 0.
///
/// The mesh arrays are built once at construction; the Model must outlive the
/// writer and must not change.
class VtuWriter {
 public:
  explicit VtuWriter(const Model& model, VtuEncoding encoding = VtuEncoding::Base64);

  /// Writes `results` to `file` atomically (temporary file, then rename).
  /// Throws std::invalid_argument when the result arrays do not match the
  /// mesh sizes, std::runtime_error on I/O errors.
  void write(const IncrementResults& results, const std::filesystem::path& file) const;

  /// Writes the `.vtu` document to a stream (no atomicity).
  void write(const IncrementResults& results, std::ostream& out) const;

 private:
  const Model& model_;
  VtuEncoding encoding_;
  std::vector<double> points_;
  std::vector<std::int64_t> node_ids_;
  std::vector<std::int64_t> connectivity_;
  std::vector<std::int64_t> offsets_;
  std::vector<std::uint8_t> cell_types_;
  std::vector<std::int64_t> element_ids_;
};

}  // namespace tether
