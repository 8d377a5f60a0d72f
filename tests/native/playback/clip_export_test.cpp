// Clip export: the BVH written from a clip reads back (foundation's reader) to the clip's own
// local rotations and root translation; the GLB is a well-formed glTF 2.0 container whose
// animation holds the clip's keyframes; a clip that does not fit the skeleton is an error value.
#include "playback/clip_export.h"

#include <cmath>
#include <cstring>
#include <string>

#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "skeleton/bvh.h"

namespace {

using sw::math::Transform;
using sw::synthesis::Clip;

sw::skeleton::Skeleton three_joints() {
  sw::skeleton::Skeleton s;
  Transform root;
  root.translation = glm::vec3(0.0f, 1.0f, 0.0f);
  s.joints.push_back({"hips", -1, root});
  Transform spine;
  spine.translation = glm::vec3(0.0f, 0.2f, 0.0f);
  s.joints.push_back({"spine", 0, spine});
  Transform arm;
  arm.translation = glm::vec3(0.3f, 0.1f, 0.0f);
  s.joints.push_back({"leftUpperArm", 1, arm});
  return s;
}

Clip turning_clip(int frames) {
  Clip c;
  c.fps = 30.0f;
  c.frame_count = frames;
  c.joint_names = {"hips", "spine", "leftUpperArm"};
  for (int f = 0; f < frames; ++f) {
    const float t = float(f) / float(frames - 1);
    c.rotations.push_back(glm::angleAxis(0.1f * t, glm::vec3(0, 1, 0)));
    c.rotations.push_back(glm::angleAxis(0.4f * t, glm::vec3(1, 0, 0)));
    c.rotations.push_back(glm::angleAxis(1.2f * t, glm::normalize(glm::vec3(0, 0.3f, 1))));
    c.root_translation.push_back(glm::vec3(0.05f * t, 1.0f, 0.0f));
  }
  return c;
}

float quat_distance_deg(const glm::quat& a, const glm::quat& b) {
  return glm::degrees(2.0f * std::acos(std::min(1.0f, std::abs(glm::dot(glm::normalize(a), glm::normalize(b))))));
}

}  // namespace

TEST(ClipExport, BvhReadsBackToTheClipPose) {
  const auto skeleton = three_joints();
  const Clip clip = turning_clip(12);
  std::string error;
  const sw::skeleton::Bvh bvh = sw::playback::clip_to_bvh(clip, skeleton, &error);
  ASSERT_TRUE(error.empty()) << error;
  const std::string text = sw::skeleton::write_bvh(bvh);
  const sw::skeleton::BvhReadResult back = sw::skeleton::read_bvh(text);
  ASSERT_TRUE(back.ok) << back.error.format();
  ASSERT_EQ(back.bvh.frame_count, clip.frame_count);
  EXPECT_NEAR(back.bvh.frame_time_s, 1.0 / 30.0, 1e-6);
  ASSERT_EQ(back.bvh.joints.size(), 3u);
  EXPECT_EQ(back.bvh.joints[2].name, "leftUpperArm");
  EXPECT_NEAR(back.bvh.joints[2].offset.x, 30.0, 1e-4) << "centimetres";
  std::vector<Transform> locals(3);
  for (int f = 0; f < clip.frame_count; ++f) {
    ASSERT_TRUE(sw::skeleton::frame_to_local(back.bvh, f, sw::playback::kBvhUnitToMetres, locals));
    for (int j = 0; j < 3; ++j) {
      EXPECT_LT(quat_distance_deg(locals[std::size_t(j)].rotation, clip.rotations[std::size_t(f * 3 + j)]), 1e-3f)
          << "frame " << f << " joint " << j;
    }
    EXPECT_NEAR(locals[0].translation.x, clip.root_translation[std::size_t(f)].x, 1e-6f);
  }
}

TEST(ClipExport, GlbIsAValidContainerWithTheClipKeyframes) {
  const auto skeleton = three_joints();
  const Clip clip = turning_clip(5);
  std::string error;
  const std::vector<std::uint8_t> glb = sw::playback::clip_to_glb(clip, skeleton, &error);
  ASSERT_TRUE(error.empty()) << error;
  ASSERT_GE(glb.size(), 28u);
  auto u32 = [&glb](std::size_t at) {
    std::uint32_t v;
    std::memcpy(&v, glb.data() + at, 4);
    return v;
  };
  EXPECT_EQ(std::string(glb.begin(), glb.begin() + 4), "glTF");
  EXPECT_EQ(u32(4), 2u);
  EXPECT_EQ(u32(8), glb.size());
  const std::uint32_t json_length = u32(12);
  EXPECT_EQ(json_length % 4, 0u);
  EXPECT_EQ(u32(16), 0x4E4F534Au);
  const auto gltf = nlohmann::json::parse(glb.begin() + 20, glb.begin() + 20 + json_length);
  const std::size_t bin_at = 20 + json_length;
  EXPECT_EQ(u32(bin_at + 4), 0x004E4942u);
  EXPECT_EQ(gltf["nodes"].size(), 3u);
  EXPECT_EQ(gltf["nodes"][1]["children"][0], 2);
  const auto& anim = gltf["animations"][0];
  EXPECT_EQ(anim["channels"].size(), 4u) << "a rotation per joint and the root translation";
  // The last keyframe of the arm's rotation is the clip's last arm rotation.
  const auto& sampler = anim["samplers"][2];
  const auto& input = gltf["accessors"][sampler["input"].get<int>()];
  EXPECT_EQ(input["count"], 5);
  EXPECT_NEAR(input["max"][0].get<double>(), 4.0 / 30.0, 1e-6);
  const auto& output = gltf["accessors"][sampler["output"].get<int>()];
  const auto& view = gltf["bufferViews"][output["bufferView"].get<int>()];
  float q[4];
  std::memcpy(q, glb.data() + bin_at + 8 + view["byteOffset"].get<std::size_t>() + 4 * 4 * 4, sizeof q);
  const glm::quat expected = clip.rotations[4 * 3 + 2];
  EXPECT_LT(quat_distance_deg(glm::quat(q[3], q[0], q[1], q[2]), expected), 1e-3f);
}

TEST(ClipExport, AClipForAnotherSkeletonIsAnErrorValue) {
  const auto skeleton = three_joints();
  Clip clip = turning_clip(4);
  clip.joint_names.pop_back();
  std::string error;
  EXPECT_TRUE(sw::playback::clip_to_bvh(clip, skeleton, &error).joints.empty());
  EXPECT_FALSE(error.empty());
  EXPECT_TRUE(sw::playback::clip_to_glb(clip, skeleton, &error).empty());
  EXPECT_FALSE(error.empty());
  Clip empty;
  empty.joint_names = {"hips", "spine", "leftUpperArm"};
  EXPECT_TRUE(sw::playback::clip_to_glb(empty, skeleton, &error).empty());
  EXPECT_FALSE(error.empty());
}
