#pragma once
/// \file A bolt pretension section (`*PRE-TENSION SECTION`) as read: plain data.
///
/// The reader cuts the mesh along the section's surface: every node of the
/// surface gets a duplicate that the surface's own elements (and any other
/// element lying on their side of the cut) use from then on. Linear equations
/// join each pair again, except for a prescribed opening along the normal:
/// (u_b - u_a)·t = 0 and (u_b - u_a)·n - u_p = 0, with u_p the displacement
/// of the pretension node in its dof 1 (the tightening). See
/// docs/theory/pretension.md.

#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

#include "tether/core/error.hpp"

namespace tether {

/// One `*PRE-TENSION SECTION, SURFACE=, NODE=`.
struct PretensionSection {
  std::string constraint;  ///< name of its equations in Model::constraints ("PRETENSION-<SURFACE>")
  std::string surface;     ///< the element-face surface that cuts the bolt (upper case)
  int node = 0;            ///< pretension node index: dof 1 is the tightening u_p [length], its load the bolt force
  /// Unit normal of the section, pointing out of the surface's elements (the
  /// data line's, else the length-weighted mean of the faces' outward normals).
  Eigen::Vector2d normal{0, 1};
  /// Node pairs of the cut: (node kept by the far side, its duplicate used by
  /// the surface's side), node indices.
  std::vector<std::pair<int, int>> pairs;
  SourceLocation where;
};

}  // namespace tether
