// Thorax turn (thorax_turn.h): a one-handed sign's hand low on the far side of the body turns the
// upper body towards that side. The frame change is exact for everything rigid with the upper
// chest; the clip carries the turn in the trunk chain, eased in and out by the transitions; the
// head turns three quarters of the way back; a touch still lands on its anchor on the turned
// body; a left-handed signer turns the other way; signs elsewhere do not turn.
#include "synthesis/thorax_turn.h"

#include <gtest/gtest.h>

#include "synthesis/collision.h"
#include "synthesis/hand_parts.h"
#include "synthesis/transition.h"
#include "synthesis/sign_motion.h"
#include "synthesis_fixture.h"

namespace sw::synthesis {
namespace {

using namespace testing;
using notation::BodyLevel;
using notation::Contact;
using notation::Side;
using Side_ = sw::synthesis::Side;

// Signed angle (radians) of a joint's posed forward about the body's up, towards the left.
float turn_about_up(const Rig& rig, const PoseBuilder& pb, int joint) {
  glm::vec3 f = pb.delta(joint) * rig.forward;
  f -= glm::dot(f, rig.up) * rig.up;
  return std::atan2(glm::dot(f, rig.left), glm::dot(f, rig.forward));
}

TEST(ThoraxTurn, FramesPosedWithTheTurnAreTheThoraxFrameTurnedRigidly) {
  std::string error;
  NamedRigs rigs = reference_and_project_avatar(&error);
  ASSERT_TRUE(error.empty()) << error;
  // Every joint with a different rest rotation: the locals' formula must not assume axes.
  rigs.push_back({"re-rigged", make_rotated_variant(0.9f)});
  for (const auto& [name, av] : rigs) {
    SCOPED_TRACE(name);
    SynthContext ctx;
    ASSERT_TRUE(make_context(av, SynthesisOptions{}, &ctx, &error)) << error;
    const Rig& rig = ctx.rig;
    const ThoraxTurn turn = make_thorax_turn(rig, 0.35f);
    ASSERT_TRUE(turn.active());
    PoseBuilder solved(rig), turned(rig);
    solved.set_from_local(ctx.rest_locals.data());
    std::vector<glm::quat> locals = ctx.rest_locals;
    apply_thorax_turn(rig, turn, locals.data());
    turned.set_from_local(locals.data());
    // Everything from the shoulders down: the thorax frame's pose turned about the upper chest.
    for (Side_ s : {kLeft, kRight})
      for (int j : {rig.arms[s].upper, rig.arms[s].lower, rig.arms[s].hand}) {
        const glm::vec3 expect = turn.rotation * (solved.position(j) - turn.pivot_bind) + turn.pivot_posed;
        EXPECT_LT(glm::length(turned.position(j) - expect), 1e-5f) << rig.names[j];
      }
    // The upper chest turned 0.35 rad towards the left; the head a quarter of it.
    EXPECT_NEAR(turn_about_up(rig, turned, turn.top), 0.35f, 1e-4f);
    EXPECT_NEAR(turn_about_up(rig, turned, rig.head), 0.35f * (1.0f - kHeadTurnBack), 1e-4f);
    // The hips stay.
    EXPECT_NEAR(turn_about_up(rig, turned, rig.hips), 0.0f, 1e-6f);
  }
}

TEST(ThoraxTurn, AFistTouchingBesideTheFarSideOfTheWaistTurnsTheBodyAndStillTouches) {
  avatar::Avatar av = make_reference_humanoid();
  for (bool left_handed : {false, true}) {
    SynthesisOptions opt;
    opt.left_handed = left_handed;
    SynthContext ctx;
    std::string error;
    ASSERT_TRUE(make_context(av, opt, &ctx, &error)) << error;
    const Rig& rig = ctx.rig;
    notation::SignSpec s = sign_at(fist(), BodyLevel::Waist, Side::LeftBeside, Contact::Touch);
    s.dominant.orientation.extended_finger = {0, 1, 0};
    s.dominant.orientation.palm = {0, 0, -1};
    SynthesisResult r = synthesize_sign(s, av, opt);
    ASSERT_TRUE(r.ok()) << r.errors[0].message;
    const int top = rig.upper_chest >= 0 ? rig.upper_chest : rig.chest;
    // Towards the far side: the right hand's far side is the left (+), the left hand's the right.
    const float sign = left_handed ? -1.0f : 1.0f;
    const Side_ hand = left_handed ? kLeft : kRight;
    PoseBuilder pb(rig);
    int sign_frames = 0;
    for (const auto& sg : r.clip.segments) {
      if (sg.kind != ClipSegment::Kind::Sign) continue;
      const int f0 = static_cast<int>(std::lround(sg.start_s * r.clip.fps));
      const int f1 = std::min(r.clip.frame_count - 1, static_cast<int>(std::lround(sg.end_s * r.clip.fps)));
      for (int f = f0; f <= f1; ++f, ++sign_frames) {
        pb.set_from_local(&r.clip.rotations[static_cast<size_t>(f) * rig.joint_count]);
        EXPECT_NEAR(sign * turn_about_up(rig, pb, top), 0.35f, 1e-3f) << "frame " << f;
        // The face stays towards the addressee: a quarter of the turn (5 degrees).
        EXPECT_NEAR(sign * turn_about_up(rig, pb, rig.head), 0.35f * (1.0f - kHeadTurnBack), 2e-3f) << "frame " << f;
        // The fist's palm on its anchor, on the turned body (the waist is on the spine).
        PartPoint anchor;
        ASSERT_TRUE(anchor_point(av, pb, body_anchor_name(s.dominant.location, left_handed), &anchor));
        const PartPoint palm = hand_part(pb, hand, notation::HandPlace::Palm, 1);
        EXPECT_LT(glm::length(palm.point - anchor.point), 0.01f) << "frame " << f;
      }
    }
    EXPECT_GT(sign_frames, 0);
    // The rest poses at both ends are not turned: the transitions ease the turn in and out.
    for (int f : {0, r.clip.frame_count - 1}) {
      pb.set_from_local(&r.clip.rotations[static_cast<size_t>(f) * rig.joint_count]);
      EXPECT_NEAR(turn_about_up(rig, pb, top), 0.0f, 1e-4f) << "frame " << f;
    }
  }
}

// At the far ear the head turns towards the reaching hand (0.4 rad) and the thorax stays: the
// reference humanoid's fist touching the far ear had its forearm 13.7 mm in the head; with the
// head turned it is within 5 mm and the fist still on the ear's anchor on the turned head. A
// left-handed signer's head turns the other way.
TEST(ThoraxTurn, TheHeadTurnsTowardsAHandAtTheFarEar) {
  avatar::Avatar av = make_reference_humanoid();
  for (bool left_handed : {false, true}) {
    SynthesisOptions opt;
    opt.left_handed = left_handed;
    SynthContext ctx;
    std::string error;
    ASSERT_TRUE(make_context(av, opt, &ctx, &error)) << error;
    const Rig& rig = ctx.rig;
    notation::SignSpec s = sign_at(fist(), BodyLevel::Ears, Side::Left, Contact::Touch);
    s.dominant.orientation.extended_finger = {0, 1, 0};
    s.dominant.orientation.palm = {0, 0, -1};
    SynthesisResult r = synthesize_sign(s, av, opt);
    ASSERT_TRUE(r.ok()) << r.errors[0].message;
    const int top = rig.upper_chest >= 0 ? rig.upper_chest : rig.chest;
    // Towards the reaching hand: the right hand's side is a negative turn about up.
    const float towards_hand = left_handed ? 1.0f : -1.0f;
    const Side_ hand = left_handed ? kLeft : kRight;
    PoseBuilder pb(rig);
    int sign_frames = 0;
    for (const auto& sg : r.clip.segments) {
      if (sg.kind != ClipSegment::Kind::Sign) continue;
      const int f0 = static_cast<int>(std::lround(sg.start_s * r.clip.fps));
      const int f1 = std::min(r.clip.frame_count - 1, static_cast<int>(std::lround(sg.end_s * r.clip.fps)));
      for (int f = f0; f <= f1; ++f, ++sign_frames) {
        pb.set_from_local(&r.clip.rotations[static_cast<size_t>(f) * rig.joint_count]);
        EXPECT_NEAR(turn_about_up(rig, pb, top), 0.0f, 1e-4f) << "frame " << f;
        EXPECT_NEAR(towards_hand * turn_about_up(rig, pb, rig.head), 0.4f, 2e-3f) << "frame " << f;
        PartPoint ear;
        ASSERT_TRUE(anchor_point(av, pb, body_anchor_name(s.dominant.location, left_handed), &ear));
        EXPECT_LT(glm::length(hand_part(pb, hand, notation::HandPlace::Palm, 1).point - ear.point), 0.01f)
            << "frame " << f;
        for (Side_ side : {kLeft, kRight}) {
          const bool contact = r.report.intended_contact[f] & exempt_bit(side, false);
          EXPECT_LE(arm_penetration(ctx.body, pb, side, true, contact, false).depth_m, 0.005f) << "frame " << f;
        }
      }
    }
    EXPECT_GT(sign_frames, 0) << "left-handed " << left_handed;
  }
}

TEST(ThoraxTurn, SignsElsewhereDoNotTurn) {
  avatar::Avatar av = make_reference_humanoid();
  SynthContext ctx;
  std::string error;
  ASSERT_TRUE(make_context(av, SynthesisOptions{}, &ctx, &error)) << error;
  const Rig& rig = ctx.rig;
  struct Place { BodyLevel level; Side side; };
  // The near side low down, the far side at the chest (its anchors turn with the chest: a turn
  // would change nothing there), neutral space.
  for (const Place& p : {Place{BodyLevel::Waist, Side::RightBeside}, Place{BodyLevel::Waist, Side::Right},
                         Place{BodyLevel::Chest, Side::LeftBeside}, Place{BodyLevel::NeutralSpace, Side::Centre}}) {
    notation::SignSpec s = sign_at(fist(), p.level, p.side, Contact::Touch);
    SynthesisResult r = synthesize_sign(s, av, SynthesisOptions{});
    ASSERT_TRUE(r.ok()) << r.errors[0].message;
    PoseBuilder pb(rig);
    for (int f = 0; f < r.clip.frame_count; ++f) {
      pb.set_from_local(&r.clip.rotations[static_cast<size_t>(f) * rig.joint_count]);
      ASSERT_EQ(turn_about_up(rig, pb, rig.upper_chest >= 0 ? rig.upper_chest : rig.chest), 0.0f)
          << "level " << static_cast<int>(p.level) << " frame " << f;
    }
  }
}

}  // namespace
}  // namespace sw::synthesis
