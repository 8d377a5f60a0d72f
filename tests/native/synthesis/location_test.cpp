// Location acceptance (issue 4): the contact part reaches the body anchor (< 1 cm with touch),
// stays 3-10 cm away without contact, two hands (the other hand as the place), symmetry and the
// left-handed option; missing anchors are errors, not crashes.
#include "synthesis/sign_motion.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "notation/hamnosys.h"
#include "synthesis/arm_ik.h"
#include "synthesis/hand_parts.h"
#include "synthesis/orientation.h"
#include "synthesis/phrase_text.h"
#include "synthesis/synthesize.h"
#include "arm_depths.h"
#include "synthesis_fixture.h"

namespace sw::synthesis {
namespace {

using namespace testing;
using notation::BodyLevel;
using notation::Contact;
using notation::Side;

const BodyLevel kTouchLevels[] = {
    BodyLevel::HeadTop, BodyLevel::Forehead, BodyLevel::Eyebrows, BodyLevel::Nose, BodyLevel::Cheeks,
    BodyLevel::Mouth, BodyLevel::Chin, BodyLevel::UnderChin, BodyLevel::Neck, BodyLevel::Shoulders,
    BodyLevel::Chest, BodyLevel::Stomach, BodyLevel::Belly, BodyLevel::Waist, BodyLevel::BelowWaist};

TEST(SynthesisLocation, TouchReachesEveryBodyPlaceWithin1cm) {
  for (int variant = 0; variant < 2; ++variant) {
    avatar::Avatar av = variant == 0 ? make_reference_humanoid() : make_rotated_variant(0.9f);
    for (BodyLevel level : kTouchLevels)
      for (Side side : {Side::Right, Side::Centre, Side::Left}) {
        notation::SignSpec s = sign_at(index_point(), level, side, Contact::Touch);
        // Face: the finger points up and away; trunk: across the body (to the signer's left),
        // palm to the body — how a signer touches these places with an index fingertip.
        bool trunk = static_cast<int>(level) >= static_cast<int>(BodyLevel::Chest);
        s.dominant.orientation.extended_finger = trunk ? notation::Direction{1, 0, 0} : notation::Direction{0, 1, 1};
        s.dominant.orientation.palm = notation::Direction{0, 0, -1};
        SynthesisResult r = synthesize_sign(s, av);
        ASSERT_TRUE(r.ok()) << r.errors[0].message;
        ASSERT_EQ(r.report.contact_distances_m.size(), 1u);
        EXPECT_LT(r.report.contact_distances_m[0], 0.01f)
            << "variant " << variant << " level " << int(level) << " side " << int(side);
      }
  }
}

TEST(SynthesisLocation, NoContactKeepsTheHand3To10cmAway) {
  avatar::Avatar av = make_reference_humanoid();
  for (BodyLevel level : {BodyLevel::Forehead, BodyLevel::Chin, BodyLevel::Chest, BodyLevel::Stomach})
    for (Contact c : {Contact::None, Contact::Close})
      for (Side side : {Side::Right, Side::Centre}) {
        notation::SignSpec s = sign_at(flat(), level, side, c);
        s.dominant.orientation.extended_finger = {0, 1, 0};
        s.dominant.orientation.palm = {0, 0, -1};
        SynthesisResult r = synthesize_sign(s, av);
        ASSERT_TRUE(r.ok());
        ASSERT_EQ(r.report.contact_distances_m.size(), 1u);
        float d = r.report.contact_distances_m[0];
        EXPECT_GE(d, 0.03f) << "level " << int(level) << " contact " << int(c);
        EXPECT_LE(d, 0.10f) << "level " << int(level) << " contact " << int(c);
      }
}

// A hand held off a body place whose arm, with the written orientation, would be in the trunk or
// have its elbow behind the body moves within the 3-10 cm band instead of turning out of the body
// (sign_motion.cpp, hold_off_clear). Before, turn_hand_out_of_body turned it one 15-degree step:
// a flat hand held off the chest, palm in (PERSON; the reference humanoid's forearm 6.7 mm in the
// trunk), 14.9 degrees off; a flat O beside the temple, palm forward (TEACH; the reference
// humanoid's elbow behind the body), 14.9; a flat hand beside the waist, palm down (CHILD; the
// project avatar's elbow behind), 14.9. Now each keeps its palm within 10 degrees at the key pose
// with the contact part still 3-10 cm from the place and the arms out of the trunk (5 mm).
TEST(SynthesisLocation, AHandHeldOffMovesWithinTheBandRatherThanTurnOutOfTheBody) {
  std::string error;
  testing::NamedRigs rigs = testing::reference_and_project_avatar(&error);
  ASSERT_TRUE(error.empty()) << error;
  const char* signs[] = {
      "R(H(flat), E(o), P(l), Loc(chest, right, none))",
      "R(H(pinchall, bent), E(u), P(o), Loc(forehead, right_beside, close))",
      "R(H(flat), E(o), P(d), Loc(waist, right_beside, none))",
  };
  for (const auto& rg : rigs) {
    Rig rig;
    ASSERT_TRUE(build_rig(rg.second, &rig, &error)) << error;
    SynthContext ctx;
    ASSERT_TRUE(make_context(rg.second, SynthesisOptions{}, &ctx, &error)) << error;
    for (const char* text : signs) {
      PhraseText t = phrase_from_text(text, {});
      ASSERT_TRUE(t.ok()) << text;
      const notation::SignSpec& sign = t.items[0].sign;
      SynthesisResult r = synthesize_sign(sign, rg.second);
      ASSERT_TRUE(r.ok()) << rg.first << " " << text << ": " << r.errors[0].message;
      PoseBuilder pose = frame_pose(rig, r.clip, first_sign_frame(r.clip));
      const HandFrame requested = orientation_frame(rig, sign.dominant.orientation, kRight, false);
      const HandFrame posed = posed_hand_frame(rig, kRight, pose.delta(rig.arms[kRight].hand));
      const float palm_deg = angle_deg(requested.palm, posed.palm);
      EXPECT_LE(palm_deg, 10.0f) << rg.first << " " << text;
      ASSERT_EQ(r.report.contact_distances_m.size(), 1u);
      EXPECT_GE(r.report.contact_distances_m[0], 0.03f) << rg.first << " " << text << ": held off, too near";
      EXPECT_LE(r.report.contact_distances_m[0], 0.10f) << rg.first << " " << text << ": held off, too far";
      const ArmDepths d = arm_depths(ctx, r);
      EXPECT_LE(d.trunk_m, 0.005f) << rg.first << " " << text << ": " << d.trunk_what;
    }
  }
}

TEST(SynthesisLocation, ArmJointsStayWithinLimits) {
  avatar::Avatar av = make_reference_humanoid();
  Rig rig;
  std::string error;
  ASSERT_TRUE(build_rig(av, &rig, &error));
  const ArmLimits& lim = arm_limits();
  SynthContext ctx;
  ASSERT_TRUE(make_context(av, SynthesisOptions{}, &ctx, &error));
  PartPoint anchor;
  PoseBuilder bind(ctx.rig);
  bind.finalize();
  for (const auto& a : av.anchors) {
    if (!anchor_point(av, bind, a.name, &anchor)) continue;
    ArmTarget t;
    t.point = anchor.point + 0.05f * anchor.normal;
    t.hand_delta = axis_angle(glm::vec3(0, 0, 1), 1.0f);
    ArmPose p = solve_arm(rig, kRight, t);
    EXPECT_LE(p.elbow_flex_rad, lim.elbow_flex_max + 1e-4f) << a.name;
    EXPECT_GE(p.elbow_flex_rad, -1e-4f) << a.name;
    EXPECT_LE(p.twist_rad, lim.twist_hi + 1e-4f) << a.name;
    EXPECT_GE(p.twist_rad, lim.twist_lo - 1e-4f) << a.name;
    EXPECT_LE(p.wrist_flex_rad, lim.wrist_flex + 1e-4f) << a.name;
    EXPECT_GE(p.wrist_flex_rad, -lim.wrist_ext - 1e-4f) << a.name;
    EXPECT_LE(p.wrist_dev_rad, lim.radial_dev + 1e-4f) << a.name;
    EXPECT_GE(p.wrist_dev_rad, -lim.ulnar_dev - 1e-4f) << a.name;
    EXPECT_LE(p.clavicle_elevation_rad, lim.clavicle_elevation + 1e-4f);
    EXPECT_LE(p.clavicle_protraction_rad, lim.clavicle_protraction + 1e-4f);
  }
}

TEST(SynthesisLocation, ClavicleRisesOnlyForHighTargets) {
  avatar::Avatar av = make_reference_humanoid();
  Rig rig;
  std::string error;
  ASSERT_TRUE(build_rig(av, &rig, &error));
  ArmTarget low, high;
  low.point = rig.bind_pos[rig.spine] + glm::vec3(-0.1f, 0.1f, 0.3f);
  high.point = rig.bind_pos[rig.head] + glm::vec3(-0.1f, 0.25f, 0.15f);
  EXPECT_NEAR(solve_arm(rig, kRight, low).clavicle_elevation_rad, 0.0f, 1e-4f);
  EXPECT_GT(solve_arm(rig, kRight, high).clavicle_elevation_rad, 0.1f);
}

TEST(SynthesisLocation, ArmSolveNeverUsesAnotherRigsMeasurements) {
  // The arm IK keeps each arm's bind-pose geometry for the last rig it saw (the chain is solved
  // thousands of times per sign); a rig rebuilt in place for another avatar (here 0.8 times the
  // size) must not get the first avatar's measurements. Checked by forward kinematics on the
  // rig itself: the posed wrist is where the solve aimed it.
  avatar::Avatar a = make_reference_humanoid(), b = make_rotated_variant(0.8f);
  std::string error;
  Rig rig;
  auto wrist_miss = [&](const char* which) {
    ArmTarget t;
    t.point = rig.bind_pos[rig.chest] + 0.3f * rig.forward - 0.1f * rig.left;
    t.auto_swivel = false;
    const ArmPose p = solve_arm(rig, kRight, t);
    const float miss = glm::length(arm_segments(rig, kRight, p).wrist - t.point);
    EXPECT_LT(miss, 0.001f) << which;
    return miss;
  };
  ASSERT_TRUE(build_rig(a, &rig, &error)) << error;
  wrist_miss("first avatar");
  ASSERT_TRUE(build_rig(b, &rig, &error)) << error;
  wrist_miss("second avatar, same Rig object");
  ASSERT_TRUE(build_rig(a, &rig, &error)) << error;
  wrist_miss("first avatar again");
}

TEST(SynthesisLocation, OtherHandIsThePlace) {
  avatar::Avatar av = make_reference_humanoid();
  Rig rig;
  std::string error;
  ASSERT_TRUE(build_rig(av, &rig, &error));
  notation::SignSpec s = sign_at(index_point(), BodyLevel::NeutralSpace, Side::Centre, Contact::Touch);
  s.dominant.location.kind = notation::Location::Kind::OtherHand;
  s.dominant.location.hand_place = notation::HandPlace::Palm;
  s.dominant.orientation.extended_finger = {0, -1, 1};
  s.dominant.orientation.palm = {0, 0, -1};
  notation::HandSpec nd;
  nd.shape = flat();
  nd.orientation.extended_finger = {-1, 0, 1};
  nd.orientation.palm = {0, 1, 0};
  nd.location.kind = notation::Location::Kind::NeutralSpace;
  nd.location.side = Side::Left;
  s.nondominant = nd;
  s.nondominant_is_place = true;
  SynthesisResult r = synthesize_sign(s, av);
  ASSERT_TRUE(r.ok()) << r.errors[0].message;
  // The right index tip on the left palm.
  PoseBuilder pb = frame_pose(rig, r.clip, first_sign_frame(r.clip));
  glm::vec3 tip = pb.tip(kRight, 1);
  PartPoint palm = hand_part(pb, kLeft, notation::HandPlace::Palm, 1);
  EXPECT_LT(glm::length(tip - palm.point), 0.01f);
  EXPECT_LE(r.report.max_penetration_m, 0.005f);
}

// An earring-like sign read from HamNoSys: the index nail touches the earlobe, the part named in
// brackets after the place (HamNoSys 4; SiGML's location_bodyarm with a location_hand child).
// The reader made the bracket a movement to the other hand, and make_plans dropped that target
// for one-handed signs (the hand stayed at the ear with its default part). Read as the contact
// part, the synthesis places the nail itself on the earlobe: within 1 cm (issue 4's reach).
TEST(SynthesisLocation, ABracketedContactPartReachesTheEarlobeFromHamNoSys) {
  notation::SignSpec s;
  ASSERT_TRUE(
      read_one_hamnosys("hampinch12,hamextfingeru,hampalml,hamearlobe,hamlrat,"
                        "hamseqbegin,hamtouch,hamindexfinger,hamfingernail,hamseqend",
                        &s));
  ASSERT_TRUE(s.dominant.location.contact_part.has_value());
  for (int variant = 0; variant < 2; ++variant) {
    avatar::Avatar av = variant == 0 ? make_reference_humanoid() : make_rotated_variant(0.9f);
    Rig rig;
    std::string error;
    ASSERT_TRUE(build_rig(av, &rig, &error)) << error;
    SynthesisResult r = synthesize_sign(s, av);
    ASSERT_TRUE(r.ok()) << r.errors[0].message;
    PoseBuilder pb = frame_pose(rig, r.clip, first_sign_frame(r.clip));
    PartPoint earlobe;
    ASSERT_TRUE(anchor_point(av, pb, "body/ears/right", &earlobe));
    const PartPoint nail = hand_part(pb, kRight, notation::HandPlace::FingerNail, 1);
    EXPECT_LT(glm::length(nail.point - earlobe.point), 0.01f) << "variant " << variant;
    ASSERT_EQ(r.report.contact_distances_m.size(), 1u);
    EXPECT_LT(r.report.contact_distances_m[0], 0.01f) << "variant " << variant;
    EXPECT_LE(r.report.max_penetration_m, 0.005f) << "variant " << variant;
  }
}

// A one-handed sign that moves to a place on the other hand or arm (the corpus's INJECTION1A:
// into the crook of the other elbow; here the index from the chest to the other palm).
// make_plans dropped such a target (its workaround for the reader's brackets, now read as
// contact parts); kept, the hand went for the resting hand by the hip, the arm through the torso
// (the corpus's zastrzyk 59 mm, dyzurny 54). The other hand is brought up as the place, as for a
// sign placed on it from the start, and no arm goes into the body. The index lands on the palm
// (within 1 cm), with the other hand left to the synthesis and written: the straight move's
// offset was added on top of its goal, which is that place already, and took the index 105-117
// mm past it on both rigs (sign_motion.cpp, a path that ends on the other hand).
TEST(SynthesisLocation, AOneHandedSignMovingToTheOtherHandBringsThatHandUp) {
  // The same movement with the other hand left to the synthesis and with it written (flat,
  // fingers forward-right, palm up).
  const char* const signs[] = {
      "hamfinger2,hamextfingerl,hampalmd,hamchest,hamclose,hammovel,hampalm,hamtouch",
      "hamparbegin,hamfinger2,hamextfingerl,hampalmd,hamplus,hamflathand,hamextfingeror,hampalmu,"
      "hamparend,"
      "hamchest,hamclose,hammovel,hampalm,hamtouch"};
  for (const char* names : signs) {
    notation::SignSpec s;
    ASSERT_TRUE(read_one_hamnosys(names, &s));
    ASSERT_EQ(s.movements.size(), 1u);
    ASSERT_TRUE(s.movements[0].dominant[0].to_location.has_value());
    for (int variant = 0; variant < 2; ++variant) {
      avatar::Avatar av = variant == 0 ? make_reference_humanoid() : make_rotated_variant(0.9f);
      Rig rig;
      std::string error;
      ASSERT_TRUE(build_rig(av, &rig, &error)) << error;
      SynthesisResult r = synthesize_sign(s, av);
      ASSERT_TRUE(r.ok()) << r.errors[0].message;
      // The left wrist at the sign's last frame, against where it hangs at rest (the clip's first
      // frame).
      const int last = last_sign_frame(r.clip);
      const int left_hand = rig.arms[kLeft].hand;
      const glm::vec3 at_rest = frame_pose(rig, r.clip, 0).position(left_hand);
      const PoseBuilder end = frame_pose(rig, r.clip, last);
      const float raised_m = glm::dot(end.position(left_hand) - at_rest, rig.up);
      // The index fingertip (the pointing hand's contact part) on the other palm (the named
      // place), the avatar's anchor where it has one, at the sign's last frame.
      PartPoint palm;
      if (!anchor_point(av, end, hand_part_anchor_name(kLeft, notation::HandPlace::Palm, 1), &palm))
        palm = hand_part(end, kLeft, notation::HandPlace::Palm, 1);
      const float gap_m =
          glm::length(hand_part(end, kRight, notation::HandPlace::Fingertip, 1).point - palm.point);
      const std::string what = std::string(s.nondominant ? "written other hand" : "one hand") +
                               ", variant " + std::to_string(variant);
      std::printf(
          "%s: the other hand raised %.0f mm, the index %.1f mm from the palm, deepest %.1f mm\n",
          what.c_str(), raised_m * 1000.0f, gap_m * 1000.0f, r.report.max_penetration_m * 1000.0f);
      if (!s.nondominant) {
        EXPECT_GT(raised_m, 0.15f) << what << ": the other hand was left hanging";
      }
      EXPECT_LT(gap_m, 0.01f) << what << ": the index does not reach the other palm";
      EXPECT_LE(r.report.max_penetration_m, 0.005f) << what;
    }
  }
}

// A one-handed sign on the other ARM (the corpus's INJECTION1A: into the crook of the elbow;
// T-SHIRT1: the flat hand in to the upper arm). The other hand was brought up as for a place on
// the hand, held in front of the chest with its elbow and upper arm hanging beside the torso, so
// the reaching arm went through the chest to them (INJECTION1A 64 mm, T-SHIRT1 127 mm on the
// project avatar). That arm is presented, held out in front (hamarmextended): the reaching hand
// gets to its place on it and no arm is in the body.
TEST(SynthesisLocation, AOneHandedSignOnTheOtherArmPresentsThatArm) {
  struct Case {
    const char* names;
    notation::HandPlace place;  // on the other arm
    notation::HandPlace part;   // of the reaching hand
    int finger;
  };
  const Case cases[] = {
      {"hamfinger2,hamextfingerdl,hampalmd,hammovedl,hamelbowinside,hamtouch",
       notation::HandPlace::ElbowInside, notation::HandPlace::Fingertip, 1},
      {"hamfinger2,hamextfingerl,hampalmd,hammovel,hamelbow,hamtouch", notation::HandPlace::Elbow,
       notation::HandPlace::Fingertip, 1},
  };
  for (const Case& c : cases) {
    notation::SignSpec s;
    ASSERT_TRUE(read_one_hamnosys(c.names, &s));
    ASSERT_FALSE(s.nondominant.has_value());
    for (int variant = 0; variant < 2; ++variant) {
      avatar::Avatar av = variant == 0 ? make_reference_humanoid() : make_rotated_variant(0.9f);
      Rig rig;
      std::string error;
      ASSERT_TRUE(build_rig(av, &rig, &error)) << error;
      SynthesisResult r = synthesize_sign(s, av);
      ASSERT_TRUE(r.ok()) << r.errors[0].message;
      const int last = last_sign_frame(r.clip);
      const PoseBuilder end = frame_pose(rig, r.clip, last);
      PartPoint place;
      if (!anchor_point(av, end, hand_part_anchor_name(kLeft, c.place, 1), &place))
        place = hand_part(end, kLeft, c.place, 1);
      const float gap_m = glm::length(hand_part(end, kRight, c.part, c.finger).point - place.point);
      const std::string what = std::string(c.names) + ", variant " + std::to_string(variant);
      std::printf("%s: %.1f mm from the place, deepest %.1f mm\n", what.c_str(), gap_m * 1000.0f,
                  r.report.max_penetration_m * 1000.0f);
      EXPECT_LT(gap_m, 0.01f) << what << ": the hand does not reach its place on the other arm";
      EXPECT_LE(r.report.max_penetration_m, 0.005f) << what;
    }
  }
}

// A symmetric sign whose hands are each written on the other, with no location symbol
// (HamNoSys: made in neutral space, the hands touching each other there; the corpus's
// RUBBING-ONES-HANDS-TOGETHER, FRESH, SHIP): the notation gives the non-dominant hand the
// dominant hand's spec mirrored, so each hand's place is on the other and neither has one of its
// own. It was refused ("each hand is placed on the other"); the pair now meets at the neutral
// space in front of the body, the dominant hand's part on the other hand's named part.
TEST(SynthesisLocation, HandsWrittenEachOnTheOtherMeetInNeutralSpaceOnBothRigs) {
  std::string rig_error;
  const NamedRigs rigs = reference_and_project_avatar(&rig_error);
  ASSERT_TRUE(rig_error.empty()) << rig_error;
  struct Pair {
    const char* name;
    notation::HandShape shape;
    notation::Direction fingers, palm;
    notation::HandPlace part;  // the part of each hand, on the same part of the other
    int finger;
  };
  const Pair pairs[] = {
      // Flat hands, fingers forward, palms together.
      {"palms together", flat(), {0, 0, 1}, {1, 0, 0}, notation::HandPlace::Palm, 1},
      // Index hands pointing at each other across the body, palms down, the tips together.
      {"index tips together", index_point(), {1, 0, 0}, {0, -1, 0}, notation::HandPlace::Fingertip, 1},
  };
  for (const Pair& pair : pairs) {
    notation::SignSpec s = sign_at(pair.shape, BodyLevel::NeutralSpace, Side::Centre, Contact::Touch);
    s.dominant.location.kind = notation::Location::Kind::OtherHand;
    s.dominant.location.hand_place = pair.part;
    s.dominant.location.finger = static_cast<std::int8_t>(pair.finger);
    s.dominant.location.contact_part = pair.part;
    s.dominant.location.contact_finger = static_cast<std::int8_t>(pair.finger);
    s.dominant.orientation.extended_finger = pair.fingers;
    s.dominant.orientation.palm = pair.palm;
    s.symmetry = notation::Symmetry::MirrorLR;
    // As the HamNoSys reader writes such a sign: with a symmetry operator both hands move, the
    // other hand is not a still place.
    s.nondominant_is_place = false;
    for (const auto& rg : rigs) {
      for (bool left_handed : {false, true}) {
        const std::string what = rg.first + ", " + pair.name + (left_handed ? ", left-handed" : "");
        SynthesisOptions options;
        options.left_handed = left_handed;  // the left hand on the right one, mirrored
        const synthesis::Side dom = left_handed ? kLeft : kRight, place = left_handed ? kRight : kLeft;
        Rig rig;
        std::string error;
        ASSERT_TRUE(build_rig(rg.second, &rig, &error)) << error;
        SynthesisResult r = synthesize_sign(s, rg.second, options);
        ASSERT_TRUE(r.ok()) << what << ": " << r.errors[0].message;
        PoseBuilder pb = frame_pose(rig, r.clip, first_sign_frame(r.clip));
        // The touching part of the dominant hand; the place on the other hand as the synthesis aims
        // at it, the avatar's anchor where it has one (Solver::other_hand_place).
        const PartPoint touching = hand_part(pb, dom, pair.part, pair.finger);
        PartPoint placed;
        if (!anchor_point(rg.second, pb, hand_part_anchor_name(place, pair.part, pair.finger), &placed))
          placed = hand_part(pb, place, pair.part, pair.finger);
        EXPECT_LT(glm::length(touching.point - placed.point), 0.01f) << what << ": the hands do not touch";
        // The pair in neutral space: in front of the chest (at least 15 cm forward of its joint),
        // between the waist and the shoulders, and within 12 cm of the body's mid-plane.
        const glm::vec3 meet = 0.5f * (touching.point + placed.point);
        const glm::vec3 from_chest = meet - rig.bind_pos[rig.chest];
        EXPECT_GT(glm::dot(from_chest, rig.forward), 0.15f) << what << ": not in front of the body";
        EXPECT_LT(std::abs(glm::dot(from_chest, rig.left)), 0.12f) << what << ": off the centre";
        const float shoulders = glm::dot(rig.bind_pos[rig.arms[kRight].upper], rig.up);
        const float hips = glm::dot(rig.bind_pos[rig.hips], rig.up);
        EXPECT_LT(glm::dot(meet, rig.up), shoulders) << what << ": above the shoulders";
        EXPECT_GT(glm::dot(meet, rig.up), hips + 0.1f) << what << ": down at the hips";
        EXPECT_LT(r.report.max_reach_error_m, 0.01f) << what;
        EXPECT_LE(r.report.max_penetration_m, 0.005f) << what << ": an arm in the body";
      }
    }
  }
}

// LATER's key pose: the right thumb tip on the left palm, the index up, palm left, the left flat
// hand upright, palm right, in neutral space. Put on the left palm where the left hand is held
// first, the right wrist was at its extension limit and the palm 17 degrees off (reference
// humanoid; 16 on the project avatar). Both hands meet where both hold their orientations
// (sign_motion.cpp, meet_where_both_hands_hold): the left hand moves within neutral space, and
// both palms are within 10 degrees with the thumb still on the palm.
TEST(SynthesisLocation, BothHandsMeetWhereBothHoldTheirOrientationsOnBothRigs) {
  std::string rig_error;
  const NamedRigs rigs = reference_and_project_avatar(&rig_error);
  ASSERT_TRUE(rig_error.empty()) << rig_error;
  PhraseText t = phrase_from_text(
      "R(H(finger2, thumbout), E(u), P(l), Loc(hand, palm, touch), C(tip, 1)) L(H(flat), E(u), P(r), Loc(neutral, centre))", {});
  ASSERT_TRUE(t.ok() && t.items.size() == 1u);
  const notation::SignSpec& s = t.items[0].sign;
  for (const auto& rg : rigs) {
    Rig rig;
    std::string error;
    ASSERT_TRUE(build_rig(rg.second, &rig, &error)) << error;
    SynthesisResult r = synthesize_sign(s, rg.second);
    ASSERT_TRUE(r.ok()) << rg.first << ": " << r.errors[0].message;
    PoseBuilder pb = frame_pose(rig, r.clip, first_sign_frame(r.clip));
    for (synthesis::Side side : {kRight, kLeft}) {
      const notation::HandSpec& spec = side == kRight ? s.dominant : *s.nondominant;
      const HandFrame requested = orientation_frame(rig, spec.orientation, side, false);
      const HandFrame posed = posed_hand_frame(rig, side, pb.delta(rig.arms[side].hand));
      EXPECT_LE(angle_deg(requested.palm, posed.palm), 10.0f)
          << rg.first << (side == kRight ? " right" : " left") << " palm";
    }
    const PartPoint palm = hand_part(pb, kLeft, notation::HandPlace::Palm, 1);
    EXPECT_LT(glm::length(pb.tip(kRight, 0) - palm.point), 0.01f) << rg.first << ": the thumb leaves the palm";
    EXPECT_LT(r.report.max_reach_error_m, 0.01f) << rg.first;
    EXPECT_LE(r.report.max_penetration_m, 0.005f) << rg.first;
  }
}

// The place hand of NUMBER, FRIEND and SCHOOL: the left hand in neutral space, fingers to the
// right, palm up. Its forearm must lie across the body below the chest with the elbow at the
// side; the neutral search's rings stopped 12 cm in at chest height, where the left palm was
// 16-17 degrees off on both rigs. Rings nearer the body and lower, tried while the hand is still
// over 10 degrees, find it (sign_motion.cpp, key_state).
TEST(SynthesisLocation, AHandAcrossTheBodyPalmUpInNeutralSpaceHoldsItsPalmOnBothRigs) {
  std::string rig_error;
  const NamedRigs rigs = reference_and_project_avatar(&rig_error);
  ASSERT_TRUE(rig_error.empty()) << rig_error;
  PhraseText t = phrase_from_text(
      "R(H(pinchall, bent), E(l), P(d), Loc(neutral, right, close)) L(H(pinchall, bent), E(r), P(u), Loc(neutral, centre))", {});
  ASSERT_TRUE(t.ok() && t.items.size() == 1u);
  const notation::SignSpec& s = t.items[0].sign;
  for (const auto& rg : rigs) {
    Rig rig;
    std::string error;
    ASSERT_TRUE(build_rig(rg.second, &rig, &error)) << error;
    SynthesisResult r = synthesize_sign(s, rg.second);
    ASSERT_TRUE(r.ok()) << rg.first << ": " << r.errors[0].message;
    PoseBuilder pb = frame_pose(rig, r.clip, first_sign_frame(r.clip));
    const HandFrame requested = orientation_frame(rig, s.nondominant->orientation, kLeft, false);
    const HandFrame posed = posed_hand_frame(rig, kLeft, pb.delta(rig.arms[kLeft].hand));
    EXPECT_LE(angle_deg(requested.palm, posed.palm), 10.0f)
        << rg.first << ": the left palm";
    EXPECT_LE(r.report.max_penetration_m, 0.005f) << rg.first;
  }
}

// DAY's place: the right elbow on the back of a left hand written in neutral space, which lies
// beyond the right upper arm's reach from the shoulder (the elbow missed it by 78 mm on the
// project avatar, 116 mm on the reference humanoid). The place comes to the elbow: the touch is
// within 1 cm on both rigs, with neither arm in the body.
TEST(SynthesisLocation, ElbowOnTheBackOfAHandInNeutralSpaceTouchesOnBothRigs) {
  std::string rig_error;
  const NamedRigs rigs = reference_and_project_avatar(&rig_error);
  ASSERT_TRUE(rig_error.empty()) << rig_error;
  notation::SignSpec s = sign_at(index_point(), BodyLevel::NeutralSpace, Side::Centre, Contact::Touch);
  s.dominant.location.kind = notation::Location::Kind::OtherHand;
  s.dominant.location.hand_place = notation::HandPlace::BackOfHand;
  s.dominant.location.contact_part = notation::HandPlace::Elbow;
  s.dominant.orientation.extended_finger = {0, 1, 0};
  s.dominant.orientation.palm = {1, 0, 0};
  notation::HandSpec nd;
  nd.shape = flat();
  nd.orientation.extended_finger = {-1, 0, 0};
  nd.orientation.palm = {0, -1, 0};
  nd.location.kind = notation::Location::Kind::NeutralSpace;
  nd.location.side = Side::Centre;
  s.nondominant = nd;
  s.nondominant_is_place = true;
  for (const auto& rg : rigs) {
    SynthesisResult r = synthesize_sign(s, rg.second);
    ASSERT_TRUE(r.ok()) << rg.first << ": " << r.errors[0].message;
    EXPECT_LT(r.report.max_reach_error_m, 0.01f) << rg.first << ": the elbow misses the back of the hand";
    EXPECT_LE(r.report.max_penetration_m, 0.005f) << rg.first;
  }
}

// MORNING: the left hand in the crook of the right elbow, the right forearm forward in neutral
// space. Solved where the notation puts it, the right elbow hung at the side of the body (4 cm in
// front of the shoulders on the reference humanoid) and the left arm reached across the whole
// torso to it: 96 mm in the trunk at the key pose, cleared frame by frame to 4.9-7.0 mm over the
// frame rates and speeds. The place comes to the hand when the arm reaching it would be in the
// trunk, as it does when the hand cannot reach it: the right hand's key target moves out by
// that arm's depth + 2 cm and 5 cm forward, the right elbow with it. Both arms stay out of the
// trunk at every frame rate and speed, and the left hand still touches.
TEST(SynthesisLocation, AHandInTheCrookOfTheOtherElbowBringsThatArmForwardOnBothRigs) {
  std::string rig_error;
  const NamedRigs rigs = reference_and_project_avatar(&rig_error);
  ASSERT_TRUE(rig_error.empty()) << rig_error;
  PhraseText t = phrase_from_text(
      "R(H(flat), E(o), P(u), Loc(neutral, right), M(replace, E(u), P(i))) L(H(flat), E(r), P(d), Loc(hand, elbow, touch))", {});
  ASSERT_TRUE(t.ok());
  for (const auto& rg : rigs) {
    SynthContext ctx;
    std::string error;
    ASSERT_TRUE(make_context(rg.second, SynthesisOptions{}, &ctx, &error)) << error;
    for (float fps : {25.0f, 30.0f, 60.0f})
      for (float speed : {0.8f, 1.25f}) {
        SynthesisOptions o;
        o.fps = fps;
        o.speed = speed;
        SynthesisResult r = synthesize_sign(t.items[0].sign, rg.second, o);
        ASSERT_TRUE(r.ok()) << rg.first;
        const std::string what = rg.first + " fps " + std::to_string(fps) + " speed " + std::to_string(speed);
        EXPECT_LT(r.report.max_reach_error_m, 0.01f) << what << ": the left hand misses the elbow";
        float worst = 0.0f;
        for (int f = 0; f < r.clip.frame_count; ++f) {
          PoseBuilder pb = frame_pose(ctx.rig, r.clip, f);
          for (sw::synthesis::Side s : {kLeft, kRight})
            worst = std::max(worst, arm_penetration(ctx.body, pb, s, true,
                                                    r.report.intended_contact[f] & exempt_bit(s, false), false).depth_m);
        }
        EXPECT_LE(worst, 0.005f) << what;
        EXPECT_LE(r.report.max_penetration_m, 0.005f) << what;
      }
  }
}

// DAY: the right elbow on the back of the left hand, the right index arcing down to the left
// (the sun's path). The place came to the elbow (above), and the arc was led by the wrist so that
// the elbow stays; but moved by the path's offset the wrist went beyond the arm's reach (0.586 m
// from the shoulder joint for a 0.55 m arm on the reference humanoid): the arm ran straight, the
// elbow slid 9.1 cm along the other hand and the upper arm went 5.6 mm into the torso. The wrist
// now goes round the elbow at the forearm's distance: the elbow stays within 3 cm of where it
// touched (measured 2.6 cm: the clavicle follows the wrist) and no arm enters the trunk. On
// the project avatar the elbow reaches its written place, the place does not move and the arc
// moves the elbow itself (3.8 cm; not led by the wrist): only the depth is checked there.
TEST(SynthesisLocation, AnElbowOnTheOtherHandStaysWhileTheForearmTurnsAboutIt) {
  std::string rig_error;
  const NamedRigs rigs = reference_and_project_avatar(&rig_error);
  ASSERT_TRUE(rig_error.empty()) << rig_error;
  PhraseText t = phrase_from_text(
      "R(H(finger2), E(u), P(l), Loc(hand, back, touch), C(elbow), Par(M(arc, dl, bulge=u), M(replace, E(l), P(d)))) "
      "L(H(flat), E(r), P(d), Loc(neutral, centre))", {});
  ASSERT_TRUE(t.ok());
  for (const auto& rg : rigs) {
    SynthContext ctx;
    std::string error;
    ASSERT_TRUE(make_context(rg.second, SynthesisOptions{}, &ctx, &error)) << error;
    SynthesisOptions o;
    o.start_from_rest = false;
    SynthesisResult r = synthesize_sign(t.items[0].sign, rg.second, o);
    ASSERT_TRUE(r.ok()) << rg.first;
    EXPECT_LT(r.report.max_reach_error_m, 0.01f) << rg.first;
    const glm::vec3 elbow0 = frame_pose(ctx.rig, r.clip, 0).position(ctx.rig.arms[kRight].lower);
    float slide = 0.0f, worst = 0.0f;
    for (int f = 0; f < r.clip.frame_count; ++f) {
      PoseBuilder pb = frame_pose(ctx.rig, r.clip, f);
      slide = std::max(slide, glm::length(pb.position(ctx.rig.arms[kRight].lower) - elbow0));
      for (sw::synthesis::Side s : {kLeft, kRight})
        worst = std::max(worst, arm_penetration(ctx.body, pb, s, true,
                                                r.report.intended_contact[f] & exempt_bit(s, false), false).depth_m);
    }
    if (rg.first == "reference") {
      EXPECT_LT(slide, 0.03f) << rg.first << ": the elbow slides along the other hand";
    }
    EXPECT_LE(worst, 0.005f) << rg.first;
  }
}

TEST(SynthesisLocation, MirrorSymmetryPlacesTheOtherHandOnTheOtherSide) {
  avatar::Avatar av = make_reference_humanoid();
  Rig rig;
  std::string error;
  ASSERT_TRUE(build_rig(av, &rig, &error));
  notation::SignSpec s = sign_at(flat(), BodyLevel::Chest, Side::Right, Contact::Close);
  s.symmetry = notation::Symmetry::MirrorLR;
  SynthesisResult r = synthesize_sign(s, av);
  ASSERT_TRUE(r.ok());
  PoseBuilder pb = frame_pose(rig, r.clip, first_sign_frame(r.clip));
  glm::vec3 rh = pb.position(rig.arms[kRight].hand), lh = pb.position(rig.arms[kLeft].hand);
  EXPECT_NEAR(rh.x, -lh.x, 0.01f);
  EXPECT_NEAR(rh.y, lh.y, 0.01f);
  EXPECT_NEAR(rh.z, lh.z, 0.01f);
  EXPECT_LT(rh.x, 0.0f);  // the right hand on the signer's right (-X)
}

TEST(SynthesisLocation, LeftHandedSignerMirrorsEverything) {
  avatar::Avatar av = make_reference_humanoid();
  Rig rig;
  std::string error;
  ASSERT_TRUE(build_rig(av, &rig, &error));
  notation::SignSpec s = sign_at(index_point(), BodyLevel::Cheeks, Side::Right, Contact::Touch);
  SynthesisOptions lh;
  lh.left_handed = true;
  SynthesisResult a = synthesize_sign(s, av), b = synthesize_sign(s, av, lh);
  ASSERT_TRUE(a.ok() && b.ok());
  PoseBuilder pa = frame_pose(rig, a.clip, first_sign_frame(a.clip));
  PoseBuilder pbb = frame_pose(rig, b.clip, first_sign_frame(b.clip));
  glm::vec3 ra = pa.tip(kRight, 1), lb = pbb.tip(kLeft, 1);
  EXPECT_NEAR(ra.x, -lb.x, 0.01f);
  EXPECT_NEAR(ra.y, lb.y, 0.01f);
  EXPECT_NEAR(ra.z, lb.z, 0.01f);
  EXPECT_LT(b.report.contact_distances_m[0], 0.01f);
}

TEST(SynthesisLocation, MissingAnchorIsAnErrorValue) {
  avatar::Avatar av = make_reference_humanoid();
  av.anchors.clear();
  SynthesisResult r = synthesize_sign(sign_at(flat(), BodyLevel::Chin, Side::Centre, Contact::Touch), av);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.errors[0].message.find("body/chin/centre"), std::string::npos) << r.errors[0].message;
}

TEST(SynthesisLocation, AvatarWithoutArmsIsAnErrorValue) {
  avatar::Avatar av = make_reference_humanoid();
  for (auto& j : av.skeleton.joints)
    if (j.name == "rightLowerArm") j.name = "bone_017";
  SynthesisResult r = synthesize_sign(sign_at(flat(), BodyLevel::Chin, Side::Centre, Contact::Touch), av);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.errors[0].where, "avatar");
  EXPECT_NE(r.errors[0].message.find("rightLowerArm"), std::string::npos);
  avatar::Avatar empty;
  EXPECT_FALSE(synthesize_sign(notation::SignSpec{}, empty).ok());
}

