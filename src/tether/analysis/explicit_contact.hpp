#pragma once
/// \file Contact in explicit dynamics: the predictor–corrector with
/// forward-increment Lagrange multipliers (Carpenter, Taylor & Katona 1991;
/// ABAQUS/Explicit's kinematic contact), hard, with Coulomb friction, node to segment.
///
/// After the central-difference predictor has moved every node without
/// contact, each slave node is paired with its closest master segment
/// (find_closest, segment_geometry); the slaves that penetrate (gap g_k < 0
/// inside a segment) get a multiplier lambda_k [force]. The forces act at
/// time t_n, so their direction is taken there: D_k = [n; -N_1 n; ...], the gap
/// gradient at t_n of the slave against the same segment (n its outward
/// normal and N_a its shape functions at the slave's projection at t_n).
/// The forces f_c = D^T lambda move the predicted positions by c M^-1 f_c
/// with c = h_{n+1/2} (h_{n-1/2} + h_{n+1/2}) / 2, and the multipliers solve
///     g(x~ + c M^-1 D^T lambda) = 0       (one row per penetrating slave)
/// by Newton (Jacobian c G M^-1 D^T, G the gap gradient at the corrected
/// positions), to 1e-12 of the model's size: exact in one pass against a
/// master that cannot move. Slaves whose multiplier comes out negative
/// (pulled back) are released and the system solved again. The forces of a
/// slave and its segment sum to zero (sum N_a = 1): linear momentum is
/// conserved exactly. Their moment about the positions x_n at which they act
/// is (x_s - y(xi_n)) x n = g_n n x n = 0: the discrete angular momentum of
/// central differences, sum m x_n x v_{n+1/2}, is conserved exactly too
/// (SHAKE's choice: the constraint met at t_{n+1}, its gradient taken at t_n).
/// Prescribed dofs do not move (their inverse mass is 0): a held master is
/// rigid, and the force on it goes into its reaction.
///
/// Coulomb friction (stick/slip): after the normal correction, each closed
/// slave's tangential motion relative to the master's material point at ξ*
/// over the increment, Δs_k = T_k (x' − x_n) with T_k = [t; −N_1 t; …], is
/// removed by tangential multipliers (c T M⁻¹ Tᵀ λ_t = −Δs, stick); a slave
/// whose |λ_t| would exceed μ λ_k slips with λ_t = ±μ λ_k (the sign of the
/// stick force), and the others are solved again with it fixed. The
/// dissipation −λ_t Δs' (Δs' the corrected slip) of each increment is
/// added by commit(). The friction forces' moment about x_n is g_n λ_t
/// (zero for a slave that sat on the master at t_n): with friction, angular
/// momentum changes at the increments where a slave arrives.
/// See docs/theory/explicit_dynamics.md.

#include <Eigen/Core>
#include <vector>

#include "tether/analysis/discretization.hpp"
#include "tether/contact/contact_search.hpp"
#include "tether/model/results.hpp"

namespace tether {

class ExplicitContact {
 public:
  /// The contact pairs of `discretization` (must outlive this). Throws
  /// ModelError naming the pair for what the explicit corrector does not
  /// support: a soft pressure–overclosure law, SMOOTH, a stick slope or ELASTIC SLIP.
  explicit ExplicitContact(const Discretization& discretization);

  [[nodiscard]] bool empty() const { return pairs_.empty(); }

  /// Contact forces f_c (over all unknowns; 0 where no contact) that remove
  /// the penetrations of the predicted displacements `u` when the nodes move by
  /// c M^-1 f_c (`inverse_mass` over all unknowns, 0 at prescribed dofs), and
  /// with friction the slip relative to the displacements `u_now` at t_n
  /// (stick) or oppose it with mu times the normal force (slip).
  /// Remembers each slave's pairing, gap and forces for values().
  void correct(const Eigen::VectorXd& u_now, const Eigen::VectorXd& u, const Eigen::VectorXd& inverse_mass, double c,
               Eigen::VectorXd& force);
  /// The increment whose forces the last correct() gave is taken: its
  /// friction dissipation and slip join the totals.
  void commit();

  /// The contact output of the last correct(), per pair (forces at time t_n;
  /// slip and dissipation totals as committed).
  [[nodiscard]] std::vector<ContactPairValues> values() const;
  /// Friction dissipation committed so far, over every pair [energy].
  [[nodiscard]] double dissipation() const;

