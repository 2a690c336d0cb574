// tether command-line program: parse arguments -> read deck -> run -> write -> exit code.
//
// Exit codes: 0 success, 1 bad input (deck or arguments), 2 the analysis did
// not complete (non-convergence, singular model, a step the chosen solver
// cannot factorize, an unusable scratch directory for out-of-core factors),
// 3 I/O or internal error.

#include <CLI/CLI.hpp>
#include <fmt/core.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>

#include "energy_plot.hpp"
#include "progress_observer.hpp"
#include "tether/core/error.hpp"
#include "tether/io/deck_reader.hpp"
#include "tether/io/deck_survey.hpp"
#include "tether/output/restart_file.hpp"
#include "tether/job/job.hpp"
#include "tether/solvers/blas_kernels.hpp"

namespace fs = std::filesystem;
using namespace tether;

namespace {

enum ExitCode { kOk = 0, kInput = 1, kNotCompleted = 2, kInternal = 3 };

std::string warning_text(const DeckWarning& w) { return fmt::format("{}: warning: {}", w.where.str(), w.message); }

int check(const std::string& deck, Dialect dialect) {
  std::vector<DeckWarning> warnings;
  const Model model = read_deck(deck, &warnings, dialect);
  for (const auto& w : warnings) fmt::print(stderr, "{}\n", warning_text(w));
  Discretization discretization(model);  // materials and elements can be built
  fmt::print("{}: OK: {} nodes, {} elements, {} step(s), {} dofs (dialect {})\n", deck, model.n_nodes(),
             model.n_elements(), model.steps.size(), discretization.dofs().n_dofs(), dialect_name(dialect));
  return kOk;
}

/// The .inp decks of `paths`: files as given, folders searched recursively
/// (sorted). InputError for a path that does not exist.
std::vector<std::string> decks_of(const std::vector<std::string>& paths) {
  std::vector<std::string> decks;
  for (const std::string& p : paths) {
    if (fs::is_directory(p)) {
      std::vector<std::string> found;
      for (const auto& entry : fs::recursive_directory_iterator(p))
        if (entry.is_regular_file() && entry.path().extension() == ".inp") found.push_back(entry.path().string());
      std::sort(found.begin(), found.end());
      decks.insert(decks.end(), found.begin(), found.end());
    } else if (fs::exists(p)) {
      decks.push_back(p);
    } else {
      throw InputError(SourceLocation{p, 0}, "no such deck or folder '" + p + "'");
    }
  }
  return decks;
}

/// One deck of a survey: its refusals, or the first error of reading it when
/// the keyword table refuses nothing ("" when it reads).
struct SurveyedDeck {
  std::vector<Refusal> refusals;
  std::string error;
};

SurveyedDeck survey(const std::string& deck, Dialect dialect) {
  SurveyedDeck s{survey_deck(deck), ""};
  if (s.refusals.size() == 1 && s.refusals[0].kind == Refusal::Kind::Unreadable)
    return {{}, s.refusals[0].what};  // an error, not something the deck needs
  if (!s.refusals.empty()) return s;
  try {
    const Model model = read_deck(deck, nullptr, dialect);
    Discretization discretization(model);
  } catch (const InputError& e) {
    s.error = e.what();
  } catch (const std::exception& e) {
    s.error = deck + ": error: " + e.what();
  }
  return s;
}

/// `tether check` over several decks: one line per deck, then one table of
/// what tether refused (kind, what, decks, occurrences), most decks first.
int check_many(const std::vector<std::string>& decks, Dialect dialect) {
  std::map<std::pair<Refusal::Kind, std::string>, std::pair<int, int>> table;  // -> (decks, occurrences)
  int ok = 0, other_errors = 0;
  for (const std::string& deck : decks) {
    const SurveyedDeck s = survey(deck, dialect);
    if (s.refusals.empty() && s.error.empty()) {
      fmt::print("{}: OK\n", deck);
      ++ok;
      continue;
    }
    if (!s.error.empty()) {
      fmt::print("{}\n", s.error.substr(0, s.error.find('\n')));
      ++other_errors;
      continue;
    }
    std::map<std::pair<Refusal::Kind, std::string>, int> here;
    for (const Refusal& r : s.refusals) ++here[{r.kind, r.what}];
    std::string list;
    for (const auto& [key, n] : here) {
      list += (list.empty() ? "" : ", ") + key.second + (n > 1 ? fmt::format(" ({}x)", n) : "");
      table[key].first += 1;
      table[key].second += n;
    }
    fmt::print("{}: refused: {}\n", deck, list);
  }
  std::vector<std::pair<std::pair<Refusal::Kind, std::string>, std::pair<int, int>>> rows(table.begin(), table.end());
  std::stable_sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) { return a.second.first > b.second.first; });
  fmt::print("\n{} deck(s): {} read, {} refused by the keyword table, {} with other errors (dialect {})\n",
             decks.size(), ok, decks.size() - ok - other_errors, other_errors, dialect_name(dialect));
  if (!rows.empty()) {
    fmt::print("\nWhat the decks need (refused by tether):\n{:<16} {:<48} {:>6} {:>11}\n", "kind", "what", "decks",
               "occurrences");
    for (const auto& [key, counts] : rows)
      fmt::print("{:<16} {:<48} {:>6} {:>11}\n", refusal_kind_name(key.first), key.second, counts.first,
                 counts.second);
  }
  return ok == static_cast<int>(decks.size()) ? kOk : kInput;
}

