// NewtonSolver's divergence test on a scripted one-equation problem: which
// growths of the residual count (docs/theory/newton.md, "Which growths count").

#include <gtest/gtest.h>

#include <vector>

#include "tether/analysis/newton.hpp"

namespace tether {
namespace {

/// Residual k is script[k] (k = the evaluation with a tangent), with
/// `changes[k]` contact nodes that changed their branch; the tangent is 1.
class ScriptedProblem final : public NewtonProblem {
 public:
  ScriptedProblem(std::vector<double> residuals, std::vector<int> changes)
      : residuals_(std::move(residuals)), changes_(std::move(changes)) {
    tangent_.resize(1, 1);
    tangent_.insert(0, 0) = 1.0;
    tangent_.makeCompressed();
  }
  bool evaluate(Eigen::VectorXd& residual, bool with_tangent, IterationNorms& norms, double& force_scale) override {
    const std::size_t k = std::min(calls_, residuals_.size() - 1);
    if (with_tangent) ++calls_;
    residual = Eigen::VectorXd::Constant(1, residuals_[k]);
    norms.force_residual = residuals_[k];
    norms.contact_closed = 1;
    norms.contact_changes = k < changes_.size() ? changes_[k] : 0;
    norms.increment = 1;
    force_scale = 1;
    return false;
  }
  [[nodiscard]] const SparseMatrix& tangent() const override { return tangent_; }
  void apply_correction(const Eigen::VectorXd&, double) override {}
  [[nodiscard]] double displacement_norm(const Eigen::VectorXd& c) const override { return c.cwiseAbs().maxCoeff(); }
  [[nodiscard]] bool symmetric() const override { return true; }
  [[nodiscard]] std::string describe_equation(int) const override { return "the equation"; }
  [[nodiscard]] bool is_multiplier_equation(int) const override { return false; }

 private:
  std::vector<double> residuals_;
  std::vector<int> changes_;
  std::size_t calls_ = 0;
  SparseMatrix tangent_;
};

NewtonOutcome solve(std::vector<double> residuals, std::vector<int> changes) {
  ScriptedProblem problem(std::move(residuals), std::move(changes));
  const auto solver = make_linear_solver(SolverKind::Auto);
  Controls controls;  // R_n = 5e-3 of the force scale 1: the residuals below never converge
  NewtonSolver newton(*solver, controls, 1.0);
  return newton.solve(problem, 0, 0);
}

TEST(Newton, TwoGrowthsOnTheSameBranchAreDivergence) {
  const NewtonOutcome out = solve({1, 0.5, 0.6, 0.7, 0.8, 0.9}, {});
  EXPECT_EQ(out.status, NewtonOutcome::Status::Diverged);
  EXPECT_EQ(out.iterations, 4);  // the check starts at the fourth iteration
  EXPECT_EQ(out.message, "the residual grew in two consecutive iterations");
}

TEST(Newton, GrowthWhereTheContactActiveSetChangedDoesNotCount) {
  // The same residuals, each from an iteration whose active set changed:
  // Newton goes on to the iteration limit.
  const NewtonOutcome out = solve({1, 0.5, 0.6, 0.7, 0.8, 0.9}, std::vector<int>(6, 3));
  EXPECT_EQ(out.status, NewtonOutcome::Status::TooManyIterations);
  EXPECT_EQ(out.iterations, Controls{}.max_iterations);
  // A growth on an unchanged branch after changed ones still counts, and a
  // changed iteration between two growths neither counts nor resets.
  const NewtonOutcome mixed = solve({1, 0.5, 0.6, 0.7, 0.8, 0.9}, {0, 0, 0, 2, 0, 0});
  EXPECT_EQ(mixed.status, NewtonOutcome::Status::Diverged);
  EXPECT_EQ(mixed.iterations, 4);  // growths at 2 and 4 (3 changed): two in a row that count
}

TEST(Newton, ARunawayResidualCountsEvenWhereTheActiveSetChanged) {
  // 10 times the larger of iterations 0 and 1 (here 1) is a runaway: 13.5 and
  // 40.5 count, 1.5 and 4.5 do not.
  const NewtonOutcome out = solve({1, 0.5, 1.5, 4.5, 13.5, 40.5, 121.5}, std::vector<int>(7, 3));
  EXPECT_EQ(out.status, NewtonOutcome::Status::Diverged);
  EXPECT_EQ(out.iterations, 5);
}

TEST(Newton, AFallingResidualResetsTheCount) {
  const NewtonOutcome out = solve({1, 0.5, 0.6, 0.4, 0.45, 0.3, 0.35, 0.2, 0.25, 0.1, 0.11, 0.05, 0.06, 0.03, 0.035,
                                   0.02, 0.025, 0.015},
                                  {});
  EXPECT_EQ(out.status, NewtonOutcome::Status::TooManyIterations);
}

TEST(Newton, GrowthBelowOneHundredthOfTheStartDoesNotCount) {
  // Residuals that have fallen two orders below the larger of the first two
  // (here 100) and then grow, as where integration points switch between the
  // elastic and the plastic branch near the solution: Newton goes on.
  const NewtonOutcome settled = solve({100, 50, 0.5, 0.6, 0.7, 0.8, 0.9, 0.95}, {});
  EXPECT_EQ(settled.status, NewtonOutcome::Status::TooManyIterations);
  EXPECT_EQ(settled.iterations, Controls{}.max_iterations);
  // Above it, two growths in a row are divergence as before.
  const NewtonOutcome growing = solve({100, 50, 1.5, 1.6, 1.7, 1.8}, {});
  EXPECT_EQ(growing.status, NewtonOutcome::Status::Diverged);
  EXPECT_EQ(growing.iterations, 4);
}

}  // namespace
}  // namespace tether
