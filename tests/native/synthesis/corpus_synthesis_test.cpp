// Synthesis on real signs: every clean sign of ../shared/corpus/hamnosys-dev.jsonl (4,482 DGS and
// PJM signs, 4,433 of them parse clean) synthesised on the project avatar, as `signweave check
// FILE --field hamnosys` does; skipped, saying so, where the corpus or the avatar is absent. The
// share asserted is the measured one minus a small margin (as hamnosys_corpus_test.cpp does for
// the parse rates), and the commonest failure reasons are printed.
//
// Sampled: every kSampleStride-th clean sign (in file order), so the test takes 15-23 s
// natively instead of 31-39 s for all 4,433 (measured on the shared 2-core machine); set
// SIGNWEAVE_CORPUS_FULL=1 to synthesise every one. `signweave check` gives the full figures.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "notation/parse.h"
#include "synthesis/synthesize.h"
#include "synthesis_fixture.h"

namespace sw::synthesis {
namespace {

// The corpus's `hamnosys` field per line (Unicode HamNoSys; some lines have only `names`, which
// the check with --field hamnosys does not read either), with its gloss.
constexpr int kSampleStride = 2;

struct CorpusSign {
  std::string gloss, hamnosys;
};

std::vector<CorpusSign> load_corpus_hamnosys() {
  std::vector<CorpusSign> out;
  std::ifstream in(std::string(SIGNWEAVE_SHARED_DIR) + "/corpus/hamnosys-dev.jsonl");
  std::string line;
  while (std::getline(in, line)) {
    const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    if (!j.is_object()) continue;
    CorpusSign s{j.value("gloss", ""), j.value("hamnosys", "")};
    // One sign per line, as cli/sign_input.cpp reads it: a newline in the field would split it.
    std::replace(s.hamnosys.begin(), s.hamnosys.end(), '\n', ' ');
    std::replace(s.hamnosys.begin(), s.hamnosys.end(), '\r', ' ');
    out.push_back(std::move(s));
  }
  return out;
}

TEST(CorpusSynthesis, EveryCleanSignSynthesises) {
  const std::vector<CorpusSign> corpus = load_corpus_hamnosys();
  if (corpus.empty()) GTEST_SKIP() << "../shared/corpus/hamnosys-dev.jsonl not found: corpus synthesis test skipped";
  testing::ProjectAvatar project = testing::load_project_avatar();
  if (!project.present) GTEST_SKIP() << "models/signweave-avatar.glb not found: corpus synthesis test skipped";
  ASSERT_TRUE(project.error.empty()) << project.error;
  const Synthesizer synthesizer(project.avatar);
  ASSERT_TRUE(synthesizer.ok()) << synthesizer.error();

  const char* full = std::getenv("SIGNWEAVE_CORPUS_FULL");
  const int stride = full && std::string(full) == "1" ? 1 : kSampleStride;
  const auto started = std::chrono::steady_clock::now();
  int clean = 0, sampled = 0, synthesised = 0;
  std::map<std::string, std::vector<std::string>> reasons;  // message -> glosses
  for (const CorpusSign& c : corpus) {
    if (c.hamnosys.empty()) continue;
    const std::vector<notation::SignParse> parsed = notation::parse_signs(c.hamnosys, notation::NotationFormat::HamNoSys);
    if (parsed.empty() || !parsed[0].ok() || !parsed[0].spec) continue;
    if (clean++ % stride != 0) continue;
    ++sampled;
    const SynthesisResult r = synthesizer.sign(*parsed[0].spec, SynthesisOptions{});
    if (r.ok()) {
      ++synthesised;
    } else {
      ASSERT_FALSE(r.errors.empty()) << c.gloss << ": a failed synthesis without an error";
      EXPECT_FALSE(r.errors.front().message.empty()) << c.gloss << ": an error without a message";
      reasons[r.errors.front().message.substr(0, 100)].push_back(c.gloss);
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

  std::printf("[corpus] synthesis on the project avatar: %d of %d sampled clean signs (%.2f%%; 1 in %d of %d clean) "
              "in %.1f s\n",
              synthesised, sampled, 100.0 * synthesised / std::max(1, sampled), stride, clean, seconds);
  std::vector<std::pair<size_t, std::string>> ranked;
  for (const auto& [message, glosses] : reasons) ranked.emplace_back(glosses.size(), message);
  std::sort(ranked.rbegin(), ranked.rend());
  for (size_t i = 0; i < ranked.size() && i < 8; ++i) {
    const std::vector<std::string>& g = reasons[ranked[i].second];
    std::printf("    %5zu  %s (e.g. %s)\n", ranked[i].first, ranked[i].second.c_str(), g.front().c_str());
  }

  // Measured (corpus-pair), all and sampled alike: every clean sign synthesises (4,433 of 4,433;
  // 4,313 before a pair of hands written each on the other was placed in neutral space, 2.7 % of
  // them refused). A margin of 0.5 % for changes that trade a sign or two.
  EXPECT_GE(clean, 4400) << "the corpus parses less cleanly than measured: hamnosys_corpus_test.cpp says why";
  EXPECT_GE(synthesised, static_cast<int>(0.995 * sampled)) << "of " << sampled << " clean signs synthesised";
}

}  // namespace
}  // namespace sw::synthesis