/// The restart file to continue from: --restart, else FILE= of *RESTART, READ
/// (relative to the deck); "" when the run starts from the beginning.
std::string restart_source(const Model& model, const std::string& deck, const std::string& restart) {
  if (!restart.empty()) return restart;
  if (!model.restart_read) return "";
  if (model.restart_read->file.empty())
    throw InputError(model.restart_read->where,
                     "*RESTART, READ without FILE=: name the restart file there or run `tether run " + deck +
                         " --restart FILE.rst`");
  const fs::path file(model.restart_read->file);
  return (file.is_absolute() ? file : fs::path(deck).parent_path() / file).string();
}

/// Where a run writes. A run from the beginning: -o, else DECKDIR/JOB. A
/// restart never writes over another run's results: -o must not hold results
/// of JOB already (InputError otherwise), and without -o it gets the first
/// free DECKDIR/JOB-restart, JOB-restart-2, ...
fs::path output_directory(const std::string& deck, const std::string& output_dir, const std::string& restart_file) {
  const fs::path deck_dir = fs::path(deck).parent_path();
  const std::string job = fs::path(deck).stem().string();
  if (restart_file.empty()) return output_dir.empty() ? deck_dir / job : fs::path(output_dir);
  if (output_dir.empty()) {
    for (int k = 1;; ++k) {
      const fs::path candidate = deck_dir / (job + "-restart" + (k > 1 ? "-" + std::to_string(k) : std::string()));
      if (!fs::exists(candidate)) return candidate;
    }
  }
  const fs::path dir(output_dir);
  for (const char* extension : {".sta", ".dat", ".rst", ".pvd"})
    if (fs::exists(dir / (job + extension)))
      throw InputError(SourceLocation{restart_file, 0},
                       "-o " + output_dir + " holds the results of a run of " + job + " (" + job + extension +
                           "), which this restart would overwrite; give a new directory with -o, or leave -o out "
                           "to write to " + (deck_dir / (job + "-restart")).string() +
                           " (or the next free -restart-N)");
  return dir;
}


/// What `tether run` was asked to do (its command line).
struct RunRequest {
  std::string deck, output_dir, solver = "auto", restart, mortar_condensation = "dense";
  bool condense = true, ascii = false, quiet = false, reuse = true, plot = true;
  double memory_mb = 0;
  Dialect dialect = Dialect::Abaqus;
};

AnalysisOptions analysis_options(const RunRequest& request) {
  AnalysisOptions options;
  options.solver = parse_solver_kind(request.solver);
  // Refuse before the run, not when the factors first go to disk; only the
  // solvers that can put them there (MUMPS, directly or through auto) need it.
  if (request.memory_mb > 0 && (options.solver == SolverKind::Auto || options.solver == SolverKind::Mumps))
    check_out_of_core_directory();
  options.condense_contact = request.condense;
  options.reuse_linear_bulk = request.reuse;
  options.mortar_condensation = parse_mortar_condensation(request.mortar_condensation);
  options.memory_budget_mb = request.memory_mb;
  options.stream_element_results = true;  // the writer does not keep the results
  return options;
}

