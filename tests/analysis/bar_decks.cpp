#include "bar_decks.hpp"

#include <cstdio>
#include <sstream>

namespace tether::testing {

std::string full_digits(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

std::string bar_deck(int n, double h, const std::string& bc, const std::string& step) {
  std::ostringstream d;
  d.precision(17);
  d << "*NODE\n";
  for (int i = 0; i <= n; ++i) d << i + 1 << ", " << i * h << ", 0\n" << n + 2 + i << ", " << i * h << ", " << h << "\n";
  d << "*ELEMENT, TYPE=CPE4, ELSET=BAR\n";
  for (int i = 0; i < n; ++i) d << i + 1 << ", " << i + 1 << ", " << i + 2 << ", " << n + 3 + i << ", " << n + 2 + i << "\n";
  d << "*NSET, NSET=ALLN, GENERATE\n1, " << 2 * n + 2 << ", 1\n*NSET, NSET=LEFT\n1, " << n + 2 << "\n*NSET, NSET=RIGHT\n"
    << n + 1 << ", " << 2 * n + 2 << "\n*NSET, NSET=INNER, GENERATE\n2, " << n << ", 1\n" << n + 3 << ", " << 2 * n + 1
    << ", 1\n*MATERIAL, NAME=STEEL\n*ELASTIC\n2e11, 0.3\n*DENSITY\n7800.\n"
    << "*SOLID SECTION, ELSET=BAR, MATERIAL=STEEL\n1.\n*BOUNDARY\nALLN, 2, 2\n" << bc << "*STEP, INC=100000\n" << step
    << "*END STEP\n";
  return d.str();
}

std::string wall_deck(int n, double h, double v0, const std::string& procedure, double gap) {
  std::string deck = bar_deck(n, h, "", procedure);
  const int w = 2 * n + 10;
  std::ostringstream wall;
  wall.precision(17);
  wall << "*NODE\n" << w + 1 << ", " << -h - gap << ", " << -h << "\n" << w + 2 << ", " << -gap << ", " << -h << "\n"
       << w + 3 << ", " << -gap << ", " << 2 * h << "\n" << w + 4 << ", " << -h - gap << ", " << 2 * h << "\n*ELEMENT, TYPE=CPE4, ELSET=WALL\n" << n + 1 << ", "
       << w + 1 << ", " << w + 2 << ", " << w + 3 << ", " << w + 4 << "\n*NSET, NSET=WALLN, GENERATE\n" << w + 1 << ", "
       << w + 4 << ", 1\n*SOLID SECTION, ELSET=WALL, MATERIAL=STEEL\n1.\n*SURFACE, NAME=BAREND\n1, S4\n"
       << "*SURFACE, NAME=WALLFACE\n" << n + 1 << ", S2\n*SURFACE INTERACTION, NAME=I\n"
       << "*CONTACT PAIR, INTERACTION=I, TYPE=NODE TO SURFACE\nBAREND, WALLFACE\n*BOUNDARY\nWALLN, 1, 2\n"
       << "*INITIAL CONDITIONS, TYPE=VELOCITY\nALLN, 1, " << -v0 << "\n";
  deck.replace(deck.find("*STEP"), 5, wall.str() + "*STEP");
  return deck;
}

}  // namespace tether::testing
