#include "face/emotion.h"

#include <gtest/gtest.h>

#include "face/channel_set.h"

namespace sw::face {
namespace {

TEST(Emotion, NamesRoundTripAndUnknownIsRejected) {
  for (const std::string& name : emotion_names()) {
    Emotion e{};
    ASSERT_TRUE(emotion_from_name(name, &e)) << name;
    EXPECT_EQ(name, emotion_name(e));
  }
  Emotion e = Emotion::Happy;
  EXPECT_FALSE(emotion_from_name("grumpy", &e));
  EXPECT_EQ(e, Emotion::Happy);  // untouched on failure
  EXPECT_TRUE(emotion_from_name("SURPRISE", &e));
  EXPECT_EQ(e, Emotion::Surprised);
}

TEST(Emotion, SadIsSeed001sActionUnits) {
  // seed 001: sad = AU1 + AU4 + AU15 + AU23.
  const ChannelWeights w = emotion_weights(Emotion::Sad, 1.0f);
  EXPECT_GT(w[channel_index("browInnerUp")], 0.5f);     // AU1
  EXPECT_GT(w[channel_index("browDownLeft")], 0.0f);    // AU4
  EXPECT_GT(w[channel_index("mouthFrownLeft")], 0.5f);  // AU15
  EXPECT_GT(w[channel_index("mouthPress")], 0.0f);      // AU23
  EXPECT_EQ(w[channel_index("mouthSmileLeft")], 0.0f);
}

TEST(Emotion, HappyRaisesMouthCornersAndIntensityScales) {
  const ChannelWeights full = emotion_weights(Emotion::Happy, 1.0f);
  const ChannelWeights half = emotion_weights(Emotion::Happy, 0.5f);
  const int smile = channel_index("mouthSmileRight");
  EXPECT_GT(full[smile], 0.5f);
  EXPECT_NEAR(half[smile], 0.5f * full[smile], 1e-6f);
  const ChannelWeights none = emotion_weights(Emotion::Happy, 0.0f);
  for (int c = 0; c < kChannelCount; ++c) EXPECT_EQ(none[c], 0.0f);
  const ChannelWeights clamped = emotion_weights(Emotion::Happy, 7.0f);
  EXPECT_FLOAT_EQ(clamped[smile], full[smile]);
}

TEST(Emotion, PerformanceIsDampedWhereTheEmotionAlreadyPushes) {
  // seed 002: a channel already pushed by the emotion gets only the remaining headroom.
  ChannelWeights emotion, performance;
  const int brow = channel_index("browInnerUp");
  const int jaw = channel_index("jawOpen");
  emotion[brow] = 0.8f;
  performance[brow] = 0.8f;
  performance[jaw] = 0.5f;
  const ChannelWeights out = combine_damped(emotion, performance);
  EXPECT_NEAR(out[brow], 0.8f + 0.8f * 0.2f, 1e-6f);
  EXPECT_LE(out[brow], 1.0f);
  EXPECT_NEAR(out[jaw], 0.5f, 1e-6f);  // untouched by the emotion: full performance
}

}  // namespace
}  // namespace sw::face
