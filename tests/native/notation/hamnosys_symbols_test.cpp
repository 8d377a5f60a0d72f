// Tests of the compiled-in HamNoSys symbol table (src/notation/hamnosys_symbols.h) against the
// shared TSV it was generated from (skipped, saying so, when ../shared is absent).
#include "notation/hamnosys_symbols.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

namespace sw::notation {
namespace {

TEST(HamNoSysSymbols, LookupsBothWays) {
  ASSERT_NE(ham_symbol_by_code(0xE001), nullptr);
  EXPECT_STREQ(ham_symbol_by_code(0xE001)->name, "hamflathand");
  EXPECT_EQ(ham_symbol_by_name("hamflathand")->code, static_cast<char32_t>(hamflathand));
  EXPECT_EQ(ham_symbol_group(hamreplace), HamGroup::Replacement);
  EXPECT_EQ(ham_symbol_by_name("hamfoo"), nullptr);
  EXPECT_EQ(ham_symbol_by_code(0xE0FF), nullptr);
  EXPECT_STREQ(ham_symbol_name(0xE0FF), "");
}

TEST(HamNoSysSymbols, TableMatchesTheSharedTsv) {
  std::ifstream in(std::string(SIGNWEAVE_SHARED_DIR) + "/docs/hamnosys-symbols.tsv");
  if (!in) GTEST_SKIP() << "../shared/docs/hamnosys-symbols.tsv not found: table check skipped";
  std::string line;
  std::getline(in, line);  // header
  int rows = 0;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const std::size_t a = line.find('\t'), b = line.find('\t', a + 1);
    const char32_t code = static_cast<char32_t>(std::stoul(line.substr(2, a - 2), nullptr, 16));
    const std::string name = line.substr(a + 1, b - a - 1);
    const HamSymbolInfo* s = ham_symbol_by_code(code);
    ASSERT_NE(s, nullptr) << name;
    EXPECT_EQ(s->name, name);
    EXPECT_EQ(ham_symbol_by_name(name), s);
    ++rows;
  }
  EXPECT_EQ(rows, 209);
}

}  // namespace
}  // namespace sw::notation
