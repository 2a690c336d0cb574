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
///   YZ, XZ; tensor shear strains), `S_Mises`, and `CONSTRAINT_FORCE`,
///   `LAGRANGE_MULTIPLIER` and `LAGRANGE_MULTIPLIERS` when the increment has
///   multipliers of their kind (see below),
///   and the `CONTACT_*` arrays when it has contact pairs (see below);
/// - CellData `ElementId` (element labels), `S` and `S_Mises`: the arithmetic
///   mean of the integration-point stresses and its von Mises value.
/// - for an ABAQUS/CAE deck (Model::instances not empty): FieldData
///   `INSTANCE_NAMES` (a string array, the instances in deck order), PointData
///   and CellData `INSTANCE` (1-based number into INSTANCE_NAMES, 0 for a
///   node or element of no instance) and `PART_NODE_ID` / `PART_ELEMENT_ID`
///   (the label in the part, as the user wrote it; NodeId / ElementId keep
///   tether's internal labels, unique over the model). Threshold on INSTANCE
///   to show one instance; `Upper-1.7` is INSTANCE 2 with PART_NODE_ID 7.
/// - after the elements, one VTK_VERTEX cell per node that no element uses
///   (nodes held only by constraints, e.g. the ends of a rigid link), with
///   ElementId 0 and zero cell stress, so such nodes are drawn and a model
///   without elements still has cells.
/// A field whose vector in IncrementResults is empty is left out.
///
/// `CONSTRAINT_FORCE` (3 components, z = 0) [force]: at each node the sum over
/// all constraints of the force they exert on it, -sum_k lambda_k df_k/du
/// (MultiplierValues::nodal_force); 0 at nodes without constraints. This is
/// the well-defined nodal picture of the multipliers: at a node that is also
/// prescribed it equals minus the reaction force the constraint causes there
/// (RF = internal force + constraint residual), and with Warp By Vector /
/// Glyph it shows where and in which direction constraints push.
/// `CONSTRAINT_MOMENT` (scalar) [force x length], written when a constraint
/// acts on a rotation (an *MPC BEAM's reference node): the moment on that
/// node's rotation, 0 elsewhere.
///
/// `LAGRANGE_MULTIPLIER` (scalar; written when some constraint has exactly
/// one equation): the multiplier of every single-equation constraint (LINK,
/// SLIDER, one-row *EQUATION, EXPRESSION or USER) put on each node it lists,
/// summed where such constraints meet; 0 elsewhere.
///
/// `LAGRANGE_MULTIPLIERS` (3 components; written when some constraint has two
/// or three equations): (lambda_1, lambda_2, lambda_3) of each such constraint
/// (0 for a missing third) at the first node it lists — the slave node of a
/// *TIE, the first node of a *PERIODIC pair, the dependent node of an *MPC
/// TIE or PIN (then lambda_1, lambda_2 are its x and y equations), the body
/// node of an *MPC BEAM — summed where several constraints start at one node;
/// 0 elsewhere. Multipliers of constraints with more equations are only in
/// CONSTRAINT_FORCE and, per equation, in the `.dat` multiplier blocks.
///
/// Contact (IncrementResults::contact not empty, i.e. the model has
/// *CONTACT PAIRs), point data on every node, 0 on nodes that are no slave:
/// - `CONTACT_SLAVE` (Int64): 1 on slave nodes, 0 elsewhere (the mask that
///   tells a zero gap from "not a slave");
/// - `CONTACT_STATUS` (Int64): 0 open, 1 stick, 2 slip (closed frictionless
///   is slip), -1 not a slave;
/// - `CONTACT_PRESSURE` [force/area] (ContactNodeValues::pressure, > 0 in
///   compression), `CONTACT_GAP` [length] (> 0 open), `CONTACT_SHEAR`
///   [force/area] (T/area along the master tangent, face node 1 -> 2, with the
///   sign of the slip), `CONTACT_SLIP` [length] (total slip: the sum of |Δs|
///   over the slipping increments);
/// - `CONTACT_FORCE` (3 components, z = 0) [force]: the force of the master on
///   the slave node, N n - T t.
/// A node that is slave in several pairs gets the sums of pressure, shear,
/// slip and force, the smallest gap and the highest status.
///
/// The mesh arrays (points, connectivity, ids) are generated from the Model
/// while a file is written, and every array is encoded piece by piece, so the
/// writer keeps no mesh-sized data; the Model must outlive the writer and
/// must not change.
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
  std::vector<int> lonely_nodes_;             ///< nodes outside every element (one VTK_VERTEX cell each)
  std::size_t n_element_connectivity_ = 0;    ///< sum of the elements' node counts
};

}  // namespace tether
