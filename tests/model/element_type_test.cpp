#include <gtest/gtest.h>

#include "tether/model/element_type.hpp"

using namespace tether;

TEST(ElementType, LooksUpNamesCaseInsensitively) {
  auto t = find_element_type("cpe8r");
  ASSERT_TRUE(t);
  EXPECT_EQ(t->n_nodes, 8);
  EXPECT_EQ(t->family, Family::PlaneStrain);
  EXPECT_TRUE(t->reduced);
  EXPECT_FALSE(find_element_type("C3D8"));
}

TEST(ElementType, RefusesReducedFourNodeWithReason) {
  EXPECT_NE(unsupported_reason(*find_element_type("CPE4R")).find("hourglass"), std::string::npos);
  EXPECT_TRUE(unsupported_reason(*find_element_type("CAX8R")).empty());
}

TEST(ElementType, FacesFollowAbaqusNumbering) {
  EXPECT_EQ(face_nodes(Shape::Quad4, 3), (std::array<int, 3>{3, 0, -1}));
  EXPECT_EQ(face_nodes(Shape::Tri6, 2), (std::array<int, 3>{2, 0, 5}));
  EXPECT_EQ(face_nodes(Shape::Quad8, 1), (std::array<int, 3>{1, 2, 5}));
}
