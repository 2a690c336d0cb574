// Constraints computed outside the deck (ExternalConstraint, what the Python
// module builds from callables), enforced by the same constraint element.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "tether/io/deck_reader.hpp"
#include "tether/job/job.hpp"

using namespace tether;

namespace {

/// The seed's rigid link written as an external function: f = |x_b - x_a| - L.
class RigidLink final : public ExternalConstraint {
 public:
  mutable int evaluations = 0;
  bool poison = false;  ///< return NaN from the second evaluation on

  int n_equations() const override { return 1; }
  void evaluate(const Eigen::VectorXd& u, const Eigen::VectorXd& reference, double, double, Eigen::VectorXd& f,
                Eigen::MatrixXd& gradient, std::vector<Eigen::MatrixXd>* hessian) const override {
    ++evaluations;
    const Eigen::VectorXd x = reference + u;
    const Eigen::Vector2d d = x.segment<2>(2) - x.segment<2>(0);
    const double length = d.norm(), length0 = (reference.segment<2>(2) - reference.segment<2>(0)).norm();
    const Eigen::Vector2d n = d / length;
    f[0] = poison && evaluations > 1 ? std::numeric_limits<double>::quiet_NaN() : length - length0;
    gradient.block<1, 2>(0, 0) = -n.transpose();
    gradient.block<1, 2>(0, 2) = n.transpose();
    if (!hessian) return;
    const Eigen::Matrix2d a = (Eigen::Matrix2d::Identity() - n * n.transpose()) / length;
    Eigen::MatrixXd& h = (*hessian)[0];
    h.block<2, 2>(0, 0) = a, h.block<2, 2>(2, 2) = a, h.block<2, 2>(0, 2) = -a, h.block<2, 2>(2, 0) = -a;
  }
};

/// The rigid-link example with its *MPC LINK replaced by `link` (same name).
Model external_link_model(const std::shared_ptr<const ExternalConstraint>& link, Enforcement::Method method) {
  Model model = read_deck(std::string(TETHER_SOURCE_DIR) + "/examples/rigid_link/rigid_link.inp");
  ConstraintData& c = model.constraints.at(0);
  c.kind = ConstraintData::Kind::External;
  c.external = link;
  c.enforcement.method = method;
  if (method != Enforcement::Method::Lagrange) c.enforcement.penalty = 1e6, c.enforcement.tolerance = 1e-12;
  return model;
}

JobIncrement run_last(Model model) {
  Job job(std::move(model), JobOptions{.keep = JobOptions::Keep::Last});
  const JobSummary summary = job.run();
  EXPECT_TRUE(summary.completed) << summary.message;
  return job.results().back();
}

}  // namespace

TEST(ExternalConstraint, RigidLinkReproducesMpcLink) {
  const JobIncrement native = run_last(read_deck(std::string(TETHER_SOURCE_DIR) + "/examples/rigid_link/rigid_link.inp"));
  auto link = std::make_shared<RigidLink>();
  const JobIncrement external = run_last(external_link_model(link, Enforcement::Method::Lagrange));
  EXPECT_GT(link->evaluations, 20);
  for (std::size_t n = 0; n < 2; ++n) {
    EXPECT_NEAR((external.results.displacement[n] - native.results.displacement[n]).norm(), 0, 1e-10);
    EXPECT_NEAR((external.results.reaction[n] - native.results.reaction[n]).norm(), 0, 1e-10);
  }
  ASSERT_EQ(external.results.multipliers.size(), 1u);
  EXPECT_EQ(external.results.multipliers[0].owner, "LINK");
  EXPECT_NEAR(external.results.multipliers[0].value[0], native.results.multipliers[0].value[0], 1e-10);
}

TEST(ExternalConstraint, PenaltyAndAugmentedApproachTheLagrangeForce) {
  const JobIncrement lagrange =
      run_last(external_link_model(std::make_shared<RigidLink>(), Enforcement::Method::Lagrange));
  const double force = lagrange.results.multipliers[0].value[0];
  const JobIncrement augmented =
      run_last(external_link_model(std::make_shared<RigidLink>(), Enforcement::Method::Augmented));
  EXPECT_NEAR(augmented.results.multipliers[0].value[0], force, 1e-6 * force);
  const JobIncrement penalty =
      run_last(external_link_model(std::make_shared<RigidLink>(), Enforcement::Method::Penalty));
  // Penalty: the link stretches by f = lambda / rho (1.7e-5), which turns it a little.
  const MultiplierValues& p = penalty.results.multipliers[0];
  EXPECT_NEAR(p.value[0], force, 1e-3 * force);
  EXPECT_NEAR(p.constraint[0], p.value[0] / 1e6, 1e-12);
}

TEST(ExternalConstraint, NonFiniteValueStopsTheStepNamingTheConstraint) {
  auto link = std::make_shared<RigidLink>();
  link->poison = true;
  Job job(external_link_model(link, Enforcement::Method::Lagrange));
  const JobSummary summary = job.run();
  EXPECT_FALSE(summary.completed);
  EXPECT_NE(summary.message.find("LINK"), std::string::npos) << summary.message;
  EXPECT_NE(summary.message.find("not finite"), std::string::npos) << summary.message;
}
