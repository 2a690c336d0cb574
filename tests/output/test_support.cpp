#include <fstream>
#include <sstream>
#include <sys/wait.h>

#include "output/tiny_model.hpp"

namespace tether::test {

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

int count_temporary_files(const std::filesystem::path& dir) {
  int n = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (entry.path().extension() == ".tmp") ++n;
  return n;
}

bool python_with_meshio_available() {
  if (!std::filesystem::exists("/usr/bin/python3")) return false;
  return std::system("/usr/bin/python3 -c 'import meshio, numpy' > /dev/null 2>&1") == 0;
}

int run_python(const std::string& arguments) {
  // The scripts import the readers of tools/tethertools (no sys.path edits in them).
  const std::string command = "PYTHONPATH='" + std::string(TETHER_SOURCE_DIR) + "/tools' /usr/bin/python3 " + arguments;
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace tether::test
