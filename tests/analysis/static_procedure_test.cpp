// StaticProcedure alone, over a StepSystem: what one attempt does with the
// state, what it reports, and its restart state.

#include "tether/analysis/static_procedure.hpp"

#include <gtest/gtest.h>

#include "tether/io/deck_reader.hpp"

using namespace tether;

namespace {

/// One CPE4 [0,1]^2, base on rollers with node 1 pinned; the top pulled up
/// by 0.01 over the step (`restrained`), or only pushed sideways with the
/// base free in y (a rigid-body mode: singular at the first iteration).
std::string square(bool restrained) {
  return std::string("*NODE\n1, 0, 0\n2, 1, 0\n3, 1, 1\n4, 0, 1\n*ELEMENT, TYPE=CPE4, ELSET=E\n1, 1, 2, 3, 4\n"
                     "*MATERIAL, NAME=M\n*ELASTIC\n1000, 0.3\n*SOLID SECTION, ELSET=E, MATERIAL=M\n") +
         (restrained ? "*BOUNDARY\n1, 1, 2\n2, 2\n*STEP\n*STATIC\n0.5, 1\n*BOUNDARY\n3, 2, 2, 0.01\n4, 2, 2, 0.01\n"
                     : "*BOUNDARY\n1, 1\n*STEP\n*STATIC\n0.5, 1\n*CLOAD\n3, 1, 1.\n") +
         "*END STEP\n";
}

struct Reports final : AnalysisObserver {
  void on_increment(const IncrementReport& r) override { increments.push_back(r); }
  void on_results(const IncrementResults& r, const Step&, bool last) override {
    results.push_back(r);
    last_in_step.push_back(last);
  }
  std::vector<IncrementReport> increments;
  std::vector<IncrementResults> results;
  std::vector<bool> last_in_step;
};

struct OneSquare {
  Model model;
  std::unique_ptr<Discretization> disc;
  std::unique_ptr<StepSystem> system;
  Reports reports;
  std::unique_ptr<StaticProcedure> procedure;
  explicit OneSquare(bool restrained) {
    model = read_deck_string(square(restrained), "test.inp");
    disc = std::make_unique<Discretization>(model);
    const Step& step = model.steps.at(0);
    const Eigen::VectorXd u = Eigen::VectorXd::Zero(disc->dofs().n_dofs());
    system = std::make_unique<StepSystem>(*disc, step, make_step_loads(step, disc->dofs(), u, {}, {}), u, 0.0,
                                          SolverSettings{});
    procedure = std::make_unique<StaticProcedure>(*system, reports, false);
  }
  /// The first attempt of the step's first increment, after 7 earlier iterations.
  IncrementAttempt first_attempt() const {
    IncrementController clock(model.steps.at(0), 2.0);
    return IncrementAttempt{1, 1, 1, clock.next_attempt(), 7};
  }
};

}  // namespace

TEST(StaticProcedure, ConvergedAttemptMovesTheStateAndReportsIt) {
  OneSquare s(true);
  EXPECT_EQ(s.procedure->keyword(), "*STATIC");
  Eigen::VectorXd u = Eigen::VectorXd::Zero(s.disc->dofs().n_dofs());
  const IncrementAttempt attempt = s.first_attempt();
  const IncrementOutcome outcome = s.procedure->solve_increment(attempt, u);
  ASSERT_TRUE(outcome.converged) << outcome.message;
  EXPECT_EQ(outcome.iterations, 1);  // linear: one solve
  // The prescribed value at the end of the increment: half of 0.01.
  EXPECT_DOUBLE_EQ(u[s.disc->dofs().displacement(s.model.node_index.at(3), 1)], 0.005);
  ASSERT_EQ(s.reports.increments.size(), 1u);
  const IncrementReport& r = s.reports.increments[0];
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.total_iterations, 8);
  EXPECT_DOUBLE_EQ(r.step_time, 0.5);
  EXPECT_DOUBLE_EQ(r.total_time, 2.5);
  ASSERT_EQ(s.reports.results.size(), 1u);
  EXPECT_EQ(s.reports.results[0].increment, 1);
  EXPECT_DOUBLE_EQ(s.reports.results[0].total_time, 2.5);
  EXPECT_FALSE(s.reports.last_in_step[0]);
  EXPECT_GT(s.procedure->timing().factorizations, 0);
}

TEST(StaticProcedure, FailedAttemptLeavesTheConvergedState) {
  OneSquare s(false);
  Eigen::VectorXd u = Eigen::VectorXd::Constant(s.disc->dofs().n_dofs(), 1e-3);
  const Eigen::VectorXd before = u;
  const IncrementOutcome outcome = s.procedure->solve_increment(s.first_attempt(), u);
  EXPECT_FALSE(outcome.converged);
  EXPECT_TRUE(outcome.singular_at_start) << outcome.message;
  EXPECT_FALSE(outcome.singular_multiplier);
  EXPECT_EQ(u, before);
  ASSERT_EQ(s.reports.increments.size(), 1u);
  EXPECT_FALSE(s.reports.increments[0].converged);
  EXPECT_EQ(s.reports.increments[0].note, outcome.message);
  EXPECT_TRUE(s.reports.results.empty());
}

TEST(StaticProcedure, RestartStateHoldsTheAveragedForce) {
  OneSquare s(true);
  RestartState fresh;
  s.procedure->save(fresh);
  EXPECT_EQ(fresh.n_averaged, 0);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(s.disc->dofs().n_dofs());
  ASSERT_TRUE(s.procedure->solve_increment(s.first_attempt(), u).converged);
  RestartState saved;
  s.procedure->save(saved);
  EXPECT_EQ(saved.n_averaged, 1);
  EXPECT_GT(saved.averaged_force, 0);
  OneSquare other(true);
  other.procedure->restore(saved);
  RestartState again;
  other.procedure->save(again);
  EXPECT_EQ(again.n_averaged, saved.n_averaged);
  EXPECT_EQ(again.averaged_force, saved.averaged_force);
}
