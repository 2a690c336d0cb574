#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "tether/dofs/dof_map.hpp"

using namespace tether;

TEST(DofMap, NumbersMultipliersAfterDisplacements) {
  DofMap map({10, 20, 30});
  EXPECT_EQ(map.n_displacement_dofs(), 6);
  EXPECT_EQ(map.displacement(2, 1), 5);
  const int first = map.add_multipliers(2, "constraint LINK-1");
  EXPECT_EQ(first, 6);
  EXPECT_EQ(map.n_dofs(), 8);
  EXPECT_EQ(map.n_multipliers(), 2);
  EXPECT_EQ(map.describe(3), "node 20 dof 2");
  EXPECT_EQ(map.describe(7), "multiplier 2 of constraint LINK-1");
}

TEST(DofMap, RotationMapsToItsNodeNotPastTheMesh) {
  // 4 nodes (8 displacement dofs), a multiplier block, then the rotation of
  // node index 3: dof 10, whose dof / 2 = 5 would name a node outside the mesh.
  DofMap map({1, 2, 3, 100});
  const int lambda = map.add_multipliers(2, "constraint MPC-1 BEAM");
  const int theta = map.add_rotation(3);
  ASSERT_EQ(lambda, 8);
  ASSERT_EQ(theta, 10);
  EXPECT_EQ(map.add_rotation(3), theta);  // one rotation per node
  EXPECT_EQ(map.rotation(3), theta);
  EXPECT_EQ(map.rotation(0), -1);
  EXPECT_EQ(map.node_of(theta), 3);
  EXPECT_EQ(map.component_of(theta), kRotationComponent);
  EXPECT_TRUE(map.is_rotation(theta));
  EXPECT_FALSE(map.is_multiplier(theta));
  EXPECT_EQ(map.describe(theta), "node 100 dof 6 (rotation)");
  EXPECT_EQ(map.n_multipliers(), 2);
  EXPECT_EQ(map.n_dofs(), 11);
}

TEST(DofMap, DisplacementDofsRoundTrip) {
  const DofMap map({5, 6, 7});
  for (int node = 0; node < map.n_nodes(); ++node)
    for (int c = 0; c < kDofsPerNode; ++c) {
      const int dof = map.displacement(node, c);
      EXPECT_EQ(map.node_of(dof), node);
      EXPECT_EQ(map.component_of(dof), c);
      EXPECT_FALSE(map.is_rotation(dof));
    }
}

TEST(DofMap, MultiplierIsNoNodalUnknown) {
  DofMap map({10, 20});
  const int lambda = map.add_multipliers(1, "constraint LINK-1");
  map.add_rotation(1);
  for (const auto& call : {+[](const DofMap& m, int d) { return m.node_of(d); },
                           +[](const DofMap& m, int d) { return m.component_of(d); }}) {
    try {
      call(map, lambda);
      ADD_FAILURE() << "a multiplier was given a node";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("multiplier 1 of constraint LINK-1 is a multiplier"), std::string::npos)
          << e.what();
    }
    EXPECT_THROW(call(map, map.n_dofs()), std::invalid_argument);
    EXPECT_THROW(call(map, -1), std::invalid_argument);
  }
  EXPECT_FALSE(map.is_rotation(lambda));
}
