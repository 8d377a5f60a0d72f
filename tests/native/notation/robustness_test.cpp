// Fuzz-ish robustness of every reader (formula, HamNoSys, H-SiGML, G-SiGML, JSON): random bytes,
// random symbol soups and random truncations of real signs must give diagnostics with sane
// positions, never a crash, a hang or (under the ASan+UBSan build) a memory error.
#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "notation/hamnosys_symbols.h"
#include "notation/parse.h"
#include "notation/sign_spec_json.h"
#include "notation/text_position.h"

namespace sw::notation {
namespace {

constexpr NotationFormat kFormats[] = {NotationFormat::Formula, NotationFormat::HamNoSys,
                                       NotationFormat::HSiGML, NotationFormat::GSiGML};

void parse_everything(const std::string& text) {
  for (NotationFormat f : kFormats) {
    const std::vector<SignParse> signs = parse_signs(text, f);
    for (const SignParse& s : signs) {
      for (const Diagnostic& d : s.diagnostics) {
        ASSERT_LE(d.offset, text.size());
        ASSERT_LE(d.offset + d.length, text.size());
        ASSERT_GE(d.line, 1);
        ASSERT_GE(d.column, 1);
        ASSERT_FALSE(d.message.empty());
      }
      if (s.spec) {  // whatever was built prints in every notation without trouble
        for (NotationFormat g : kFormats) (void)print_notation({*s.spec}, g);
        SignSpec back;
        std::string error;
        ASSERT_TRUE(sign_from_json(sign_to_json(*s.spec), &back, &error)) << error;
      }
    }
    (void)parse_notation(text, f);
  }
  (void)detect_format(text);
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(NotationRobustness, RandomBytes) {
  std::mt19937 rng(20261122);
  for (int round = 0; round < 400; ++round) {
    std::string text(rng() % 200, '\0');
    for (char& c : text) c = static_cast<char>(rng() & 0xFF);
    parse_everything(text);
  }
}

TEST(NotationRobustness, RandomSymbolSoupsAndFormulaTokens) {
  std::mt19937 rng(7);
  const char* tokens[] = {"R(", "L(", ")", ",", "F_0^1", "(0.5)", "H(", "flat", "M(", "straight", "u",
                          "Par(", "Loc(", "chest", "hand", "Sym(lr)", "N(", "mouth=", "\"x", "=", "#",
                          "L1(1)", "D3", "E(", "P(", "9", "-1", "\n", "В"};
  for (int round = 0; round < 400; ++round) {
    std::string formula, hamnosys;
    const int n = static_cast<int>(rng() % 40);
    for (int i = 0; i < n; ++i) {
      formula += tokens[rng() % (sizeof tokens / sizeof tokens[0])];
      append_utf8(&hamnosys, 0xE000 + static_cast<char32_t>(rng() % 0x100));
    }
    parse_everything(formula);
    parse_everything(hamnosys);
  }
}

TEST(NotationRobustness, DeepNestingIsRefusedNotRecursedInto) {
  std::string groups = "hamflathand";
  for (int i = 0; i < 5000; ++i) groups += ",hamparbegin";
  parse_everything(groups);
  std::string xml;
  for (int i = 0; i < 5000; ++i) xml += "<a>";
  parse_everything(xml);
  const std::vector<SignParse> signs = parse_signs(xml, NotationFormat::GSiGML);
  ASSERT_FALSE(signs.empty());
  EXPECT_NE(signs.back().diagnostics[0].message.find("deeper"), std::string::npos);
}

TEST(NotationRobustness, TruncatedCorpusSigns) {
  const std::string dir = std::string(SIGNWEAVE_SHARED_DIR) + "/corpus/";
  const std::string jsonl = read_file(dir + "hamnosys-dev.jsonl");
  const std::string hsigml = read_file(dir + "sigml-dev/dgs-collection.sigml");
  const std::string gsigml = read_file(dir + "sigml-dev/ngt-gestural-dev.sigml");
  if (jsonl.empty() || hsigml.empty() || gsigml.empty()) GTEST_SKIP() << "../shared/corpus not found: truncation test skipped";
  std::mt19937 rng(11);
  std::istringstream lines(jsonl);
  std::string line;
  int n = 0;
  while (std::getline(lines, line) && n < 600) {
    if (++n % 3 != 0) continue;
    const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    for (const char* field : {"hamnosys", "names"}) {
      const std::string s = j.value(field, "");
      if (s.empty()) continue;
      parse_everything(s.substr(0, rng() % (s.size() + 1)));
      std::string damaged = s;  // a byte flipped in the middle
      damaged[rng() % damaged.size()] ^= static_cast<char>(1 + rng() % 255);
      parse_everything(damaged);
    }
  }
  for (const std::string* doc : {&hsigml, &gsigml}) {
    for (int round = 0; round < 12; ++round) {
      // A window of a few signs, cut at random places (mid-element, mid-attribute).
      const std::size_t start = rng() % (doc->size() - 8000);
      parse_everything("<sigml>" + doc->substr(start, 1 + rng() % 6000));
      parse_everything(doc->substr(0, 200 + rng() % 3000));
    }
  }
}

}  // namespace
}  // namespace sw::notation
