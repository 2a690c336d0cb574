#include "tether/analysis/newton.hpp"

#include <chrono>
#include <cmath>

#include "tether/core/error.hpp"

namespace tether {

namespace {
/// A residual this many times the larger of the attempt's first two has run away.
constexpr double kRunawayFactor = 10;
/// Below this fraction of the larger of the attempt's first two residuals a
/// growth does not count: Newton has closed in on the solution, and what
/// grows there is the piecewise-smooth residual of points switching between
/// branches (integration points between the elastic and the plastic one).
constexpr double kSettledFraction = 1e-2;

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

NewtonSolver::NewtonSolver(LinearSolver& solver, const Controls& controls, double length_scale)
    : solver_(solver), controls_(controls), criteria_(controls, length_scale) {}

NewtonOutcome NewtonSolver::solve(NewtonProblem& problem, double averaged_force, int n_averaged,
                                  const IterationListener& listener) {
  NewtonOutcome out;
  Eigen::VectorXd residual, correction;
  Eigen::VectorXd rhs;  // -residual, kept between iterations (no temporary per solve)
  IterationNorms norms;
  double previous = 0;
  int growths = 0;       // consecutive growths of the force residual that count (below)
  double reference = 0;  // the larger force residual of iterations 0 and 1
  problem.begin_solve();

  for (int iteration = 0;; ++iteration) {
    double q = 0;
    try {
      const bool changed = problem.evaluate(residual, true, norms, q);
      problem.add_evaluation_time(timing_);
      if (changed) analysed_ = false;
    } catch (const ModelError& e) {
      out.status = NewtonOutcome::Status::ElementFailure;
      out.message = e.what();
      out.iterations = iteration;
      return out;
    }
    const double scale = (averaged_force * n_averaged + q) / (n_averaged + 1);
    norms.previous_force_residual = previous;
    out.iterations = iteration;
    out.force_residual = norms.force_residual;
    out.force_scale = scale;
    if (listener) listener(iteration, norms);

    if (criteria_.converged(norms, iteration, scale)) return out;

    if (!std::isfinite(norms.force_residual) || !std::isfinite(norms.multiplier_residual)) {
      out.status = NewtonOutcome::Status::Diverged;
      out.message = "the residual is not finite (NaN or Inf)";
      return out;
    }
    // Divergence: the residual grew in two consecutive iterations on the
    // same branch. An iteration whose contact active set changed (a node
    // opened, closed, switched between stick and slip or slip direction, or
    // was re-paired) evaluates a different branch of the nonsmooth residual
    // than the one linearised, so its growth is not a sign of divergence
    // (ABAQUS likewise leaves its severe-discontinuity iterations out of the
    // divergence check); it neither counts nor resets the count, unless the
    // residual has run away to over kRunawayFactor times the larger of the
    // first two (measured on the block-on-foundation decks: converged attempts
    // stay within 2.2 times, runaways pass 20 within four iterations and end
    // with a body that has lost its contact and a singular matrix). Cycling
    // below that is the contact guards' business, and max_iterations bounds it.
    // Likewise no growth counts once the residual is below kSettledFraction
    // of that reference: integration points switching between the elastic
    // and the plastic branch make the residual grow there without Newton
    // diverging (without the static predictor the necking bar took 283
    // increments when they counted, 218 when they did not; measured before
    // the predictor). A plastic analysis's runaways pass the reference
    // itself (the necking bar's grow from 0.1 to 1.2 times it in two
    // iterations).
    if (iteration <= 1) reference = std::max(reference, norms.force_residual);
    if (iteration > 0) {
      const bool same_branch = norms.contact_changes == 0 && norms.contact_repaired == 0;
      if (norms.force_residual <= previous)
        growths = 0;
      else if ((same_branch && norms.force_residual > kSettledFraction * reference) ||
               norms.force_residual > kRunawayFactor * reference)
        ++growths;
    }
    if (iteration >= 4 && growths >= 2) {
      out.status = NewtonOutcome::Status::Diverged;
      out.message = "the residual grew in two consecutive iterations";
      return out;
    }
    if (iteration >= controls_.max_iterations) {
      out.status = NewtonOutcome::Status::TooManyIterations;
      out.message = "no convergence in " + std::to_string(controls_.max_iterations) + " iterations";
      return out;
    }

    try {
      const SparseMatrix& tangent = problem.tangent();
      auto t0 = std::chrono::steady_clock::now();
      if (!analysed_) {
        factorized_revision_ = factorized_outer_revision_ = 0;
        solver_.analyze(tangent), analysed_ = true;
        timing_.analyse += seconds_since(t0);
        t0 = std::chrono::steady_clock::now();
      }
      // The same matrix as the one factorized last (a linear step at a
      // fixed increment): its factors serve again.
      const std::uint64_t revision = problem.tangent_revision();
      if (revision != 0 && revision == factorized_revision_) {
        ++timing_.reused_factorizations;
      } else {
        const std::uint64_t outer = problem.outer_revision();
        if (outer != 0 && outer == factorized_outer_revision_) solver_.note_outer_unchanged();
        factorized_revision_ = factorized_outer_revision_ = 0;
        solver_.factorize(tangent, problem.symmetric());
        factorized_revision_ = revision;
        factorized_outer_revision_ = outer;
        ++timing_.factorizations;
        timing_.factorize += seconds_since(t0);
      }
      t0 = std::chrono::steady_clock::now();
      rhs = -residual;
      solver_.solve(rhs, correction);
      timing_.solve += seconds_since(t0);
    } catch (const SolverError& e) {
      out.status = NewtonOutcome::Status::SingularMatrix;
      out.singular_at_start = iteration == 0;
      out.message = e.what();
      if (e.equation() >= 0) {
        out.message += " at " + problem.describe_equation(e.equation());
        out.singular_multiplier = problem.is_multiplier_equation(e.equation());
      }
      return out;
    }
    if (!correction.allFinite()) {
      out.status = NewtonOutcome::Status::Diverged;
      out.message = "the linear solve returned a non-finite correction";
      return out;
    }

    double alpha = 1.0;
    problem.apply_correction(correction, alpha);
    if (controls_.line_search) {
      // Backtrack while the residual grows; at most 5 halvings.
      Eigen::VectorXd trial;
      IterationNorms trial_norms;
      double trial_q = 0;
      for (int k = 0; k < 5; ++k) {
        try {
          // A re-pairing here may have rebuilt the pattern: the next factorization must analyse it.
          if (problem.evaluate(trial, false, trial_norms, trial_q)) analysed_ = false;
          problem.add_evaluation_time(timing_);
        } catch (const ModelError&) {
          trial_norms.force_residual = INFINITY;
        }
        if (trial.norm() <= (1 - 1e-4 * alpha) * residual.norm()) break;
        problem.apply_correction(correction, -0.5 * alpha);
        alpha *= 0.5;
      }
    }
    previous = norms.force_residual;
    norms.correction = alpha * problem.displacement_norm(correction);
  }
}

}  // namespace tether
