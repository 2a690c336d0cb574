// Ironing (issue #4): a die (half disc, Rd = 5 mm, same material as the block:
// E = 200 000 MPa, nu = 0.3) pressed 0.02 mm into an elastic block by its
// driven top nodes (contact half-width ~0.22 mm), then slid along it under
// NLGEOM, 1.25 master segments of 0.1 mm per increment; decks from
// tools/make_ironing_deck.py (gmsh quads) written into the build tree.
// mu = 0.3: 3 mm slide (30 segments, 24 increments, 4.6k dofs); the 15 mm
// slide (150 segments, 120 increments, 7.6k dofs) is the disabled long
// variant. mu = 0: 5 mm slide in 40 increments.
// In steady sliding every contact node slips, so the friction force is mu N;
// the normal forces' horizontal part (ploughing) vanishes for a pressure
// symmetric about the die axis, which identical materials give (decoupling),
// so Fx / |Fy| of the driven nodes' reactions = mu (issue: within 2 %), and
// with mu = 0, Fx = 0 (checked: |Fx| <= 1e-3 |Fy|). Steady sliding: slide
// >= 1 mm. Newton (issue): every attempt takes <= 8 iterations, and the last
// ones should be quadratic: checked as an order >= 1.5 of the last iteration
// (on the force residual; with friction in the slide step, plus the order and
// the quadratic constant on the whole residual in every increment, and a
// reduction >= 20x everywhere; kFrictionLast). The history is printed.
// Skipped without python3/gmsh.

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "verification_support.hpp"

namespace fs = std::filesystem;
using namespace tether;

