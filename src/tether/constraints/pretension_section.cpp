#include "tether/constraints/pretension_section.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

namespace tether {

namespace {

constexpr double kSmallCoefficient = 1e-12;

std::string node_name(const Model& model, int node) {
  return label_text(model.instances, model.node_ids[static_cast<std::size_t>(node)]);
}

std::string face_name(const Model& model, const ElementFace& f) {
  return "face S" + std::to_string(f.face + 1) + " of element " +
         label_text(model.instances, model.elements[static_cast<std::size_t>(f.element)].id);
}

/// The face's chord, from its first to its second corner (counter-clockwise).
Eigen::Vector2d face_chord(const Model& model, const ElementFace& f) {
  const Element& e = model.elements[static_cast<std::size_t>(f.element)];
  const auto local = face_nodes(e.type.shape, f.face);
  const auto corner = [&](int k) { return model.coords[static_cast<std::size_t>(e.nodes[static_cast<std::size_t>(local[static_cast<std::size_t>(k)])])]; };
  return corner(1) - corner(0);
}

Eigen::Vector2d centroid(const Model& model, const Element& e) {
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  for (int n : e.nodes) c += model.coords[static_cast<std::size_t>(n)];
  return c / static_cast<double>(e.nodes.size());
}

/// Appends a node at the place of `original`, labelled `label`; returns its index.
int duplicate_node(Model& model, int original, int label) {
  const int index = model.n_nodes();
  model.node_ids.push_back(label);
  model.coords.push_back(model.coords[static_cast<std::size_t>(original)]);
  model.node_index[label] = index;
  return index;
}

void add_term(std::vector<EquationTerm>& row, int node, int dof, double coefficient) {
  if (std::abs(coefficient) >= kSmallCoefficient) row.push_back({node, dof, coefficient});
}

}  // namespace

Eigen::Vector2d face_outward_normal(const Model& model, const ElementFace& face) {
  const Eigen::Vector2d d = face_chord(model, face);
  const double length = d.norm();
  if (!(length > 0)) return Eigen::Vector2d::Zero();
  return Eigen::Vector2d(d.y(), -d.x()) / length;  // counter-clockwise element: outward is to the right
}

Eigen::Vector2d mean_outward_normal(const Model& model, const std::vector<ElementFace>& faces) {
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (const ElementFace& f : faces) {
    const Eigen::Vector2d d = face_chord(model, f);
    sum += Eigen::Vector2d(d.y(), -d.x());
  }
  const double length = sum.norm();
  return length > 0 ? Eigen::Vector2d(sum / length) : Eigen::Vector2d::Zero();
}

std::vector<std::pair<int, int>> cut_mesh_along(Model& model, const std::vector<ElementFace>& faces,
                                                const Eigen::Vector2d& normal) {
  std::vector<bool> near(model.elements.size(), false);
  std::vector<int> originals;  // in the order the faces name them
  for (const ElementFace& f : faces) {
    if (face_outward_normal(model, f).dot(normal) <= 0)
      throw std::invalid_argument(face_name(model, f) + " points against the section's normal: the surface must "
                                  "list the faces of the elements on one side of the cut only");
    near[static_cast<std::size_t>(f.element)] = true;
    const Element& e = model.elements[static_cast<std::size_t>(f.element)];
    for (int local : face_nodes(e.type.shape, f.face))
      if (local >= 0) originals.push_back(e.nodes[static_cast<std::size_t>(local)]);
  }
  std::map<int, int> duplicate;  // original -> duplicate
  // Above every node label and every instance's label range, so that a
  // duplicate never reads as a node of an instance.
  int label = model.node_ids.empty() ? 0 : *std::max_element(model.node_ids.begin(), model.node_ids.end());
  for (const PartInstance& i : model.instances) label = std::max(label, i.last);
  std::vector<std::pair<int, int>> pairs;
  for (int a : originals)
    if (!duplicate.count(a)) {
      const int b = duplicate_node(model, a, ++label);
      duplicate[a] = b;
      pairs.emplace_back(a, b);
    }
  std::map<int, int> far_uses;  // original -> elements still using it
  for (std::size_t k = 0; k < model.elements.size(); ++k) {
    Element& e = model.elements[k];
    const Eigen::Vector2d c = centroid(model, e);
    for (int& n : e.nodes) {
      const auto it = duplicate.find(n);
      if (it == duplicate.end()) continue;
      if (near[k] || (c - model.coords[static_cast<std::size_t>(n)]).dot(normal) < 0)
        n = it->second;
      else
        ++far_uses[n];
    }
  }
  for (const auto& [a, b] : pairs)
    if (!far_uses.count(a))
      throw std::invalid_argument("node " + node_name(model, a) + " of the surface has no element on the far side "
                                  "of the cut: a pre-tension surface must cut through the bolt, not lie on its "
                                  "boundary");
  return pairs;
}

std::vector<std::vector<EquationTerm>> pretension_equations(const std::vector<std::pair<int, int>>& pairs,
                                                            const Eigen::Vector2d& normal, int pretension_node) {
  const Eigen::Vector2d t(-normal.y(), normal.x());
  std::vector<std::vector<EquationTerm>> rows;
  rows.reserve(2 * pairs.size() + 1);
  for (const auto& [a, b] : pairs) {
    std::vector<EquationTerm> tangential, opening;
    for (int c = 0; c < 2; ++c) {
      add_term(tangential, b, c, t[c]);
      add_term(tangential, a, c, -t[c]);
      add_term(opening, b, c, normal[c]);
      add_term(opening, a, c, -normal[c]);
    }
    opening.push_back({pretension_node, 0, -1.0});
    rows.push_back(std::move(tangential));
    rows.push_back(std::move(opening));
  }
  rows.push_back({{pretension_node, 1, 1.0}});
  return rows;
}

}  // namespace tether
