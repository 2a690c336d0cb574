#pragma once
// Decks of a 1D-strain bar (plane-strain CPE4, every node held in y) for the
// dynamics tests: stress waves and impact on a rigid wall.
#include <string>

namespace tether::testing {

/// A number with all its digits, for deck text.
std::string full_digits(double x);

/// A bar of `n` square CPE4 of side `h` along x, one element high, every
/// node held in y (1D strain), steel (E 2e11, nu 0.3, rho 7800). Node i
/// (1..n+1) at x = (i-1) h, y = 0; node n+1+i above it. Sets: LEFT (x = 0),
/// RIGHT (x = L), INNER (the rest), ALLN, element set BAR. `bc` and `step`
/// are appended to the model data and the step.
std::string bar_deck(int n, double h, const std::string& bc, const std::string& step);

/// The bar of bar_deck at rest against a rigid wall: one held CPE4 left of
/// x = 0 (3 h tall, node set WALLN) whose right face is the master of the
/// bar's left end (node-to-surface, HARD), the bar moving at -v0. `procedure`
/// is the step's procedure block (e.g. "*DYNAMIC, EXPLICIT\n, 1e-4\n");
/// `gap` [length] >= 0 moves the wall that far left of the bar.
std::string wall_deck(int n, double h, double v0, const std::string& procedure, double gap = 0);

}  // namespace tether::testing
