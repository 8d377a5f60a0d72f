#include "face/face_track.h"

#include <gtest/gtest.h>

#include "face/channel_set.h"

namespace sw::face {
namespace {

// hips -> spine -> neck -> head -> leftEye / rightEye, identity rest rotations.
skeleton::Skeleton small_head_skeleton() {
  skeleton::Skeleton s;
  auto add = [&](const char* name, int parent, glm::vec3 t) {
    skeleton::Joint j;
    j.name = name;
    j.parent = parent;
    j.rest.translation = t;
    s.joints.push_back(j);
  };
  add("hips", -1, {0, 1.0f, 0});
  add("spine", 0, {0, 0.2f, 0});
  add("neck", 1, {0, 0.3f, 0});
  add("head", 2, {0, 0.1f, 0});
  add("leftEye", 3, {0.03f, 0.07f, 0.08f});
  add("rightEye", 3, {-0.03f, 0.07f, 0.08f});
  return s;
}

synthesis::Clip identity_clip(const skeleton::Skeleton& s, int frames) {
  synthesis::Clip clip;
  clip.fps = 30.0f;
  clip.frame_count = frames;
  for (const auto& j : s.joints) clip.joint_names.push_back(j.name);
  clip.rotations.assign(std::size_t(frames) * s.joints.size(), glm::quat(1, 0, 0, 0));
  clip.root_translation.assign(std::size_t(frames), glm::vec3(0, 1, 0));
  return clip;
}

float weight(const synthesis::Clip& clip, int frame, const char* channel) {
  return clip.morph_weights[std::size_t(frame) * std::size_t(kChannelCount) +
                            std::size_t(channel_index(channel))];
}

TEST(FaceTrack, FillsEveryChannelForEveryFrame) {
  const auto s = small_head_skeleton();
  auto clip = identity_clip(s, 60);
  ASSERT_TRUE(add_face_tracks(clip, s, face_rig_by_names(s), {}, FaceOptions{}));
  EXPECT_EQ(clip.morph_count(), kChannelCount);
  EXPECT_EQ(clip.morph_weights.size(), std::size_t(60 * kChannelCount));
  for (float w : clip.morph_weights) {
    EXPECT_GE(w, 0.0f);
    EXPECT_LE(w, 1.0f);
  }
}

TEST(FaceTrack, RejectsAClipThatDoesNotMatchTheSkeleton) {
  const auto s = small_head_skeleton();
  auto clip = identity_clip(s, 10);
  clip.joint_names.pop_back();
  EXPECT_FALSE(add_face_tracks(clip, s, face_rig_by_names(s), {}, FaceOptions{}));
  EXPECT_TRUE(clip.morph_weights.empty());
}

TEST(FaceTrack, EmotionReachesItsTargetThroughIntermediateStates) {
  const auto s = small_head_skeleton();
  auto clip = identity_clip(s, 90);
  FaceCue sign;
  sign.start_s = 0.0;
  sign.end_s = 3.0;
  sign.nonmanual.expression = "happy";
  sign.nonmanual.expression_intensity = 1.0f;
  FaceOptions options;
  options.blinks = false;
  ASSERT_TRUE(add_face_tracks(clip, s, face_rig_by_names(s), {sign}, options));
  EXPECT_LT(weight(clip, 0, "mouthSmileLeft"), 0.05f);  // starts neutral
  const float early = weight(clip, 3, "mouthSmileLeft");
  EXPECT_GT(early, 0.05f);                                       // moving...
  EXPECT_LT(early, 0.8f);                                        // ...but not there yet (seed 003)
  EXPECT_NEAR(weight(clip, 89, "mouthSmileLeft"), 0.9f, 0.05f);  // settled at the preset
}

TEST(FaceTrack, MouthingAndBrowsFollowTheSign) {
  const auto s = small_head_skeleton();
  auto clip = identity_clip(s, 60);
  FaceCue question;
  question.start_s = 0.0;
  question.end_s = 2.0;
  question.nonmanual.mouthing = "mama";
  question.nonmanual.eyebrows = "up";
  FaceOptions options;
  options.blinks = false;
  ASSERT_TRUE(add_face_tracks(clip, s, face_rig_by_names(s), {question}, options));
  float pp = 0.0f, aa = 0.0f;
  for (int f = 0; f < 60; ++f) {
    pp = std::max(pp, weight(clip, f, "viseme_PP"));
    aa = std::max(aa, weight(clip, f, "viseme_aa"));
  }
  EXPECT_GT(pp, 0.7f);
  EXPECT_GT(aa, 0.9f);
  EXPECT_GT(weight(clip, 30, "browInnerUp"), 0.7f);
  EXPECT_LT(weight(clip, 0, "browInnerUp"), 0.05f);
  // The mouth rests during the final hold of the sign.
  EXPECT_LT(weight(clip, 55, "viseme_aa"), 1e-6f);
}

TEST(FaceTrack, HeadShakeKeepsTheEyesOnTheAddressee) {
  const auto s = small_head_skeleton();
  auto clip = identity_clip(s, 60);
  FaceCue no;
  no.start_s = 0.0;
  no.end_s = 2.0;
  no.nonmanual.head = "shake";
  ASSERT_TRUE(add_face_tracks(clip, s, face_rig_by_names(s), {no}, FaceOptions{}));
  const int head = s.find("head"), eye = s.find("leftEye");
  float largest_turn = 0.0f;
  for (int f = 0; f < 60; ++f) {
    const glm::quat* locals = clip.rotations.data() + std::size_t(f) * s.joints.size();
    largest_turn =
        std::max(largest_turn, 2.0f * std::acos(std::min(1.0f, std::fabs(locals[head].w))));
    const glm::quat eye_world = locals[0] * locals[1] * locals[2] * locals[head] * locals[eye];
    const glm::vec3 looking = eye_world * glm::vec3(0, 0, 1);
    EXPECT_GT(looking.z, 0.999f) << "frame " << f;
  }
  EXPECT_GT(largest_turn, 0.1f);  // the head really turned
}

TEST(FaceTrack, BlinksHappenAtPauses) {
  const auto s = small_head_skeleton();
  auto clip = identity_clip(s, 90);
  FaceCue pause;
  pause.start_s = 1.5;
  pause.end_s = 2.0;
  pause.is_pause = true;
  ASSERT_TRUE(add_face_tracks(clip, s, face_rig_by_names(s), {pause}, FaceOptions{}));
  float lid = 0.0f;
  for (int f = 45; f < 55; ++f) lid = std::max(lid, weight(clip, f, "eyeBlinkLeft"));
  EXPECT_GT(lid, 0.9f);
}

}  // namespace
}  // namespace sw::face