// Each hand of a symmetric sign's pair at its own side (hamnosys_parser.cpp read_initial_location):
// at the key pose the right wrist is 5 cm or more to the signer's right of the body's middle and
// the left one as far to the left.
// `as_meant`: the same sign written with each hand's place spelled out; the sign is no deeper
// than it (+ 1 mm).
void expect_each_hand_on_its_own_side(const char* hamnosys_names, const char* as_meant) {
  notation::SignSpec sign;
  ASSERT_TRUE(read_one_hamnosys(hamnosys_names, &sign));
  notation::SignSpec meant_sign;
  ASSERT_TRUE(read_one_hamnosys(as_meant, &meant_sign));
  std::string error;
  const NamedRigs rigs = reference_and_project_avatar(&error);
  ASSERT_TRUE(error.empty()) << error;
  for (const auto& [name, av] : rigs) {
    Rig rig;
    ASSERT_TRUE(build_rig(av, &rig, &error)) << error;
    const SynthesisResult r = synthesize_sign(sign, av);
    ASSERT_TRUE(r.ok()) << name << ": " << r.errors[0].message;
    const glm::vec3 middle = rig.bind_pos[rig.neck];
    const PoseBuilder key = frame_pose(rig, r.clip, first_sign_frame(r.clip));
    const float right_m = glm::dot(key.position(rig.arms[kRight].hand) - middle, rig.left);
    const float left_m = glm::dot(key.position(rig.arms[kLeft].hand) - middle, rig.left);
    EXPECT_LT(right_m, -0.05f) << name << ": the right wrist " << right_m * 1000.0f
                               << " mm to the left";
    EXPECT_GT(left_m, 0.05f) << name << ": the left wrist " << left_m * 1000.0f
                             << " mm to the left";
    const float meant_m = synthesize_sign(meant_sign, av).report.max_penetration_m;
    EXPECT_LE(r.report.max_penetration_m, meant_m + 0.001f)
        << name << ": " << r.report.max_penetration_m * 1000.0f << " mm, as meant "
        << meant_m * 1000.0f << " mm";
  }
}

