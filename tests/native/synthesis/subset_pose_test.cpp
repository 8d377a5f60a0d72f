// SubsetPose (subset_pose.h): posing only some joints (and their ancestors) must give each of
// them exactly (bit for bit) the position the full PoseBuilder gives: the transition measures
// that use it (eq. (10)'s L_max over the arm joints, the arms' and fingertips' acceleration)
// decide a transition's number of states, and a changed bit could change a clip. Checked on the
// frames of a real clip, on rigs with and without rest rotations, for the arm joints and for the
// fingertips (whose chains run through the finger joints).
#include "synthesis/subset_pose.h"

#include <gtest/gtest.h>

#include <cstring>

#include "synthesis_fixture.h"

namespace sw::synthesis {
namespace {

using namespace testing;

class SynthesisSubsetPose : public ::testing::TestWithParam<int> {};

TEST_P(SynthesisSubsetPose, WantedJointsArePlacedAsTheFullPosePlacesThem) {
  avatar::Avatar av = GetParam() == 0 ? make_reference_humanoid() : make_rotated_variant(0.9f);
  Rig rig;
  std::string error;
  ASSERT_TRUE(build_rig(av, &rig, &error)) << error;
  PhraseText t = phrase_from_text(
      "R(H(flat), E(o), P(u), Loc(neutral, centre, none), M(circle axis=o cw)) Sym(lr)\n"
      "R(H(finger2), E(u), P(o), Loc(chin, centre, touch))", {});
  ASSERT_TRUE(t.ok());
  SynthesisResult r = synthesize_phrase(t.items, av, {});
  ASSERT_TRUE(r.ok());
  const Clip& clip = r.clip;
  ASSERT_GT(clip.frame_count, 20);
  std::vector<int> arms, tips;
  for (const ArmRig& a : rig.arms) {
    for (int j : {a.shoulder, a.upper, a.lower, a.hand})
      if (j >= 0) arms.push_back(j);
    for (const FingerChain& finger : a.fingers) tips.push_back(finger.tip >= 0 ? finger.tip : finger.bones[2]);
  }
  SubsetPose arm_pose(rig, arms), tip_pose(rig, tips);
  // The subset is the wanted joints and their ancestors, not the skeleton: the arm joints' pose
  // leaves out at least the fingers.
  EXPECT_LT(arm_pose.joints().size() + 30, static_cast<size_t>(rig.joint_count));
  for (int j : arms)
    for (int a = j; a >= 0; a = rig.parent[a])
      EXPECT_NE(std::find(arm_pose.joints().begin(), arm_pose.joints().end(), a), arm_pose.joints().end()) << a;
  PoseBuilder full(rig);
  for (int f = 0; f < clip.frame_count; ++f) {
    const glm::quat* frame = &clip.rotations[static_cast<size_t>(f) * rig.joint_count];
    full.set_from_local(frame);
    arm_pose.set_from_local(frame);
    tip_pose.set_from_local(frame);
    for (int j : arm_pose.joints())
      ASSERT_EQ(std::memcmp(&arm_pose.position(j), &full.position(j), sizeof(glm::vec3)), 0)
          << "frame " << f << ", joint " << j;
    for (int j : tip_pose.joints())
      ASSERT_EQ(std::memcmp(&tip_pose.position(j), &full.position(j), sizeof(glm::vec3)), 0)
          << "frame " << f << ", joint " << j;
  }
}

INSTANTIATE_TEST_SUITE_P(Rigs, SynthesisSubsetPose, ::testing::Values(0, 1));

}  // namespace
}  // namespace sw::synthesis
