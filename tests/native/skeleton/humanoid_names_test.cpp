// Tests for skeleton/humanoid_names.h: the canonical table and every alias convention.
#include "skeleton/humanoid_names.h"

#include <set>
#include <string>

#include <gtest/gtest.h>

namespace sw::skeleton {
namespace {

TEST(HumanoidNames, CanonicalNamesRoundTripAndAreUnique) {
  std::set<std::string_view> seen;
  for (int id = 0; id < kHumanoidJointCount; ++id) {
    const std::string_view name = humanoid_joint_name(id);
    ASSERT_FALSE(name.empty()) << id;
    EXPECT_TRUE(seen.insert(name).second) << name;
    EXPECT_EQ(canonical_joint_id(name), id) << name;
  }
  EXPECT_TRUE(humanoid_joint_name(-1).empty());
  EXPECT_TRUE(humanoid_joint_name(kHumanoidJointCount).empty());
  // VRM 1.0 humanoid (55 bones incl. thumbs' metacarpal) + 8 metacarpals + 10 tips.
  EXPECT_EQ(kHumanoidJointCount, 9 + 2 * 28 + 2 * 4);
}

TEST(HumanoidNames, CanonicalNamesAreCaseAndSeparatorTolerant) {
  EXPECT_EQ(canonical_joint_id("LeftUpperArm"), kLeftUpperArm);
  EXPECT_EQ(canonical_joint_id("left_upper_arm"), kLeftUpperArm);
  EXPECT_EQ(canonical_joint_id("UPPERCHEST"), kUpperChest);
  EXPECT_EQ(canonical_joint_id("right-index-tip"), kRightIndexTip);
  EXPECT_EQ(canonical_joint_id(""), -1);
  EXPECT_EQ(canonical_joint_id("hair_03"), -1);
  EXPECT_EQ(canonical_joint_id("Armature"), -1);
}

TEST(HumanoidNames, MixamoNames) {
  EXPECT_EQ(canonical_joint_id("mixamorig:Hips"), kHips);
  EXPECT_EQ(canonical_joint_id("mixamorig:Spine"), kSpine);
  EXPECT_EQ(canonical_joint_id("mixamorig:Spine1"), kChest);
  EXPECT_EQ(canonical_joint_id("mixamorig:Spine2"), kUpperChest);
  EXPECT_EQ(canonical_joint_id("mixamorig:LeftShoulder"), kLeftShoulder);
  EXPECT_EQ(canonical_joint_id("mixamorig:LeftArm"), kLeftUpperArm);
  EXPECT_EQ(canonical_joint_id("mixamorig:LeftForeArm"), kLeftLowerArm);
  EXPECT_EQ(canonical_joint_id("mixamorig:RightHand"), kRightHand);
  EXPECT_EQ(canonical_joint_id("mixamorig:LeftHandThumb1"), kLeftThumbMetacarpal);
  EXPECT_EQ(canonical_joint_id("mixamorig:LeftHandThumb2"), kLeftThumbProximal);
  EXPECT_EQ(canonical_joint_id("mixamorig:LeftHandThumb3"), kLeftThumbDistal);
  EXPECT_EQ(canonical_joint_id("mixamorig:LeftHandThumb4"), kLeftThumbTip);
  EXPECT_EQ(canonical_joint_id("mixamorig:LeftHandIndex1"), kLeftIndexProximal);
  EXPECT_EQ(canonical_joint_id("mixamorig:LeftHandIndex2"), kLeftIndexIntermediate);
  EXPECT_EQ(canonical_joint_id("mixamorig:RightHandPinky3"), kRightLittleDistal);
  EXPECT_EQ(canonical_joint_id("mixamorig:RightHandPinky4"), kRightLittleTip);
  EXPECT_EQ(canonical_joint_id("mixamorig_LeftUpLeg"), kLeftUpperLeg);
  EXPECT_EQ(canonical_joint_id("mixamorigLeftLeg"), kLeftLowerLeg);
  EXPECT_EQ(canonical_joint_id("mixamorig:LeftToeBase"), kLeftToes);
  EXPECT_EQ(canonical_joint_id("mixamorig:HeadTop_End"), -1);
}

TEST(HumanoidNames, Vrm0ThumbsShiftByOneSegment) {
  EXPECT_EQ(canonical_joint_id_vrm0("leftThumbProximal"), kLeftThumbMetacarpal);
  EXPECT_EQ(canonical_joint_id_vrm0("leftThumbIntermediate"), kLeftThumbProximal);
  EXPECT_EQ(canonical_joint_id_vrm0("leftThumbDistal"), kLeftThumbDistal);
  EXPECT_EQ(canonical_joint_id_vrm0("rightIndexProximal"), kRightIndexProximal);
  EXPECT_EQ(canonical_joint_id_vrm0("upperChest"), kUpperChest);
  // Read as VRM 1.0, the same name is the proximal phalanx.
  EXPECT_EQ(canonical_joint_id("leftThumbProximal"), kLeftThumbProximal);
}

TEST(HumanoidNames, BvhAndBipedAndUnrealNames) {
  // CMU ASF-derived BVH.
  EXPECT_EQ(canonical_joint_id("lhumerus"), kLeftUpperArm);
  EXPECT_EQ(canonical_joint_id("rradius"), kRightLowerArm);
  EXPECT_EQ(canonical_joint_id("lhand"), kLeftHand);
  EXPECT_EQ(canonical_joint_id("lclavicle"), kLeftShoulder);
  EXPECT_EQ(canonical_joint_id("rfemur"), kRightUpperLeg);
  EXPECT_EQ(canonical_joint_id("lowerback"), kSpine);
  EXPECT_EQ(canonical_joint_id("thorax"), kUpperChest);
  // cgspeed BVH.
  EXPECT_EQ(canonical_joint_id("Hips"), kHips);
  EXPECT_EQ(canonical_joint_id("Spine1"), kChest);
  EXPECT_EQ(canonical_joint_id("LeftArm"), kLeftUpperArm);
  EXPECT_EQ(canonical_joint_id("LeftForeArm"), kLeftLowerArm);
  EXPECT_EQ(canonical_joint_id("LeftCollar"), kLeftShoulder);
  EXPECT_EQ(canonical_joint_id("RightElbow"), kRightLowerArm);
  EXPECT_EQ(canonical_joint_id("RightWrist"), kRightHand);
  // 3ds Max Biped.
  EXPECT_EQ(canonical_joint_id("Bip01 Pelvis"), kHips);
  EXPECT_EQ(canonical_joint_id("Bip01 L UpperArm"), kLeftUpperArm);
  EXPECT_EQ(canonical_joint_id("Bip01 R Forearm"), kRightLowerArm);
  EXPECT_EQ(canonical_joint_id("Bip01 L Finger0"), kLeftThumbMetacarpal);
  EXPECT_EQ(canonical_joint_id("Bip01 L Finger11"), kLeftIndexIntermediate);
  EXPECT_EQ(canonical_joint_id("Bip01 R Finger42"), kRightLittleDistal);
  EXPECT_EQ(canonical_joint_id("Bip01 R Finger2Nub"), kRightMiddleTip);
  // Unreal mannequin and Blender/Rigify suffixes.
  EXPECT_EQ(canonical_joint_id("upperarm_l"), kLeftUpperArm);
  EXPECT_EQ(canonical_joint_id("lowerarm_r"), kRightLowerArm);
  EXPECT_EQ(canonical_joint_id("index_01_l"), kLeftIndexProximal);
  EXPECT_EQ(canonical_joint_id("thumb_01_r"), kRightThumbMetacarpal);
  EXPECT_EQ(canonical_joint_id("index_metacarpal_l"), kLeftIndexMetacarpal);
  EXPECT_EQ(canonical_joint_id("spine_03"), kUpperChest);
  EXPECT_EQ(canonical_joint_id("DEF-forearm.L"), kLeftLowerArm);
  EXPECT_EQ(canonical_joint_id("DEF-f_ring.02.R"), kRightRingIntermediate);
  EXPECT_EQ(canonical_joint_id("DEF-palm.04.L"), kLeftLittleMetacarpal);
  EXPECT_EQ(canonical_joint_id("Hand.R"), kRightHand);
  EXPECT_EQ(canonical_joint_id("Armature|LeftHand"), kLeftHand);
}

TEST(HumanoidNames, WholeRigMappingDetectsVrm0ThumbsAndIsInjective) {
  const std::vector<std::string> vrm0 = {"leftThumbProximal", "leftThumbIntermediate",
                                         "leftThumbDistal", "hips"};
  const std::vector<int> ids = map_humanoid_names(vrm0);
  EXPECT_EQ(ids,
            (std::vector<int>{kLeftThumbMetacarpal, kLeftThumbProximal, kLeftThumbDistal, kHips}));

  const std::vector<std::string> vrm1 = {"leftThumbMetacarpal", "leftThumbProximal",
                                         "leftThumbDistal"};
  EXPECT_EQ(map_humanoid_names(vrm1),
            (std::vector<int>{kLeftThumbMetacarpal, kLeftThumbProximal, kLeftThumbDistal}));

  // cgspeed: Neck and Neck1 both read as "neck"; the first keeps it.
  const std::vector<std::string> dup = {"Neck", "Neck1", "Head"};
  EXPECT_EQ(map_humanoid_names(dup), (std::vector<int>{kNeck, -1, kHead}));
}

TEST(HumanoidNames, FingerJointIds) {
  EXPECT_EQ(finger_joint_id(true, Finger::Thumb, FingerSegment::Metacarpal), kLeftThumbMetacarpal);
  EXPECT_EQ(finger_joint_id(true, Finger::Thumb, FingerSegment::Intermediate), -1);
  EXPECT_EQ(finger_joint_id(true, Finger::Thumb, FingerSegment::Tip), kLeftThumbTip);
  EXPECT_EQ(finger_joint_id(false, Finger::Index, FingerSegment::Metacarpal),
            kRightIndexMetacarpal);
  EXPECT_EQ(finger_joint_id(false, Finger::Middle, FingerSegment::Distal), kRightMiddleDistal);
  EXPECT_EQ(finger_joint_id(true, Finger::Little, FingerSegment::Tip), kLeftLittleTip);
  EXPECT_EQ(finger_joint_id(true, Finger::Ring, FingerSegment::Intermediate),
            kLeftRingIntermediate);
}

TEST(HumanoidNames, ParentsFormTheVrmTree) {
  EXPECT_EQ(humanoid_parent(kHips), -1);
  EXPECT_EQ(humanoid_parent(kHead), kNeck);
  EXPECT_EQ(humanoid_parent(kLeftShoulder), kUpperChest);
  EXPECT_EQ(humanoid_parent(kLeftHand), kLeftLowerArm);
  EXPECT_EQ(humanoid_parent(kLeftThumbMetacarpal), kLeftHand);
  EXPECT_EQ(humanoid_parent(kRightIndexMetacarpal), kRightHand);
  EXPECT_EQ(humanoid_parent(kRightIndexProximal), kRightIndexMetacarpal);
  EXPECT_EQ(humanoid_parent(kRightLittleTip), kRightLittleDistal);
  EXPECT_EQ(humanoid_parent(kLeftFoot), kLeftLowerLeg);
  EXPECT_EQ(humanoid_parent(kRightUpperLeg), kHips);
  // Every joint reaches the hips, and parents come before children in id order.
  for (int id = 1; id < kHumanoidJointCount; ++id) {
    const int parent = humanoid_parent(id);
    ASSERT_GE(parent, 0) << humanoid_joint_name(id);
    EXPECT_LT(parent, id) << humanoid_joint_name(id);
  }
}

TEST(HumanoidNames, RequiredJoints) {
  int required = 0;
  for (int id = 0; id < kHumanoidJointCount; ++id) required += humanoid_joint_required(id);
  EXPECT_EQ(required, 10 + 2 * 15);
  EXPECT_TRUE(humanoid_joint_required(kLeftThumbMetacarpal));
  EXPECT_FALSE(humanoid_joint_required(kLeftIndexMetacarpal));
  EXPECT_FALSE(humanoid_joint_required(kLeftIndexTip));
  EXPECT_FALSE(humanoid_joint_required(kJaw));
  EXPECT_FALSE(humanoid_joint_required(kLeftUpperLeg));
}

}  // namespace
}  // namespace sw::skeleton