// A mirror-symmetric pair written at the same side of one place for both hands (the PJM "n weeks
// ago" signs: "hamparbegin hamlrat hamshoulders hamplus hamlrat hamshoulders hamparend", then
// "hammoveil ... hamlrat hamshouldertop"): the hands mirror each other, so they are not both at
// the left of the shoulders; each is at its own side, and the dominant hand's target, written
// the same way, at its own shoulder top. Read literally, the right hand started at the left
// shoulder and the left hand, mirroring the movement, crossed to the right shoulder top (the
// corpus's sześć tygodni temu 115 mm deep).
TEST(SynthesisLocation, APairWrittenAtOneSideOfAPlaceIsEachHandAtItsOwnSide) {
  expect_each_hand_on_its_own_side(
      "hamsymmlr,hamfinger2345,hamthumboutmod,hamextfingeru,hampalmd,"
      "hamparbegin,hamlrat,hamshoulders,hamplus,hamlrat,hamshoulders,hamparend,"
      "hamparbegin,hammoveil,hamclose,hamreplace,hamextfingeri,hampalmd,hamlrat,hamshouldertop,"
      "hamparend",
      "hamsymmlr,hamfinger2345,hamthumboutmod,hamextfingeru,hampalmd,"
      "hamparbegin,hamshoulders,hamlrat,hamplus,hamlrat,hamshoulders,hamparend,"
      "hamparbegin,hammoveil,hamclose,hamreplace,hamextfingeri,hampalmd,hamshouldertop,hamlrat,"
      "hamparend");
}

