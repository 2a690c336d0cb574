// Benchmark (not a test): times pattern build, assembly, one factorization +
// solve (CHOLMOD and UMFPACK) and a whole linear StaticAnalysis for a
// structured plane-strain CPE4 mesh, and reports the peak resident memory of
// every phase. Run one size per process so the peaks belong to that size;
// bench/run.sh does that for all sizes and prints a Markdown table.
//
// Output: a readable report on stderr and one `@key=value` line per figure on
// stdout (what run.sh parses). Times are wall-clock seconds; memory is MiB.

#include <CLI/CLI.hpp>
#include <cholmod.h>
#include <fmt/core.h>
#include <sys/resource.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "tether/analysis/discretization.hpp"
#include "tether/analysis/static_analysis.hpp"
#include "tether/assembly/assembler.hpp"
#include "tether/io/deck_reader.hpp"
#include "tether/output/result_writer.hpp"
#include "tether/solvers/linear_solver.hpp"

namespace {

using namespace tether;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

/// CPU seconds of the whole process (all threads): on a loaded machine the
/// CPU time of a single-threaded phase is a steadier figure than wall time.
double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// ---------------------------------------------------------------- memory ---

/// One field of /proc/self/status in KiB (VmHWM, VmRSS), or -1.
long status_kib(const std::string& field) {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(field + ":", 0) == 0) return std::stol(line.substr(field.size() + 1));
  return -1;
}

/// Peak resident memory per phase. Linux resets the high-water mark when "5"
/// is written to /proc/self/clear_refs; where that is refused the phase peaks
/// are cumulative (still correct for the last, largest phase).
class PeakMemory {
 public:
  /// Starts a phase: the peak from now on.
  void reset() {
    std::ofstream out("/proc/self/clear_refs");
    out << "5";
    out.flush();
    resettable_ = resettable_ && static_cast<bool>(out);
  }
  /// Peak RSS since the last reset(), MiB; also raises the process peak.
  double phase_peak_mib() {
    const long hwm = status_kib("VmHWM");
    process_peak_kib_ = std::max(process_peak_kib_, hwm);
    return hwm / 1024.0;
  }
  /// Peak of the whole process, MiB (the largest phase peak, and getrusage's).
  [[nodiscard]] double process_peak_mib() const {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return std::max(process_peak_kib_, static_cast<long>(usage.ru_maxrss)) / 1024.0;
  }
  [[nodiscard]] bool resettable() const { return resettable_; }

 private:
  long process_peak_kib_ = 0;
  bool resettable_ = true;
};

// ---------------------------------------------------------------- report ---

/// Prints a figure for people (stderr) and for run.sh (stdout, `@key=value`).
void report(const std::string& key, double value, const std::string& unit) {
  fmt::print(stderr, "  {:<34} {:>12.4g} {}\n", key, value, unit);
  fmt::print("@{}={:.6g}\n", key, value);
}
void report_int(const std::string& key, long long value) {
  fmt::print(stderr, "  {:<34} {:>12}\n", key, value);
  fmt::print("@{}={}\n", key, value);
}

/// Best (smallest) of `repeat` calls of `f`, each returning seconds.
double best_of(int repeat, const std::function<double()>& f) {
  double best = std::numeric_limits<double>::infinity();
  for (int r = 0; r < repeat; ++r) best = std::min(best, f());
  return best;
}

int max_threads() {
#ifdef _OPENMP
  return omp_get_max_threads();
#else
  return 1;
#endif
}
void set_threads(int n) {
#ifdef _OPENMP
  omp_set_num_threads(n);
#else
  (void)n;
#endif
}

// ------------------------------------------------------------------ mesh ---

