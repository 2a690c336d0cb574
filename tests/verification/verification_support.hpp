#pragma once
// Shared helpers of the verification suite: deck paths, the Lame and beam
// closed forms, and a reader for the CalculiX reference CSVs.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/run_deck.hpp"

namespace tether::verification {

/// Deck written by the generator tools/`tool` with `options` into
/// <build>/tests/verification/`folder`/`name`.inp, once (cached while the
/// command stays the same: it is kept in `name`.command); throws
/// std::runtime_error("skip") without python3 and gmsh, and "generator
/// failed: ..." when the tool fails.
inline std::filesystem::path generated_deck(const std::string& tool, const std::string& folder,
                                            const std::string& name, const std::string& options) {
  namespace fs = std::filesystem;
  if (std::system("command -v python3 > /dev/null 2>&1 && command -v gmsh > /dev/null 2>&1") != 0)
    throw std::runtime_error("skip");
  const fs::path dir = fs::path(TETHER_BINARY_DIR) / "tests" / "verification" / folder;
  fs::create_directories(dir);
  const fs::path deck = dir / (name + ".inp");
  // The command that wrote the cached deck sits beside it: a test whose
  // options changed gets a fresh deck, not the old one under the same name.
  const fs::path written_by = dir / (name + ".command");
  const std::string command = "python3 \"" + std::string(TETHER_SOURCE_DIR) + "/tools/" + tool + "\" " + options +
                              " \"" + deck.string() + "\" > /dev/null";
  // ... and the generator's modification time: an edited generator writes the deck again.
  const fs::path script = fs::path(TETHER_SOURCE_DIR) / "tools" / tool;
  std::error_code ec;
  const auto stamp = fs::last_write_time(script, ec).time_since_epoch().count();
  const std::string key = command + " # " + std::to_string(ec ? 0 : stamp);
  std::string cached;
  if (std::ifstream in(written_by); in) std::getline(in, cached);
  if (!fs::exists(deck) || cached != key) {
    fs::remove(written_by);
    if (std::system(command.c_str()) != 0) throw std::runtime_error("generator failed: " + command);
    std::ofstream(written_by) << key << "\n";
  }
  return deck;
}

/// Path of a committed deck, e.g. deck_path("lame_cpe8_4x8").
inline std::string deck_path(const std::string& name) {
  return std::string(TETHER_SOURCE_DIR) + "/tests/verification/decks/" + name + ".inp";
}

/// Lame thick cylinder under internal pressure. The constants are those of
/// tools/make_lame_deck.py (A, B, P, E, NU); the tests check that the deck's
/// material agrees with them.
namespace lame {
inline constexpr double a = 10, b = 20, p = 100, young = 200000, poisson = 0.3;
inline constexpr double c = p * a * a / (b * b - a * a);  ///< C = p a^2 / (b^2 - a^2)
inline constexpr double d = c * b * b;                    ///< D = p a^2 b^2 / (b^2 - a^2)

/// Radial displacement, plane strain (also CAX with u_z = 0 top and bottom).
inline double radial_displacement_plane_strain(double r) {
  return (1 + poisson) * p * a * a / (young * (b * b - a * a)) * ((1 - 2 * poisson) * r + b * b / r);
}
/// Radial displacement, plane stress (thin disc).
inline double radial_displacement_plane_stress(double r) {
  return ((1 - poisson) * c * r + (1 + poisson) * d / r) / young;
}
inline double hoop_stress(double r) { return c * (1 + b * b / (r * r)); }
inline double radial_stress(double r) { return c * (1 - b * b / (r * r)); }
}  // namespace lame

/// One row of a CalculiX reference CSV (tools/ccx_reference.py).
struct ReferenceRow {
  std::string kind;  ///< "U" or "RF"
  std::string set;   ///< node set the row was printed for
  int node = 0;      ///< node label
  double x = 0, y = 0;
};

/// Reads tests/verification/reference/NAME.csv ('#' lines are comments, then a header line).
inline std::vector<ReferenceRow> read_reference(const std::string& name) {
  const std::string path = std::string(TETHER_SOURCE_DIR) + "/tests/verification/reference/" + name + ".csv";
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  std::vector<ReferenceRow> rows;
  std::string line;
  bool header = true;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (header) {
      header = false;
      continue;
    }
    std::istringstream fields(line);
    ReferenceRow row;
    std::string node, x, y;
    std::getline(fields, row.kind, ',');
    std::getline(fields, row.set, ',');
    std::getline(fields, node, ',');
    std::getline(fields, x, ',');
    std::getline(fields, y, ',');
    row.node = std::stoi(node);
    row.x = std::stod(x);
    row.y = std::stod(y);
    rows.push_back(row);
  }
  return rows;
}

}  // namespace tether::verification
