#pragma once
/// \file Newton, then the contributions' acceptance of its solution: what
/// every implicit procedure (static, implicit dynamic) does with one attempt.

#include <vector>

#include "tether/analysis/analysis_observer.hpp"
#include "tether/analysis/increment_problem.hpp"
#include "tether/analysis/newton.hpp"

namespace tether {

/// Solves `problem` by `newton`, then asks every contribution whether it
/// accepts the converged state (augmented-Lagrangian updates and contact
/// guards may ask for another pass): another Newton pass while one asks for
/// it, at most 50. A ModelError from a contribution's acceptance ends the
/// attempt as an element failure. Adds the iterations of every pass to
/// `iterations`; reports iterations and repeated passes to `observer`.
NewtonOutcome solve_with_acceptance(NewtonSolver& newton, IncrementProblem& problem,
                                    const std::vector<Contribution*>& contributions, AnalysisObserver& observer,
                                    double averaged_force, int n_averaged, int& iterations);

}  // namespace tether