/// Deck of a plane-strain square [0,1]^2 of nx x ny CPE4 elements, nodes
/// numbered row by row from 1. The left edge is fixed (both components), the
/// right edge is pulled by u_x = 1e-3 in one linear *STATIC step.
std::string square_deck(int nx, int ny) {
  std::string d;
  d.reserve(static_cast<std::size_t>(nx + 1) * (ny + 1) * 40 + static_cast<std::size_t>(nx) * ny * 40 + 1024);
  auto out = std::back_inserter(d);
  fmt::format_to(out, "*HEADING\nbenchmark square {}x{} CPE4\n*NODE, NSET=ALL\n", nx, ny);
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      fmt::format_to(out, "{}, {}, {}\n", j * (nx + 1) + i + 1, static_cast<double>(i) / nx,
                     static_cast<double>(j) / ny);
  fmt::format_to(out, "*ELEMENT, TYPE=CPE4, ELSET=EALL\n");
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int n1 = j * (nx + 1) + i + 1;
      fmt::format_to(out, "{}, {}, {}, {}, {}\n", j * nx + i + 1, n1, n1 + 1, n1 + nx + 2, n1 + nx + 1);
    }
  const int last_row_first = ny * (nx + 1) + 1;
  fmt::format_to(out, "*NSET, NSET=LEFT, GENERATE\n1, {}, {}\n", last_row_first, nx + 1);
  fmt::format_to(out, "*NSET, NSET=RIGHT, GENERATE\n{}, {}, {}\n", nx + 1, (ny + 1) * (nx + 1), nx + 1);
  fmt::format_to(out,
                 "*MATERIAL, NAME=STEEL\n*ELASTIC\n210000., 0.3\n"
                 "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n1.\n"
                 "*BOUNDARY\nLEFT, 1, 2\n"
                 "*STEP\n*STATIC\n*BOUNDARY\nRIGHT, 1, 1, 1.e-3\n*END STEP\n");
  return d;
}

// ------------------------------------------------------------- observers ---

/// Keeps nothing: the end-to-end run without result files.
class SilentObserver final : public AnalysisObserver {
 public:
  void on_results(const IncrementResults& /*results*/, const Step& /*step*/, bool /*last*/) override { ++results; }
  int results = 0;
};

/// Writes every result file the CLI would write (.vtu/.pvd/.dat/.sta) and times it.
class WritingObserver final : public AnalysisObserver {
 public:
  explicit WritingObserver(ResultWriter& writer) : writer_(writer) {}
  void on_increment(const IncrementReport& r) override {
    const auto t0 = Clock::now();
    IncrementStatus s;
    s.step = r.step;
    s.increment = r.increment;
    s.attempt = r.attempt;
    s.converged = r.converged;
    s.iterations = r.iterations;
    s.total_iterations = r.total_iterations;
    s.total_time = r.total_time;
    s.step_time = r.step_time;
    s.increment_size = r.increment_size;
    s.residual_norm = r.residual;
    writer_.write_status(s);
    write_seconds += seconds_since(t0);
  }
  void on_results(const IncrementResults& results, const Step& step, bool last_in_step) override {
    const auto t0 = Clock::now();
    writer_.write_increment(results, step.outputs, last_in_step);
    write_seconds += seconds_since(t0);
  }
  double write_seconds = 0;

 private:
  ResultWriter& writer_;
};

// ---------------------------------------------------------------- phases ---

struct Options {
  int nx = 0, ny = 0;
  int repeat = 5;          ///< repetitions of pattern build and assembly (best is reported)
  int solve_repeat = 1;    ///< repetitions of each factorization + solve
  std::vector<int> threads;
  std::string phase = "kernels";
  std::string write_dir;
  bool factor_stats = true;
};

/// Best times of `repeat` fresh solvers: analyze, factorize, solve, and a
/// second factorization on the same pattern (what a Newton iteration costs).
struct SolverTimes {
  double analyze = 1e300, factorize = 1e300, solve = 1e300, total = 1e300, refactorize = 1e300;
  double total_cpu = 1e300;       ///< CPU seconds of analyze + factorize + solve
  double relative_residual = 0;  ///< |K x - b| / |b|
};

