#pragma once
/// \file Contact in explicit dynamics: the predictor–corrector with
/// forward-increment Lagrange multipliers (Carpenter, Taylor & Katona 1991;
/// ABAQUS/Explicit's kinematic contact), hard and frictionless, node to segment.
///
/// After the central-difference predictor has moved every node without
/// contact, each slave node is paired with its closest master segment
/// (find_closest, segment_geometry); the slaves that penetrate (gap g_k < 0
/// inside a segment) get a multiplier lambda_k [force] acting on the slave
/// along the master's outward normal n and on the segment's nodes as
/// -N_a lambda_k n. The forces f_c = G^T lambda act at time t_n, so they move
/// the predicted positions by c M^-1 f_c with c = h_{n+1/2} (h_{n-1/2} + h_{n+1/2}) / 2;
/// the multipliers solve
///     c G M^-1 G^T lambda = -g       (one row per penetrating slave),
/// which removes the penetration exactly to first order in the correction
/// (exactly for masters that cannot move). Slaves whose multiplier comes out
/// negative (pulled back) are released and the system solved again. The
/// forces sum to zero over each pair of slave and segment (sum N_a = 1), so
/// the correction conserves linear momentum exactly. Prescribed dofs do not
/// move (their inverse mass is 0): a held master is rigid, and the force on it
/// goes into its reaction. See docs/theory/explicit_dynamics.md.

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
  /// support: a soft pressure–overclosure law, friction, SMOOTH.
  explicit ExplicitContact(const Discretization& discretization);

  [[nodiscard]] bool empty() const { return pairs_.empty(); }

  /// Contact forces f_c (over all unknowns; 0 where no contact) that remove
  /// the penetrations of the predicted displacements `u` when the nodes move by
  /// c M^-1 f_c (`inverse_mass` over all unknowns, 0 at prescribed dofs).
  /// Remembers each slave's pairing, gap and multiplier for values().
  void correct(const Eigen::VectorXd& u, const Eigen::VectorXd& inverse_mass, double c, Eigen::VectorXd& force);

  /// The contact output of the last correct(), per pair (normal forces at time t_n).
  [[nodiscard]] std::vector<ContactPairValues> values() const;

 private:
  struct Constraint {
    int pair = 0, slave = 0;       ///< pair index, slave index in it
    std::vector<int> dofs;         ///< slave x, y, then the segment nodes' x, y
    std::vector<double> gradient;  ///< dg/d(dofs): n, -N_1 n, ...
    double gap = 0;                ///< predicted gap [length], < 0
  };
  struct Pair {
    explicit Pair(const ContactPairSetup& s) : setup(&s), surface(s.master_faces) {}
    const ContactPairSetup* setup = nullptr;
    MasterSurface surface;
    std::vector<ContactPairing> pairing;  ///< per slave, last search
    std::vector<double> multiplier;       ///< per slave, last correction [force]
    std::vector<Eigen::Vector2d> normal;  ///< per slave, master normal of the last correction
  };
  /// The penetrating slaves of the predicted positions.
  std::vector<Constraint> penetrations(const Eigen::VectorXd& u);
  /// Solves c G M^-1 G^T lambda = -g over the `active` constraints.
  [[nodiscard]] Eigen::VectorXd multipliers(const std::vector<Constraint>& constraints, const std::vector<int>& active,
                                            const Eigen::VectorXd& inverse_mass, double c) const;

  const Discretization& discretization_;
  std::vector<Pair> pairs_;
  std::vector<Eigen::Vector2d> positions_;  ///< current node positions (scratch)
};

}  // namespace tether
