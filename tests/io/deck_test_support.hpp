#pragma once
// Helpers shared by the deck-reader tests.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "tether/io/deck_reader.hpp"

namespace tether::test {

/// Directory of the test decks.
inline std::string decks_dir() { return std::string(TETHER_SOURCE_DIR) + "/tests/io/decks"; }

/// 1-based number of the line where the first occurrence of `marker` starts
/// (leading newlines of the marker skipped; 0 if not found). Markers may span lines.
inline int line_of(const std::string& text, const std::string& marker) {
  auto pos = text.find(marker);
  if (pos == std::string::npos) return 0;
  for (std::size_t i = 0; i < marker.size() && marker[i] == '\n'; ++i) ++pos;
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(pos), '\n'));
}

/// Reading `deck` (named bad.inp) must throw an InputError at bad.inp:`line`
/// whose message contains every one of `words` (read in `dialect`).
inline void expect_deck_error(const std::string& deck, int line, const std::vector<std::string>& words,
                              Dialect dialect = Dialect::Abaqus) {
  ASSERT_GT(line, 0) << "marker not found in the test deck";
  try {
    (void)read_deck_string(deck, "bad.inp", nullptr, dialect);
    ADD_FAILURE() << "expected an InputError at bad.inp:" << line << ", deck read fine:\n" << deck;
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("bad.inp:" + std::to_string(line) + ": error:"), std::string::npos)
        << "wrong location, expected line " << line << ": " << msg;
    EXPECT_EQ(e.where().line, line) << msg;
    for (const std::string& w : words) EXPECT_NE(msg.find(w), std::string::npos) << "missing '" << w << "' in: " << msg;
  }
}

/// Error at the first line containing `marker`.
inline void expect_deck_error_at(const std::string& deck, const std::string& marker,
                                 const std::vector<std::string>& words) {
  expect_deck_error(deck, line_of(deck, marker), words);
}

/// A valid two-quad model (CPE4) with sets LEFT/RIGHT/ALL/PLATE, material STEEL,
/// and a model-level *BOUNDARY; steps are appended by the tests.
inline const std::string kMesh = R"(*HEADING
Two quads
*NODE, NSET=ALL
1, 0, 0
2, 1, 0
3, 2, 0
4, 0, 1
5, 1, 1
6, 2, 1
*ELEMENT, TYPE=CPE4, ELSET=PLATE
1, 1, 2, 5, 4
2, 2, 3, 6, 5
*NSET, NSET=LEFT
1, 4
*NSET, NSET=RIGHT
3, 6
*ELSET, ELSET=E1
1
*SURFACE, NAME=TOP
PLATE, S3
*MATERIAL, NAME=STEEL
*ELASTIC
200e3, 0.3
*SOLID SECTION, ELSET=PLATE, MATERIAL=STEEL
1.0
*AMPLITUDE, NAME=RAMP
0, 0, 1, 1
*BOUNDARY
LEFT, 1, 2
)";

/// kMesh plus one minimal static step.
inline const std::string kDeck = kMesh + R"(*STEP
*STATIC
*CLOAD
RIGHT, 1, 10
*END STEP
)";

/// Replaces the first occurrence of `from` in `text` by `to` (asserting it exists).
inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto pos = text.find(from);
  EXPECT_NE(pos, std::string::npos) << "test deck has no '" << from << "'";
  if (pos != std::string::npos) text.replace(pos, from.size(), to);
  return text;
}

}  // namespace tether::test