SolverTimes time_solver(SolverKind kind, const SparseMatrix& k, const Eigen::VectorXd& b, int repeat) {
  SolverTimes best;
  Eigen::VectorXd x;
  for (int r = 0; r < repeat; ++r) {
    auto solver = make_linear_solver(kind);
    const double cpu0 = cpu_seconds();
    auto t0 = Clock::now();
    solver->analyze(k);
    const double analyze = seconds_since(t0);
    t0 = Clock::now();
    solver->factorize(k, true);
    const double factorize = seconds_since(t0);
    t0 = Clock::now();
    solver->solve(b, x);
    const double solve = seconds_since(t0);
    best.total_cpu = std::min(best.total_cpu, cpu_seconds() - cpu0);
    t0 = Clock::now();
    solver->factorize(k, true);
    best.refactorize = std::min(best.refactorize, seconds_since(t0));
    best.analyze = std::min(best.analyze, analyze);
    best.factorize = std::min(best.factorize, factorize);
    best.solve = std::min(best.solve, solve);
    best.total = std::min(best.total, analyze + factorize + solve);
  }
  best.relative_residual = (k * x - b).norm() / b.norm();
  return best;
}

/// Pattern build, assembly, CHOLMOD and UMFPACK on the model's first step.
int run_kernels(const Options& opt, PeakMemory& memory) {
  fmt::print(stderr, "kernels: {}x{} CPE4, plane strain\n", opt.nx, opt.ny);

  memory.reset();
  auto t0 = Clock::now();
  const std::string deck = square_deck(opt.nx, opt.ny);
  report("generate_deck_s", seconds_since(t0), "s");
  t0 = Clock::now();
  const Model model = read_deck_string(deck, "bench.inp");
  report("read_deck_s", seconds_since(t0), "s");
  t0 = Clock::now();
  const Discretization disc(model);
  report("discretization_s", seconds_since(t0), "s");
  report("model_peak_mib", memory.phase_peak_mib(), "MiB");

  // The first step's prescribed dofs: left edge (both components), right edge (x).
  const DofMap& dofs = disc.dofs();
  std::vector<bool> prescribed(dofs.n_dofs(), false);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(dofs.n_dofs());
  for (int n : model.node_sets.at("LEFT")) prescribed[dofs.displacement(n, 0)] = prescribed[dofs.displacement(n, 1)] = true;
  for (int n : model.node_sets.at("RIGHT")) {
    prescribed[dofs.displacement(n, 0)] = true;
    u[dofs.displacement(n, 0)] = 1e-3;
  }
  std::vector<Contribution*> contributions;
  for (const auto& e : disc.elements()) contributions.push_back(e.get());
  fmt::print("@mesh={}x{}\n", opt.nx, opt.ny);
  report_int("nodes", model.n_nodes());
  report_int("elements", model.n_elements());
  report_int("dofs", dofs.n_dofs());

  memory.reset();
  set_threads(opt.threads.back());
  Assembler assembler(contributions, EquationMap(prescribed));
  report_int("equations", assembler.equations().n_equations());
  report_int("nnz_K", assembler.pattern().nonZeros());
  report_int("colours", assembler.n_colours());
  for (int t : opt.threads) {
    set_threads(t);
    const double s = best_of(opt.repeat, [&] {
      assembler.set_equations(EquationMap(prescribed));
      return assembler.timing().pattern;
    });
    report(fmt::format("pattern_s_t{}", t), s, "s");
  }
  report("pattern_peak_mib", memory.phase_peak_mib(), "MiB");

  memory.reset();
  const EvaluationState state{u, u, 1.0, 1.0, 1.0, false};
  Eigen::VectorXd residual;
  SparseMatrix tangent;
  for (int t : opt.threads) {
    set_threads(t);
    const double s = best_of(opt.repeat, [&] {
      assembler.assemble(state, residual, &tangent);
      return assembler.timing().evaluate;
    });
    report(fmt::format("assembly_s_t{}", t), s, "s");
    const double r = best_of(opt.repeat, [&] {
      assembler.assemble(state, residual, nullptr);
      return assembler.timing().evaluate;
    });
    report(fmt::format("residual_only_s_t{}", t), r, "s");
  }
  report("assembly_peak_mib", memory.phase_peak_mib(), "MiB");
  set_threads(opt.threads.back());

  // Right-hand side over the free equations: K du = -r.
  const EquationMap& eqs = assembler.equations();
  Eigen::VectorXd rhs(eqs.n_equations());
  for (int e = 0; e < eqs.n_equations(); ++e) rhs[e] = -residual[eqs.dof(e)];

  for (const auto& [kind, label] : {std::pair{SolverKind::Cholmod, "cholmod"}, std::pair{SolverKind::Umfpack, "umfpack"}}) {
    memory.reset();
    try {
      const SolverTimes t = time_solver(kind, tangent, rhs, opt.solve_repeat);
      report(fmt::format("{}_analyze_s", label), t.analyze, "s");
      report(fmt::format("{}_factorize_s", label), t.factorize, "s");
      report(fmt::format("{}_solve_s", label), t.solve, "s");
      report(fmt::format("{}_total_s", label), t.total, "s  (analyze + factorize + solve)");
      report(fmt::format("{}_total_cpu_s", label), t.total_cpu, "CPU s");
      report(fmt::format("{}_refactorize_s", label), t.refactorize, "s");
      report(fmt::format("{}_relative_residual", label), t.relative_residual, "");
    } catch (const std::exception& e) {
      // Report and go on with the next solver (e.g. UMFPACK's 32-bit di_ routines running out of memory).
      fmt::print(stderr, "  {} failed: {}\n", label, e.what());
      fmt::print("@{}_error={}\n", label, e.what());
    }
    report(fmt::format("{}_peak_mib", label), memory.phase_peak_mib(), "MiB");
  }

  if (opt.factor_stats) {
    // Fill and flop count of CHOLMOD's orderings: the default analysis (what
    // CholmodSolver uses) and each method forced, to show what a different
    // ordering would save. Not timed with the solvers above.
    cholmod_sparse s{};
    s.nrow = s.ncol = static_cast<size_t>(tangent.rows());
    s.nzmax = static_cast<size_t>(tangent.nonZeros());
    s.p = tangent.outerIndexPtr();
    s.i = tangent.innerIndexPtr();
    s.x = tangent.valuePtr();
    s.stype = -1;
    s.itype = CHOLMOD_INT;
    s.xtype = CHOLMOD_REAL;
    s.dtype = CHOLMOD_DOUBLE;
    s.sorted = s.packed = 1;
    static const char* const kNames[] = {"natural", "given", "amd", "metis", "nesdis", "colamd", "?", "?", "?"};
    for (const auto& [method, label] : {std::pair{-1, "default"}, std::pair{CHOLMOD_AMD, "amd"},
                                        std::pair{CHOLMOD_METIS, "metis"}, std::pair{CHOLMOD_NESDIS, "nesdis"}}) {
      cholmod_common common;
      cholmod_start(&common);
      common.supernodal = CHOLMOD_SUPERNODAL;
      common.print = 0;
      common.error_handler = nullptr;
      if (method >= 0) {
        common.nmethods = 1;
        common.method[0].ordering = method;
      }
      const auto t = Clock::now();
      cholmod_factor* factor = cholmod_analyze(&s, &common);
      const double seconds = seconds_since(t);
      if (factor) {
        const std::string prefix = std::string("order_") + label;
        report_int(prefix + "_nnz_L", static_cast<long long>(common.lnz));
        report(prefix + "_gflop", common.fl / 1e9, "GFlop (factorization)");
        report(prefix + "_analyze_s", seconds, "s");
        if (method < 0) {
          fmt::print(stderr, "  default ordering chosen: {}\n", kNames[std::clamp(factor->ordering, 0, 8)]);
          fmt::print("@order_default_method={}\n", kNames[std::clamp(factor->ordering, 0, 8)]);
        }
        cholmod_free_factor(&factor, &common);
      }
      cholmod_finish(&common);
    }
  }
  return 0;
}

