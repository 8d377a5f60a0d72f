// Notation out (`signweave convert`, GET /api/signs/{id}?format=, the page's export): every clean
// sign of the dev corpora (../shared/corpus: hamnosys-dev.jsonl, sigml-dev/*.sigml; skipped,
// saying so, where absent) is printed in each notation the core writes and parsed back, and must
// give the same SignSpec (compared as JSON). The share that round-trips per target is printed and
// held as a ratchet: the measured share minus a small margin.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "notation/parse.h"
#include "notation/sign_spec_json.h"

namespace sw::notation {
namespace {

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Every clean sign of the corpora, or none when they are absent.
std::vector<SignSpec> corpus_signs() {
  std::vector<SignSpec> signs;
  const std::string dir = std::string(SIGNWEAVE_SHARED_DIR) + "/corpus/";
  std::ifstream hamnosys(dir + "hamnosys-dev.jsonl");
  std::string line;
  while (std::getline(hamnosys, line)) {
    const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    if (!j.is_object() || !j.contains("hamnosys")) continue;
    for (const SignParse& s :
         parse_signs(j["hamnosys"].get<std::string>(), NotationFormat::HamNoSys)) {
      if (s.ok()) signs.push_back(*s.spec);
    }
  }
  for (const char* file : {"sigml-dev/dgs-collection.sigml", "sigml-dev/ngt-gestural-dev.sigml"}) {
    const std::string text = read_file(dir + file);
    for (const SignParse& s : parse_signs(text, detect_format(text))) {
      if (s.ok()) signs.push_back(*s.spec);
    }
  }
  return signs;
}

// Prints the first few failures of each target (what was printed, and why it differs).
bool round_trips(const SignSpec& sign, NotationFormat format, int* shown) {
  const std::string printed = print_notation({sign}, format);
  const std::vector<SignParse> again = parse_signs(printed, format);
  if (again.size() == 1 && again[0].ok() && sign_to_json(*again[0].spec) == sign_to_json(sign))
    return true;
  if ((*shown)++ < 3) {
    std::string why = again.size() != 1 ? std::to_string(again.size()) + " signs parsed back" : "";
    if (again.size() == 1 && !again[0].ok() && !again[0].diagnostics.empty()) {
      why = format_diagnostic(again[0].diagnostics.front());
    } else if (again.size() == 1) {
      why = "a different sign: " + sign_to_json_text(*again[0].spec);
    }
    std::printf("  round-trip failure (%s): %s\n    printed: %s\n    %s\n", format_name(format),
                sign.gloss.c_str(), printed.substr(0, 300).c_str(), why.substr(0, 400).c_str());
  }
  return false;
}

TEST(ConvertRoundTrip, EveryCorpusSignPrintsAndParsesBackInEachNotation) {
  const std::vector<SignSpec> signs = corpus_signs();
  if (signs.empty()) GTEST_SKIP() << "../shared/corpus not found: notation round-trip test skipped";
  struct Target {
    NotationFormat format;
    double ratchet;  // the share that must round-trip: measured minus a margin
  };
  // Measured over the 7,464 clean signs: formula 92.0 %, HamNoSys 84.7 %, H-SiGML 94.7 %,
  // G-SiGML 96.5 % (each notation's own signs round-trip at 98.5 %+ in the corpus tests; the gap
  // is signs read from one notation that another prints or reads back differently).
  const Target targets[] = {{NotationFormat::Formula, 0.915},
                            {NotationFormat::HamNoSys, 0.842},
                            {NotationFormat::HSiGML, 0.942},
                            {NotationFormat::GSiGML, 0.955}};
  for (const Target& target : targets) {
    int same = 0, shown = 0;
    for (const SignSpec& sign : signs) same += round_trips(sign, target.format, &shown);
    const double share = static_cast<double>(same) / signs.size();
    std::printf("[round trip] %s: %d of %zu clean corpus signs (%.2f%%)\n",
                format_name(target.format), same, signs.size(), 100.0 * share);
    EXPECT_GE(share, target.ratchet) << format_name(target.format);
  }
}

}  // namespace
}  // namespace sw::notation
