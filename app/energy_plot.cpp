#include "energy_plot.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <vector>

extern char** environ;

namespace tether::app {
namespace {

/// argv: script, csv, png, title. Exit 3: matplotlib missing.
constexpr const char* kScript = R"PY(
import csv, sys
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError as e:
    print(f"matplotlib is not installed ({e})", file=sys.stderr)
    sys.exit(3)
source, target, title = sys.argv[1:4]
with open(source, newline="") as f:
    rows = list(csv.DictReader(f))
if not rows:
    print(f"{source} has no rows", file=sys.stderr)
    sys.exit(2)
time = [float(r["time"]) for r in rows]
names = ["ALLKE", "ALLSE", "ALLWK", "ALLFD", "ALLVD", "ALLPD", "NUMERICAL", "ETOTAL"]
fig, ax = plt.subplots(figsize=(8, 4.5), dpi=100)
for name in names:
    values = [float(r[name]) for r in rows]
    if name == "ETOTAL" or any(v != 0 for v in values):
        ax.plot(time, values, label=name, linewidth=2.2 if name == "ETOTAL" else 1.2,
                linestyle="--" if name == "NUMERICAL" else "-")
ax.set_xlabel("total time")
ax.set_ylabel("energy")
ax.set_title(f"{title}: energies (ETOTAL = ALLKE + ALLSE + ALLVD + ALLFD + ALLPD - ALLWK)", fontsize=9)
ax.grid(True, alpha=0.3)
ax.legend(fontsize=8, ncol=4)
fig.tight_layout()
fig.savefig(target)
)PY";

std::string interpreter() { return access("/usr/bin/python3", X_OK) == 0 ? "/usr/bin/python3" : "python3"; }

}  // namespace

std::string plot_energy(const std::filesystem::path& csv, const std::filesystem::path& png, const std::string& title) {
  const std::string python = interpreter();
  std::vector<std::string> args{python, "-c", kScript, csv.string(), png.string(), title};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, python.c_str(), nullptr, nullptr, argv.data(), environ);
  if (spawned != 0) return "cannot start " + python + " (" + std::strerror(spawned) + ")";
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return "lost the plotting process (" + std::string(std::strerror(errno)) + ")";
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return "";
  if (WIFEXITED(status) && WEXITSTATUS(status) == 3) return python + " has no matplotlib";
  return python + " failed to draw " + png.string() + " (see its message above)";
}

}  // namespace tether::app
