// Synthesis on real signs: the clean signs of ../shared/corpus/hamnosys-dev.jsonl (4,482 DGS and
// PJM signs in HamNoSys, 4,433 of them parse clean) synthesised on the project avatar, as
// `signweave check FILE --field hamnosys` does. The lexicon's signs are hand-picked; the corpus
// exercises places, movements and hand pairs they do not. Read from SIGNWEAVE_SHARED_DIR, never
// copied into the repository; skipped, saying so, where the corpus or the avatar is absent.
//
// Sampled: every kSampleStride-th clean sign (in file order), synthesised once per process for
// both tests (about 10-15 s natively for the half, 31-39 s for all 4,433 on the shared 2-core
// machine; ctest runs each test in its own process, so there each pays it: 9-12 s natively,
// about 200 s under ASan+UBSan); set SIGNWEAVE_CORPUS_FULL=1 to synthesise every one.
// `signweave check` gives the full figures.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <regex>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "notation/parse.h"
#include "synthesis/synthesize.h"
#include "synthesis_fixture.h"

namespace sw::synthesis {
namespace {

constexpr int kSampleStride = 2;

struct CorpusSign {
  std::string gloss, hamnosys;
};

// The corpus's `hamnosys` field per line (Unicode HamNoSys; some lines have only `names`, which
// the check with --field hamnosys does not read either), with its gloss.
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

// What one sampled clean sign gave.
struct SampledSign {
  std::string gloss;
  bool ok = false;
  std::string error;                  // the first error's message when !ok
  float max_penetration_m = 0.0f;     // SynthesisReport::max_penetration_m when ok
  std::vector<std::string> warnings;  // SynthesisReport::warnings when ok
  // Where elbow_path.h carried an elbow round (SynthesisReport::elbow_frames_carried > 0): the
  // same sign's depth with the frames as solved (SynthesisOptions::carry_elbows false).
  int elbow_frames_carried = 0;
  float uncarried_penetration_m = 0.0f;
};

struct CorpusSample {
  std::string skip;  // why the tests skip, when they do
  int clean = 0;     // clean signs in the corpus
  int stride = kSampleStride;
  double seconds = 0.0;
  std::vector<SampledSign> signs;
};

// Synthesised once per process: both tests read the same clips' results when run together.
const CorpusSample& corpus_sample() {
  static const CorpusSample sample = [] {
    CorpusSample s;
    const std::vector<CorpusSign> corpus = load_corpus_hamnosys();
    if (corpus.empty()) {
      s.skip = "../shared/corpus/hamnosys-dev.jsonl not found: corpus synthesis tests skipped";
      return s;
    }
    testing::ProjectAvatar project = testing::load_project_avatar();
    if (!project.present) {
      s.skip = "models/signweave-avatar.glb not found: corpus synthesis tests skipped";
      return s;
    }
    if (!project.error.empty()) {
      s.skip = "the project avatar does not load: " + project.error;
      return s;
    }
    const Synthesizer synthesizer(project.avatar);
    if (!synthesizer.ok()) {
      s.skip = "no synthesizer for the project avatar: " + synthesizer.error();
      return s;
    }
    const char* full = std::getenv("SIGNWEAVE_CORPUS_FULL");
    s.stride = full && std::string(full) == "1" ? 1 : kSampleStride;
    const auto started = std::chrono::steady_clock::now();
    for (const CorpusSign& c : corpus) {
      if (c.hamnosys.empty()) continue;
      const std::vector<notation::SignParse> parsed =
          notation::parse_signs(c.hamnosys, notation::NotationFormat::HamNoSys);
      if (parsed.empty() || !parsed[0].ok() || !parsed[0].spec) continue;
      if (s.clean++ % s.stride != 0) continue;
      const SynthesisResult r = synthesizer.sign(*parsed[0].spec, SynthesisOptions{});
      SampledSign out;
      out.gloss = c.gloss;
      out.ok = r.ok();
      if (r.ok()) {
        out.max_penetration_m = r.report.max_penetration_m;
        out.warnings = r.report.warnings;
        out.elbow_frames_carried = r.report.elbow_frames_carried;
        if (out.elbow_frames_carried > 0) {
          SynthesisOptions as_solved;
          as_solved.carry_elbows = false;
          out.uncarried_penetration_m =
              synthesizer.sign(*parsed[0].spec, as_solved).report.max_penetration_m;
        }
      } else {
        out.error = r.errors.empty() ? std::string() : r.errors.front().message;
      }
      s.signs.push_back(std::move(out));
    }
    s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return s;
  }();
  return sample;
}

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

TEST(CorpusSynthesis, EveryCleanSignSynthesises) {
  const CorpusSample& s = corpus_sample();
  if (!s.skip.empty()) GTEST_SKIP() << s.skip;
  int synthesised = 0;
  std::map<std::string, std::vector<std::string>> reasons;  // message -> glosses
  for (const SampledSign& sign : s.signs) {
    if (sign.ok) {
      ++synthesised;
      continue;
    }
    EXPECT_FALSE(sign.error.empty()) << sign.gloss << ": a failed synthesis without an error message";
    reasons[sign.error.substr(0, 100)].push_back(sign.gloss);
  }
  const int sampled = static_cast<int>(s.signs.size());
  std::printf("[corpus] synthesis on the project avatar: %d of %d sampled clean signs (%.2f%%; 1 in %d of %d clean) "
              "in %.1f s\n",
              synthesised, sampled, 100.0 * synthesised / std::max(1, sampled), s.stride, s.clean, s.seconds);
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
  EXPECT_GE(s.clean, 4460) << "the corpus parses less cleanly than measured: hamnosys_corpus_test.cpp says why";
  EXPECT_GE(synthesised, static_cast<int>(0.995 * sampled)) << "of " << sampled << " clean signs synthesised";
}

// Issue 4: no frame may penetrate more than 5 mm except at intended contact. The corpus is held to
// its measured share of signs over 5 mm (with a small margin) so that it can only improve; the
// causes that remain are printed, the commonest first (docs/SYNTHESIS.md "Real signs (the
// corpus)").
TEST(CorpusSynthesis, RealSignsKeepTheirArmsAndHandsOutOfTheBody) {
  const CorpusSample& s = corpus_sample();
  if (!s.skip.empty()) GTEST_SKIP() << s.skip;
  // The sample's measured figures, every 2nd clean sign: 2,237 synthesised, 18 over 5 mm
  // (0.8 %), deepest 77 mm (ratować), sign-hands merged with leap and arm-side; 37 (1.7 %) after
  // sign-hands on rest-meet (a symmetric pair written at one place laid
  // apart to both sides; hand in other hand 18 -> 2 signs); 62 (2.8 %) after rest-meet (the hands of a rest transition come
  // together along a line they stay clear along; hand in other hand 23 -> 18 signs); 67 (3.0 %)
  // on main before it; 68 (3.0 %) after push-rest (a hand caught between the chin and the
  // torso leaves by one way, judged with the sign's transitions); 94 over 5 mm (4.2 %) after ramp-side (one swivel side per run of fixes); 95
  // (4.2 %) after centre-push (hands side by side parted along the line
  // between their centres); 114 (5.1 %) before it. szkoła (119 mm, the whole corpus's deepest)
  // is not among the 2,237 the stride now takes. 108 (4.8 %), deepest 119 mm (szkoła), after
  // other-hand and trunk-depth merged. Before: 110
  // (4.9 %), deepest 129 mm, with other-hand alone (a path that ends on the other hand ends there;
  // a one-handed sign on the other arm presents that arm); 113 (5.1 %), deepest 119 mm (szkoła),
  // with trunk-depth alone (a symmetric pair's sides, same_side_pair and mirrored_place; one
  // handshape's paired orientations, read_orientation_pair); 115 (5.1 %) before both; 120 (5.4 %)
  // before pair-mirror's two-handed plans (sign_motion.cpp, mirror_copy_for_the_written_other_hand,
  // ride_on_the_carrying_hand); 140 (6.3 %) before hands-meet (a rest transition into a sign whose
  // hands meet holds the wrists apart until the last quarter); 179 (8.0 %), deepest 133 mm, before
  // rest-route (movements stop at the body; a rest transition no route clears takes the hand's path
  // that adds least); 208 (9.4 %) of 2,217 before the HamNoSys reader read the bracketed contact
  // part after a place as that (hamnosys_parser.cpp, read_contact_bracket); 21 % of all signs
  // before corpus-depth.
  constexpr float kMeasuredShareOver5mm = 0.008f;
  constexpr float kMeasuredDeepest_m = 0.077f;

  int synthesised = 0, over = 0;
  float worst_m = 0.0f;
  std::string worst_gloss;
  std::map<std::string, DepthCause> causes;
  for (const SampledSign& sign : s.signs) {
    if (!sign.ok) continue;  // EveryCleanSignSynthesises counts those
    ++synthesised;
    if (sign.max_penetration_m > worst_m) {
      worst_m = sign.max_penetration_m;
      worst_gloss = sign.gloss;
    }
    if (sign.max_penetration_m <= 0.005f) continue;
    ++over;
    DepthCause& c = causes[depth_cause(sign.warnings)];
    ++c.signs;
    c.worst_m = std::max(c.worst_m, sign.max_penetration_m);
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
  std::printf("[corpus] 1 in %d clean signs: %d synthesised, %d over 5 mm (%.1f%%), deepest %.0f mm (%s)\n%s",
              s.stride, synthesised, over, 100.0f * share, worst_m * 1000.0f, worst_gloss.c_str(),
              table.c_str());

  // The margins: 1 point (about 20 signs) and 10 mm, for changes elsewhere that move a sign
  // across the 5 mm line; a fix that lowers the figures lowers the constants with it.
  EXPECT_LE(share, kMeasuredShareOver5mm + 0.01f) << table;
  EXPECT_LE(worst_m, kMeasuredDeepest_m + 0.01f) << worst_gloss;
}

// The elbow's carried path (elbow_path.h) trades a jump for a swing at a signer's speed; it may
// not buy that with depth. Every sampled sign whose elbow was carried is no deeper than its frames
// as solved, or than the 5 mm rule where those were shallower, but for 2 mm (the pass compares
// each arm's parts with the clip's own; the final check's exemptions differ a little: 1.4 mm
// measured at most, on the whole corpus). Comparing one deepest number for the whole arm instead
// let a hand's own contact depth excuse an arm swung into the trunk: this test fails on it (ból
// głowy, Węgry, pan, pani; boczek 51.7 -> 92.2 mm on the whole corpus). Leaving the swung hand
// against the other forearm out of the comparison let it in (alarm 16.3 -> 21.5 mm; not in the
// sample, `signweave-cli check` on the whole corpus shows it).
TEST(CorpusSynthesis, CarryingAnElbowRoundNeverTakesTheArmDeeper) {
  const CorpusSample& s = corpus_sample();
  if (!s.skip.empty()) GTEST_SKIP() << s.skip;
  int carried = 0;
  for (const SampledSign& sign : s.signs) {
    if (!sign.ok || sign.elbow_frames_carried == 0) continue;
    ++carried;
    EXPECT_LE(sign.max_penetration_m, std::max(sign.uncarried_penetration_m, 0.005f) + 0.002f)
        << sign.gloss << ": " << sign.uncarried_penetration_m * 1000.0f << " mm as solved";
  }
  std::printf("[corpus] elbows carried round in %d of %zu sampled signs\n", carried, s.signs.size());
  // Measured: the whole corpus has 92 signs whose step over 100 mm a frame the pass removes.
  EXPECT_GT(carried, 0) << "the pass carried no elbow in the sample";
}

}  // namespace
}  // namespace sw::synthesis
