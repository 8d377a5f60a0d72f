// The real-sign corpus (../shared/corpus/hamnosys-dev.jsonl: DGS and PJM signs in HamNoSys)
// synthesised on the project avatar: the lexicon's signs are hand-picked, the corpus exercises
// places, movements and hand pairs they do not. Read from SIGNWEAVE_SHARED_DIR, never copied into
// the repository; skipped with a message when absent.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "notation/parse.h"
#include "synthesis_fixture.h"

namespace sw::synthesis {
namespace {

using namespace testing;

// Every `kDepthSampleEvery`-th sign of the corpus: the whole of it takes about 30 s natively
// (7 ms a sign: a corpus sign is longer than a lexicon sign and most touch the body), a half
// about 15 s, and it still draws on every kind of place, movement and hand pair.
constexpr int kDepthSampleEvery = 2;
// The sample's measured figures (docs/SYNTHESIS.md "Real signs (the corpus)").
constexpr float kMeasuredShareOver5mm = 0.090f;
constexpr float kMeasuredDeepest_m = 0.135f;

// The penetration warning synthesize.cpp writes ("penetration of 42.1 mm: right forearm in torso
// right") as its cause with the sides taken out, so that both hands' cases count together.
std::string depth_cause(const std::vector<std::string>& warnings) {
  static const std::regex side(R"(\b(left|right) )");
  for (const std::string& w : warnings) {
    if (w.rfind("penetration of ", 0) != 0) continue;
    const std::size_t colon = w.find(": ");
    std::string what = colon == std::string::npos ? w : w.substr(colon + 2);
    what = std::regex_replace(what, side, "");
    what = std::regex_replace(what, std::regex(R"( (left|right)$)"), "");
    return what;
  }
  return "(no warning)";
}

struct DepthCause {
  int signs = 0;
  float worst_m = 0.0f;
};

}  // namespace

// Issue 4: no frame may penetrate more than 5 mm except at intended contact. The corpus is held to
// its measured share of signs over 5 mm (with a small margin) so that it can only improve; the
// causes that remain are printed, the commonest first. Measured on this sample (every 2nd sign,
// 2,170 synthesised: 195 over 5 mm, deepest 135 mm): docs/SYNTHESIS.md "Real signs (the corpus)".
TEST(CorpusSynthesis, RealSignsKeepTheirArmsAndHandsOutOfTheBody) {
  const std::string path = std::string(SIGNWEAVE_SHARED_DIR) + "/corpus/hamnosys-dev.jsonl";
  std::ifstream in(path);
  if (!in) GTEST_SKIP() << path << " absent (the shared corpus is not in this checkout)";
  ProjectAvatar project = load_project_avatar();
  ASSERT_TRUE(project.error.empty()) << project.error;
  if (!project.present) GTEST_SKIP() << "models/signweave-avatar.glb absent (generate it first)";
  Synthesizer synth(project.avatar);
  ASSERT_TRUE(synth.ok()) << synth.error();

  int line_no = 0, synthesised = 0, over = 0;
  float worst_m = 0.0f;
  std::string worst_gloss;
  std::map<std::string, DepthCause> causes;
  std::string line;
  while (std::getline(in, line)) {
    if (line_no++ % kDepthSampleEvery != 0) continue;
    const nlohmann::json entry = nlohmann::json::parse(line, nullptr, false);
    if (!entry.is_object()) continue;
    const notation::ParseOutcome parsed =
        notation::parse_notation(entry.value("hamnosys", ""), notation::NotationFormat::HamNoSys);
    if (!parsed.ok() || parsed.signs.empty()) continue;
    const SynthesisResult r = synth.sign(parsed.signs.front(), SynthesisOptions{});
    if (!r.ok()) continue;  // signs that do not synthesise are CorpusSynthesis.EveryCleanSignSynthesises'
    ++synthesised;
    const float depth = r.report.max_penetration_m;
    if (depth > worst_m) {
      worst_m = depth;
      worst_gloss = entry.value("gloss", "");
    }
    if (depth <= 0.005f) continue;
    ++over;
    DepthCause& c = causes[depth_cause(r.report.warnings)];
    ++c.signs;
    c.worst_m = std::max(c.worst_m, depth);
  }
  ASSERT_GT(synthesised, 1000) << "too few corpus signs synthesised to measure";

  std::vector<std::pair<std::string, DepthCause>> ranked(causes.begin(), causes.end());
  std::sort(ranked.begin(), ranked.end(),
            [](const auto& a, const auto& b) { return a.second.signs > b.second.signs; });
  std::string table;
  for (const auto& [what, c] : ranked)
    table += "  " + std::to_string(c.signs) + " signs: " + what + " (deepest " +
             std::to_string(static_cast<int>(c.worst_m * 1000.0f + 0.5f)) + " mm)\n";
  const float share = static_cast<float>(over) / static_cast<float>(synthesised);
  std::printf("corpus (every %d%s sign): %d synthesised, %d over 5 mm (%.1f%%), deepest %.0f mm (%s)\n%s",
              kDepthSampleEvery, kDepthSampleEvery == 2 ? "nd" : "th", synthesised, over, 100.0f * share,
              worst_m * 1000.0f, worst_gloss.c_str(), table.c_str());

  // The margins: 1 point (about 20 signs) and 10 mm, for changes elsewhere that move a sign
  // across the 5 mm line; a fix that lowers the figures lowers the constants with it.
  EXPECT_LE(share, kMeasuredShareOver5mm + 0.01f) << table;
  EXPECT_LE(worst_m, kMeasuredDeepest_m + 0.01f) << worst_gloss;
}

}  // namespace sw::synthesis
