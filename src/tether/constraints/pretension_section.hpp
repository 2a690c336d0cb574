#pragma once
/// \file Cutting a mesh along a bolt pretension section (`*PRE-TENSION
/// SECTION`) and the linear equations that join the cut again, less the
/// tightening. Geometry and bookkeeping on the model only; the equations are
/// enforced like any *EQUATION. Theory: docs/theory/pretension.md.

#include <Eigen/Core>
#include <stdexcept>
#include <utility>
#include <vector>

#include "tether/model/model.hpp"

namespace tether {

/// Outward unit normal of one element face, from its corner chord (the
/// elements are counter-clockwise); zero for a face of zero length.
Eigen::Vector2d face_outward_normal(const Model& model, const ElementFace& face);

/// Length-weighted mean of the faces' outward normals, normalised: the sum of
/// their chords turned outward. Zero when they cancel out (or there are none).
Eigen::Vector2d mean_outward_normal(const Model& model, const std::vector<ElementFace>& faces);

/// Cuts `model` along `faces` (the faces of the elements on one side of the
/// cut, all with outward normals along `normal`, a unit vector):
/// - every node of the faces gets a duplicate at the same place, labelled
///   above the largest node label and every instance's label range
///   (appended to the model's nodes);
/// - the faces' elements, and every other element using a node of the faces
///   whose centroid lies behind it (on the faces' side, (x_c - x_node)·n < 0),
///   use the duplicate from then on;
/// - the original stays with the elements on the far side.
/// Returns the pairs (original, duplicate) in the order the faces first name
/// the nodes. Throws std::invalid_argument with a message naming the face or
/// node (labels as the user knows them) when a face points against `normal`
/// or when an original keeps no element: the faces do not cut the mesh.
std::vector<std::pair<int, int>> cut_mesh_along(Model& model, const std::vector<ElementFace>& faces,
                                                const Eigen::Vector2d& normal);

/// The section's equations (each a list of terms summing to 0), with u_p the
/// pretension node's dof 1 and t = (-n_y, n_x):
/// per pair (a = original, b = duplicate), (u_b - u_a)·t = 0 and
/// (u_b - u_a)·n - u_p = 0; last, u_{p,2} = 0 (the pretension node has no
/// other dof). Coefficients of magnitude below 1e-12 are left out.
std::vector<std::vector<EquationTerm>> pretension_equations(const std::vector<std::pair<int, int>>& pairs,
                                                            const Eigen::Vector2d& normal, int pretension_node);

}  // namespace tether
