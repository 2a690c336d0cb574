#include "tether/model/element_type.hpp"

#include <algorithm>
#include <cctype>
#include <deque>
#include <mutex>

namespace tether {

namespace {

constexpr ElementType kCatalogue[] = {
    {"CPE3", Family::PlaneStrain, Shape::Tri3, 3, false},
    {"CPE4", Family::PlaneStrain, Shape::Quad4, 4, false},
    {"CPE4R", Family::PlaneStrain, Shape::Quad4, 4, true},
    {"CPE6", Family::PlaneStrain, Shape::Tri6, 6, false},
    {"CPE8", Family::PlaneStrain, Shape::Quad8, 8, false},
    {"CPE8R", Family::PlaneStrain, Shape::Quad8, 8, true},
    {"CPS3", Family::PlaneStress, Shape::Tri3, 3, false},
    {"CPS4", Family::PlaneStress, Shape::Quad4, 4, false},
    {"CPS4R", Family::PlaneStress, Shape::Quad4, 4, true},
    {"CPS6", Family::PlaneStress, Shape::Tri6, 6, false},
    {"CPS8", Family::PlaneStress, Shape::Quad8, 8, false},
    {"CPS8R", Family::PlaneStress, Shape::Quad8, 8, true},
    {"CAX3", Family::Axisymmetric, Shape::Tri3, 3, false},
    {"CAX4", Family::Axisymmetric, Shape::Quad4, 4, false},
    {"CAX4R", Family::Axisymmetric, Shape::Quad4, 4, true},
    {"CAX6", Family::Axisymmetric, Shape::Tri6, 6, false},
    {"CAX8", Family::Axisymmetric, Shape::Quad8, 8, false},
    {"CAX8R", Family::Axisymmetric, Shape::Quad8, 8, true},
    // Hybrid: only the constant-pressure 4-node elements are supported.
    {"CPE4H", Family::PlaneStrain, Shape::Quad4, 4, false, true},
    {"CAX4H", Family::Axisymmetric, Shape::Quad4, 4, false, true},
    {"CPE3H", Family::PlaneStrain, Shape::Tri3, 3, false, true},
    {"CPE4RH", Family::PlaneStrain, Shape::Quad4, 4, true, true},
    {"CPE6H", Family::PlaneStrain, Shape::Tri6, 6, false, true},
    {"CPE8H", Family::PlaneStrain, Shape::Quad8, 8, false, true},
    {"CPE8RH", Family::PlaneStrain, Shape::Quad8, 8, true, true},
    {"CAX3H", Family::Axisymmetric, Shape::Tri3, 3, false, true},
    {"CAX4RH", Family::Axisymmetric, Shape::Quad4, 4, true, true},
    {"CAX6H", Family::Axisymmetric, Shape::Tri6, 6, false, true},
    {"CAX8H", Family::Axisymmetric, Shape::Quad8, 8, false, true},
    {"CAX8RH", Family::Axisymmetric, Shape::Quad8, 8, true, true},
    // Not an ABAQUS name: what FAMILY=PLANE STRESS of *SOLID SECTION makes of CPE4H or CAX4H.
    {"CPS4H", Family::PlaneStress, Shape::Quad4, 4, false, true},
};

bool iequals(std::string_view a, std::string_view b) {
  return a.size() == b.size() &&
         std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::toupper(static_cast<unsigned char>(x)) ==
                  std::toupper(static_cast<unsigned char>(y));
         });
}

std::string plane_stress_hybrid_reason(const std::string& name) {
  return "plane-stress elements have no hybrid form (ABAQUS has none: the pressure of a plane-stress element "
         "follows from sigma_33 = 0, so there is nothing to interpolate); use " +
         name.substr(0, name.size() - 1) + " instead";
}

}  // namespace

const ElementType& intern_element_type(const ElementType& type) {
  static std::mutex mutex;
  static std::deque<ElementType> stored;  // a deque: references stay valid as it grows
  const std::scoped_lock lock(mutex);
  for (const ElementType& t : stored)
    if (t.name == type.name && t.family == type.family && t.shape == type.shape && t.n_nodes == type.n_nodes &&
        t.reduced == type.reduced && t.hybrid == type.hybrid)
      return t;
  return stored.emplace_back(type);
}

std::optional<ElementType> find_element_type(std::string_view name) {
  for (const auto& t : kCatalogue)
    if (iequals(t.name, name)) return t;
  return std::nullopt;
}

int line_element_nodes(std::string_view name) {
  if (name == "T3D2" || name == "T2D2") return 2;
  if (name == "T3D3" || name == "T2D3") return 3;
  return 0;
}

std::string unsupported_reason(const ElementType& type) {
  const std::string name(type.name);
  if (type.hybrid && type.family == Family::PlaneStress)
    return plane_stress_hybrid_reason(name);
  if (type.hybrid && type.shape == Shape::Tri3)
    return "the hybrid 3-node element " + name +
           " has one integration point, so its constant pressure adds nothing for a compressible material, and "
           "tether does not solve for the pressure of an incompressible one; use CPE4H or CAX4H";
  if (type.hybrid && type.reduced && type.shape == Shape::Quad4)
    return "the reduced-integration hybrid element " + name +
           " needs hourglass control, which tether does not provide; use the fully integrated " +
           std::string(type.family == Family::Axisymmetric ? "CAX4H" : "CPE4H") + " instead";
  if (type.hybrid && type.shape != Shape::Quad4)
    return "ABAQUS interpolates the pressure of its 6- and 8-node hybrid elements such as " + name +
           " linearly, which tether does not implement; tether's hybrid elements are the constant-pressure "
           "(mean-dilatation) CPE4H and CAX4H";
  if (type.reduced && (type.shape == Shape::Quad4))
    return "reduced-integration 4-node element " + std::string(type.name) +
           " needs hourglass control, which tether does not provide; use the "
           "fully integrated " +
           std::string(type.name.substr(0, type.name.size() - 1)) + " instead";
  return {};
}

std::string unknown_element_reason(std::string_view name) {
  const std::string n(name);
  const bool plane_stress_hybrid =
      n.size() > 4 && iequals(n.substr(0, 3), "CPS") && std::toupper(static_cast<unsigned char>(n.back())) == 'H';
  if (plane_stress_hybrid) return plane_stress_hybrid_reason(n);
  return "tether has 2D continuum elements only; expected one of CPE3, CPE4, CPE4H, CPE6, CPE8, CPE8R, CPS3, "
         "CPS4, CPS6, CPS8, CPS8R, CAX3, CAX4, CAX4H, CAX6, CAX8, CAX8R (or the line elements T2D2, T2D3, T3D2, "
         "T3D3, which only name faces)";
}

int n_corners(Shape shape) { return (shape == Shape::Tri3 || shape == Shape::Tri6) ? 3 : 4; }

int n_faces(Shape shape) { return n_corners(shape); }

int n_face_nodes(Shape shape) { return (shape == Shape::Tri3 || shape == Shape::Quad4) ? 2 : 3; }

std::array<int, 3> face_nodes(Shape shape, int face) {
  const int nc = n_corners(shape);
  const int a = face;
  const int b = (face + 1) % nc;
  const int mid = n_face_nodes(shape) == 3 ? nc + face : -1;
  return {a, b, mid};
}

}  // namespace tether
