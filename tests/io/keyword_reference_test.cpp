// The keyword table is complete and docs/keywords.md is generated from it.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "tether/io/assembly_flattening.hpp"
#include "tether/io/deck_reader.hpp"
#include "tether/io/keyword_table.hpp"

using namespace tether;

TEST(KeywordTable, EveryEntryIsDescribedAndHandledOrExplicitlyNotSupported) {
  for (const deck::KeywordSpec& k : deck::keyword_table()) {
    EXPECT_FALSE(k.description.empty()) << k.name;
    EXPECT_NE(k.where, 0u) << k.name;
    const bool lexer_keyword = k.name == "INCLUDE" || deck::is_assembly_keyword(k.name);
    EXPECT_TRUE(lexer_keyword || (k.handler != nullptr) != !k.not_supported.empty()) << k.name;
    for (const deck::ParameterSpec& p : k.parameters) EXPECT_FALSE(p.description.empty()) << k.name << " " << p.name;
    EXPECT_EQ(deck::lookup_keyword(k.name), &k) << "duplicate entry " << k.name;
  }
}

TEST(KeywordReference, ListsEveryKeywordAndParameter) {
  const std::string md = keyword_reference_markdown();
  for (const deck::KeywordSpec& k : deck::keyword_table()) {
    EXPECT_NE(md.find("*" + std::string(k.name)), std::string::npos) << k.name;
    for (const deck::ParameterSpec& p : k.parameters)
      EXPECT_NE(md.find("| " + std::string(p.name) + " |"), std::string::npos) << k.name << " " << p.name;
  }
}

TEST(KeywordReference, CommittedDocsMatchTheGeneratedText) {
  const std::string generated = keyword_reference_markdown();
  const std::string out = std::string(TETHER_BINARY_DIR) + "/keywords.md";
  std::ofstream(out) << generated;
  std::ifstream in(std::string(TETHER_SOURCE_DIR) + "/docs/keywords.md");
  std::stringstream committed;
  committed << in.rdbuf();
  EXPECT_TRUE(committed.str() == generated)
      << "docs/keywords.md is out of date with the keyword table; regenerate it with:\n  cp " << out << " "
      << TETHER_SOURCE_DIR << "/docs/keywords.md";
}
