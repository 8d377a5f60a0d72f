// Handshape acceptance (issue 4): fist, flat, spread, thumb contact, joint limits — measured on
// the posed finger chains of two differently rigged humanoids.
#include "synthesis/handshape.h"

#include <gtest/gtest.h>

#include "synthesis_fixture.h"

namespace sw::synthesis {
namespace {

using namespace testing;

struct Posed {
  Rig rig;
  PoseBuilder* pose = nullptr;
};

class HandshapeTest : public ::testing::TestWithParam<int> {
 protected:
  void SetUp() override {
    avatar_ = GetParam() == 0 ? make_reference_humanoid() : make_rotated_variant(0.85f);
    std::string error;
    ASSERT_TRUE(build_rig(avatar_, &rig_, &error)) << error;
  }
  // Hand-relative pose (hand delta identity) of a shape on the right hand.
  PoseBuilder pose(const notation::HandShape& shape, HandAngles* angles_out = nullptr) {
    HandAngles a = solve_handshape(rig_, kRight, shape);
    if (angles_out) *angles_out = a;
    PoseBuilder pb(rig_);
    pose_fingers(rig_, kRight, a, glm::quat(1, 0, 0, 0), &pb);
    pb.finalize();
    return pb;
  }
  avatar::Avatar avatar_;
  Rig rig_;
};

TEST_P(HandshapeTest, FistBringsEveryFingertipWithin3cmOfThePalmCentre) {
  PoseBuilder pb = pose(fist());
  glm::vec3 centre = bind_palm_centre(rig_, kRight);
  for (int f = 1; f < 5; ++f)
    EXPECT_LT(glm::length(pb.tip(kRight, f) - centre), 0.03f) << "finger " << f;
}

TEST_P(HandshapeTest, FlatHandHasStraightFingersAndAdjacentTips) {
  PoseBuilder pb = pose(flat());
  const ArmRig& a = rig_.arms[kRight];
  for (int f = 1; f < 5; ++f) {
    const FingerChain& c = a.fingers[f];
    glm::vec3 d0 = glm::normalize(pb.position(c.bones[1]) - pb.position(c.bones[0]));
    glm::vec3 d1 = glm::normalize(pb.position(c.bones[2]) - pb.position(c.bones[1]));
    glm::vec3 d2 = glm::normalize(pb.tip(kRight, f) - pb.position(c.bones[2]));
    EXPECT_GT(glm::dot(d0, d1), std::cos(5.0f / 57.3f)) << "finger " << f;
    EXPECT_GT(glm::dot(d1, d2), std::cos(5.0f / 57.3f)) << "finger " << f;
    // Straight along the hand, in the palm plane.
    EXPECT_GT(glm::dot(d0, a.finger_dir), std::cos(8.0f / 57.3f)) << "finger " << f;
  }
  for (int f = 1; f < 4; ++f)
    EXPECT_LT(glm::length(pb.tip(kRight, f) - pb.tip(kRight, f + 1)), 0.025f) << "fingers " << f << "," << f + 1;
}

TEST_P(HandshapeTest, SpreadMovesAdjacentTipsApart) {
  PoseBuilder flat_pose = pose(flat());
  PoseBuilder spread = pose(shape_all(notation::kFingerSpread, notation::kThumbOut));
  for (int f = 1; f < 4; ++f) {
    float d_flat = glm::length(flat_pose.tip(kRight, f) - flat_pose.tip(kRight, f + 1));
    float d_spread = glm::length(spread.tip(kRight, f) - spread.tip(kRight, f + 1));
    EXPECT_GT(d_spread, d_flat + 0.01f) << "fingers " << f << "," << f + 1;
  }
  // Thumb out: the thumb tip is far from the index.
  EXPECT_GT(glm::length(spread.tip(kRight, 0) - spread.tip(kRight, 1)), 0.06f);
}

TEST_P(HandshapeTest, ThumbContactStatesTouchTheTargetFingertip) {
  const int thumb_ids[4] = {notation::kThumbPadOnIndex, notation::kThumbOnMiddle,
                            notation::kThumbOnRing, notation::kThumbOnLittle};
  for (int i = 0; i < 4; ++i) {
    // Pinch: the target finger starts straight (F_0(1)); the solve curls it to meet the thumb.
    notation::HandShape s = flat();
    s.fingers[0] = notation::FingerConfig{thumb_ids[i], false, 1.0f, 0.0f};
    HandAngles angles;
    PoseBuilder pb = pose(s, &angles);
    float d = glm::length(pb.tip(kRight, 0) - pb.tip(kRight, i + 1));
    EXPECT_LT(d, 0.01f) << "thumb on finger " << i + 1;
    EXPECT_TRUE(within_limits(angles)) << "thumb on finger " << i + 1;
  }
}

TEST_P(HandshapeTest, EveryConfigurationStaysWithinJointLimits) {
  for (int fid = 0; fid <= notation::kFingerDoubleHooked; ++fid)
    for (int tid = 0; tid <= notation::kThumbAlongside; ++tid)
      for (float t : {0.0f, 0.5f, 1.0f})
        for (float spread : {0.0f, 1.0f}) {
          HandAngles a = solve_handshape(rig_, kLeft, shape_all(fid, tid, true, t, spread));
          EXPECT_TRUE(within_limits(a)) << "finger " << fid << " thumb " << tid << " t " << t;
        }
}

TEST_P(HandshapeTest, ParameterTInterpolatesPressedToStraight) {
  // Seed eq. (4): F_0^k(t) goes from pressed (t = 0) to straight (t = 1); the tip moves away
  // from the palm monotonically.
  glm::vec3 centre = bind_palm_centre(rig_, kRight);
  float prev = 0.0f;
  for (float t : {0.0f, 0.25f, 0.5f, 0.75f, 1.0f}) {
    PoseBuilder pb = pose(shape_all(0, 0, true, t));
    float d = glm::length(pb.tip(kRight, 2) - centre);
    EXPECT_GT(d, prev) << "t " << t;
    prev = d;
  }
}

TEST_P(HandshapeTest, LeftHandMirrorsTheRightHand) {
  // The same shape on both hands: the left fingertips mirror the right ones across the body's
  // midline (hand frames are derived per hand from the bind pose, chirality included).
  HandAngles a = solve_handshape(rig_, kRight, fist());
  HandAngles b = solve_handshape(rig_, kLeft, fist());
  PoseBuilder pb(rig_);
  pose_fingers(rig_, kRight, a, glm::quat(1, 0, 0, 0), &pb);
  pose_fingers(rig_, kLeft, b, glm::quat(1, 0, 0, 0), &pb);
  pb.finalize();
  for (int f = 0; f < 5; ++f) {
    glm::vec3 r = pb.tip(kRight, f), l = pb.tip(kLeft, f);
    glm::vec3 rl = r - rig_.bind_pos[rig_.hips], ll = l - rig_.bind_pos[rig_.hips];
    EXPECT_NEAR(glm::dot(rl, rig_.left), -glm::dot(ll, rig_.left), 0.004f) << f;
    EXPECT_NEAR(glm::dot(rl, rig_.up), glm::dot(ll, rig_.up), 0.004f) << f;
    EXPECT_NEAR(glm::dot(rl, rig_.forward), glm::dot(ll, rig_.forward), 0.004f) << f;
  }
}

INSTANTIATE_TEST_SUITE_P(Avatars, HandshapeTest, ::testing::Values(0, 1));

}  // namespace
}  // namespace sw::synthesis
