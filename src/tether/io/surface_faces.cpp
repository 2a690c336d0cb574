#include "tether/io/surface_faces.hpp"

#include <algorithm>
#include <array>

namespace tether::deck {

namespace {

std::pair<int, int> edge_key(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

/// Node indices of face `f` of element `e`: two corners, then the mid-side node (-1 if none).
std::array<int, 3> face_node_indices(const Element& e, int f) {
  const auto local = face_nodes(e.type.shape, f);
  std::array<int, 3> out{};
  for (std::size_t i = 0; i < 3; ++i)
    out[i] = local[i] < 0 ? -1 : e.nodes[static_cast<std::size_t>(local[i])];
  return out;
}

std::string element_label(const Model& m, int e) { return std::to_string(m.elements[static_cast<std::size_t>(e)].id); }

}  // namespace

FaceIndex::FaceIndex(const Model& model) {
  for (int e = 0; e < model.n_elements(); ++e) {
    const Element& el = model.elements[static_cast<std::size_t>(e)];
    for (int f = 0; f < n_faces(el.type.shape); ++f) {
      const auto n = face_node_indices(el, f);
      faces_[edge_key(n[0], n[1])].push_back({e, f});
    }
  }
}

std::vector<ElementFace> FaceIndex::faces_on(int a, int b) const {
  const auto it = faces_.find(edge_key(a, b));
  return it == faces_.end() ? std::vector<ElementFace>{} : it->second;
}

std::vector<ElementFace> exposed_faces(const Model& model, const FaceIndex& index, const std::vector<int>& elements) {
  std::vector<ElementFace> out;
  for (int e : elements) {
    const Element& el = model.elements[static_cast<std::size_t>(e)];
    for (int f = 0; f < n_faces(el.type.shape); ++f) {
      const auto n = face_node_indices(el, f);
      if (index.faces_on(n[0], n[1]).size() == 1) out.push_back({e, f});
    }
  }
  return out;
}

std::vector<ElementFace> faces_under_lines(const DeckState& state, const FaceIndex& index, const std::vector<int>& lines,
                                           const SourceLocation& at) {
  const Model& m = state.model;
  std::vector<ElementFace> out;
  for (int l : lines) {
    const DeckState::LineElement& line = state.lines[static_cast<std::size_t>(l)];
    const std::string name = "line element " + label_text(m.instances, line.id) + " (" + line.type + ", " + line.where.str() + ")";
    const std::vector<ElementFace> faces = index.faces_on(line.nodes[0], line.nodes[1]);
    if (faces.empty())
      throw InputError(at, name + " lies on no face of a solid element: expected its two end nodes to be the corners of "
                                  "one face of a solid element");
    if (faces.size() > 1)
      throw InputError(at, name + " lies between solid elements " + element_label(m, faces[0].element) + " and " +
                               element_label(m, faces[1].element) +
                               " (inside the mesh): expected a line on the boundary, or element faces with face ids");
    const auto n = face_node_indices(m.elements[static_cast<std::size_t>(faces[0].element)], faces[0].face);
    const int mid = line.nodes.size() > 2 ? line.nodes[2] : -1;
    if (mid >= 0 && n[2] >= 0 && mid != n[2])
      throw InputError(at, name + " has mid-side node " + label_text(m.instances, m.node_ids[static_cast<std::size_t>(mid)]) +
                               " but the face of element " + element_label(m, faces[0].element) + " under it has " +
                               std::to_string(m.node_ids[static_cast<std::size_t>(n[2])]) +
                               ": expected the same mid-side node");
    out.push_back(faces[0]);
  }
  return out;
}

}  // namespace tether::deck
