#pragma once
// Deck of a flat block pressed onto and slid over an elastic foundation
// (faceted_master_test.cpp, condensation_test.cpp).

#include <sstream>
#include <string>

#include "support/block_mesh.hpp"

namespace tether::testing {

/// A 1 x 0.5 block (`block_faces` x 2 CPE4, slave: its bottom, nodes 1/block_faces apart, 0.125 by default) with its
/// left edge at `x0`, pressed by p = 10 (step 1, 2 increments) onto an
/// elastic foundation 2 x 1 (80 x 30 CPE4, master: its top, faces 0.025 long,
/// base clamped), then its top edge pushed in x by 0.05 in 8 increments
/// (step 2) by `slide`. `pair_options` go on the *CONTACT PAIR line (", SMOOTH=0.2").
/// x0 = 0.5: every slave node starts exactly above a master node.
inline std::string block_on_foundation(double x0, const std::string& interaction, const std::string& pair_options = "",
                                       double slide = 0.05, int block_faces = 8) {
  const Block top{x0, x0 + 1, 1, 1.5, block_faces, 2, false, 1, 1, "TOP"};
  const Block bottom{0, 2, 0, 1, 80, 30, false, 1001, 1001, "BOTTOM"};
  std::ostringstream d;
  d.precision(17);
  top.write(d);
  bottom.write(d);
  top.write_surface(d, "SLAVE", 0);
  bottom.write_surface(d, "MASTER", 2);
  d << "*SURFACE INTERACTION, NAME=I\n" << interaction;
  d << "*CONTACT PAIR, INTERACTION=I, TYPE=NODE TO SURFACE" << pair_options << "\nSLAVE, MASTER\n";
  d << "*MATERIAL, NAME=M\n*ELASTIC\n1000, 0.3\n";
  d << "*SOLID SECTION, ELSET=TOP, MATERIAL=M\n*SOLID SECTION, ELSET=BOTTOM, MATERIAL=M\n";
  d << "*NSET, NSET=BASE, GENERATE\n" << bottom.grid(0, 0) << ", " << bottom.grid(bottom.nx, 0) << "\n";
  d << "*NSET, NSET=PUSHED\n";
  for (int i = 0; i <= top.nx; ++i) d << top.grid(i, top.ny) << "\n";
  d << "*BOUNDARY\nBASE, 1, 2\nPUSHED, 1\n";
  d << "*STEP\n*STATIC\n0.5, 1\n*CONTROLS, PARAMETERS=FIELD\n1e-10, 1e-10\n*DLOAD\n";
  for (int k = 0; k < top.nx; ++k) d << top.element(k, top.ny - 1) << ", P3, 10\n";
  d << "*END STEP\n";
  d << "*STEP, INC=100\n*STATIC, DIRECT\n0.125, 1\n*CONTROLS, PARAMETERS=FIELD\n1e-10, 1e-10\n";
  d << "*BOUNDARY\nPUSHED, 1, 1, " << slide << "\n*END STEP\n";
  return d.str();
}

}  // namespace tether::testing
