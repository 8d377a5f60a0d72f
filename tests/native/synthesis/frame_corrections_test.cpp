// Frame corrections (frame_corrections.h): the ramps that spread a per-frame collision
// correction over its neighbours, and the nearest clear swivel with a preferred side.
#include "synthesis/frame_corrections.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

namespace sw::synthesis {
namespace {

// Largest |second difference| of a series: a joint driven by it changes its per-frame step by
// at most this much (times the lever).
template <typename T, typename Len>
float max_second_difference(const std::vector<T>& v, Len len) {
  float m = 0.0f;
  for (size_t f = 1; f + 1 < v.size(); ++f) m = std::max(m, len(v[f + 1] - 2.0f * v[f] + v[f - 1]));
  return m;
}

TEST(SynthesisFrameCorrections, RampWeightIsASmoothstepEnvelope) {
  EXPECT_FLOAT_EQ(ramp_weight(0, 8), 1.0f);
  EXPECT_FLOAT_EQ(ramp_weight(9, 8), 0.0f);
  EXPECT_FLOAT_EQ(ramp_weight(20, 8), 0.0f);
  EXPECT_NEAR(ramp_weight(-3, 8), ramp_weight(3, 8), 1e-7f);
  for (int d = 0; d < 9; ++d) EXPECT_GT(ramp_weight(d, 8), ramp_weight(d + 1, 8)) << d;
  // Zero slope at both ends: the first and last steps are small against the middle ones.
  EXPECT_LT(1.0f - ramp_weight(1, 8), 0.05f);
  EXPECT_LT(ramp_weight(8, 8), 0.05f);
}

// One frame needs a correction (THANK-YOU's turn at the end of its path): the ramped series
// holds that frame's full correction and eases in and out with no kink, at the peak included.
// The linear tent this replaced turned round at the peak by 2/(radius+1) of the correction per
// frame (0.22 of it over 8 frames; the wrist reversed, 94 mm change of step).
TEST(SynthesisFrameCorrections, ASingleFramesCorrectionEasesInAndOutWithoutAKink) {
  const int n = 41, peak = 20, radius = 8;
  std::vector<float> fix(n, 0.0f);
  fix[peak] = 1.0f;
  std::vector<float> s = ramp_scalars(fix, radius);
  EXPECT_FLOAT_EQ(s[peak], 1.0f);
  EXPECT_EQ(s[peak - radius - 1], 0.0f);
  EXPECT_EQ(s[peak + radius + 1], 0.0f);
  EXPECT_LT(max_second_difference(s, [](float x) { return std::fabs(x); }), 0.1f);

  std::vector<glm::vec3> push(n, glm::vec3(0.0f));
  push[peak] = glm::vec3(0.0f, 0.0f, 0.05f);
  std::vector<glm::vec3> p = ramp_offsets(push, radius);
  EXPECT_FLOAT_EQ(p[peak].z, 0.05f);
  EXPECT_LT(max_second_difference(p, [](const glm::vec3& v) { return glm::length(v); }), 0.1f * 0.05f);

  std::vector<glm::quat> turn(n, glm::quat(1, 0, 0, 0));
  turn[peak] = glm::angleAxis(0.6f, glm::vec3(0, 1, 0));
  std::vector<glm::quat> q = ramp_turns(turn, radius);
  std::vector<float> angle(n);
  for (int f = 0; f < n; ++f) angle[f] = rotation_angle(q[f]);
  EXPECT_NEAR(angle[peak], 0.6f, 1e-4f);
  EXPECT_NEAR(angle[peak + radius + 1], 0.0f, 1e-4f);
  EXPECT_LT(max_second_difference(angle, [](float x) { return std::fabs(x); }), 0.1f * 0.6f);
}

TEST(SynthesisFrameCorrections, EveryFrameKeepsAtLeastItsOwnCorrection) {
  std::vector<float> fix = {0.0f, 0.3f, 0.1f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f,
                            0.0f, 0.0f, 0.9f, 0.2f, 0.0f, 0.5f, 0.0f, 0.0f, 0.0f, 0.0f};
  std::vector<float> s = ramp_scalars(fix, 8);
  for (size_t f = 0; f < fix.size(); ++f) EXPECT_GE(s[f], fix[f]) << f;
}

// Neighbouring pushes that point different ways (LOOK on the project avatar: the hand pushed
// out of the head by 91 mm at the key pose and 110 mm two frames into the movement, about 50
// degrees apart): the ramped push hands over from one to the other without a jump. Taking the
// largest alone switched direction between two frames and moved the target 58 mm at once.
TEST(SynthesisFrameCorrections, PushesThatPointDifferentWaysHandOverWithoutAJump) {
  const glm::vec3 a = 0.091f * glm::normalize(glm::vec3(0.8f, 0.15f, 0.58f));
  const glm::vec3 b = 0.110f * glm::normalize(glm::vec3(1.0f, 0.0f, -0.05f));
  std::vector<glm::vec3> push(24, glm::vec3(0.0f));
  for (int f = 0; f <= 3; ++f) push[f] = a;
  push[5] = b;
  std::vector<glm::vec3> r = ramp_offsets(push, 8);
  float max_step = 0.0f;
  for (size_t f = 1; f < r.size(); ++f) max_step = std::max(max_step, glm::length(r[f] - r[f - 1]));
  EXPECT_LT(max_step, 0.02f);
  // Every frame is still pushed at least as far as it asked.
  for (size_t f = 0; f < r.size(); ++f) EXPECT_GE(glm::length(r[f]) + 1e-6f, glm::length(push[f])) << f;
  // Opposite pushes have no direction to blend: the larger one is taken.
  std::vector<glm::vec3> opposite(3, glm::vec3(0.0f));
  opposite[0] = glm::vec3(0.03f, 0.0f, 0.0f);
  opposite[1] = glm::vec3(-0.03f, 0.0f, 0.0f);
  std::vector<glm::vec3> o = ramp_offsets(opposite, 8);
  EXPECT_NEAR(glm::length(o[0]), 0.03f, 1e-6f);
  EXPECT_NEAR(glm::length(o[1]), 0.03f, 1e-6f);
}

// A depth landscape measured on TELL's elbow leaving the chin (reference rig, second round):
// at swivel offsets -0.5..-0.1 and +0.2..+0.6 the arm is clear, at 0 and +0.1 it is 8-10 mm in.
float tell_depth(float offset) {
  const int k = static_cast<int>(std::lround(offset * 10.0f));
  if (k <= -6) return 0.0048f;
  if (k <= -1) return 0.0f;
  if (k <= 1) return 0.009f;
  return k <= 6 ? 0.0f : 0.001f;
}

TEST(SynthesisFrameCorrections, TheNearestClearSwivelKeepsToThePreferredSide) {
  auto depth = [](float offset, bool* usable) {
    *usable = true;
    return tell_depth(offset);
  };
  // No preference: the nearest (-0.1).
  SwivelChoice none = nearest_clear_swivel(0.0095f, 0.002f, 0.0f, 0.0f, depth);
  EXPECT_NEAR(none.offset_rad, -0.1f, 1e-5f);
  EXPECT_EQ(none.depth_m, 0.0f);
  // Earlier rounds turned this elbow up (+): +0.2, one step further but the same way as the
  // neighbours' fixes (the nearest flipped the sign between two frames: 0.3 rad in one frame).
  SwivelChoice up = nearest_clear_swivel(0.0095f, 0.002f, 1.0f, 0.0f, depth);
  EXPECT_NEAR(up.offset_rad, 0.2f, 1e-5f);
  SwivelChoice down = nearest_clear_swivel(0.0095f, 0.002f, -1.0f, 0.0f, depth);
  EXPECT_NEAR(down.offset_rad, -0.1f, 1e-5f);
  // The preferred side only while it is at most kPreferSlackSteps further than the other.
  auto far_up = [](float offset, bool* usable) {
    *usable = true;
    const int k = static_cast<int>(std::lround(offset * 10.0f));
    return k == -1 || k >= 1 + kPreferSlackSteps + 1 ? 0.0f : 0.01f;
  };
  EXPECT_NEAR(nearest_clear_swivel(0.01f, 0.002f, 1.0f, 0.0f, far_up).offset_rad, -0.1f, 1e-5f);
}

TEST(SynthesisFrameCorrections, ASwivelSideChosenForARunIsTheOnlySideSearched) {
  // The - side clears at -0.1, the + side only gains (4 mm at +0.7): a run given the + side
  // (sign_motion.cpp) keeps to it, clear or not; a run given the - side takes -0.1.
  auto depth = [](float offset, bool* usable) {
    *usable = true;
    const int k = static_cast<int>(std::lround(offset * 10.0f));
    return k == -1 ? 0.0f : k == 7 ? 0.004f : 0.009f;
  };
  EXPECT_NEAR(nearest_clear_swivel(0.009f, 0.002f, 1.0f, 0.0f, depth).offset_rad, -0.1f, 1e-5f);
  SwivelChoice up = nearest_clear_swivel(0.009f, 0.002f, 1.0f, 0.0f, depth, true);
  EXPECT_NEAR(up.offset_rad, 0.7f, 1e-5f);
  EXPECT_NEAR(up.depth_m, 0.004f, 1e-7f);
  EXPECT_NEAR(nearest_clear_swivel(0.009f, 0.002f, -1.0f, 0.0f, depth, true).offset_rad, -0.1f, 1e-5f);
  // Nothing on the forced side gains: no fix (the other side's clear offset is not taken).
  auto only_down = [](float offset, bool* usable) {
    *usable = true;
    return offset < 0.0f ? 0.0f : 0.009f;
  };
  EXPECT_EQ(nearest_clear_swivel(0.009f, 0.002f, 1.0f, 0.0f, only_down, true).offset_rad, 0.0f);
}

TEST(SynthesisFrameCorrections, AnUnusableSwivelIsSkippedAndWithoutAClearOneTheShallowestWinsIfItGainsEnough) {
  // +0.1 would clear but loses the touch: skipped, -0.2 is taken.
  auto depth = [](float offset, bool* usable) {
    const int k = static_cast<int>(std::lround(offset * 10.0f));
    *usable = k != 1;
    return k == 1 || k == -2 ? 0.0f : 0.01f;
  };
  EXPECT_NEAR(nearest_clear_swivel(0.01f, 0.002f, 0.0f, 0.0f, depth).offset_rad, -0.2f, 1e-5f);
  // Nothing clears: the shallowest (+0.7, 4 mm) wins; nothing better than the base: offset 0.
  auto never = [](float offset, bool* usable) {
    *usable = true;
    return std::fabs(offset - 0.7f) < 1e-3f ? 0.004f : 0.009f;
  };
  SwivelChoice c = nearest_clear_swivel(0.009f, 0.002f, 0.0f, 0.0f, never);
  EXPECT_NEAR(c.offset_rad, 0.7f, 1e-5f);
  EXPECT_NEAR(c.depth_m, 0.004f, 1e-7f);
  // On a path, a gain under min_gain_m is no fix (THANK-YOU: +0.1 rad gaining 0.1 mm at one
  // frame, +0.6 gaining 0.4 mm at the next); a clear offset is a fix whatever it gains.
  EXPECT_EQ(nearest_clear_swivel(0.009f, 0.002f, 0.0f, 0.006f, never).offset_rad, 0.0f);
  EXPECT_NEAR(nearest_clear_swivel(0.009f, 0.002f, 0.0f, 0.004f, never).offset_rad, 0.7f, 1e-5f);
  auto just_clear = [](float offset, bool* usable) {
    *usable = true;
    return offset > 0.25f ? 0.0015f : 0.0025f;
  };
  EXPECT_NEAR(nearest_clear_swivel(0.0025f, 0.002f, 0.0f, 0.001f, just_clear).offset_rad, 0.3f, 1e-5f);
  auto worse = [](float, bool* usable) {
    *usable = true;
    return 0.02f;
  };
  SwivelChoice w = nearest_clear_swivel(0.009f, 0.002f, 1.0f, 0.0f, worse);
  EXPECT_EQ(w.offset_rad, 0.0f);
  EXPECT_EQ(w.depth_m, 0.009f);
}

}  // namespace
}  // namespace sw::synthesis
