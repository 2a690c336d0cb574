#include <gtest/gtest.h>

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
