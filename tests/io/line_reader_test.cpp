// Lexing: comments, blank lines, continuation lines, case, quotes, *INCLUDE.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "deck_test_support.hpp"
#include "tether/io/line_reader.hpp"

using namespace tether;
using namespace tether::deck;
using tether::test::decks_dir;
using tether::test::expect_deck_error;

TEST(SplitDataLine, TrimsFieldsAndReportsTrailingComma) {
  const DataFields d = split_data_line(" 1 ,  2.5,, \"a, b\" , ");
  ASSERT_EQ(d.fields.size(), 4u);
  EXPECT_EQ(d.fields[0], "1");
  EXPECT_EQ(d.fields[1], "2.5");
  EXPECT_EQ(d.fields[2], "");
  EXPECT_EQ(d.fields[3], "a, b");
  EXPECT_TRUE(d.trailing_comma);
  EXPECT_FALSE(split_data_line("1, 2").trailing_comma);
}

TEST(NormalizeName, UpperCasesAndCollapsesBlanks) {
  EXPECT_EQ(normalize_name("  solid   Section "), "SOLID SECTION");
  EXPECT_EQ(normalize_name("neo\thooke"), "NEO HOOKE");
}

TEST(LexDeck, SkipsCommentsAndBlankLinesAndJoinsContinuations) {
  const std::string text =
      "** a comment\n"
      "\n"
      "*Solid section, elset=Plate,\n"
      "** comment inside the continuation\n"
      "   material=\"Steel A\"  ,  Flag\r\n"
      "  2.5,\n"
      "*node\n"
      "1, 0, 0\n";
  const auto blocks = lex_deck_text(text, "x.inp", "");
  ASSERT_EQ(blocks.size(), 2u);
  EXPECT_EQ(blocks[0].keyword, "SOLID SECTION");
  EXPECT_EQ(blocks[0].where.line, 3);
  ASSERT_EQ(blocks[0].parameters.size(), 3u);
  EXPECT_EQ(blocks[0].parameters[0].name, "ELSET");
  EXPECT_EQ(blocks[0].parameters[0].value, "Plate");
  EXPECT_EQ(blocks[0].parameters[1].name, "MATERIAL");
  EXPECT_EQ(blocks[0].parameters[1].value, "Steel A");
  EXPECT_EQ(blocks[0].parameters[2].name, "FLAG");
  EXPECT_FALSE(blocks[0].parameters[2].has_value);
  ASSERT_EQ(blocks[0].data.size(), 1u);
  EXPECT_EQ(blocks[0].data[0].line, 6);
  EXPECT_EQ(blocks[1].keyword, "NODE");
  EXPECT_EQ(blocks[1].data[0].where().str(), "x.inp:8");
}

TEST(LexDeck, DataBeforeAnyKeywordIsAnError) {
  expect_deck_error("** comment\n1, 2, 3\n*NODE\n", 2, {"data line before any keyword", "'*'"});
}

TEST(LexDeck, KeywordContinuationAtEndOfFileIsAnError) {
  expect_deck_error("*HEADING\nx\n*NODE, NSET=A,\n", 3, {"continuation"});
}

TEST(LexDeck, VeryLongLinesAreRead) {
  std::string deck = "*HEADING\n" + std::string(200000, 'x') + "\n";
  const auto blocks = lex_deck_text(deck, "long.inp", "");
  ASSERT_EQ(blocks.size(), 1u);
  EXPECT_EQ(blocks[0].data[0].text.size(), 200000u);
}

TEST(Include, ResolvesPathsRelativeToTheIncludingFile) {
  const Model m = read_deck(decks_dir() + "/include_main.inp");
  EXPECT_EQ(m.n_nodes(), 4);
  ASSERT_EQ(m.n_elements(), 1);
  EXPECT_EQ(m.elements[0].type.name, "CPS4");
  EXPECT_EQ(m.node_sets.at("ALL").size(), 4u);
  EXPECT_EQ(m.location(m.elements[0].where).file, decks_dir() + "/mesh/connectivity.inp");
  EXPECT_EQ(m.location(m.elements[0].where).line, 1);
  EXPECT_EQ(m.heading, "Included mesh");
}

