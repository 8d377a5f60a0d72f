// The synthetic humanoid used by benchmarks and parity cases (skeleton/synthetic_humanoid.h).
#include "skeleton/synthetic_humanoid.h"

#include <gtest/gtest.h>

namespace sw::skeleton {
namespace {

TEST(SyntheticHumanoid, HasSixtyFiveValidVrmNamedJoints) {
  const Skeleton s = make_synthetic_humanoid();
  EXPECT_EQ(s.joint_count(), 65);
  EXPECT_EQ(s.validate(), "");
  for (const char* name :
       {"hips", "head", "leftHand", "rightLittleTip", "leftThumbMetacarpal", "rightToes"}) {
    EXPECT_GE(s.find(name), 0) << name;
  }
  // +X is the signer's left.
  EXPECT_GT(s.joints[static_cast<std::size_t>(s.find("leftUpperArm"))].rest.translation.x, 0.0f);
}

TEST(SyntheticHumanoid, FingerMetacarpalsAddEightJointsAndMoveNothing) {
  const Skeleton s65 = make_synthetic_humanoid();
  const Skeleton s73 = make_synthetic_humanoid({/*finger_metacarpals=*/true});
  EXPECT_EQ(s73.joint_count(), 73);
  EXPECT_EQ(s73.validate(), "");
  const auto parent_name = [](const Skeleton& s, const char* joint) {
    return s
        .joints[static_cast<std::size_t>(s.joints[static_cast<std::size_t>(s.find(joint))].parent)]
        .name;
  };
  EXPECT_EQ(parent_name(s73, "leftIndexProximal"), "leftIndexMetacarpal");
  EXPECT_EQ(parent_name(s65, "leftIndexProximal"), "leftHand");
  // Every joint of the 65 sits where the same joint of the 73 does (1.70 m figure, +Y up).
  const std::vector<glm::vec3> p65 = rest_positions(s65), p73 = rest_positions(s73);
  for (std::size_t i = 0; i < s65.joints.size(); ++i) {
    const int j = s73.find(s65.joints[i].name);
    ASSERT_GE(j, 0) << s65.joints[i].name;
    EXPECT_NEAR(glm::length(p65[i] - p73[static_cast<std::size_t>(j)]), 0.0f, 1e-6f)
        << s65.joints[i].name;
  }
  EXPECT_NEAR(p65[static_cast<std::size_t>(s65.find("head"))].y, 1.56f, 1e-6f);
  EXPECT_NEAR(p65[static_cast<std::size_t>(s65.find("leftHand"))].x, 0.72f, 1e-6f);
}

TEST(SyntheticHumanoid, PoseIsDeterministicAndSeedDependent) {
  const Skeleton s = make_synthetic_humanoid();
  const auto a = make_synthetic_pose(s, 42), b = make_synthetic_pose(s, 42),
             c = make_synthetic_pose(s, 43);
  ASSERT_EQ(a.size(), 65u);
  bool differs = false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].rotation, b[i].rotation);
    EXPECT_NEAR(glm::length(a[i].rotation), 1.0f, 1e-5f);
    differs = differs || a[i].rotation != c[i].rotation;
    EXPECT_EQ(a[i].translation, s.joints[i].rest.translation);
  }
  EXPECT_TRUE(differs);
}

TEST(SyntheticHumanoid, PoseDrawsAreSequencedPortably) {
  // Regression: the hash draws were once function arguments, whose evaluation order g++ and clang
  // (the WASM compiler) differ on, so native and WASM poses disagreed. Pin the first joint's
  // rotation for seed 1 as computed with the draws in statement order (x, y, z, angle).
  const Skeleton s = make_synthetic_humanoid();
  const math::Transform t = make_synthetic_pose(s, 1).front();
  const glm::vec3 axis = glm::axis(t.rotation);
  // The x draw comes first, so a reordering would permute these components.
  EXPECT_NEAR(glm::angle(t.rotation), 0.0296305f,
              1e-5f);  // from an independent Python model of the hash
  EXPECT_NEAR(axis.x, -0.198581f, 1e-4f);
}

}  // namespace
}  // namespace sw::skeleton
