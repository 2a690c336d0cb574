#pragma once
/// \file Catalogue of the 2D continuum element types tether knows.
///
/// Plain data: node counts, topology, faces and default integration. The shape
/// functions live in fem/; this table is what the deck reader and the model
/// checks need.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace tether {

/// Kinematic assumption of a 2D continuum element.
enum class Family : std::uint8_t { PlaneStrain, PlaneStress, Axisymmetric };

/// Reference shape of an element (ABAQUS node ordering: corners first,
/// counter-clockwise, then mid-side nodes starting on edge 1-2).
enum class Shape : std::uint8_t { Tri3, Quad4, Tri6, Quad8 };

/// One row of the catalogue. 24 bytes (the enums and counts are single
/// bytes): the model keeps one per element.
struct ElementType {
  std::string_view name;  ///< ABAQUS name, e.g. "CPE8R"
  Family family;
  Shape shape;
  std::uint8_t n_nodes;
  bool reduced;           ///< reduced integration (R suffix)
  /// Hybrid (H suffix): mixed displacement-pressure. tether has the
  /// constant-pressure 4-node CPE4H and CAX4H, formulated as mean dilatation
  /// (elements/mean_dilatation.hpp); the other ABAQUS hybrid names (and
  /// CPS4H, which FAMILY=PLANE STRESS makes of a CPE4H) are listed so that
  /// unsupported_reason() can refuse them.
  bool hybrid = false;
};

/// The one stored copy of `type` (equal in every field, the name compared by
/// its text): a reference that stays valid for the life of the program, so
/// that many elements of a type can share one ElementType (8 bytes each
/// instead of 32). Thread-safe. The name's characters are not copied: they
/// must outlive the program's use of the returned type, as for any copy of
/// `type` (the catalogue's names are static).
const ElementType& intern_element_type(const ElementType& type);

/// Looks up an ABAQUS element name (case-insensitive). Returns nothing for an
/// unknown name. Reduced-integration 4-node types and the hybrid types other
/// than CPE4H and CAX4H are listed (so the reader can refuse them with a
/// clear reason) but refused by unsupported_reason().
std::optional<ElementType> find_element_type(std::string_view name);

/// Nodes of a line-element type the reader accepts only to name faces: the
/// trusses T3D2/T3D3 Gmsh writes for physical curves and their 2D twins
/// T2D2/T2D3 (upper-case name); 0 for any other type.
int line_element_nodes(std::string_view name);

/// Empty when the type is supported, else the reason it is refused.
std::string unsupported_reason(const ElementType& type);

/// Why find_element_type() knows no type `name`, with the list of the
/// continuum types tether accepts: the text of the deck reader's error.
std::string unknown_element_reason(std::string_view name);

/// Number of corner nodes (3 or 4).
int n_corners(Shape shape);

/// Number of faces (edges) of the 2D shape: 3 or 4.
int n_faces(Shape shape);

/// Local node numbers (0-based) of face `face` (0-based, S1 = 0): two corner
/// nodes, then the mid-side node for quadratic shapes (-1 for linear ones).
/// Order follows the element's counter-clockwise orientation.
std::array<int, 3> face_nodes(Shape shape, int face);

/// Nodes per face: 2 for linear shapes, 3 for quadratic ones.
int n_face_nodes(Shape shape);

}  // namespace tether