// An element keeps its deck line as an index into the model's file table and
// a line (8 bytes, not a file name each); the messages that name it print the
// same file:line as before: here an element of an included file, named from
// the main deck's duplicate.
TEST(Include, ElementsNameTheirIncludedFileAndLineInMessages) {
  const auto dir = std::filesystem::path(TETHER_BINARY_DIR) / "tests" / "io" / "include_lines";
  std::filesystem::create_directories(dir);
  const std::string main = (dir / "main.inp").string(), mesh = decks_dir() + "/mesh";
  std::ofstream(main) << "*NODE, NSET=ALL\n*INCLUDE, INPUT=" << mesh << "/nodes.inp\n*INCLUDE, INPUT=" << mesh
                      << "/elements.inp\n*ELEMENT, TYPE=CPS4, ELSET=MORE\n1, 1, 2, 3, 4\n";
  try {
    (void)read_deck(main);
    ADD_FAILURE() << "duplicate element accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, main);
    EXPECT_EQ(e.where().line, 5);
    EXPECT_NE(std::string(e.what()).find("duplicate element 1: element labels must be unique (it is already defined "
                                         "at " + mesh + "/connectivity.inp:1)"),
              std::string::npos)
        << e.what();
  }
  const Model m = read_deck(decks_dir() + "/include_main.inp");
  ASSERT_EQ(m.source_files.size(), 1u);  // only the files that elements name
  EXPECT_EQ(m.elements[0].where.file, 0);
}

TEST(Include, RecursionIsAnErrorAtTheIncludeLine) {
  try {
    (void)read_deck(decks_dir() + "/recursive_a.inp");
    FAIL() << "recursive include accepted";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("recursive_b.inp:2: error:"), std::string::npos) << msg;
    EXPECT_NE(msg.find("recursive *INCLUDE"), std::string::npos) << msg;
  }
}

TEST(Include, MissingFileIsAnErrorAtTheIncludeLine) {
  try {
    (void)read_deck(decks_dir() + "/missing_include.inp");
    FAIL() << "missing include accepted";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("missing_include.inp:3: error:"), std::string::npos) << msg;
    EXPECT_NE(msg.find("no_such_file.inp"), std::string::npos) << msg;
  }
}

TEST(Include, MissingIncludeParameterIsAnError) {
  expect_deck_error("*HEADING\nx\n*INCLUDE, FILE=a.inp\n", 3, {"unknown parameter FILE", "INPUT"});
}

TEST(Include, FromAStringIsRelativeToTheCurrentDirectory) {
  const auto old = std::filesystem::current_path();
  std::filesystem::current_path(decks_dir() + "/mesh");
  std::vector<tether::deck::KeywordBlock> blocks;
  try {
    blocks = lex_deck_text("*NODE\n*INCLUDE, INPUT=nodes.inp\n", "s.inp", "");
  } catch (...) {
    std::filesystem::current_path(old);
    throw;
  }
  std::filesystem::current_path(old);
  ASSERT_EQ(blocks.size(), 1u);
  EXPECT_EQ(blocks[0].data.size(), 4u);
  EXPECT_EQ(blocks[0].data[0].where().str(), "nodes.inp:2");
}

TEST(ReadDeck, MissingDeckFileIsAnInputError) {
  EXPECT_THROW((void)read_deck(decks_dir() + "/does_not_exist.inp"), InputError);
}

TEST(ReadDeck, ReadsACompleteDeckFile) {
  const Model m = read_deck(decks_dir() + "/two_steps.inp");
  ASSERT_EQ(m.steps.size(), 2u);
  EXPECT_EQ(m.steps[0].name, "pull");
  EXPECT_TRUE(m.steps[0].nlgeom);
  EXPECT_DOUBLE_EQ(m.steps[0].max_increment, 0.5);
  EXPECT_EQ(m.steps[0].boundary.size(), 6u);
  EXPECT_EQ(m.steps[1].boundary.size(), 6u);  // continues from step 1
  EXPECT_TRUE(m.steps[0].pressures.empty());
  EXPECT_EQ(m.steps[1].pressures.size(), 2u);
  EXPECT_EQ(m.steps[0].outputs.size(), 2u);
  // step 2 gives its own *Node File; step 1's *Node Print and *El File carry over
  EXPECT_EQ(m.steps[1].outputs.size(), 3u);
  EXPECT_DOUBLE_EQ(m.sections[0].thickness, 0.5);
}

TEST(ReadDeck, ErrorsInADeckFileNameThePathAndLine) {
  try {
    (void)read_deck(decks_dir() + "/bad_folded_quad.inp");
    FAIL() << "folded quad accepted";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("bad_folded_quad.inp:8: error: element 1 (CPE4) is inverted"), std::string::npos) << msg;
  }
}
