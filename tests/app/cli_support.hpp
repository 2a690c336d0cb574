#pragma once
// Running the tether program from tests: its output, exit code and a scratch folder.

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>

namespace cli_test {

namespace fs = std::filesystem;

struct Result {
  int code = -1;
  std::string out;  ///< stdout and stderr together
};

/// Runs the tether program with `args` (stdout is a pipe, so not a terminal),
/// with `environment` ("NAME=value ...", shell syntax) added to its environment.
inline Result tether(const std::string& args, const std::string& environment = "") {
  const std::string command =
      (environment.empty() ? "" : "env " + environment + " ") + std::string(TETHER_CLI) + " " + args + " 2>&1";
  Result r;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buffer{};
  while (fgets(buffer.data(), buffer.size(), pipe)) r.out += buffer.data();
  const int status = pclose(pipe);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

/// An empty folder tests/app/scratch/NAME under the build tree.
inline fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(TETHER_BINARY_DIR) / "tests" / "app" / "scratch" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

inline void write(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

/// The whole file at `p`.
inline std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

/// One CPE4 under tension, held at its left edge: a deck that runs.
inline constexpr const char* kGoodDeck = R"(*HEADING
one CPE4 under tension
*NODE, NSET=ALL
1, 0, 0
2, 1, 0
3, 1, 1
4, 0, 1
*ELEMENT, TYPE=CPE4, ELSET=E
1, 1, 2, 3, 4
*NSET, NSET=LEFT
1, 4
*MATERIAL, NAME=M
*ELASTIC
1000, 0.3
*SOLID SECTION, ELSET=E, MATERIAL=M
*BOUNDARY
LEFT, 1
1, 2
*STEP
*STATIC
0.5, 1.
*CLOAD
2, 1, 1.
3, 1, 1.
*NODE PRINT, NSET=ALL
U
*END STEP
)";

inline /// The first `count` numbers of the ascii DataArray `name` after `from` in a .vtu.
std::vector<double> vtu_values(const std::string& vtu, const std::string& name, std::size_t count,
                               std::size_t from = 0) {
  const auto at = vtu.find("Name=\"" + name + "\"", from);
  if (at == std::string::npos) return {};
  const auto begin = vtu.find('>', at) + 1;
  std::istringstream in(vtu.substr(begin, vtu.find("</DataArray>", begin) - begin));
  std::vector<double> values;
  for (double v = 0; values.size() < count && in >> v;) values.push_back(v);
  return values;
}

}  // namespace cli_test