int run(const RunRequest& request) {
  const std::string& deck = request.deck;
  const bool quiet = request.quiet;
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<DeckWarning> warnings;
  Model model = read_deck(deck, &warnings, request.dialect);
  if (!quiet)
    for (const auto& w : warnings) fmt::print(stderr, "{}\n", warning_text(w));
  const std::string job_name = fs::path(deck).stem().string();
  const std::string restart_file = restart_source(model, deck, request.restart);
  JobOptions options;
  options.analysis = analysis_options(request);
  options.output_dir = output_directory(deck, request.output_dir, restart_file);
  options.name = job_name;
  if (request.ascii) options.writer.encoding = VtuEncoding::Ascii;
  options.keep = JobOptions::Keep::None;  // written, not kept
  options.started = t0;
  const fs::path dir = options.output_dir;
  Job job(std::move(model), options);

  // The model is discretized and a restart state read and checked before any
  // output file is touched: a deck or restart refused here leaves the
  // previous results (and the restart file) as they were.
  job.prepare();
  if (!restart_file.empty()) {
    job.resume(read_restart_file(restart_file), restart_file);
    if (!quiet) fmt::print("{}: restarting from {}; the results go to {}\n", job_name, restart_file, dir.string());
  }
  job.log(fmt::format("deck {} read in the {} dialect", deck, dialect_name(request.dialect)));
  for (const auto& w : warnings) job.log(warning_text(w));
  if (!restart_file.empty()) job.log("restart from " + restart_file + " into " + dir.string());

  ProgressObserver progress;
  const JobSummary summary = job.run(!quiet && isatty(fileno(stdout)) ? &progress : nullptr);
  std::vector<fs::path> files = job.written_files();
  const fs::path energy_csv = dir / (job_name + "_energy.csv");
  if (request.plot && std::find(files.begin(), files.end(), energy_csv) != files.end()) {
    const fs::path png = dir / (job_name + "_energy.png");
    const std::string why = app::plot_energy(energy_csv, png, job_name);
    if (why.empty())
      files.push_back(png);
    else if (!quiet)
      fmt::print(stderr, "{}: warning: no energy plot ({}); the energies are in {}\n", deck, why, energy_csv.string());
  }
  if (!quiet) {
    std::string written;
    for (const fs::path& f : files) written += (written.empty() ? "" : "  ") + f.string();
    fmt::print("{}: {} ({} increments, {} iterations, {} cut-backs, {:.2f} s)\n{}\nresults: {}\n", job_name,
               summary.message, summary.increments, summary.iterations, summary.cutbacks, summary.seconds,
               timing_line(summary.seconds, summary.timing), written);
  }
  if (!summary.completed) {
    fmt::print(stderr, "{}: error: {}\n", deck, summary.message);
    return kNotCompleted;
  }
  return kOk;
}

}  // namespace

