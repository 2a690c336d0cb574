// libFuzzer target: the deck reader and model builder, i.e. what `tether check`
// does before any solve (app/main.cpp, check()):
//
//   read_deck(path, &warnings, dialect)   lexing, *INCLUDE, keyword table, handlers, model
//                                         checks; once in each dialect (abaqus, calculix)
//   Discretization(model)        materials, elements, constraint functions and elements
//
// A deck that is rejected with InputError (file:line message) or ModelError is
// a correct outcome. Anything else is a finding: a crash or a sanitizer report
// (libFuzzer stops and saves the input), a hang (-timeout), a huge allocation
// (-rss_limit_mb / -malloc_limit_mb) or any other exception escaping, which
// `tether` would report as exit 3 "internal error" instead of naming the deck
// line; the target aborts on those so that libFuzzer saves the input.
//
// Sandbox. The deck is written to `deck.inp` in a private directory created by
// mkdtemp() at start-up (removed at exit) and read from there by its absolute
// path, so relative `*INCLUDE, INPUT=` and `LIBRARY=` paths resolve inside
// that directory (the process's own working directory plays no part). It
// holds a copy of the corpus's include files (includes/*.inp, see
// TETHER_FUZZ_INCLUDES) and nothing else. Inputs that could name a file
// outside it are skipped before reading (see names_outside_work_dir()): a
// parameter value starting with '/' (absolute path) or any "..". So the
// fuzzer only ever opens files of its own directory: it cannot block on
// /dev/stdin, read /dev/zero forever or dlopen() a system library.

#include <stdlib.h>  // mkdtemp

#include <cctype>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "tether/analysis/discretization.hpp"
#include "tether/core/error.hpp"
#include "tether/io/deck_reader.hpp"

namespace fs = std::filesystem;

namespace {

/// The private working directory and the deck file inside it.
fs::path g_work_dir;
std::string g_deck_path;

void remove_work_dir() {
  std::error_code ec;
  if (!g_work_dir.empty()) fs::remove_all(g_work_dir, ec);
}

/// True when the input could make the reader open a file outside the working
/// directory: a `NAME=value` whose value (after blanks and a quote, as the
/// lexer strips them) starts with '/', or a ".." anywhere. Deliberately
/// broader than the path parameters (INCLUDE's INPUT and MPC/CONSTRAINT's
/// LIBRARY, which `check` opens; RESTART's FILE, which only `run` opens): it
/// needs no knowledge of the keywords, and the few other inputs it skips
/// cost nothing.
bool names_outside_work_dir(std::string_view text) {
  if (text.find("..") != std::string_view::npos) return true;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '=') continue;
    std::size_t j = i + 1;
    while (j < text.size() && (std::isspace(static_cast<unsigned char>(text[j])) || text[j] == '"')) ++j;
    if (j < text.size() && text[j] == '/') return true;
  }
  return false;
}

[[noreturn]] void fail(const char* what, const std::string& message) {
  std::fprintf(stderr, "deck_fuzzer: %s escaped read_deck/Discretization: %s\n", what, message.c_str());
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* /*argc*/, char*** /*argv*/) {
  const char* tmp = std::getenv("TMPDIR");
  std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/tether-fuzz-XXXXXX";
  if (!mkdtemp(pattern.data())) {
    std::perror("deck_fuzzer: mkdtemp");
    std::exit(1);
  }
  g_work_dir = fs::absolute(fs::path(pattern));
  g_deck_path = (g_work_dir / "deck.inp").string();
  std::atexit(remove_work_dir);
#ifdef TETHER_FUZZ_INCLUDES
  // The include files the corpus decks name (includes/loop_a.inp, ...), so
  // those seeds reach their *INCLUDE paths (recursion, errors inside includes).
  std::error_code ec;
  fs::create_directory(g_work_dir / "includes", ec);
  for (const auto& entry : fs::directory_iterator(TETHER_FUZZ_INCLUDES, ec))
    if (entry.is_regular_file() && entry.path().extension() == ".inp")
      fs::copy_file(entry.path(), g_work_dir / "includes" / entry.path().filename(), ec);
#endif
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  if (names_outside_work_dir(text)) return -1;  // -1: do not add this input to the corpus

  // read_deck() takes a path (as `tether check`): relative includes and
  // libraries are then resolved against the working directory.
  std::FILE* f = std::fopen(g_deck_path.c_str(), "wb");
  if (!f || std::fwrite(data, 1, size, f) != size || std::fclose(f) != 0) {
    std::perror("deck_fuzzer: writing deck.inp");
    std::abort();
  }

  // Both dialects: where ABAQUS and CalculiX read the same data differently
  // (`tether run --dialect`), each reading has its own code.
  for (const tether::Dialect dialect : {tether::Dialect::Abaqus, tether::Dialect::Calculix}) {
    try {
      std::vector<tether::DeckWarning> warnings;
      const tether::Model model = tether::read_deck(g_deck_path, &warnings, dialect);
      const tether::Discretization discretization(model);
      // Touch the results as `tether check` prints them.
      if (discretization.dofs().n_dofs() < 0) std::abort();
    } catch (const tether::InputError&) {
      // a bad deck, reported with file:line: the expected outcome
    } catch (const tether::ModelError&) {
      // a deck that reads but cannot be discretized (e.g. *CONTACT PAIR, a missing library)
    } catch (const std::exception& e) {
      fail("exception", e.what());
    } catch (...) {
      fail("non-standard exception", "(no message)");
    }
  }
  return 0;
}
