#include "tether/model/element_type.hpp"

#include <algorithm>
#include <cctype>

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
};

bool iequals(std::string_view a, std::string_view b) {
  return a.size() == b.size() &&
         std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::toupper(static_cast<unsigned char>(x)) ==
                  std::toupper(static_cast<unsigned char>(y));
         });
}

}  // namespace

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
  if (type.reduced && (type.shape == Shape::Quad4))
    return "reduced-integration 4-node element " + std::string(type.name) +
           " needs hourglass control, which tether does not provide; use the "
           "fully integrated " +
           std::string(type.name.substr(0, type.name.size() - 1)) + " instead";
  return {};
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
