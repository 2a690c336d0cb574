// The whole assembled Newton system of a plastic increment against finite
// differences: the necking bar (examples/necking_bar, 5 x 15 elements, J2 with
// a 100-row saturation-hardening table) pulled by a fixed increment straight
// from virgin material into the plastic range, at the iterates Newton visits.
// What is checked is what Newton factorizes: every contribution, the
// prescribed dofs' elimination and the state the step's loads set.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "tether/analysis/discretization.hpp"
#include "tether/analysis/increment_problem.hpp"
#include "tether/analysis/step_system.hpp"
#include "tether/io/deck_reader.hpp"

using namespace tether;
namespace fs = std::filesystem;

namespace {

std::string necking_bar_deck() {
  std::ifstream in(fs::path(TETHER_SOURCE_DIR) / "tests/analysis/decks/necking_bar_5x15.inp");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "deck has no '" << from << "'";
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

/// The necking bar with elements `type`, NLGEOM or not, 50 fixed increments of 0.14 mm.
std::string fixed_increment_bar(const std::string& type, bool nlgeom) {
  std::string d = replaced(necking_bar_deck(), "TYPE=CAX8R", "TYPE=" + type);
  d = replaced(d, "*STEP, NLGEOM, INC=1000", nlgeom ? "*STEP, NLGEOM, INC=50" : "*STEP, INC=50");
  return replaced(d, "*STATIC\n0.01, 1., 1e-5, 0.02", "*STATIC, DIRECT\n0.02, 1.");
}

/// The first increment of the deck's first step, set up as StaticProcedure sets it up.
struct FirstIncrement {
  Model model;
  std::unique_ptr<Discretization> disc;
  std::unique_ptr<StepSystem> system;
  Eigen::VectorXd u, u_start, external;
  std::unique_ptr<IncrementProblem> problem;

  explicit FirstIncrement(const std::string& deck) {
    model = read_deck_string(deck, "test.inp");
    disc = std::make_unique<Discretization>(model);
    const Step& step = model.steps.at(0);
    u = Eigen::VectorXd::Zero(disc->dofs().n_dofs());
    u_start = u;
    external = u;
    system = std::make_unique<StepSystem>(*disc, step, make_step_loads(step, disc->dofs(), u, {}, {}), u, 0.0,
                                          SolverSettings{});
    const IncrementTimes t{0.02, 0.02, 0.02, 1.0, false};
    system->apply_loads(t, u, external);
    problem = std::make_unique<IncrementProblem>(system->assembler(), disc->dofs(), u, u_start, external,
                                                 system->load_contributions(),
                                                 IncrementTime{t.step_time, t.total_time, t.dt, step.nlgeom},
                                                 system->symmetric());
  }

  /// Residual over the free equations at the current u (and the tangent when asked).
  Eigen::VectorXd residual(bool with_tangent) {
    Eigen::VectorXd r;
    IterationNorms norms;
    double q = 0;
    problem->evaluate(r, with_tangent, norms, q);
    return r;
  }

  /// One Newton iteration: the correction solved at the current u, applied in full.
  void newton_step() {
    const Eigen::VectorXd r = residual(true);
    LinearSolver& solver = system->solver();
    solver.analyze(problem->tangent());
    solver.factorize(problem->tangent(), problem->symmetric());
    Eigen::VectorXd dx;
    solver.solve(-r, dx);
    problem->apply_correction(dx, 1.0);
  }

  /// Largest difference between the assembled tangent and central
  /// differences of the residual (step h), relative to the largest entry.
  double tangent_error(double h) {
    residual(true);
    const Eigen::MatrixXd K(problem->tangent());
    const Eigen::Index n = K.cols();
    Eigen::MatrixXd fd(n, n);
    const Eigen::VectorXd u0 = u;
    for (Eigen::Index j = 0; j < n; ++j) {
      Eigen::VectorXd e = Eigen::VectorXd::Zero(n);
      e(j) = h;
      problem->apply_correction(e, 1.0);
      const Eigen::VectorXd rp = residual(false);
      u = u0;
      problem->apply_correction(e, -1.0);
      const Eigen::VectorXd rm = residual(false);
      u = u0;
      fd.col(j) = (rp - rm) / (2 * h);
    }
    return (K - fd).cwiseAbs().maxCoeff() / K.cwiseAbs().maxCoeff();
  }
};

}  // namespace

TEST(GlobalTangent, NeckingBarFirstIncrementMatchesFiniteDifferences) {
  for (const char* type : {"CPE8R", "CPE8", "CPE4", "CAX8R"})
    for (bool nlgeom : {false, true}) {
      FirstIncrement inc(fixed_increment_bar(type, nlgeom));
      for (int iteration = 0; iteration < 3; ++iteration) {
        const double error = inc.tangent_error(1e-7);
        std::printf("%s%s iteration %d: max |K - K_fd| / max |K| = %.2e\n", type, nlgeom ? " NLGEOM" : "",
                    iteration, error);
        EXPECT_LT(error, 1e-5) << type << (nlgeom ? " NLGEOM" : "") << " iteration " << iteration;
        inc.newton_step();
      }
    }
}

TEST(GlobalTangent, Experiment) {
  for (int mode = 0; mode < 2; ++mode) {
    FirstIncrement inc(fixed_increment_bar("CPE8R", false));
    if (mode == 1) {
      // ccx-like: tangent at the start, prescribed increment as a load.
      const Eigen::VectorXd up = inc.u;
      inc.u = inc.u_start;
      const Eigen::VectorXd r0 = inc.residual(true);
      const double eps = 1e-6;
      inc.u = inc.u_start + eps * (up - inc.u_start);
      const Eigen::VectorXd r1 = inc.residual(false);
      inc.u = inc.u_start;
      inc.residual(true);
      LinearSolver& solver = inc.system->solver();
      solver.analyze(inc.problem->tangent());
      solver.factorize(inc.problem->tangent(), true);
      Eigen::VectorXd dx;
      solver.solve(-(r0 + (r1 - r0) / eps), dx);
      inc.u = up;
      inc.problem->apply_correction(dx, 1.0);
      std::printf("predictor max |dx| %.4e\n", dx.cwiseAbs().maxCoeff());
    }
    for (int it = 0; it < 12; ++it) {
      const Eigen::VectorXd r = inc.residual(false);
      std::printf("mode %d it %d: |r|max %.4e\n", mode, it, r.cwiseAbs().maxCoeff());
      try { inc.newton_step(); } catch (const std::exception& e) { std::printf("%s\n", e.what()); break; }
    }
  }
}
