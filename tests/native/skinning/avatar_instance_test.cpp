// Tests for skinning/avatar_instance.h: the whole pose -> skinned mesh pipeline.
#include "skinning/avatar_instance.h"

#include <limits>

#include <gtest/gtest.h>
#include <glm/gtc/quaternion.hpp>

#include "avatar/gltf_loader.h"
#include "avatar/synthetic_avatar.h"
#include "skeleton/humanoid_names.h"

namespace sw::skinning {
namespace {

avatar::Avatar load_humanoid() {
  const std::vector<std::uint8_t> glb = avatar::make_synthetic_avatar_glb();
  avatar::LoadResult r = avatar::load_avatar(glb.data(), glb.size());
  EXPECT_TRUE(r.ok()) << r.message();
  return r.avatar;
}

TEST(AvatarInstance, RestUpdateReproducesTheBindMesh) {
  const avatar::Avatar a = load_humanoid();
  AvatarInstance instance(a);
  ASSERT_TRUE(instance.update()) << instance.error();
  ASSERT_EQ(instance.positions().size(), 3 * a.mesh.positions.size());
  for (std::size_t v = 0; v < a.mesh.positions.size(); ++v)
    for (int k = 0; k < 3; ++k)
      ASSERT_NEAR(instance.positions()[3 * v + static_cast<std::size_t>(k)], a.mesh.positions[v][k],
                  1e-5f);
}

TEST(AvatarInstance, MorphWeightsMoveTheMeshBeforeSkinning) {
  const avatar::Avatar a = load_humanoid();
  AvatarInstance instance(a);
  ASSERT_EQ(instance.morph_weights().size(), a.morphs.size());
  instance.morph_weights()[0] = 1.0f;  // jawOpen: chin vertices 1 cm down
  ASSERT_TRUE(instance.update());
  int moved = 0;
  for (std::size_t v = 0; v < a.mesh.positions.size(); ++v) {
    const glm::vec3 expected = a.mesh.positions[v] + a.morphs[0].position_deltas[v];
    for (int k = 0; k < 3; ++k)
      ASSERT_NEAR(instance.positions()[3 * v + static_cast<std::size_t>(k)], expected[k], 1e-5f);
    if (a.morphs[0].position_deltas[v] != glm::vec3(0.0f)) ++moved;
  }
  EXPECT_GT(moved, 10);
  instance.morph_weights()[0] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_FALSE(instance.update());
  EXPECT_NE(instance.error().find("not finite"), std::string::npos);
}

TEST(AvatarInstance, PosedSimdAndScalarAgree) {
  const avatar::Avatar a = load_humanoid();
  AvatarInstance simd(a), scalar(a);
  const int shoulder = a.canonical_to_joint[skeleton::kRightUpperArm];
  for (AvatarInstance* i : {&simd, &scalar}) {
    i->locals()[static_cast<std::size_t>(shoulder)].rotation =
        glm::angleAxis(1.0f, glm::vec3(0, 0, 1));
    i->morph_weights()[1] = 0.5f;
  }
  ASSERT_TRUE(simd.update(SkinningPath::Simd));
  ASSERT_TRUE(scalar.update(SkinningPath::Scalar));
  for (std::size_t k = 0; k < simd.positions().size(); ++k) {
    ASSERT_NEAR(simd.positions()[k], scalar.positions()[k], 1e-5f);
    ASSERT_NEAR(simd.normals()[k], scalar.normals()[k], 1e-5f);
  }
}

TEST(AvatarInstance, AnchorsRideTheirJoint) {
  avatar::Avatar a = load_humanoid();
  const int hand = a.canonical_to_joint[skeleton::kLeftHand];
  avatar::Anchor anchor;
  anchor.name = "test/palm";
  anchor.joint = hand;
  const glm::vec3 wrist(0.72f, 1.43f, 0.0f);  // the synthetic humanoid's left wrist, bind pose
  const glm::vec3 bind_point = wrist + glm::vec3(0.03f, -0.03f, 0.0f);
  anchor.offset =
      glm::vec3(a.inverse_bind[static_cast<std::size_t>(hand)] * glm::vec4(bind_point, 1.0f));
  anchor.normal = {0, -1, 0};
  a.anchors.push_back(anchor);
  AvatarInstance instance(a);
  ASSERT_TRUE(instance.update());
  EXPECT_NEAR(instance.anchor_positions()[0], bind_point.x, 1e-5f);
  EXPECT_NEAR(instance.anchor_positions()[1], bind_point.y, 1e-5f);
  // Turn the wrist 90° about +Z: the palm-down normal turns to +X, the point swings round the
  // wrist.
  instance.locals()[static_cast<std::size_t>(hand)].rotation =
      glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 0, 1));
  ASSERT_TRUE(instance.update());
  EXPECT_NEAR(instance.anchor_normals()[0], 1.0f, 1e-5f);
  EXPECT_NEAR(instance.anchor_positions()[0], wrist.x + 0.03f, 1e-5f);
  EXPECT_NEAR(instance.anchor_positions()[1], wrist.y + 0.03f, 1e-5f);
  instance.reset_pose();
  ASSERT_TRUE(instance.update());
  EXPECT_NEAR(instance.anchor_positions()[0], bind_point.x, 1e-5f);
}

}  // namespace
}  // namespace sw::skinning
