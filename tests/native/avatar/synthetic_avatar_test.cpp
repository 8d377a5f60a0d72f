// Tests for avatar/synthetic_avatar.h: deterministic bytes, a loadable humanoid, option effects.
#include "avatar/synthetic_avatar.h"

#include <gtest/gtest.h>

#include "avatar/gltf_loader.h"
#include "skeleton/synthetic_humanoid.h"

namespace sw::avatar {
namespace {

TEST(SyntheticAvatar, SameBytesEveryTime) {
  EXPECT_EQ(make_synthetic_avatar_glb(), make_synthetic_avatar_glb());
}

TEST(SyntheticAvatar, IsASkinnedHumanoidWithinBudget) {
  const std::vector<std::uint8_t> glb = make_synthetic_avatar_glb();
  const LoadResult r = load_avatar(glb.data(), glb.size());
  ASSERT_TRUE(r.ok()) << r.message();
  EXPECT_LE(r.avatar.mesh.indices.size() / 3, 30000u);
  EXPECT_GE(r.avatar.mesh.positions.size(), 3000u);
  // The tallest point is the top of the head, about 1.72 m.
  float top = 0.0f;
  for (const glm::vec3& p : r.avatar.mesh.positions) top = std::max(top, p.y);
  EXPECT_NEAR(top, SyntheticAvatarGeometry::kHeadCentreY + 0.11f, 1e-3f);
}

// One body for every test figure: the glTF avatar's joints are the synthetic humanoid's (with
// finger metacarpals), same names, parents and bind positions.
TEST(SyntheticAvatar, HasTheSyntheticHumanoidsSkeleton) {
  const std::vector<std::uint8_t> glb = make_synthetic_avatar_glb();
  const LoadResult r = load_avatar(glb.data(), glb.size());
  ASSERT_TRUE(r.ok()) << r.message();
  const skeleton::Skeleton s = skeleton::make_synthetic_humanoid({/*finger_metacarpals=*/true});
  const std::vector<glm::vec3> rest = skeleton::rest_positions(s);
  ASSERT_EQ(r.avatar.skeleton.joint_count(), s.joint_count());
  for (std::size_t i = 0; i < s.joints.size(); ++i) {
    const int j = r.avatar.skeleton.find(s.joints[i].name);
    ASSERT_GE(j, 0) << s.joints[i].name;
    const glm::vec3 bind = glm::inverse(r.avatar.inverse_bind[static_cast<std::size_t>(j)])[3];
    EXPECT_NEAR(glm::length(bind - rest[i]), 0.0f, 1e-5f) << s.joints[i].name;
  }
}

TEST(SyntheticAvatar, OptionsChangeTheModel) {
  SyntheticAvatarOptions no_morphs;
  no_morphs.morphs = false;
  EXPECT_TRUE(make_synthetic_avatar_model(no_morphs).meshes[0].primitives[0].targets.empty());
  SyntheticAvatarOptions mixamo;
  mixamo.names = SyntheticAvatarOptions::Names::Mixamo;
  const tinygltf::Model m = make_synthetic_avatar_model(mixamo);
  EXPECT_EQ(m.nodes[static_cast<std::size_t>(synthetic_avatar_node(m, "leftLowerArm"))].name, "mixamorig:LeftForeArm");
  SyntheticAvatarOptions omit;
  omit.omit_joints = {"leftHand"};
  EXPECT_EQ(synthetic_avatar_node(make_synthetic_avatar_model(omit), "leftIndexTip"), -1);
}

}  // namespace
}  // namespace sw::avatar