// A symmetric sign that writes the two hands' configurations and one place ("hamsymmpar
// hamparbegin config hamplus config hamparend hamshoulders hamclose"): the other hand is at the
// mirror place, as a hand copied under a symmetry is. Its HandSpec, made for the configurations,
// kept neutral space (the corpus's dziewięć tygodni temu: the left hand from there to the right
// shoulder top, 109 mm deep).
TEST(SynthesisLocation, APairWithTwoConfigurationsAndOnePlaceHasTheOtherHandAtTheMirrorPlace) {
  expect_each_hand_on_its_own_side(
      "hamsymmlr,hamparbegin,hamfinger2345,hamthumbacrossmod,hamextfingeru,hampalmd,hamplus,"
      "hamfinger2345,hamthumboutmod,hamextfingeru,hampalmd,hamparend,hamchest,hamlrbeside,hamclose,"
      "hammoveu",
      "hamsymmlr,hamparbegin,hamfinger2345,hamthumbacrossmod,hamextfingeru,hampalmd,hamplus,"
      "hamfinger2345,hamthumboutmod,hamextfingeru,hampalmd,hamparend,"
      "hamparbegin,hamchest,hamlrbeside,hamclose,hamplus,hamlrbeside,hamchest,hamclose,hamparend,"
      "hammoveu");
}

}  // namespace
}  // namespace sw::synthesis
