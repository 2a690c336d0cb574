// Benchmark (not a test): the cost of explicit dynamics per element and per
// explicit increment. A 1D-strain steel bar (plane strain, every node on
// rollers in y) of N square CPE4 moves at 1 m/s onto its held left end; the
// `*DYNAMIC, EXPLICIT` step is sized to K explicit increments (0.9 of the
// stable increment h / c_p each). No writers: of the 100 report intervals, 20
// (the result files' default output) build the element results, which are
// dropped, and 80 only the nodal values and energies.
//
//   OMP_NUM_THREADS=1 tether_bench_explicit --elements 1000000 --increments 400
//
// The figure is the difference of a run of K and one of 2K increments, both
// with 100 reports: set-up and reports cancel in it, but their noise does not.
// At 1M elements one report costs about as much as 5 increments, so K must be
// a few hundred for the K increments to dominate the runs: the bench prints
// their share of the 2K run's CPU time and warns below one half.
//
// Output: a readable report on stderr and `@key=value` lines on stdout:
// elements, increments, ns per element per increment from the CPU time (and
// from the wall time of the explicit loop, as the procedure times it), peak
// RSS [MiB]. One thread (OMP_NUM_THREADS=1): the explicit loop is serial.

#include <CLI/CLI.hpp>
#include <fmt/core.h>
#include <sys/resource.h>
#include <time.h>

#include <chrono>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "tether/analysis/static_analysis.hpp"
#include "tether/io/deck_reader.hpp"

namespace {

using namespace tether;

double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double peak_rss_mib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;
}

/// The bar deck: n CPE4 of side h, steel, left end held, the rest at -1 m/s, `period` [s].
std::string bar_deck(long n, double h, double period) {
  std::ostringstream d;
  d.precision(17);
  d << "*NODE\n";
  for (long i = 0; i <= n; ++i) d << i + 1 << ", " << i * h << ", 0\n" << n + 2 + i << ", " << i * h << ", " << h << "\n";
  d << "*ELEMENT, TYPE=CPE4, ELSET=BAR\n";
  for (long i = 0; i < n; ++i) d << i + 1 << ", " << i + 1 << ", " << i + 2 << ", " << n + 3 + i << ", " << n + 2 + i << "\n";
  d << "*NSET, NSET=ALLN, GENERATE\n1, " << 2 * n + 2 << ", 1\n*NSET, NSET=LEFT\n1, " << n + 2
    << "\n*MATERIAL, NAME=STEEL\n*ELASTIC\n2e11, 0.3\n*DENSITY\n7800.\n*SOLID SECTION, ELSET=BAR, MATERIAL=STEEL\n1.\n"
    << "*BOUNDARY\nALLN, 2, 2\nLEFT, 1, 1\n*INITIAL CONDITIONS, TYPE=VELOCITY\nALLN, 1, -1.\n*STEP\n*DYNAMIC, EXPLICIT\n, "
    << period << "\n*END STEP\n";
  return d.str();
}

class Silent final : public AnalysisObserver {};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"tether_bench_explicit: ns per CPE4 per explicit increment on a 1D-strain bar"};
  long elements = 100000;
  long increments = 200;
  double h = 0.01;
  app.add_option("--elements", elements, "CPE4 along the bar")->check(CLI::PositiveNumber);
  app.add_option("--increments", increments, "explicit increments (a multiple of 100 is run exactly)")
      ->check(CLI::PositiveNumber);
  app.add_option("--element-size", h, "side of the square elements [m]")->check(CLI::PositiveNumber);
  CLI11_PARSE(app, argc, argv);

  const double e = 2e11, nu = 0.3, rho = 7800;
  const double cp = std::sqrt(e * (1 - nu) / (rho * (1 + nu) * (1 - 2 * nu)));
  const double limit = 0.9 * h / cp;  // the procedure's increment: 0.9 of a / c_p (y held)
  // Two runs, K and 2K increments, both with 100 reports: the difference of
  // their CPU times is K increments and nothing else (set-up, reports and
  // the stable increment cancel), a figure that a loaded machine does not inflate.
  struct Figures {
    long increments = 0;
    double cpu = 0, wall = 0, evaluation = 0, output = 0;
  };
  const auto run_bar = [&](long k) {
    const Model model = read_deck_string(bar_deck(elements, h, static_cast<double>(k) * limit * (1 - 1e-12)), "bar.inp");
    Silent observer;
    StaticAnalysis analysis(model, observer);
    const auto wall_start = std::chrono::steady_clock::now();
    const double cpu_start = cpu_seconds();
    const AnalysisSummary summary = analysis.run();
    Figures f;
    f.cpu = cpu_seconds() - cpu_start;
    f.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
    if (!summary.completed) throw std::runtime_error("the run failed: " + summary.message);
    const long reports = std::min(100L, k);
    f.increments = reports * ((k + reports - 1) / reports);
    f.evaluation = summary.timing.assembly, f.output = summary.timing.output;
    return f;
  };
  const Figures once = run_bar(increments), twice = run_bar(2 * increments);
  const double per = 1e9 / (static_cast<double>(elements) * static_cast<double>(twice.increments - once.increments));
  const double ns_cpu = (twice.cpu - once.cpu) * per;
  const double ns_wall = (twice.evaluation - once.evaluation) * per;
  const double share = (twice.cpu - once.cpu) / twice.cpu;  // the K increments' share of the 2K run
  const double rest = (2 * once.cpu - twice.cpu) / 100;       // set-up and reports of one run, per report
  fmt::print(stderr,
             "{} CPE4: {} and {} explicit increments took {:.3f} and {:.3f} s CPU ({:.3f} and {:.3f} s wall, of "
             "which the explicit loop {:.3f} and {:.3f} s, the 100 reports {:.3f} and {:.3f} s): {:.1f} ns CPU "
             "({:.1f} ns wall) per element per increment; peak RSS {:.0f} MiB\n",
             elements, once.increments, twice.increments, once.cpu, twice.cpu, once.wall, twice.wall, once.evaluation,
             twice.evaluation, once.output, twice.output, ns_cpu, ns_wall, peak_rss_mib());
  fmt::print(stderr, "the K increments are {:.0f} % of the 2K run's CPU; set-up and reports {:.3f} s CPU per report{}\n",
             100 * share, rest,
             share < 0.5 ? ": below one half, the reports' noise weighs on the figure; run more increments" : "");
  fmt::print("@elements={}\n@increments={}\n@ns_per_element_increment_cpu={:.4g}\n"
             "@ns_per_element_increment_wall={:.4g}\n@cpu_s_2k={:.6g}\n@increments_share_2k={:.3f}\n"
             "@peak_rss_mib={:.1f}\n@peak_rss_bytes_per_element={:.0f}\n",
             elements, twice.increments - once.increments, ns_cpu, ns_wall, twice.cpu, share, peak_rss_mib(),
             peak_rss_mib() * 1048576.0 / static_cast<double>(elements));
  return 0;
}
