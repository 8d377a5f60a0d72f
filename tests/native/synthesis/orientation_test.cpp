// Orientation acceptance: the posed palm normal within 10 degrees of the requested direction
// (projected perpendicular to the finger direction), for HamNoSys pairs and the seed's D1-D5.
#include "synthesis/orientation.h"

#include <gtest/gtest.h>

#include "synthesis_fixture.h"

namespace sw::synthesis {
namespace {

using namespace testing;
using notation::Direction;

struct Measured {
  HandFrame requested, achieved;
};

Measured measure(const avatar::Avatar& av, const notation::Orientation& o, bool left_handed = false) {
  Rig rig;
  std::string error;
  EXPECT_TRUE(build_rig(av, &rig, &error)) << error;
  notation::SignSpec s = sign_at(flat(), notation::BodyLevel::NeutralSpace, notation::Side::Centre,
                                 notation::Contact::None);
  s.dominant.orientation = o;
  SynthesisOptions opt;
  opt.left_handed = left_handed;
  SynthesisResult r = synthesize_sign(s, av, opt);
  EXPECT_TRUE(r.ok());
  Side side = left_handed ? kLeft : kRight;
  PoseBuilder pb = frame_pose(rig, r.clip, first_sign_frame(r.clip));
  Measured m;
  m.requested = orientation_frame(rig, o, side, left_handed);
  m.achieved = posed_hand_frame(rig, side, pb.delta(rig.arms[side].hand));
  return m;
}

TEST(SynthesisOrientation, SignerDirectionsFollowTheBodyFrame) {
  avatar::Avatar av = make_reference_humanoid();
  Rig rig;
  std::string error;
  ASSERT_TRUE(build_rig(av, &rig, &error));
  EXPECT_NEAR(glm::dot(signer_direction(rig, Direction{1, 0, 0}, false), glm::vec3(1, 0, 0)), 1.0f, 1e-5f);
  EXPECT_NEAR(glm::dot(signer_direction(rig, Direction{0, 0, 1}, false), glm::vec3(0, 0, 1)), 1.0f, 1e-5f);
  EXPECT_NEAR(glm::dot(signer_direction(rig, Direction{1, 0, 0}, true), glm::vec3(-1, 0, 0)), 1.0f, 1e-5f);
  // All 26 directions are unit vectors.
  for (int x = -1; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      for (int z = -1; z <= 1; ++z) {
        if (!x && !y && !z) continue;
        Direction d{static_cast<std::int8_t>(x), static_cast<std::int8_t>(y), static_cast<std::int8_t>(z)};
        EXPECT_NEAR(glm::length(signer_direction(rig, d, false)), 1.0f, 1e-5f);
      }
}

TEST(SynthesisOrientation, PalmIsProjectedPerpendicularToTheFingers) {
  avatar::Avatar av = make_reference_humanoid();
  Rig rig;
  std::string error;
  ASSERT_TRUE(build_rig(av, &rig, &error));
  notation::Orientation o;
  o.extended_finger = {0, 1, 1};  // up and away
  o.palm = {0, 0, -1};            // towards the body: not perpendicular to the fingers
  HandFrame f = orientation_frame(rig, o, kRight, false);
  EXPECT_NEAR(glm::dot(f.finger, f.palm), 0.0f, 1e-5f);
  EXPECT_LT(glm::dot(f.palm, rig.forward), 0.0f);
}

// Reachable hand orientations in neutral space (a hand in front of the chest).
const std::pair<Direction, Direction> kPairs[] = {
    {{0, 1, 0}, {0, 0, 1}},    // fingers up, palm to the addressee
    {{0, 1, 0}, {0, 0, -1}},   // fingers up, palm to the signer
    {{0, 1, 0}, {1, 0, 0}},    // fingers up, palm to the midline
    {{0, 0, 1}, {0, -1, 0}},   // fingers out, palm down
    {{0, 0, 1}, {0, 1, 0}},    // fingers out, palm up
    {{0, 0, 1}, {1, 0, 0}},    // fingers out, palm left
    {{1, 0, 0}, {0, -1, 0}},   // fingers left (across), palm down
    {{1, 0, 0}, {0, 0, -1}},   // fingers left, palm to the body
    {{1, 1, 0}, {0, 0, 1}},    // fingers up-left, palm out
    {{0, 1, 1}, {0, -1, 1}},   // up-out, palm out/down
    // Fingers out and to the dominant side, palm down: more ulnar deviation than the wrist has
    // (35 deg) if the forearm points where it does for a central hand; the arm IK brings the
    // elbow in front of the body (swivel < 0, shoulder internal rotation) so the forearm points
    // out to the side instead (was 14 degrees off before the swivel search covered it).
    {{-1, 0, 1}, {0, -1, 0}},
    {{0, -1, 1}, {0, 0, -1}},  // down-out, palm to the body
};

TEST(SynthesisOrientation, PalmNormalWithin10DegreesOnTwoAvatars) {
  for (int variant = 0; variant < 2; ++variant) {
    avatar::Avatar av = variant == 0 ? make_reference_humanoid() : make_rotated_variant(0.9f);
    for (const auto& [finger, palm] : kPairs) {
      notation::Orientation o;
      o.extended_finger = finger;
      o.palm = palm;
      Measured m = measure(av, o);
      float palm_err = std::acos(std::min(1.0f, glm::dot(m.requested.palm, m.achieved.palm)));
      float finger_err = std::acos(std::min(1.0f, glm::dot(m.requested.finger, m.achieved.finger)));
      EXPECT_LT(deg(palm_err), 10.0f) << "variant " << variant << " finger " << int(finger.x) << int(finger.y)
                                      << int(finger.z) << " palm " << int(palm.x) << int(palm.y) << int(palm.z);
      EXPECT_LT(deg(finger_err), 15.0f) << "variant " << variant;
    }
  }
}

TEST(SynthesisOrientation, SeedPalmPositionsD1ToD5) {
  avatar::Avatar av = make_reference_humanoid();
  Rig rig;
  std::string error;
  ASSERT_TRUE(build_rig(av, &rig, &error));
  const glm::vec3 expected[5] = {rig.up, rig.forward, -rig.up, -rig.forward, rig.left};
  for (int d = 1; d <= 5; ++d) {
    notation::Orientation o;
    o.seed_palm = static_cast<notation::SeedPalm>(d);
    Measured m = measure(av, o);
    EXPECT_GT(glm::dot(m.requested.palm, expected[d - 1]), 0.99f) << "D" << d;
    float err = std::acos(std::min(1.0f, glm::dot(m.requested.palm, m.achieved.palm)));
    EXPECT_LT(deg(err), 10.0f) << "D" << d;
  }
}

TEST(SynthesisOrientation, LeftHandedSignerMirrorsTheOrientation) {
  avatar::Avatar av = make_reference_humanoid();
  notation::Orientation o;
  o.extended_finger = {1, 1, 0};
  o.palm = {0, 0, 1};
  Measured r = measure(av, o, false), l = measure(av, o, true);
  EXPECT_NEAR(r.achieved.finger.x, -l.achieved.finger.x, 0.05f);
  EXPECT_NEAR(r.achieved.finger.y, l.achieved.finger.y, 0.05f);
  EXPECT_NEAR(r.achieved.palm.z, l.achieved.palm.z, 0.05f);
}

}  // namespace
}  // namespace sw::synthesis
