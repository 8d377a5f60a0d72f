// ClipSamplingJob: frames are hit exactly, in-between times slerp/lerp, time is clamped, rest
// translations are kept except the root's, morph channels are routed, and every invalid
// configuration is refused without touching the output.
#include "playback/clip_sampling_job.h"

#include <cmath>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>

namespace {

using sw::math::Transform;
using sw::playback::ClipSamplingJob;
using sw::synthesis::Clip;

sw::skeleton::Skeleton two_joints() {
  sw::skeleton::Skeleton s;
  s.joints.push_back({"hips", -1, Transform{}});
  Transform child;
  child.translation = glm::vec3(0.0f, 0.5f, 0.0f);
  s.joints.push_back({"spine", 0, child});
  return s;
}

// Two frames at 10 fps: spine turns 0 -> 90 degrees about Y, root moves 1 m in X, one morph 0 -> 1.
Clip two_frame_clip() {
  Clip c;
  c.fps = 10.0f;
  c.frame_count = 2;
  c.joint_names = {"hips", "spine"};
  c.morph_names = {"jawOpen"};
  const glm::quat identity(1.0f, 0.0f, 0.0f, 0.0f);
  const glm::quat quarter = glm::angleAxis(glm::radians(90.0f), glm::vec3(0.0f, 1.0f, 0.0f));
  c.rotations = {identity, identity, identity, quarter};
  c.root_translation = {glm::vec3(0.0f), glm::vec3(1.0f, 0.0f, 0.0f)};
  c.morph_weights = {0.0f, 1.0f};
  return c;
}

struct Fixture {
  sw::skeleton::Skeleton skeleton = two_joints();
  Clip clip = two_frame_clip();
  std::vector<int> clip_to_morph = {1};
  std::vector<Transform> locals = std::vector<Transform>(2);
  std::vector<float> morphs = std::vector<float>(2, -1.0f);
  ClipSamplingJob job() {
    ClipSamplingJob j;
    j.clip = &clip;
    j.skeleton = &skeleton;
    j.clip_to_morph = clip_to_morph;
    j.output_locals = locals;
    j.output_morph_weights = morphs;
    return j;
  }
};

float angle_deg(const glm::quat& q) { return glm::degrees(glm::angle(q)); }

}  // namespace

TEST(ClipSamplingJob, HalfwayInterpolatesRotationTranslationAndMorph) {
  Fixture f;
  ClipSamplingJob job = f.job();
  job.time_s = 0.05;  // half a frame at 10 fps
  ASSERT_TRUE(job.run());
  EXPECT_NEAR(angle_deg(f.locals[1].rotation), 45.0f, 1e-3f);
  EXPECT_NEAR(f.locals[0].translation.x, 0.5f, 1e-6f);
  EXPECT_NEAR(f.locals[1].translation.y, 0.5f, 1e-6f) << "non-root joints keep their rest translation";
  EXPECT_NEAR(f.morphs[1], 0.5f, 1e-6f);
  EXPECT_EQ(f.morphs[0], -1.0f) << "an avatar morph no clip channel drives is untouched";
}

TEST(ClipSamplingJob, FramesAreHitExactlyAndTimeIsClamped) {
  Fixture f;
  ClipSamplingJob job = f.job();
  job.time_s = 0.1;
  ASSERT_TRUE(job.run());
  EXPECT_NEAR(angle_deg(f.locals[1].rotation), 90.0f, 1e-3f);
  job.time_s = 5.0;
  ASSERT_TRUE(job.run());
  EXPECT_NEAR(angle_deg(f.locals[1].rotation), 90.0f, 1e-3f);
  job.time_s = -3.0;
  ASSERT_TRUE(job.run());
  EXPECT_NEAR(angle_deg(f.locals[1].rotation), 0.0f, 1e-3f);
  EXPECT_NEAR(f.locals[0].translation.x, 0.0f, 1e-6f);
}

TEST(ClipSamplingJob, TakesTheShortArcBetweenOppositeSignQuaternions) {
  Fixture f;
  // q and -q are the same rotation; a naive lerp would pass through a zero quaternion.
  f.clip.rotations[3] = -f.clip.rotations[1];
  ClipSamplingJob job = f.job();
  job.time_s = 0.05;
  ASSERT_TRUE(job.run());
  EXPECT_NEAR(angle_deg(f.locals[1].rotation), 0.0f, 1e-2f);
}

TEST(ClipSamplingJob, RefusesEveryInvalidConfigurationWithoutWriting) {
  auto refused = [](auto&& mutate) {
    Fixture f;
    ClipSamplingJob job = f.job();
    mutate(f, job);
    const float before = f.locals[0].translation.x;
    EXPECT_FALSE(job.validate().empty());
    EXPECT_FALSE(job.run());
    EXPECT_EQ(f.locals[0].translation.x, before);
  };
  refused([](Fixture&, ClipSamplingJob& j) { j.clip = nullptr; });
  refused([](Fixture&, ClipSamplingJob& j) { j.skeleton = nullptr; });
  refused([](Fixture& f, ClipSamplingJob&) { f.clip.joint_names.pop_back(); });
  refused([](Fixture& f, ClipSamplingJob&) { f.clip.frame_count = 0; });
  refused([](Fixture& f, ClipSamplingJob&) { f.clip.fps = 0.0f; });
  refused([](Fixture& f, ClipSamplingJob&) { f.clip.rotations.pop_back(); });
  refused([](Fixture& f, ClipSamplingJob&) { f.clip.root_translation.pop_back(); });
  refused([](Fixture& f, ClipSamplingJob&) { f.clip.morph_weights.pop_back(); });
  refused([](Fixture& f, ClipSamplingJob& j) { f.clip_to_morph = {7}; j.clip_to_morph = f.clip_to_morph; });
  refused([](Fixture& f, ClipSamplingJob& j) { f.clip_to_morph = {0, 1}; j.clip_to_morph = f.clip_to_morph; });
  refused([](Fixture& f, ClipSamplingJob& j) { j.output_locals = sw::math::Span<Transform>(f.locals.data(), 1); });
  refused([](Fixture&, ClipSamplingJob& j) { j.time_s = std::nan(""); });
}
