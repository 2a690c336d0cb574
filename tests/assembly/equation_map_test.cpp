// EquationMap: the rows of T it stores (only the dependent dofs'), the rows
// it hands out, and the reduction and expansion through them.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "tether/assembly/equation_map.hpp"
#include "tether/core/error.hpp"

using namespace tether;

TEST(EquationMap, WithoutConstraintsStoresNoRowAndMapsAFreeDofToItself) {
  // 7 dofs, 1 and 4 prescribed: equations 0..4 for dofs 0, 2, 3, 5, 6.
  std::vector<bool> prescribed(7, false);
  prescribed[1] = prescribed[4] = true;
  const EquationMap map(prescribed);
  EXPECT_EQ(map.n_equations(), 5);
  EXPECT_FALSE(map.has_dependents());
  EXPECT_EQ(map.n_stored_weights(), 0u);  // was one (equation, 1) pair per free dof
  for (int d = 0; d < 7; ++d) {
    EXPECT_FALSE(map.is_dependent(d));
    const WeightRow row = map.weights(d);
    if (prescribed[static_cast<std::size_t>(d)]) {
      EXPECT_TRUE(row.empty());
      EXPECT_EQ(row.begin(), row.end());
      EXPECT_EQ(map.equation(d), -1);
      continue;
    }
    ASSERT_EQ(row.size(), 1u);
    EXPECT_EQ(row[0].equation, map.equation(d));
    EXPECT_EQ(row[0].weight, 1.0);
    EXPECT_EQ(map.dof(row[0].equation), d);
    int seen = 0;
    for (const EquationWeight& w : map.weights(d)) seen += w.equation == map.equation(d) && w.weight == 1.0;
    EXPECT_EQ(seen, 1);
  }
  // A copy reads its own pair, not the original's (the row holds it by value).
  WeightRow copy;
  {
    const WeightRow original = map.weights(6);
    copy = original;
  }
  ASSERT_EQ(copy.size(), 1u);
  EXPECT_EQ(copy.begin()->equation, 4);
  EXPECT_EQ(copy.end() - copy.begin(), 1);
}

TEST(EquationMap, StoresTheDependentRowsOverFreeEquationsOnly) {
  // Dofs 0..5, dof 1 prescribed. Row 1: 2 u3 - u0 - 4 u1 = 2, so u3 = 0.5 u0
  // + 2 u1 + 1 (the prescribed u1 leaves no pair in T). Row 2: 2 u5 - 2 u3 +
  // u2 = 0, so u5 = u3 - 0.5 u2 = 0.5 u0 + 2 u1 - 0.5 u2 + 1 (the chain resolved).
  std::vector<bool> prescribed(6, false);
  prescribed[1] = true;
  EliminationRow first{{{3, 2.0}, {0, -1.0}, {1, -4.0}}, 2.0, "first"};
  EliminationRow second{{{5, 2.0}, {3, -2.0}, {2, 1.0}}, 0.0, "second"};
  const EquationMap map(prescribed, {first, second});
  ASSERT_EQ(map.dependent_of_row(0), 3);
  ASSERT_EQ(map.dependent_of_row(1), 5);
  EXPECT_TRUE(map.has_dependents());
  EXPECT_TRUE(map.is_dependent(3) && map.is_dependent(5));
  EXPECT_FALSE(map.is_dependent(0) || map.is_dependent(1) || map.is_dependent(2) || map.is_dependent(4));
  EXPECT_EQ(map.n_equations(), 3);  // dofs 0, 2, 4
  EXPECT_EQ(map.n_stored_weights(), 3u);  // u3: (u0); u5: (u0, u2)

  const WeightRow u3 = map.weights(3);
  ASSERT_EQ(u3.size(), 1u);
  EXPECT_EQ(u3[0].equation, map.equation(0));
  EXPECT_DOUBLE_EQ(u3[0].weight, 0.5);
  const WeightRow u5 = map.weights(5);
  ASSERT_EQ(u5.size(), 2u);
  EXPECT_EQ(u5[0].equation, map.equation(0));
  EXPECT_DOUBLE_EQ(u5[0].weight, 0.5);
  EXPECT_EQ(u5[1].equation, map.equation(2));
  EXPECT_DOUBLE_EQ(u5[1].weight, -0.5);
  EXPECT_TRUE(map.weights(1).empty());

  // T as a dense matrix (6 dofs x 3 equations): T^T r and the dependents' values.
  Eigen::MatrixXd t = Eigen::MatrixXd::Zero(6, 3);
  for (int d = 0; d < 6; ++d)
    for (const EquationWeight& w : map.weights(d)) t(d, w.equation) = w.weight;
  Eigen::VectorXd full(6), reduced;
  full << 1.5, -2.0, 0.25, 3.0, -1.0, 0.5;
  map.reduce(full, reduced);
  const Eigen::VectorXd expected = t.transpose() * full;
  EXPECT_LT((reduced - expected).norm(), 1e-15);
  Eigen::VectorXd u(6);
  u << 0.2, 0.1, -0.3, 0, 0.7, 0;
  map.update_dependents(u);
  EXPECT_DOUBLE_EQ(u[3], 0.5 * 0.2 + 2 * 0.1 + 1);
  EXPECT_DOUBLE_EQ(u[5], u[3] + 0.15);
}

TEST(EquationMap, ARedundantRowIsRefusedByName) {
  std::vector<bool> prescribed(2, false);
  prescribed[0] = true;
  EliminationRow row{{{0, 1.0}}, 0.0, "tie A"};
  try {
    const EquationMap map(prescribed, {row});
    FAIL() << "accepted a row on a prescribed dof only";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("tie A"), std::string::npos) << e.what();
  }
}