int main(int argc, char** argv) {
  restart_with_better_blas_kernels(argv);  // OpenBLAS's generic kernels on a CPU it does not know: ask for others
  CLI::App app{"tether: nonlinear finite elements for 2D solids with constraints and contact"};
  app.set_version_flag("--version", std::string("tether ") + TETHER_VERSION);
  app.require_subcommand(1);

  std::string deck, output_dir, solver = "auto", restart, dialect = "abaqus";
  const std::string dialect_help =
      "Where ABAQUS and CalculiX give the same deck data different meanings, read it as abaqus (default) or "
      "calculix means it (docs/keywords.md, section Dialects)";
  bool ascii = false, quiet = false, no_condense = false, no_reuse = false, no_plot = false;
  std::string mortar_condensation = "dense";
  double memory_mb = 0;
  auto* run_cmd = app.add_subcommand("run", "Read an ABAQUS/CalculiX .inp deck, solve it and write the results");
  run_cmd->add_option("deck", deck, "Input deck (.inp)")->required();
  run_cmd->add_option("-o,--output", output_dir, "Output directory (default: next to the deck, named after it)");
  run_cmd->add_option("--solver", solver, "Linear solver: auto, umfpack, cholmod, mumps or sparselu")
      ->check(CLI::IsMember({"auto", "umfpack", "cholmod", "mumps", "sparselu"}, CLI::ignore_case));
  run_cmd->add_option("--restart", restart,
                      "Continue from this restart file (JOB.rst written by *RESTART, WRITE) instead of the "
                      "beginning; the results go to a new directory, DECKDIR/JOB-restart (or -restart-2, ...) "
                      "unless -o names one that holds no results of JOB");
  run_cmd->add_flag("--no-condense", no_condense,
                    "With contact: factorize the whole matrix at every iteration instead of condensing it onto "
                    "the contact equations (for comparison; same answer)");
  run_cmd->add_flag("--no-plot", no_plot,
                    "Do not draw JOB_energy.png, the energy history of dynamic steps (drawn by python3 with "
                    "matplotlib from JOB_energy.csv)");
  run_cmd->add_flag("--no-reuse", no_reuse,
                    "Assemble the tangent of a linear bulk (small strain, elastic) and factorize it at every "
                    "iteration instead of once per step and increment size (for comparison; same answer)");
  run_cmd
      ->add_flag("--mortar-condensation{sparse}", mortar_condensation,
                 "With mortar contact, how its multipliers are eliminated (all give the same answer to round-off; "
                 "docs/theory/mortar.md): =dense (default) from the dense system of the contact equations when "
                 "the solver condenses onto them (so are the normal multipliers of node-to-surface HARD pairs), "
                 "the rest factorized by Cholesky when it can be; =kept: not "
                 "eliminated, the dense system factorized by LU; without a value or =sparse: from the whole "
                 "matrix, which is then factorized at every iteration (no condensation onto the contact equations)")
      ->check(CLI::IsMember({"dense", "kept", "sparse"}, CLI::ignore_case));
  run_cmd->add_option("--memory", memory_mb,
                      "Memory the run may use, in MB (e.g. 480, 2000): MUMPS factors (the condensed contact solver, "
                      "--solver mumps, symmetric indefinite systems) that would not fit are kept on disk in the "
                      "temporary directory ($TMPDIR) and read back at each solve (slower); CHOLMOD and UMFPACK "
                      "ignore it; default: no limit, everything in core")
      ->check(CLI::PositiveNumber);
  run_cmd->add_option("--dialect", dialect, dialect_help)
      ->check(CLI::IsMember({"abaqus", "calculix"}, CLI::ignore_case));
  run_cmd->add_flag("--ascii", ascii, "Write ASCII instead of binary VTU (for debugging)");
  run_cmd->add_flag("-q,--quiet", quiet, "Print nothing but errors");
  auto* check_cmd = app.add_subcommand("check", "Read and validate a deck without solving it");
  std::vector<std::string> check_paths;
  check_cmd->add_option("deck", check_paths,
                        "Input deck (.inp); with several decks or a folder (searched for .inp files), one line per "
                        "deck and a table of what tether refused in them (keywords, procedures, parameters, values, "
                        "element types), with counts")
      ->required();
  check_cmd->add_option("--dialect", dialect, dialect_help)
      ->check(CLI::IsMember({"abaqus", "calculix"}, CLI::ignore_case));
  auto* keywords_cmd = app.add_subcommand("keywords", "Print the keyword reference (Markdown)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kOk : kInput;
  }

  try {
    if (*keywords_cmd) {
      fmt::print("{}", keyword_reference_markdown());
      return kOk;
    }
    std::transform(dialect.begin(), dialect.end(), dialect.begin(), [](unsigned char c) { return std::tolower(c); });
    const Dialect chosen = parse_dialect(dialect).value_or(Dialect::Abaqus);  // CLI11 checked the name
    if (*check_cmd) {
      if (check_paths.size() == 1 && !fs::is_directory(check_paths[0])) {
        deck = check_paths[0];
        return check(deck, chosen);
      }
      return check_many(decks_of(check_paths), chosen);
    }
    RunRequest request;
    request.deck = deck, request.output_dir = output_dir, request.solver = solver, request.restart = restart;
    request.condense = !no_condense, request.ascii = ascii, request.quiet = quiet, request.reuse = !no_reuse;
    request.plot = !no_plot, request.mortar_condensation = mortar_condensation;
    request.memory_mb = memory_mb, request.dialect = chosen;
    return run(request);
  } catch (const InputError& e) {
    fmt::print(stderr, "{}\n", e.what());
    return kInput;
  } catch (const ModelError& e) {
    fmt::print(stderr, "{}: error: {}\n", deck, e.what());
    return kInput;
  } catch (const ResourceError& e) {
    fmt::print(stderr, "{}: error: {}\n", deck, e.what());
    return kNotCompleted;
  } catch (const std::exception& e) {
    fmt::print(stderr, "{}: error: {}\n", deck, e.what());
    return kInternal;
  }
}
