// Notation parse/print time per sign (native): the seed's formula letters, HamNoSys strings and
// SiGML signs from ../shared/corpus when present (skipped, saying so on stderr, when absent).
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench.h"
#include "notation/formula.h"
#include "notation/hamnosys.h"
#include "notation/parse.h"
#include "notation/sigml.h"

namespace {

using namespace sw::notation;

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
const std::string kShared = std::string(SIGNWEAVE_SOURCE_DIR) + "/../shared/corpus/";

SW_BENCH("notation_formula") {
  const std::string letter = "R(L1(0), D1, F_0^1(0.5), F_0^2(1), F_0^3(1), F_0^4(1), F_0^5(1))";
  const std::string rich = "R(H(finger2, thumbacross), E(uo), P(dl), Loc(chin, right, touch), C(tip, 2), "
                           "M(arc, o, bulge=u, small), Par(M(circle, axis=i, cw), M(nod))) Sym(lr) "
                           "Rep(fromstart) N(mouth=\"hallo\", brows=up)";
  const SignSpec spec = *parse_formula_text(rich)[0].spec;
  return {{"formula_parse_seed_letter", sw::bench::time_ns_per_call([&] { (void)parse_formula_text(letter); }) / 1000, "us/sign"},
          {"formula_parse_two_hand_moving_sign", sw::bench::time_ns_per_call([&] { (void)parse_formula_text(rich); }) / 1000, "us/sign"},
          {"formula_print", sw::bench::time_ns_per_call([&] { (void)print_formula(spec); }) / 1000, "us/sign"}};
}

SW_BENCH("notation_hamnosys_corpus") {
  std::vector<std::string> unicode, names;
  std::istringstream lines(read_file(kShared + "hamnosys-dev.jsonl"));
  std::string line;
  while (std::getline(lines, line)) {
    const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    if (!j.is_object()) continue;
    if (!j.value("hamnosys", "").empty()) unicode.push_back(j.value("hamnosys", ""));
    if (!j.value("names", "").empty()) names.push_back(j.value("names", ""));
  }
  if (unicode.empty()) {
    std::fprintf(stderr, "notation_hamnosys_corpus: ../shared/corpus not found, skipped\n");
    return {};
  }
  std::size_t i = 0, k = 0, p = 0;
  std::vector<SignSpec> specs;
  for (std::size_t n = 0; n < unicode.size(); n += 7) {
    auto v = parse_hamnosys_text(unicode[n]);
    if (v[0].spec) specs.push_back(*v[0].spec);
  }
  return {{"hamnosys_parse_unicode", sw::bench::time_ns_per_call([&] { (void)parse_hamnosys_text(unicode[i++ % unicode.size()]); }) / 1000, "us/sign"},
          {"hamnosys_parse_names", sw::bench::time_ns_per_call([&] { (void)parse_hamnosys_text(names[k++ % names.size()]); }) / 1000, "us/sign"},
          {"hamnosys_print_names", sw::bench::time_ns_per_call([&] { (void)print_hamnosys(specs[p++ % specs.size()], HamNoSysSpelling::Names); }) / 1000, "us/sign"}};
}

SW_BENCH("notation_sigml_corpus") {
  const std::string h = read_file(kShared + "sigml-dev/dgs-collection.sigml");
  const std::string g = read_file(kShared + "sigml-dev/ngt-gestural-dev.sigml");
  if (h.empty() || g.empty()) {
    std::fprintf(stderr, "notation_sigml_corpus: ../shared/corpus not found, skipped\n");
    return {};
  }
  // Whole documents: time per document / its sign count.
  const double h_ns = sw::bench::time_ns_per_call([&] { (void)parse_sigml_text(h); }, 1.0);
  const double g_ns = sw::bench::time_ns_per_call([&] { (void)parse_sigml_text(g); }, 1.0);
  return {{"hsigml_parse_document", h_ns / 1914 / 1000, "us/sign"},
          {"gsigml_parse_document", g_ns / 1097 / 1000, "us/sign"}};
}

}  // namespace
