#pragma once
// A hand-made mesh of every element shape (two CPE4, one CPE8, one CPE6, one
// CPE3) with non-contiguous labels, and synthetic results with known values.

#include <cstdlib>
#include <filesystem>
#include <string>

#include "tether/model/model.hpp"
#include "tether/model/results.hpp"

namespace tether::test {

/// Node labels 11..25 (not in index order), element labels 101..105.
/// Sets: NSET LEFT = labels {11, 14, 22}; ELSET QUADS = elements {101, 103}.
inline Model tiny_model() {
  Model m;
  const struct { int label; double x, y; } nodes[] = {
      {11, 0, 0},   {12, 1, 0},     {13, 1, 1},   {14, 0, 1},   {19, 2, 0},
      {20, 2, 1},   {15, 1.5, 0},   {16, 2, 0.5}, {17, 1.5, 1}, {18, 1, 0.5},
      {21, 1, 2},   {22, 0, 2},     {23, 1.5, 1.5}, {24, 1, 1.5}, {25, 2, 2}};
  for (const auto& n : nodes) {
    m.node_index[n.label] = m.n_nodes();
    m.node_ids.push_back(n.label);
    m.coords.emplace_back(n.x, n.y);
  }
  const auto add = [&m](int id, const char* type, std::vector<int> labels) {
    Element e;
    e.id = id;
    e.type = *find_element_type(type);
    for (const int l : labels) e.nodes.push_back(m.node_index.at(l));
    m.element_index[id] = m.n_elements();
    m.elements.push_back(e);
  };
  add(101, "CPE4", {11, 12, 13, 14});
  add(102, "CPE8", {12, 19, 20, 13, 15, 16, 17, 18});
  add(103, "CPE4", {14, 13, 21, 22});
  add(104, "CPE6", {13, 20, 21, 17, 23, 24});
  add(105, "CPE3", {20, 25, 21});
  m.node_sets["LEFT"] = {0, 3, 11};
  m.element_sets["QUADS"] = {0, 2};
  return m;
}

/// Number of integration points used for each shape in the synthetic results.
inline int n_points(Shape s) {
  switch (s) {
    case Shape::Tri3: return 1;
    case Shape::Quad4: return 4;
    case Shape::Tri6: return 3;
    case Shape::Quad8: return 9;
  }
  return 0;
}

/// Known values, scaled by `factor`, for node (x, y, label L):
///   U = factor (1e-3 x + 1e-6 L, -2e-3 y),  RF = factor (L, -L/2),
///   nodal S = factor (100 x, 200 y, 30 (x + y), 10 x y),  nodal E = 1e-5 S,
/// and at integration point k (0-based) of element E:
///   S = factor (E + k, -k, k/2, E/100 + 2k),  E(strain) = 1e-6 S.
inline IncrementResults synthetic_results(const Model& m, int step, int increment, double total_time,
                                          double factor) {
  IncrementResults r;
  r.step = step;
  r.increment = increment;
  r.total_time = total_time;
  r.step_time = total_time;
  for (int i = 0; i < m.n_nodes(); ++i) {
    const double x = m.coords[i].x(), y = m.coords[i].y(), L = m.node_ids[i];
    r.displacement.emplace_back(factor * (1e-3 * x + 1e-6 * L), factor * (-2e-3 * y));
    r.reaction.emplace_back(factor * L, -factor * L / 2);
    const Tensor4 s{factor * 100 * x, factor * 200 * y, factor * 30 * (x + y), factor * 10 * x * y};
    r.nodal_stress.push_back(s);
    r.nodal_strain.push_back({1e-5 * s[0], 1e-5 * s[1], 1e-5 * s[2], 1e-5 * s[3]});
  }
  for (const auto& e : m.elements) {
    std::vector<PointValues> points(static_cast<std::size_t>(n_points(e.type.shape)));
    for (std::size_t k = 0; k < points.size(); ++k) {
      const double kk = static_cast<double>(k);
      points[k].stress = {factor * (e.id + kk), factor * -kk, factor * kk / 2, factor * (e.id / 100.0 + 2 * kk)};
      for (int c = 0; c < 4; ++c) points[k].strain[c] = 1e-6 * points[k].stress[c];
    }
    r.points.push_back(points);
  }
  return r;
}

/// A fresh, empty directory under the build tree for one test.
inline std::filesystem::path fresh_directory(const std::string& name) {
  const auto dir = std::filesystem::path(TETHER_BINARY_DIR) / "test_output_files" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// Whole file as a string.
std::string read_text(const std::filesystem::path& file);

/// Files in `dir` whose name ends in ".tmp".
int count_temporary_files(const std::filesystem::path& dir);

/// True when /usr/bin/python3 exists and imports meshio and numpy.
bool python_with_meshio_available();

/// Runs /usr/bin/python3 with `arguments` (already quoted) and tools/ on PYTHONPATH (for
/// tethertools); returns its exit status.
int run_python(const std::string& arguments);

}  // namespace tether::test