 private:
  struct Constraint {
    int pair = 0, slave = 0;       ///< pair index, slave index in it
    std::vector<int> nodes;                ///< the slave node, then the segment's nodes
    std::vector<int> dofs;                 ///< slave x, y, then the segment nodes' x, y
    std::vector<double> gradient;          ///< dg/d(dofs) at the predicted positions: n, -N_1 n, ...
    std::vector<double> direction;         ///< the normal force's direction: the gap gradient at t_n
    std::vector<double> tangent_gradient;  ///< ds/d(dofs): t, -N_1 t, ...
    double gap = 0;                ///< predicted gap [length], < 0
    Eigen::Vector2d normal_now{0, 0};  ///< the master's outward normal at t_n (of `direction`)
  };
  struct Pair {
    explicit Pair(const ContactPairSetup& s) : setup(&s), surface(s.master_faces) {}
    const ContactPairSetup* setup = nullptr;
    MasterSurface surface;
    std::vector<ContactPairing> pairing;  ///< per slave, last search
    std::vector<double> multiplier;       ///< per slave, last correction [force]
    std::vector<Eigen::Vector2d> normal;   ///< per slave, master normal of the last correction
    std::vector<Eigen::Vector2d> tangent;  ///< per slave, master tangent of the last correction
    std::vector<double> tangential;        ///< per slave, tangential multiplier of the last correction [force]
    std::vector<double> slip;              ///< per slave, corrected slip of the last correction [length]
    std::vector<bool> slipping;            ///< per slave, slip (true) or stick in the last correction
    std::vector<double> total_slip, dissipation;  ///< per slave, committed totals
  };
  /// The penetrating slaves of the predicted positions `u`, with their
  /// force directions at the positions `u_now` of t_n.
  std::vector<Constraint> penetrations(const Eigen::VectorXd& u_now, const Eigen::VectorXd& u);
  /// Gaps (into `gaps`) and gap gradients (into the constraints' `gradient`)
  /// of the `active` constraints at the predicted positions `u` moved by c M^-1 f.
  void corrected_gaps(std::vector<Constraint>& constraints, const std::vector<int>& active, const Eigen::VectorXd& u,
                      const Eigen::VectorXd& inverse_mass, double c, const Eigen::VectorXd& f, Eigen::VectorXd& gaps) const;
  /// Newton on g(u + c M^-1 D^T lambda) = 0 over the `active` constraints;
  /// the gradients of `constraints` are left at the corrected positions.
  [[nodiscard]] Eigen::VectorXd solve_normal(std::vector<Constraint>& constraints, const std::vector<int>& active,
                                             const Eigen::VectorXd& u, const Eigen::VectorXd& inverse_mass, double c);
  /// Solves c G M^-1 G^T lambda = rhs over the `active` constraints, G their
  /// `gradient` (normal) or `tangent_gradient` rows.
  [[nodiscard]] Eigen::VectorXd multipliers(const std::vector<Constraint>& constraints, const std::vector<int>& active,
                                            const Eigen::VectorXd& inverse_mass, double c, bool tangential,
                                            const Eigen::VectorXd& rhs) const;
  /// Normal multipliers of the penetrating constraints (0 for released ones)
  /// for the predicted positions `u`.
  [[nodiscard]] Eigen::VectorXd normal_multipliers(std::vector<Constraint>& constraints, const Eigen::VectorXd& u,
                                                   const Eigen::VectorXd& inverse_mass, double c);
  /// Coulomb friction on the closed constraints (normal forces `normal`, already in `force`):
  /// adds the tangential forces to `force`, records them per slave.
  void add_friction(const std::vector<Constraint>& constraints, const Eigen::VectorXd& normal,
                    const Eigen::VectorXd& u_now, const Eigen::VectorXd& u, const Eigen::VectorXd& inverse_mass,
                    double c, Eigen::VectorXd& force);

  const Discretization& discretization_;
  std::vector<Pair> pairs_;
  std::vector<Eigen::Vector2d> positions_;  ///< current node positions (scratch)
  Eigen::VectorXd friction_force_;          ///< tangential forces of the last correction (scratch)
  Eigen::VectorXd normal_force_;            ///< normal forces of a Newton pass (scratch, 0 off the contact dofs)
  double tolerance_ = 0;                    ///< |g| accepted after the correction [length]
};

}  // namespace tether
