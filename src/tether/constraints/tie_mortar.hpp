#pragma once
/// \file Mortar (surface-to-surface) tie of two non-matching surfaces: the
/// integrals D and M of `*TIE, TYPE=SURFACE TO SURFACE`. Pure geometry.
///
/// For every slave node k the tie asks, in x and in y,
///   sum_l D_kl u_l - sum_i M_ki u_i = 0,
///   D_kl = int_slave psi_k phi_l dGamma,  M_ki = int_slave psi_k N_i(xi(x)) dGamma,
/// with phi the slave face shape functions, psi_k = phi_k (standard mortar
/// multipliers), N_i the master face shape functions at the closest point
/// xi(x) of the slave point x. Unlike the node-to-surface tie it passes the
/// patch test for any non-matching meshes on a straight (or exactly shared)
/// interface: a constant traction is transferred consistently to both sides.

#include <Eigen/Core>
#include <map>
#include <span>
#include <vector>

namespace tether {

/// A 2- or 3-node face: node indices and reference coordinates in face_nodes() order.
struct TieFace {
  std::vector<int> nodes;
  std::vector<Eigen::Vector2d> x;
};

/// Row of one slave node: coefficient per node index (+D on slave nodes, -M on
/// master nodes; a node on both sides gets the sum).
using MortarRow = std::map<int, double>;

/// The mortar rows of every slave node of `slave` whose faces have a part
/// within `tolerance` of `master`. Each slave face is cut at the projections of
/// the master face ends and integrated with 4 Gauss points per piece (exact
/// for straight faces: integrands of degree <= 4). Slave points farther than
/// `tolerance` from the master surface are left out of the integrals.
std::map<int, MortarRow> mortar_tie_rows(std::span<const TieFace> slave, std::span<const TieFace> master,
                                         double tolerance);

}  // namespace tether
