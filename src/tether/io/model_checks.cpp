#include "tether/io/model_checks.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace tether::deck {

namespace {

/// Natural coordinates of the corners.
std::array<double, 2> corner_point(Shape shape, int corner) {
  if (shape == Shape::Tri3 || shape == Shape::Tri6) {
    constexpr double tri[3][2] = {{0, 0}, {1, 0}, {0, 1}};
    return {tri[corner][0], tri[corner][1]};
  }
  constexpr double quad[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  return {quad[corner][0], quad[corner][1]};
}

/// Shape-function derivatives (d/dxi, d/deta) of node i at (xi, eta).
std::array<double, 2> shape_gradient(Shape shape, int i, double xi, double eta) {
  switch (shape) {
    case Shape::Tri3: {
      constexpr double g[3][2] = {{-1, -1}, {1, 0}, {0, 1}};
      return {g[i][0], g[i][1]};
    }
    case Shape::Tri6: {
      const double l[3] = {1 - xi - eta, xi, eta};
      constexpr double dl[3][2] = {{-1, -1}, {1, 0}, {0, 1}};
      if (i < 3) return {(4 * l[i] - 1) * dl[i][0], (4 * l[i] - 1) * dl[i][1]};
      const int a = i - 3, b = (i - 2) % 3;  // mid-side node between corners a and b
      return {4 * (dl[a][0] * l[b] + l[a] * dl[b][0]), 4 * (dl[a][1] * l[b] + l[a] * dl[b][1])};
    }
    case Shape::Quad4: {
      const auto c = corner_point(shape, i);
      return {0.25 * c[0] * (1 + eta * c[1]), 0.25 * c[1] * (1 + xi * c[0])};
    }
    case Shape::Quad8: {
      if (i < 4) {
        const auto c = corner_point(shape, i);
        return {0.25 * c[0] * (1 + eta * c[1]) * (2 * xi * c[0] + eta * c[1]),
                0.25 * c[1] * (1 + xi * c[0]) * (xi * c[0] + 2 * eta * c[1])};
      }
      constexpr double mid[4][2] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
      const double mx = mid[i - 4][0], my = mid[i - 4][1];
      if (mx == 0) return {-xi * (1 + eta * my), 0.5 * (1 - xi * xi) * my};
      return {0.5 * mx * (1 - eta * eta), -eta * (1 + xi * mx)};
    }
  }
  return {0, 0};
}

void resolve_sections(DeckState& state) {
  Model& m = state.model;
  for (std::size_t s = 0; s < m.sections.size(); ++s) {
    SolidSection& section = m.sections[s];
    const std::string& material = state.section_material[s];
    const auto it = std::find_if(m.materials.begin(), m.materials.end(),
                                 [&](const MaterialData& md) { return md.name == material; });
    if (it == m.materials.end())
      throw InputError(section.where, "*SOLID SECTION for ELSET " + section.elset + " uses undefined material " +
                                          material + ": expected a *MATERIAL, NAME=" + material);
    section.material = static_cast<int>(it - m.materials.begin());
    for (int e : m.element_sets.at(section.elset)) {
      Element& element = m.elements[static_cast<std::size_t>(e)];
      if (element.section >= 0)
        throw InputError(section.where, "element " + label_text(m.instances, element.id) +
                                            " is in two sections: it already has the section at " +
                                            m.sections[static_cast<std::size_t>(element.section)].where.str() +
                                            " (expected each element in exactly one *SOLID SECTION)");
      element.section = static_cast<int>(s);
    }
  }
  for (const Element& e : m.elements)
    if (e.section < 0)
      throw InputError(m.location(e.where), "element " + label_text(m.instances, e.id) + " (" +
                                                std::string(e.type.name) +
                                                ") has no section: expected a *SOLID SECTION whose ELSET contains it");
}

void check_materials(const Model& m) {
  for (const MaterialData& md : m.materials)
    if (!md.elastic && !md.neo_hooke && !md.user)
      throw InputError(md.where, "material " + md.name + " has no elastic data: expected *ELASTIC, "
                                                          "*HYPERELASTIC, NEO HOOKE or *USER MATERIAL after *MATERIAL");
}

void check_geometry(const Model& m) {
  for (const Element& e : m.elements) {
    double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
    for (int n : e.nodes) {
      const auto& x = m.coords[static_cast<std::size_t>(n)];
      xmin = std::min(xmin, x.x()), xmax = std::max(xmax, x.x());
      ymin = std::min(ymin, x.y()), ymax = std::max(ymax, x.y());
      if (e.type.family == Family::Axisymmetric && x.x() < 0)
        throw InputError(m.location(e.where), "axisymmetric element " + label_text(m.instances, e.id) +
                                                  " has node " +
                                                  label_text(m.instances, m.node_ids[static_cast<std::size_t>(n)]) +
                                                  " at radius r = x < 0: expected r >= 0");
    }
    const double scale = std::max((xmax - xmin) * (xmax - xmin), (ymax - ymin) * (ymax - ymin));
    const auto dets = corner_jacobians(m, e);
    for (std::size_t c = 0; c < dets.size(); ++c)
      if (!(dets[c] > 1e-12 * scale))
        throw InputError(m.location(e.where), "element " + label_text(m.instances, e.id) + " (" +
                                                  std::string(e.type.name) + ") is inverted or degenerate: Jacobian " +
                                                  std::to_string(dets[c]) + " <= 0 at corner node " +
                                                  label_text(m.instances,
                                                             m.node_ids[static_cast<std::size_t>(e.nodes[c])]) +
                                                  " (expected corners numbered counter-clockwise and a convex shape)");
  }
}

/// Every element a body load acts on has a density (its material's *DENSITY).
void check_body_load_densities(const Model& m) {
  for (const Step& step : m.steps)
    for (const BodyLoad& b : step.body_loads) {
      const Element& e = m.elements[static_cast<std::size_t>(b.element)];
      const MaterialData& material =
          m.materials[static_cast<std::size_t>(m.sections[static_cast<std::size_t>(e.section)].material)];
      if (!material.density)
        throw InputError(b.where, std::string(b.kind == BodyLoad::Kind::Gravity ? "GRAV" : "CENTRIF") +
                                      " on element " + label_text(m.instances, e.id) + " needs the density of its material " +
                                      material.name + ": expected *DENSITY under *MATERIAL, NAME=" + material.name +
                                      " (" + material.where.str() + ")");
    }
}

/// No plane-stress element of a user material in an NLGEOM step: tether does
/// not know a user material's thickness stretch under finite strain.
void check_user_material_plane_stress(const Model& m) {
  for (const Step& step : m.steps) {
    if (!step.nlgeom) continue;
    for (const Element& e : m.elements) {
      const MaterialData& material =
          m.materials[static_cast<std::size_t>(m.sections[static_cast<std::size_t>(e.section)].material)];
      if (material.user && e.type.family == Family::PlaneStress)
        throw InputError(step.where, "NLGEOM with the plane-stress element " + label_text(m.instances, e.id) + " (" +
                                         std::string(e.type.name) + ") of user material " + material.name + " (" +
                                         material.user->where.str() +
                                         "): a user material's thickness stretch is not known under finite "
                                         "strain; expected CPE or CAX elements, or the step without NLGEOM");
    }
  }
}

}  // namespace

std::vector<double> corner_jacobians(const Model& model, const Element& e) {
  const Shape shape = e.type.shape;
  std::vector<double> dets;
  for (int c = 0; c < n_corners(shape); ++c) {
    const auto p = corner_point(shape, c);
    double j[2][2] = {{0, 0}, {0, 0}};  // j[i][k] = d x_i / d xi_k
    for (int i = 0; i < e.type.n_nodes; ++i) {
      const auto g = shape_gradient(shape, i, p[0], p[1]);
      const auto& x = model.coords[static_cast<std::size_t>(e.nodes[static_cast<std::size_t>(i)])];
      for (int k = 0; k < 2; ++k) j[0][k] += g[k] * x.x(), j[1][k] += g[k] * x.y();
    }
    dets.push_back(j[0][0] * j[1][1] - j[0][1] * j[1][0]);
  }
  return dets;
}

void check_model(DeckState& state) {
  check_materials(state.model);
  resolve_sections(state);
  check_body_load_densities(state.model);
  check_user_material_plane_stress(state.model);
  check_geometry(state.model);
}

}  // namespace tether::deck
