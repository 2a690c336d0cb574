#pragma once
// Test helper: structured blocks of CPE4/CPE8 elements written to decks, with
// their side faces and surfaces (tie, periodic and contact tests).

#include <Eigen/Core>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace tether::testing {

/// A structured block of CPE4 or CPE8 elements on [x0,x1] x [y0,y1] written to
/// a deck, with its outer faces (for consistent traction loads).
struct Block {
  double x0, x1, y0, y1;
  int nx, ny;
  bool quadratic;
  int first_node, first_element;
  std::string elset;

  [[nodiscard]] int grid(int i, int j) const { return first_node + j * (quadratic ? 2 * nx + 1 : nx + 1) + i; }
  [[nodiscard]] int step() const { return quadratic ? 2 : 1; }
  [[nodiscard]] Eigen::Vector2d position(int i, int j) const {
    const int mx = nx * step(), my = ny * step();
    return {x0 + (x1 - x0) * i / mx, y0 + (y1 - y0) * j / my};
  }
  /// Nodes of element (ex, ey) in ABAQUS order.
  [[nodiscard]] std::vector<int> element_nodes(int ex, int ey) const {
    const int k = step(), i = ex * k, j = ey * k;
    std::vector<int> n{grid(i, j), grid(i + k, j), grid(i + k, j + k), grid(i, j + k)};
    if (quadratic) {
      n.push_back(grid(i + 1, j));
      n.push_back(grid(i + 2, j + 1));
      n.push_back(grid(i + 1, j + 2));
      n.push_back(grid(i, j + 1));
    }
    return n;
  }
  [[nodiscard]] int element(int ex, int ey) const { return first_element + ey * nx + ex; }

  void write(std::ostream& d, const std::string& material_set = "") const {
    d.precision(17);
    d << "*NODE\n";
    const int mx = nx * step(), my = ny * step();
    for (int j = 0; j <= my; ++j)
      for (int i = 0; i <= mx; ++i) {
        if (quadratic && i % 2 == 1 && j % 2 == 1) continue;  // no centre nodes in CPE8
        const auto x = position(i, j);
        d << grid(i, j) << ", " << x.x() << ", " << x.y() << "\n";
      }
    d << "*ELEMENT, TYPE=" << (quadratic ? "CPE8" : "CPE4") << ", ELSET=" << (material_set.empty() ? elset : material_set)
      << "\n";
    for (int ey = 0; ey < ny; ++ey)
      for (int ex = 0; ex < nx; ++ex) {
        d << element(ex, ey);
        for (int n : element_nodes(ex, ey)) d << ", " << n;
        d << "\n";
      }
  }

  /// Faces on side `side` (0 bottom, 1 right, 2 top, 3 left) as node lists
  /// (corners then mid-side node) with the side's outward normal.
  [[nodiscard]] std::vector<std::vector<int>> side_faces(int side) const {
    std::vector<std::vector<int>> faces;
    const int count = side % 2 == 0 ? nx : ny;
    for (int k = 0; k < count; ++k) {
      const int ex = side == 0 || side == 2 ? k : (side == 1 ? nx - 1 : 0);
      const int ey = side == 1 || side == 3 ? k : (side == 0 ? 0 : ny - 1);
      const auto n = element_nodes(ex, ey);
      std::vector<int> face{n[static_cast<std::size_t>(side)], n[static_cast<std::size_t>((side + 1) % 4)]};
      if (quadratic) face.push_back(n[static_cast<std::size_t>(4 + side)]);
      faces.push_back(face);
    }
    return faces;
  }
  /// `*SURFACE` of side `side` (S1..S4 of the elements along it).
  void write_surface(std::ostream& d, const std::string& name, int side) const {
    d << "*SURFACE, NAME=" << name << "\n";
    const int count = side % 2 == 0 ? nx : ny;
    for (int k = 0; k < count; ++k) {
      const int ex = side == 0 || side == 2 ? k : (side == 1 ? nx - 1 : 0);
      const int ey = side == 1 || side == 3 ? k : (side == 0 ? 0 : ny - 1);
      d << element(ex, ey) << ", S" << side + 1 << "\n";
    }
  }
};

inline std::map<int, Eigen::Vector2d> node_positions(const Block& b) {
  std::map<int, Eigen::Vector2d> x;
  const int mx = b.nx * b.step(), my = b.ny * b.step();
  for (int j = 0; j <= my; ++j)
    for (int i = 0; i <= mx; ++i) x[b.grid(i, j)] = b.position(i, j);
  return x;
}

}  // namespace tether::testing
