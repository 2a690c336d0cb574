#pragma once
/// \file The stable time increment of central differences with a lumped mass,
/// element by element.
///
/// Central differences are stable for an undamped linear system while
/// dt <= 2 / omega_max, omega_max the highest natural frequency of the mesh.
/// For each element, omega_e^2 is the largest eigenvalue of K_e x = omega^2 M_e x
/// (K_e its tangent at the current state, M_e its lumped, diagonal mass); the
/// mesh's omega_max never exceeds max_e omega_e (Irons' bound: the Rayleigh
/// quotient of the assembled pair is a weighted mean of the elements'), so
/// 2 / max_e omega_e is a rigorous lower bound of the critical increment.
/// Held (prescribed) dofs do not vibrate: each element's pair is restricted to
/// its free dofs, which lowers omega_e (interlacing) and keeps the bound
/// rigorous (a free vector of the mesh is zero at the held dofs of every
/// element); an element without free dofs sets no limit. See
/// docs/theory/explicit_dynamics.md.

#include <functional>
#include <limits>
#include <memory>
#include <vector>

#include "tether/assembly/contribution.hpp"
#include "tether/elements/element_inertia.hpp"

namespace tether {

/// The increment a step's explicit integration must not exceed.
struct StableIncrement {
  /// min over the elements of damped_stable_increment(omega_e, beta_e) [time] (2 / omega_max
  /// without stiffness-proportional damping), no safety factor
  double dt = std::numeric_limits<double>::infinity();
  double omega_max = 0;  ///< largest element frequency [rad/time]
  int element = -1;      ///< index (in `inertia`) of the element that sets dt
};

/// The largest omega^2 [1/time^2] of K x = omega^2 M x for a symmetric `stiffness`
/// and a diagonal, positive `lumped_mass` of the same size. Throws ModelError
/// (naming `what`) when a mass entry is not positive.
double largest_frequency_squared(const Eigen::MatrixXd& stiffness, const Eigen::VectorXd& lumped_mass,
                                 const std::string& what);

/// The stable increment [time] of central differences for a mode of
/// frequency `omega` [rad/time] under stiffness-proportional damping `beta`
/// [time] evaluated with the lagged velocity v_{n-1/2} (as ABAQUS/Explicit):
/// (2/omega)(sqrt(1 + xi^2) - xi), xi = beta omega / 2 the mode's fraction of
/// critical damping; 2/omega without damping. (From the recursion
/// z^2 + (Omega^2 + 2 xi Omega - 2) z + 1 - 2 xi Omega = 0, Omega = omega h:
/// |z| <= 1 while Omega^2 + 4 xi Omega <= 4.)
double damped_stable_increment(double omega, double beta);

/// The element-by-element estimate over every element of `inertia` (lumped
/// masses) at state `s` (tangents under s.nlgeom), each restricted to the dofs
/// that `held` (global dof -> prescribed; empty: none) leaves free. Throws
/// ModelError when an element's estimate is zero, negative or not a number
/// (naming the element): a material without stiffness, a degenerate or
/// inverted element. With every dof of every element held, dt is infinite and element -1.
StableIncrement stable_increment(const std::vector<std::unique_ptr<ElementInertia>>& inertia,
                                 const EvaluationState& s, const std::function<bool(int)>& held = {});

}  // namespace tether
