#pragma once
/// \file Element faces a `*SURFACE, TYPE=ELEMENT` data line names without a
/// face id: the exposed faces of solid elements (as ABAQUS), and the faces
/// that line elements (a Gmsh physical curve) lie on.

#include <vector>

#include "tether/io/deck_state.hpp"

namespace tether::deck {

/// Faces of solid elements, keyed by their two corner nodes, for lookups by edge.
class FaceIndex {
 public:
  explicit FaceIndex(const Model& model);

  /// The faces whose corners are nodes `a` and `b` (either order): one on the
  /// model's boundary, two inside it, none when no solid has that edge.
  [[nodiscard]] std::vector<ElementFace> faces_on(int a, int b) const;

 private:
  std::map<std::pair<int, int>, std::vector<ElementFace>> faces_;
};

/// The exposed faces of `elements` (solid element indices): faces no other
/// solid element of the model shares, in element then face order, as ABAQUS
/// reads an element or element set given without a face id.
std::vector<ElementFace> exposed_faces(const Model& model, const FaceIndex& index, const std::vector<int>& elements);

/// The face of the solid element each line element lies on (its corner nodes
/// are the face's corners; for T*D3 the mid-side nodes must agree too).
/// InputError at `at` for a line on no solid face, on two (inside the mesh),
/// or whose mid-side node differs from the face's.
std::vector<ElementFace> faces_under_lines(const DeckState& state, const FaceIndex& index, const std::vector<int>& lines,
                                           const SourceLocation& at);

}  // namespace tether::deck
