#include "tether/materials/constitutive_model.hpp"

#include "tether/materials/linear_elastic.hpp"
#include "tether/materials/neo_hooke.hpp"

namespace tether {

namespace {

[[noreturn]] void fail(const MaterialData& data, const std::string& what) {
  const std::string where = data.where.file.empty() ? std::string{} : data.where.str() + ": ";
  throw ModelError(where + "material " + data.name + ": " + what);
}

}  // namespace

std::unique_ptr<ConstitutiveModel> make_constitutive_model(const MaterialData& data) {
  if (data.elastic && data.neo_hooke)
    fail(data, "both *ELASTIC and *HYPERELASTIC are given; keep one");
  if (data.elastic) {
    const auto& e = *data.elastic;
    if (!(e.young > 0)) fail(data, "Young's modulus must be positive (got " + std::to_string(e.young) + ")");
    if (!(e.poisson > -1 && e.poisson < 0.5))
      fail(data, "Poisson's ratio must lie in (-1, 0.5) (got " + std::to_string(e.poisson) + ")");
    return std::make_unique<LinearElastic>(e.young, e.poisson);
  }
  if (data.neo_hooke) {
    const auto& n = *data.neo_hooke;
    if (!(n.c10 > 0)) fail(data, "NEO HOOKE C10 must be positive (got " + std::to_string(n.c10) + ")");
    if (!(n.d1 > 0))
      fail(data, "NEO HOOKE D1 must be positive; D1 = 0 (incompressible) needs a hybrid "
                 "formulation, which tether does not provide");
    return std::make_unique<NeoHooke>(n.c10, n.d1);
  }
  fail(data, "no *ELASTIC or *HYPERELASTIC, NEO HOOKE definition");
}

Mat6 isotropic_stiffness(double lambda, double mu) {
  Mat6 D = Mat6::Zero();
  D.topLeftCorner<3, 3>().setConstant(lambda);
  for (int i = 0; i < 3; ++i) {
    D(i, i) += 2 * mu;
    D(3 + i, 3 + i) = mu;
  }
  return D;
}

Vec6 to_voigt_strain(const Eigen::Matrix3d& e) {
  Vec6 v;
  v << e(0, 0), e(1, 1), e(2, 2), 2 * e(0, 1), 2 * e(1, 2), 2 * e(0, 2);
  return v;
}

Eigen::Matrix3d from_voigt_stress(const Vec6& s) {
  Eigen::Matrix3d m;
  m << s(0), s(3), s(5),  //
      s(3), s(1), s(4),   //
      s(5), s(4), s(2);
  return m;
}

}  // namespace tether
