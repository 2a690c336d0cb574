#include <gtest/gtest.h>

#include "tether/materials/constitutive_model.hpp"
#include "tether/materials/linear_elastic.hpp"
#include "tether/materials/neo_hooke.hpp"

using namespace tether;

namespace {

MaterialData elastic(double E, double nu) {
  MaterialData d;
  d.name = "STEEL";
  d.elastic = MaterialData::Elastic{E, nu};
  d.where = {"deck.inp", 12};
  return d;
}

MaterialData neo(double c10, double d1) {
  MaterialData d;
  d.name = "RUBBER";
  d.neo_hooke = MaterialData::NeoHooke{c10, d1};
  d.where = {"deck.inp", 20};
  return d;
}

std::string error_of(const MaterialData& d) {
  try {
    make_constitutive_model(d);
  } catch (const ModelError& e) {
    return e.what();
  }
  return {};
}

}  // namespace

TEST(ConstitutiveModelFactory, BuildsTheRequestedModel) {
  EXPECT_NE(dynamic_cast<LinearElastic*>(make_constitutive_model(elastic(210e3, 0.3)).get()), nullptr);
  const auto m = make_constitutive_model(neo(0.5, 0.1));
  const auto* nh = dynamic_cast<NeoHooke*>(m.get());
  ASSERT_NE(nh, nullptr);
  EXPECT_DOUBLE_EQ(nh->shear_modulus(), 1.0);
  EXPECT_DOUBLE_EQ(nh->bulk_modulus(), 20.0);
}

TEST(ConstitutiveModelFactory, RefusesMissingBothOrBadConstantsNamingTheMaterial) {
  MaterialData none;
  none.name = "EMPTY";
  EXPECT_NE(error_of(none).find("material EMPTY"), std::string::npos);
  MaterialData both = elastic(1, 0.3);
  both.neo_hooke = MaterialData::NeoHooke{1, 1};
  EXPECT_NE(error_of(both).find("both"), std::string::npos);
  EXPECT_NE(error_of(elastic(-1, 0.3)).find("deck.inp:12"), std::string::npos);
  EXPECT_NE(error_of(elastic(1, 0.5)).find("Poisson"), std::string::npos);
  EXPECT_NE(error_of(neo(0, 0.1)).find("C10"), std::string::npos);
  EXPECT_NE(error_of(neo(1, 0)).find("incompressible"), std::string::npos);
}

TEST(ConstitutiveModelFactory, NeoHookeSmallStrainUsesInitialModuli) {
  const NeoHooke m(0.5, 0.1);  // mu = 1, K = 20
  Vec6 eps = Vec6::Zero(), sigma;
  Mat6 D;
  eps << 1e-3, 1e-3, 1e-3, 0, 0, 0;  // volumetric: p = K * 3e-3
  m.small_strain(eps, sigma, D);
  EXPECT_NEAR(sigma(0), 20 * 3e-3, 1e-14);
  eps << 0, 0, 0, 2e-3, 0, 0;  // shear: tau = mu gamma
  m.small_strain(eps, sigma, D);
  EXPECT_NEAR(sigma(3), 2e-3, 1e-15);
}
