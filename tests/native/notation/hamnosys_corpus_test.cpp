// The HamNoSys reader and printer on real signs: ../shared/corpus/hamnosys-dev.jsonl (4,482 DGS
// and PJM signs; skipped, saying so, where the corpus is absent). Parse rates and round-trip
// rates asserted here are the measured ones minus a small margin (see the report in the commit).
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "notation/hamnosys.h"
#include "notation/parse.h"
#include "notation/sign_spec_json.h"
#include "corpus_tally.h"

namespace sw::notation {
namespace {

struct Entry {
  std::string gloss, hamnosys, names;
};

std::vector<Entry> load_corpus() {
  std::vector<Entry> out;
  std::ifstream in(std::string(SIGNWEAVE_SHARED_DIR) + "/corpus/hamnosys-dev.jsonl");
  std::string line;
  while (std::getline(in, line)) {
    const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    if (!j.is_object()) continue;
    Entry e;
    e.gloss = j.value("gloss", "");
    e.hamnosys = j.value("hamnosys", "");
    e.names = j.value("names", "");
    out.push_back(std::move(e));
  }
  return out;
}

using Tally = CorpusTally;

// Parses one string; counts it; checks print -> parse gives the same SignSpec (as JSON).
void run(const std::string& text, Tally* t, std::vector<std::string>* failures) {
  ++t->signs;
  const std::vector<SignParse> signs = parse_hamnosys_text(text);
  ASSERT_EQ(signs.size(), 1u);
  const SignParse& s = signs[0];
  for (const Diagnostic& d : s.diagnostics) {
    EXPECT_GE(d.line, 1);
    EXPECT_GE(d.column, 1);
    EXPECT_LE(d.offset, text.size());
    if (d.severity == Severity::Error) ++t->reasons[d.message.substr(0, 60)];
  }
  if (!s.spec) return;
  ++t->parsed;
  if (!s.ok()) return;
  ++t->clean;
  const std::string expected = sign_to_json_text(*s.spec);
  bool same = true;
  for (HamNoSysSpelling spelling : {HamNoSysSpelling::Unicode, HamNoSysSpelling::Names}) {
    const std::string printed = print_hamnosys(*s.spec, spelling);
    const std::vector<SignParse> again = parse_hamnosys_text(printed);
    same = same && again.size() == 1 && again[0].ok() && sign_to_json_text(*again[0].spec) == expected;
    if (!same && failures->size() < 5 && spelling == HamNoSysSpelling::Names) {
      failures->push_back(text + "\n  -> " + printed);
    }
  }
  if (same) ++t->round_trips;
}

void report(const char* what, const Tally& t) { report_corpus_tally(what, t, 8); }

TEST(HamNoSysCorpus, UnicodeAndNamesParseAndRoundTrip) {
  const std::vector<Entry> corpus = load_corpus();
  if (corpus.empty()) GTEST_SKIP() << "../shared/corpus/hamnosys-dev.jsonl not found: corpus tests skipped";
  EXPECT_EQ(corpus.size(), 4482u);
  Tally unicode, names;
  std::vector<std::string> failures;
  for (const Entry& e : corpus) {
    if (!e.hamnosys.empty()) run(e.hamnosys, &unicode, &failures);
    if (!e.names.empty()) run(e.names, &names, &failures);
  }
  report("hamnosys (Unicode)", unicode);
  report("names", names);
  for (const std::string& f : failures) std::printf("  round-trip failure: %s\n", f.c_str());
  EXPECT_EQ(unicode.signs, 4482);
  EXPECT_EQ(names.signs, 1914);
  // Measured: 4481/4482 built, 4472 (99.8%) without error (4433, 98.9%, before the bracketed
  // contact part after a place was read as such: a second hand part in the bracket, read as a
  // target, was "expected a location symbol"); names 1905/1914 (99.5%) clean; print -> parse gives the
  // same SignSpec for 99.0% / 99.5% of the clean signs.
  EXPECT_EQ(unicode.parsed, unicode.signs - 1);
  EXPECT_GE(unicode.clean * 1000, unicode.signs * 995);
  EXPECT_GE(names.clean * 1000, names.signs * 980);
  EXPECT_GE(unicode.round_trips * 1000, unicode.clean * 985);
  EXPECT_GE(names.round_trips * 1000, names.clean * 985);
}

}  // namespace
}  // namespace sw::notation
