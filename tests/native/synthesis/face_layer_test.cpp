// The face layer in a synthesised phrase: morph tracks for every face channel, the sign's own
// non-manuals (brows), mouthing of the word, a blink at a pause, and options that switch it off or
// reject a bad emotion.
#include <gtest/gtest.h>

#include "face/channel_set.h"
#include "synthesis/synthesize.h"
#include "synthesis_fixture.h"

namespace sw::synthesis {
namespace {

using namespace testing;

float max_weight(const Clip& clip, const char* channel, double from_s, double to_s) {
  const int c = face::channel_index(channel);
  float best = 0.0f;
  for (int f = 0; f < clip.frame_count; ++f) {
    const double t = f / double(clip.fps);
    if (t < from_s || t > to_s) continue;
    best = std::max(best, clip.morph_weights[std::size_t(f) * clip.morph_names.size() + std::size_t(c)]);
  }
  return best;
}

std::vector<PhraseItem> question_then_pause() {
  PhraseItem where;
  where.kind = PhraseItem::Kind::Sign;
  where.sign = sign_at(index_point(), notation::BodyLevel::Chest, notation::Side::Right,
                       notation::Contact::None);
  where.sign.nonmanual.eyebrows = "down";  // wh-question brows
  where.label = "mama";
  PhraseItem pause;
  pause.kind = PhraseItem::Kind::Pause;
  pause.label = "?";
  PhraseItem again = where;
  again.sign.nonmanual.eyebrows.clear();
  return {where, pause, again};
}

TEST(SynthesisFace, PhraseCarriesEveryFaceChannelWithTheSignsNonManuals) {
  const avatar::Avatar av = make_reference_humanoid();
  const SynthesisResult r = synthesize_phrase(question_then_pause(), av);
  ASSERT_TRUE(r.ok());
  const Clip& clip = r.clip;
  ASSERT_EQ(clip.morph_count(), face::kChannelCount);
  ASSERT_EQ(clip.morph_weights.size(), std::size_t(clip.frame_count) * face::kChannelCount);
  const ClipSegment* sign = nullptr;
  const ClipSegment* pause = nullptr;
  for (const ClipSegment& s : clip.segments) {
    if (s.kind == ClipSegment::Kind::Sign && !sign) sign = &s;
    if (s.kind == ClipSegment::Kind::Pause) pause = &s;
  }
  ASSERT_NE(sign, nullptr);
  ASSERT_NE(pause, nullptr);
  EXPECT_GT(max_weight(clip, "browDownLeft", sign->start_s, sign->end_s), 0.5f);
  EXPECT_LT(max_weight(clip, "browDownLeft", 0.0, sign->start_s - 0.2), 0.05f);
  EXPECT_GT(max_weight(clip, "viseme_PP", sign->start_s, sign->end_s), 0.5f);  // "mama"
  EXPECT_GT(max_weight(clip, "eyeBlinkLeft", pause->start_s, pause->end_s + 0.3), 0.9f);
}

TEST(SynthesisFace, EmotionOptionAndSwitchingTheFaceOff) {
  const avatar::Avatar av = make_reference_humanoid();
  SynthesisOptions happy;
  happy.emotion = "happy";
  happy.emotion_intensity = 1.0f;
  const SynthesisResult r = synthesize_phrase(question_then_pause(), av, happy);
  ASSERT_TRUE(r.ok());
  EXPECT_GT(max_weight(r.clip, "mouthSmileLeft", 0.0, r.clip.duration_s()), 0.8f);

  SynthesisOptions off;
  off.face = false;
  const SynthesisResult bare = synthesize_phrase(question_then_pause(), av, off);
  ASSERT_TRUE(bare.ok());
  EXPECT_TRUE(bare.clip.morph_names.empty());
  EXPECT_TRUE(bare.clip.morph_weights.empty());
}

TEST(SynthesisFace, BadEmotionOptionsAreErrorsNotCrashes) {
  const avatar::Avatar av = make_reference_humanoid();
  SynthesisOptions bad;
  bad.emotion = "grumpy";
  SynthesisResult r = synthesize_phrase(question_then_pause(), av, bad);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.errors[0].message.find("grumpy"), std::string::npos);
  bad.emotion = "sad";
  bad.emotion_intensity = 3.0f;
  r = synthesize_phrase(question_then_pause(), av, bad);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.errors[0].message.find("intensity"), std::string::npos);
}

}  // namespace
}  // namespace sw::synthesis