/// One whole linear StaticAnalysis: read -> discretize -> solve -> results,
/// with or without writing the result files.
int run_analysis(const Options& opt, PeakMemory& memory) {
  const bool writing = !opt.write_dir.empty();
  fmt::print(stderr, "analysis: {}x{} CPE4, plane strain, {} thread(s), {}\n", opt.nx, opt.ny, max_threads(),
             writing ? "writing result files to " + opt.write_dir : "no result files");
  const std::string deck = square_deck(opt.nx, opt.ny);
  memory.reset();
  const auto t0 = Clock::now();
  const Model model = read_deck_string(deck, "bench.inp");
  const double read = seconds_since(t0);
  AnalysisSummary summary;
  double write_seconds = 0;
  int dofs = 0;
  if (writing) {
    ResultWriter writer(model, opt.write_dir, "bench");
    WritingObserver observer(writer);
    StaticAnalysis analysis(model, observer);
    summary = analysis.run();
    const auto tw = Clock::now();
    writer.finish(summary.completed, summary.message);
    write_seconds = observer.write_seconds + seconds_since(tw);
    dofs = analysis.discretization().dofs().n_dofs();
  } else {
    SilentObserver observer;
    StaticAnalysis analysis(model, observer);
    summary = analysis.run();
    dofs = analysis.discretization().dofs().n_dofs();
  }
  const double total = seconds_since(t0);
  const std::string prefix = writing ? "e2e_files" : "e2e";
  report_int("dofs", dofs);
  report_int("threads", max_threads());
  report(prefix + "_read_s", read, "s");
  report(prefix + "_total_s", total, "s  (read + analysis" + std::string(writing ? " + files)" : ")"));
  if (writing) report(prefix + "_write_s", write_seconds, "s");
  report_int(prefix + "_iterations", summary.iterations);
  report(prefix + "_peak_mib", memory.phase_peak_mib(), "MiB");
  if (!summary.completed) {
    fmt::print(stderr, "error: the analysis did not complete: {}\n", summary.message);
    return 2;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"tether benchmark: assembly and one factorization + solve for a structured CPE4 mesh"};
  Options opt;
  std::string size = "small";
  std::string threads = "1,2";
  app.add_option("--size", size, "small (~20k dofs), medium (~200k), large (~1M)")
      ->check(CLI::IsMember({"small", "medium", "large"}));
  app.add_option("--nx", opt.nx, "Elements along x (overrides --size)");
  app.add_option("--ny", opt.ny, "Elements along y (default: nx)");
  app.add_option("--phase", opt.phase, "kernels: pattern, assembly, CHOLMOD, UMFPACK; analysis: whole StaticAnalysis")
      ->check(CLI::IsMember({"kernels", "analysis"}));
  app.add_option("--repeat", opt.repeat, "Repetitions of pattern build and assembly (best reported)");
  app.add_option("--solve-repeat", opt.solve_repeat, "Repetitions of each factorization + solve (best reported)");
  app.add_option("--threads", threads, "Comma-separated thread counts for pattern build and assembly");
  app.add_option("--write", opt.write_dir, "analysis phase: write the result files into this directory");
  app.add_flag("!--no-factor-stats", opt.factor_stats, "Skip CHOLMOD's fill and flop statistics");
  CLI11_PARSE(app, argc, argv);

  if (opt.nx <= 0) opt.nx = size == "small" ? 100 : size == "medium" ? 316 : 707;
  if (opt.ny <= 0) opt.ny = opt.nx;
  for (std::size_t p = 0; p < threads.size();) {
    const std::size_t q = std::min(threads.find(',', p), threads.size());
    opt.threads.push_back(std::max(1, std::stoi(threads.substr(p, q - p))));
    p = q + 1;
  }
  if (opt.threads.empty()) opt.threads.push_back(max_threads());

  PeakMemory memory;
  int code = 0;
  try {
    code = opt.phase == "kernels" ? run_kernels(opt, memory) : run_analysis(opt, memory);
  } catch (const std::exception& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return 3;
  }
  if (!memory.resettable()) fmt::print(stderr, "note: /proc/self/clear_refs refused; phase peaks are cumulative\n");
  report("process_peak_mib", memory.process_peak_mib(), "MiB");
  return code;
}
