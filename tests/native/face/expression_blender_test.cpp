#include "face/expression_blender.h"

#include <gtest/gtest.h>

#include "face/easing.h"
#include "face/emotion.h"

namespace sw::face {
namespace {

TEST(Easing, CosineHasZeroSlopeAtTheEndsAndMeetsLinearInTheMiddle) {
  EXPECT_FLOAT_EQ(ease_cosine(0.0f), 0.0f);
  EXPECT_FLOAT_EQ(ease_cosine(1.0f), 1.0f);
  EXPECT_NEAR(ease_cosine(0.5f), 0.5f, 1e-6f);
  EXPECT_LT(ease_cosine(0.01f), 0.01f * 0.1f);  // starts slowly (acceleration), seed 001
  EXPECT_FLOAT_EQ(ease_cosine(-3.0f), 0.0f);
  EXPECT_FLOAT_EQ(ease_cosine(3.0f), 1.0f);
}

TEST(BilinearBlend, MatchesSeed001sFormulaAtTheCornersAndInside) {
  ChannelWeights q11, q12, q21, q22;
  q11[0] = 0.0f;
  q12[0] = 1.0f;
  q21[0] = 2.0f;
  q22[0] = 4.0f;
  EXPECT_FLOAT_EQ(bilinear_blend(q11, q12, q21, q22, 0, 0)[0], 0.0f);
  EXPECT_FLOAT_EQ(bilinear_blend(q11, q12, q21, q22, 0, 1)[0], 1.0f);
  EXPECT_FLOAT_EQ(bilinear_blend(q11, q12, q21, q22, 1, 0)[0], 2.0f);
  EXPECT_FLOAT_EQ(bilinear_blend(q11, q12, q21, q22, 1, 1)[0], 4.0f);
  // P = s1 (t1 Q11 + t2 Q12) + s2 (t1 Q21 + t2 Q22) with s2 = 0.25, t2 = 0.5.
  const float expected = 0.75f * (0.5f * 0 + 0.5f * 1) + 0.25f * (0.5f * 2 + 0.5f * 4);
  EXPECT_FLOAT_EQ(bilinear_blend(q11, q12, q21, q22, 0.25f, 0.5f)[0], expected);
}

TEST(ExpressionBlender, SwitchingMidwayNeverJumps) {
  // seed 001: interrupting a transition snapshots the current blend as the new source.
  ExpressionBlender blender;
  const ChannelWeights happy = emotion_weights(Emotion::Happy, 1.0f);
  const ChannelWeights sad = emotion_weights(Emotion::Sad, 1.0f);
  blender.retarget(happy, 0.0, 1.0);
  const ChannelWeights before = blender.value(0.4);
  blender.retarget(sad, 0.4, 1.0);
  const ChannelWeights after = blender.value(0.4);
  for (int c = 0; c < kChannelCount; ++c) EXPECT_NEAR(before[c], after[c], 1e-6f) << c;
  const ChannelWeights end = blender.value(1.4);
  for (int c = 0; c < kChannelCount; ++c) EXPECT_NEAR(end[c], sad[c], 1e-6f) << c;
  // And the path is continuous: small time steps give small changes.
  for (double t = 0.4; t < 1.4; t += 0.01) {
    const ChannelWeights a = blender.value(t), b = blender.value(t + 0.01);
    for (int c = 0; c < kChannelCount; ++c) EXPECT_LT(std::abs(a[c] - b[c]), 0.05f);
  }
}

}  // namespace
}  // namespace sw::face
