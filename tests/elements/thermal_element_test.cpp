// A continuum element under a nodal temperature field: the point temperature
// is the shape-function interpolation of the nodal ones, and the tangent stays
// the Jacobian of the residual (central finite differences) for every element
// type and family, small strain and NLGEOM, with tabulated E, nu and alpha.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "element_fixtures.hpp"
#include "tether/elements/continuum_element.hpp"
#include "tether/materials/linear_elastic.hpp"
#include "tether/materials/thermal_model.hpp"

using namespace tether;
using namespace tether::test;

namespace {

/// Nodal temperatures T = 100 + 40 * node index (initial: 20 everywhere).
class LinearField final : public NodalTemperatureField {
 public:
  [[nodiscard]] double current(int node, double, double) const override { return 100 + 40.0 * node; }
  [[nodiscard]] double initial(int) const override { return 20; }
};

ThermalModel tabulated() {
  return ThermalModel(std::make_unique<LinearElastic>(200, 0.3), TemperatureTable{{0, 400}, {1e-3, 2e-3}}, 0,
                      TemperatureTable{{0, 200, 400}, {200, 150, 100}}, TemperatureTable{{0, 400}, {0.3, 0.2}});
}

}  // namespace

TEST(ThermalElement, TangentMatchesFiniteDifferencesUnderATemperatureField) {
  const ThermalModel material = tabulated();
  const LinearField field;
  int checked = 0;
  for (const ElementType& type : supported_types())
    for (bool nlgeom : {false, true}) {
      const int n = n_nodes(type.shape);
      const DofMap dofs(std::vector<int>(n + 1, 0));
      std::vector<int> nodes(n);
      std::iota(nodes.begin(), nodes.end(), 1);
      const std::vector<Eigen::Vector2d> coords = coordinate_table(nodes, distorted_element(type.shape));
      ContinuumElement e(3, type, nodes, coords, material, 0.5, dofs);
      e.set_temperatures(&field);
      EXPECT_TRUE(e.residual_depends_on_time()) << e.describe();  // the thermal strain follows the temperatures
      const Eigen::VectorXd u = random_vector(dofs.n_dofs(), nlgeom ? 0.1 : 0.02, 5);
      const LocalSystem sys = evaluate_at(e, u, nlgeom);
      const Eigen::MatrixXd fd = fd_tangent(e, u, nlgeom, 1e-6);
      EXPECT_LT(max_abs(fd - sys.tangent), 1e-6 * max_abs(sys.tangent)) << e.describe() << " nlgeom " << nlgeom;
      // Without displacements the element is loaded by its thermal strain alone.
      const LocalSystem at_rest = evaluate_at(e, Eigen::VectorXd::Zero(dofs.n_dofs()), nlgeom);
      EXPECT_GT(max_abs(at_rest.residual), 0.0) << e.describe();
      ++checked;
    }
  EXPECT_EQ(checked, 17 * 2);
}

TEST(ThermalElement, UniformFieldExpandsAPlaneStressElementFreely) {
  // Free expansion of a CPS4 under a uniform field: zero residual at u = eps_th * X.
  class Uniform final : public NodalTemperatureField {
   public:
    [[nodiscard]] double current(int, double, double) const override { return 250; }
    [[nodiscard]] double initial(int) const override { return 20; }
  } field;
  const ThermalModel material = tabulated();
  const ElementType type = *find_element_type("CPS4");
  const DofMap dofs(std::vector<int>(4, 0));
  const std::vector<Eigen::Vector2d> x = distorted_element(type.shape);
  ContinuumElement e(1, type, std::vector<int>{0, 1, 2, 3}, x, material, 1, dofs);
  e.set_temperatures(&field);
  const double eth = thermal_strain(TemperatureTable{{0, 400}, {1e-3, 2e-3}}, 0, 250, 20);
  Eigen::VectorXd u(8);
  for (int a = 0; a < 4; ++a) u.segment<2>(2 * a) = eth * x[static_cast<std::size_t>(a)];
  EXPECT_LT(max_abs(evaluate_at(e, u, false).residual), 1e-12);
  EXPECT_GT(max_abs(evaluate_at(e, Eigen::VectorXd::Zero(8), false).residual), 1e-3);
}
