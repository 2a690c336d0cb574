#pragma once
/// \file Inertia and Rayleigh damping of one continuum element in a dynamic
/// step: one more contribution to the equations of motion.
///
/// With Newmark's relations the accelerations and velocities at the end of an
/// increment are affine in the displacements u there:
///   a(u) = (u - u_n - dt v_n) / (beta dt^2) - (1/(2 beta) - 1) a_n
///   v(u) = v_n + dt ((1 - gamma) a_n + gamma a(u)),
/// so M a + C v is a residual in u like any other, with the tangent
/// M / (beta dt^2) + C gamma / (beta dt). HHT-alpha divides the equation by
/// (1 + alpha) so that the other contributions keep their own scale:
/// the contribution returns (M a + C v) / (1 + alpha). C = alpha_R M + beta_R K
/// with K the element's tangent at u (ABAQUS's Rayleigh damping). See
/// docs/theory/dynamics.md.

#include <Eigen/Core>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "tether/assembly/contribution.hpp"
#include "tether/elements/continuum_element.hpp"
#include "tether/elements/mass_matrix.hpp"

namespace tether {

/// What the time integrator tells the inertia of the increment being solved.
/// Global vectors over all unknowns (DofMap numbering), owned by the procedure.
struct NewmarkIncrement {
  const Eigen::VectorXd* v_start = nullptr;  ///< velocities at the increment's start [length/time]
  const Eigen::VectorXd* a_start = nullptr;  ///< accelerations at the increment's start [length/time^2]
  double dt = 0;       ///< increment [time], > 0
  double beta = 0.25;  ///< Newmark beta
  double gamma = 0.5;  ///< Newmark gamma
  double scale = 1;    ///< 1 / (1 + alpha_HHT)

  /// a at the end of the increment for displacement u of a dof whose start values are u_n, v_n, a_n.
  [[nodiscard]] double acceleration(double u, double u_n, double v_n, double a_n) const {
    return (u - u_n - dt * v_n) / (beta * dt * dt) - (0.5 / beta - 1) * a_n;
  }
  /// v at the end of the increment, given the end acceleration a.
  [[nodiscard]] double velocity(double a, double v_n, double a_n) const {
    return v_n + dt * ((1 - gamma) * a_n + gamma * a);
  }
};

class ElementInertia final : public Contribution {
 public:
  /// `element` and `increment` must outlive this. The mass is computed now
  /// (ModelError naming the element and material when it has no *DENSITY).
  /// damping_alpha [1/time], damping_beta [time]: Rayleigh factors (0: none).
  ElementInertia(const ContinuumElement& element, MassKind kind, double damping_alpha, double damping_beta,
                 const NewmarkIncrement& increment);

  [[nodiscard]] std::span<const int> dofs() const override { return element_.dofs(); }
  /// Residual (M a + C v) * scale, tangent (M / (beta dt^2) + C gamma / (beta dt)) * scale, with
  /// u_start of `s` the displacements at the increment's start.
  void evaluate(const EvaluationState& s, LocalSystem& out, bool need_tangent) const override;
  [[nodiscard]] bool symmetric_tangent(bool /*nlgeom*/) const override { return true; }
  /// The mass is constant; stiffness-proportional damping follows the element.
  [[nodiscard]] bool linear_in_u(bool nlgeom) const override {
    return damping_beta_ == 0 || element_.linear_in_u(nlgeom);
  }
  [[nodiscard]] std::string describe() const override { return "inertia of " + element_.describe(); }

  /// The element's mass matrix over dofs() [mass] (diagonal when lumped),
  /// built from the stored nodal form at each call: bitwise the matrix of
  /// ContinuumElement::mass (or of redistribute()). Loops over entries use mass_entry().
  [[nodiscard]] Eigen::MatrixXd mass() const;
  /// Entry (i, j) of mass() over the element's local dofs, without building the matrix [mass].
  [[nodiscard]] double mass_entry(Eigen::Index i, Eigen::Index j) const;
  /// The diagonal of mass() over the element's local dofs [mass] (the lumped nodal masses per component).
  [[nodiscard]] Eigen::VectorXd mass_diagonal() const;
  /// Doubles the inertia keeps on the heap for its mass: n (lumped) or n^2
  /// (consistent) for an element of n nodes, (c n)^2 once redistribute()
  /// changed it (c components per node). The (c n)^2 matrix is built per use.
  [[nodiscard]] Eigen::Index stored_mass_values() const;
  [[nodiscard]] const ContinuumElement& element() const { return element_; }
  /// Kinetic energy 1/2 v_e^T M v_e of global velocities `v` [energy].
  [[nodiscard]] double kinetic_energy(const Eigen::VectorXd& v) const;
  /// Adds the damping force C v_e [force] at state `s` with global velocities `v` to `out` (global).
  void add_damping_force(const EvaluationState& s, const Eigen::VectorXd& v, Eigen::VectorXd& out) const;
  [[nodiscard]] bool damped() const { return damping_alpha_ != 0 || damping_beta_ != 0; }
  /// Rayleigh factors: mass-proportional [1/time], stiffness-proportional [time].
  [[nodiscard]] double damping_alpha() const { return damping_alpha_; }
  [[nodiscard]] double damping_beta() const { return damping_beta_; }
  /// Adds M_e x_e to `out` (global vectors).
  void add_mass_times(const Eigen::VectorXd& x, Eigen::VectorXd& out) const;
  /// Moves the mass of the element's nodes flagged in `massless` (the
  /// element's node order) to its other nodes (redistribute_mass, weights the
  /// lumped nodal masses); a lumped mass stays diagonal. Returns false and
  /// keeps the mass when every node is flagged. Rayleigh's mass-proportional
  /// damping follows the new mass.
  bool redistribute(const std::vector<bool>& massless);

 private:
  /// mass() into `out`.
  void expanded_mass(Eigen::MatrixXd& out) const;

  const ContinuumElement& element_;
  const NewmarkIncrement& increment_;
  /// The mass over the element's nodes, the same for every component:
  /// n x 1 nodal masses (lumped) or the n x n matrix (consistent).
  Eigen::MatrixXd nodal_;
  Eigen::Index components_ = 0;              ///< local dofs per node
  std::unique_ptr<Eigen::MatrixXd> moved_;  ///< the mass over local dofs after redistribute() (null before)
  MassKind kind_;
  double damping_alpha_ = 0, damping_beta_ = 0;
};

}  // namespace tether