namespace {

constexpr double kSteady = 1.0;  ///< steady sliding from this slide distance [mm]

fs::path generate(const std::string& name, const std::string& options) {
  return tether::verification::generated_deck("make_ironing_deck.py", "ironing", name, options);
}

/// What the test asks of the last Newton iterations of each converged increment.
struct LastIterations {
  /// Largest r_n / r_{n-1} of the max force residual in the last iteration (0: not checked).
  double max_reduction = 0;
  /// Smallest order estimate p = log(r_n / r_{n-1}) / log(r_{n-1} / r_{n-2}) of
  /// the last iteration (2 for quadratic convergence, 1 for linear; 0: not checked).
  double min_order = 0;
  /// The step whose increments the order is checked in (0: every step).
  int order_step = 0;
  /// Smallest order of the last iteration on the whole residual, max(force
  /// residual, c x constraint residual), in every increment (0: not checked).
  double min_whole_order = 0;
  /// Largest r_n / r_{n-1}^2 [1/N] of the whole residual in the last
  /// iteration of every increment (0: not checked): a step taken with the
  /// active set settled reduces it quadratically with the problem's constant.
  double max_whole_constant = 0;
};

/// The contact pair's complementarity stiffness c [N/mm] as the analysis takes
/// it (contact_builder: the largest E x thickness over the elements of the
/// slave surface's faces), so that c times a constraint row's residual (a
/// gap or a slip [mm], or a friction force error / c) is a force.
double complementarity_stiffness(const Model& model) {
  double c = 0;
  for (const ElementFace& f : model.surfaces.at(model.contact_pairs.at(0).slave).faces) {
    const Element& e = model.elements.at(static_cast<std::size_t>(f.element));
    const SolidSection& section = model.sections.at(static_cast<std::size_t>(e.section));
    c = std::max(c, model.materials.at(static_cast<std::size_t>(section.material)).modulus() * section.thickness);
  }
  return c;
}

/// Runs the deck; checks Fx / |Fy| in steady sliding (mu > 0: within `tolerance`
/// relative to mu; mu = 0: |Fx| / |Fy| <= tolerance), <= 8 iterations per
/// attempt (failed attempts too) and the last iterations (`last`).
void check(const std::string& name, const std::string& options, double mu, double slide_distance, double tolerance,
           LastIterations last_check) {
  fs::path deck;
  try {
    deck = generate(name, options);
  } catch (const std::runtime_error& e) {
    if (std::string(e.what()) == "skip") GTEST_SKIP() << "python3 or gmsh not found";
    FAIL() << e.what();
  }
  const auto start = std::chrono::steady_clock::now();
  const tether::testing::Run run = tether::testing::run_deck_file(deck.string());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(run.summary.completed) << run.summary.message;
  std::printf("[ ironing ] %s: %d displacement dofs, %d increments, %d iterations, %d cut-backs, %.1f s\n",
              name.c_str(), 2 * run.model.n_nodes(), run.summary.increments, run.summary.iterations,
              run.summary.cutbacks, seconds);

  const auto& top = run.model.node_sets.at("TOPN");
  // Attempts (failed ones too) and, for each, the residual history of its last
  // Newton pass (recorder.residuals holds one row per pass: iterations + 1
  // values; an attempt's passes together make its iteration count).
  std::vector<const IncrementReport*> converged;
  std::vector<const std::vector<double>*> last_pass;
  std::vector<const std::vector<IterationNorms>*> last_norms;
  std::size_t pass = 0;
  for (const IncrementReport& inc : run.recorder.increments) {
    EXPECT_LE(inc.iterations, 8) << "step " << inc.step << " increment " << inc.increment << " attempt " << inc.attempt;
    int solves = 0;
    const std::vector<double>* last = nullptr;
    while (solves < inc.iterations && pass < run.recorder.residuals.size()) {
      last = &run.recorder.residuals[pass++];
      solves += static_cast<int>(last->size()) - 1;
    }
    ASSERT_EQ(solves, inc.iterations) << "residual rows do not match the iteration counts";
    if (inc.converged)
      converged.push_back(&inc), last_pass.push_back(last), last_norms.push_back(&run.recorder.norms[pass - 1]);
  }
  const double c = complementarity_stiffness(run.model);
  ASSERT_EQ(converged.size(), run.recorder.results.size());
  double worst_reduction = 0, worst_order = 1e300, worst_checked_order = 1e300, worst_whole_order = 1e300,
         worst_constant = 0;
  std::vector<double> orders;
  double worst = 0, sum = 0;
  int steady = 0, max_iterations = 0;
  for (std::size_t k = 0; k < run.recorder.results.size(); ++k) {
    const IncrementResults& r = run.recorder.results[k];
    double fx = 0, fy = 0;
    for (int n : top) fx += r.reaction[n].x(), fy += r.reaction[n].y();
    const double slide = r.step == 2 ? r.step_time * slide_distance : 0.0;
    const double ratio = fx / std::abs(fy);
    const int its = converged[k]->iterations;
    max_iterations = std::max(max_iterations, its);
    const std::vector<double>& res = *last_pass[k];
    const std::size_t n = res.size();
    // Judged where the last three residuals decrease (an increment whose
    // starting state already converges has no last iteration to judge).
    const bool judged = n >= 3 && res[n - 1] < res[n - 2] && res[n - 2] < res[n - 3] && res[n - 1] > 0;
    const double reduction = judged ? res[n - 1] / res[n - 2] : 0.0;
    const double order = judged ? std::log(reduction) / std::log(res[n - 2] / res[n - 3]) : 0.0;
    // The same on the whole residual: force rows and c x constraint rows.
    const std::vector<IterationNorms>& norms = *last_norms[k];
    std::vector<double> whole(n);
    for (std::size_t i = 0; i < n; ++i) whole[i] = std::max(norms[i].force_residual, c * norms[i].multiplier_residual);
    const bool whole_judged = n >= 3 && whole[n - 1] < whole[n - 2] && whole[n - 2] < whole[n - 3] && whole[n - 1] > 0;
    const double whole_order =
        whole_judged ? std::log(whole[n - 1] / whole[n - 2]) / std::log(whole[n - 2] / whole[n - 3]) : 0.0;
    std::printf("[ ironing ]   step %d increment %2d slide %6.3f: Fx %11.5g Fy %11.5g Fx/|Fy| %+.5f  %d iterations, "
                "last residuals %.2e %.2e %.2e N, order %.2f; whole residual %.2e %.2e %.2e N, order %.2f; "
                "branch changes %d %d %d, re-paired %d %d %d\n",
                r.step, r.increment, slide, fx, fy, ratio, its, n >= 3 ? res[n - 3] : 0.0, n >= 2 ? res[n - 2] : 0.0,
                res[n - 1], order, n >= 3 ? whole[n - 3] : 0.0, n >= 2 ? whole[n - 2] : 0.0, whole[n - 1], whole_order,
                n >= 3 ? norms[n - 3].contact_changes : 0, n >= 2 ? norms[n - 2].contact_changes : 0,
                norms[n - 1].contact_changes, n >= 3 ? norms[n - 3].contact_repaired : 0,
                n >= 2 ? norms[n - 2].contact_repaired : 0, norms[n - 1].contact_repaired);
    // The quadratic constant of the last iteration, r_n / r_{n-1}^2 [1/N].
    const double constant = n >= 2 && whole[n - 2] > 0 ? whole[n - 1] / (whole[n - 2] * whole[n - 2]) : 0.0;
    worst_constant = std::max(worst_constant, constant);
    if (last_check.max_whole_constant > 0)
      EXPECT_LE(constant, last_check.max_whole_constant) << "step " << r.step << " increment " << r.increment;
    if (whole_judged) {
      worst_whole_order = std::min(worst_whole_order, whole_order);
      if (last_check.min_whole_order > 0)
        EXPECT_GE(whole_order, last_check.min_whole_order) << "step " << r.step << " increment " << r.increment;
    }
    if (last_check.min_whole_order > 0)
      EXPECT_TRUE(whole_judged) << "step " << r.step << " increment " << r.increment << ": no last iteration to judge";
    if (judged) {
      worst_reduction = std::max(worst_reduction, reduction);
      worst_order = std::min(worst_order, order);
      orders.push_back(order);
      if (last_check.max_reduction > 0)
        EXPECT_LE(reduction, last_check.max_reduction) << "step " << r.step << " increment " << r.increment;
      if (last_check.order_step == 0 || r.step == last_check.order_step) {
        worst_checked_order = std::min(worst_checked_order, order);
        if (last_check.min_order > 0)
          EXPECT_GE(order, last_check.min_order) << "step " << r.step << " increment " << r.increment;
      }
    }
    if (r.step != 2 || slide < kSteady - 1e-9) continue;
    ++steady;
    sum += ratio;
    const double error = mu > 0 ? std::abs(ratio / mu - 1) : std::abs(ratio);
    worst = std::max(worst, error);
    EXPECT_LE(error, tolerance) << "slide " << slide;
  }
  ASSERT_GT(steady, 10);
  std::printf("[ ironing ] %s: mu %g, steady sliding (%d increments): mean Fx/|Fy| %.5f, %s %.3g; "
              "max %d iterations per increment\n",
              name.c_str(), mu, steady, sum / steady, mu > 0 ? "max |Fx/|Fy| / mu - 1|" : "max |Fx/Fy|", worst,
              max_iterations);
  ASSERT_FALSE(orders.empty());
  std::sort(orders.begin(), orders.end());
  std::printf("[ ironing ] %s: last iteration of %zu increments: max force residual reduced by 1/%.0f at worst; "
              "order min %.2f median %.2f (min %.2f in %s)\n",
              name.c_str(), orders.size(), 1 / worst_reduction, worst_order, orders[orders.size() / 2],
              worst_checked_order, last_check.order_step == 0 ? "every step" : "the checked step");
  std::printf("[ ironing ] %s: whole residual (c = %g N/mm), last iteration: order min %.2f, r_n / r_{n-1}^2 max "
              "%.2e 1/N\n", name.c_str(), c, worst_whole_order, worst_constant);
}

// The last iteration of every slide increment is quadratic with friction too
// since the slip increment's dependence on the committed segment's nodes is in
// the tangent (a slave node handed over to another master segment since the
// last converged increment measures its slip from a point of the old
// segment; at 1.25 segments per increment every contact node is handed over
// in every increment; docs/theory/contact.md, "Friction"). Measured on the
// 3 mm deck: force-residual order 1.85-3.5 in the 24 slide increments
// (before the hand-over tangent: 0.95-5.2).
// In the indentation step three of four increments estimate 0.77-1.36 on the
// force residual alone: there the active set settles in the last-but-one
// iterate (nodes closing, a node that has just closed with λn = 0 starting to
// carry a normal force so that its friction row turns from the open one to
// slip or stick, a re-pairing over a master node), and the error of the
// switch sits in the constraint rows, which the force residual does not see.
// On the whole residual, max(force residual, c x constraint residual), the
// last iteration - the step after the settle - has order 2.08-3.04 there
// and r_n / r_{n-1}^2 = 1.2e-5 - 1.3e-4 1/N, the constant of the slide
// step's settled increments (up to 3.1e-4; order >= 1.85). Both are checked in every
// increment (order >= 1.5, constant <= 2e-3 1/N; the 15 mm variant reaches
// 1.4e-3 in one of its 124 increments since the friction force acts at the
// contact point, 3.1e-4 at most on the 3 mm deck): without the gap Hessian
// -λn ∇²g indentation increments 3 and 4 fail them (order 0.90, constants
// 0.05 and 0.09), without the friction force's Jacobian λt ∂F/∂x the slide
// increments do (order 0.87; docs/theory/contact.md). The reduction of the
// last iteration is checked everywhere (>= 20x; measured >= 150x).
constexpr LastIterations kFrictionLast{
    .max_reduction = 0.05, .min_order = 1.5, .order_step = 2, .min_whole_order = 1.5, .max_whole_constant = 2e-3};

// 3 mm slide, 24 increments: 17 increments of steady sliding (slide >= 1 mm),
// every slave node crosses 30 master segments. 4 580 dofs, 28 increments, 153
// iterations with two threads, 154 with one (146 before the friction force
// was put at the contact point), at most 7 per increment, no cut-back,
// Fx/|Fy| within 0.92 % of mu; about 3-9 s in Release (docs/verification_contact.md).
TEST(Ironing, Cpe4FrictionRatioIsMu) {
  check("ironing_cpe4_mu03_slide3", "--mu 0.3 --slide 3 --slide-increments 24", 0.3, 3, 0.02, kFrictionLast);
}

// The long variant: 15 mm (150 segments, 120 increments, 7 564 dofs), the same
// physics as the 3 mm run over five times the distance. Disabled for its run
// time (124 increments, 722 iterations, 23 s wall on the idle 2-core
// machine, 91 s loaded); it passes with at most 7 iterations per increment,
// Fx/|Fy| within 1.0 % of mu and a slide-step order >= 1.65 (since the
// friction force acts at the contact point; before: 701 iterations, at most
// 8, 0.93 %, 1.79). Run with --gtest_also_run_disabled_tests.
TEST(Ironing, DISABLED_Cpe4FrictionRatioIsMuLongSlide) {
  check("ironing_cpe4_mu03", "--mu 0.3", 0.3, 15, 0.02, kFrictionLast);
}

// A die 100 times stiffer than the block, as the master (the track's nodes
// are the slaves), exact stick: the stiffer body as the master, as ABAQUS
// advises and as tether warns when a deck does otherwise. As the slave the
// same die stops in the slide (INC=100 reached at 0.32 of a 1 mm slide: one
// die node closed per straight master segment, the closed set changing every
// iteration; finding 2 of docs/verification_contact.md). Measured: 24
// increments, 106-113 iterations (thread count; corner friction), at most 6 per
// increment, no cut-back; Fx/|Fy| within 1.9 % of mu over 13 steady
// increments (the track's slave nodes, 0.1 mm apart, pass under a contact a
// few of them wide: the ratio swings ±1.5 % around 0.297). The last
// iterations are not checked for order: increments whose active set or
// pairing changes in their last iterations end with orders down to 0.2
// (median 2.0).
TEST(Ironing, StiffDieAsMasterSlidesWithFrictionRatioMu) {
  check("ironing_stiff_die_master_slide25", "--mu 0.3 --die-modulus 100 --die-as-master --slide 2.5 --slide-increments 20",
        0.3, 2.5, 0.02, {});
}

TEST(Ironing, Cpe4FrictionlessHasNoDrag) {
  check("ironing_cpe4_mu0", "--mu 0 --slide 5 --slide-increments 40", 0.0, 5, 1e-3, {.min_order = 1.5});
}

}  // namespace
