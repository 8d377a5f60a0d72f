// Collisions (issue 4): no frame of an alphabet-like sequence, nor of a transition between any
// two letters, lets a hand penetrate the body or the other hand by more than 5 mm except at an
// intended contact; a transition that would pass through the body is routed via a pulled-out pose.
// The letters are handshape x orientation x location combinations built here (the data
// alphabets are exercised through the notation parser in the CLI/data tests once merged).
#include "synthesis/collision.h"

#include <gtest/gtest.h>

#include "synthesis/transition.h"
#include "synthesis_fixture.h"

namespace sw::synthesis {
namespace {

using namespace testing;
using notation::BodyLevel;
using notation::Contact;
using notation::Direction;
using notation::Side;

std::vector<notation::SignSpec> constructed_alphabet() {
  struct L {
    notation::HandShape shape;
    Direction finger, palm;
    BodyLevel level;
    Side side;
    Contact contact;
  };
  notation::HandShape pinch = flat();
  pinch.fingers[0] = notation::FingerConfig{notation::kThumbPadOnIndex, false, 1.0f, 0.0f};
  notation::HandShape vee = fist();
  vee.fingers[1] = notation::FingerConfig{notation::kFingerSpread, false, 1.0f, 1.0f};
  vee.fingers[2] = notation::FingerConfig{notation::kFingerSpread, false, 1.0f, 1.0f};
  notation::HandShape cee = shape_all(notation::kFingerRound, notation::kThumbOpposed);
  notation::HandShape hook = shape_all(notation::kFingerHooked, notation::kThumbAcross);
  notation::HandShape spread = shape_all(notation::kFingerSpread, notation::kThumbOut, false, 1.0f, 1.0f);
  notation::HandShape horiz = shape_all(notation::kFingerHorizontal, notation::kThumbAlongside);
  const L letters[] = {
      {fist(), {0, 1, 0}, {0, 0, 1}, BodyLevel::Shoulders, Side::Right, Contact::None},
      {flat(), {0, 1, 0}, {0, 0, 1}, BodyLevel::Shoulders, Side::Right, Contact::None},
      {cee, {0, 1, 0}, {1, 0, 0}, BodyLevel::Shoulders, Side::Right, Contact::None},
      {index_point(), {0, 1, 0}, {0, 0, 1}, BodyLevel::Chest, Side::Right, Contact::None},
      {hook, {0, 1, 0}, {0, 0, 1}, BodyLevel::Shoulders, Side::Right, Contact::None},
      {pinch, {0, 1, 0}, {1, 0, 0}, BodyLevel::Shoulders, Side::Right, Contact::None},
      {vee, {1, 0, 0}, {0, 0, -1}, BodyLevel::Chest, Side::Right, Contact::None},
      {index_point(), {0, 0, 1}, {0, -1, 0}, BodyLevel::NeutralSpace, Side::Right, Contact::None},
      {horiz, {1, 0, 0}, {0, -1, 0}, BodyLevel::NeutralSpace, Side::Centre, Contact::None},
      {spread, {0, 1, 0}, {0, 0, 1}, BodyLevel::Chest, Side::Centre, Contact::Close},
      {flat(), {0, 1, 0}, {0, 0, -1}, BodyLevel::Chin, Side::Centre, Contact::Touch},
      {index_point(), {0, 1, 1}, {0, 0, -1}, BodyLevel::Forehead, Side::Right, Contact::Touch},
      {fist(), {1, 0, 0}, {0, 0, -1}, BodyLevel::Chest, Side::Left, Contact::Touch},
  };
  std::vector<notation::SignSpec> out;
  for (const L& l : letters) {
    notation::SignSpec s = sign_at(l.shape, l.level, l.side, l.contact);
    s.dominant.orientation.extended_finger = l.finger;
    s.dominant.orientation.palm = l.palm;
    out.push_back(s);
  }
  return out;
}

std::vector<PhraseItem> items_of(const std::vector<notation::SignSpec>& signs) {
  std::vector<PhraseItem> items;
  for (size_t i = 0; i < signs.size(); ++i) {
    PhraseItem it;
    it.kind = PhraseItem::Kind::Letter;
    it.sign = signs[i];
    it.label = "L" + std::to_string(i);
    items.push_back(it);
  }
  return items;
}

TEST(SynthesisCollision, BodyModelHasCapsulesFromTheSkeleton) {
  avatar::Avatar av = make_reference_humanoid();
  Rig rig;
  std::string error;
  ASSERT_TRUE(build_rig(av, &rig, &error));
  BodyModel body = build_body_model(av, rig);
  ASSERT_EQ(body.trunk.size(), 4u);  // torso halves, neck, head
  for (const Capsule& c : body.trunk) {
    EXPECT_GT(c.radius_m, 0.03f) << c.name;
    EXPECT_LT(c.radius_m, 0.2f) << c.name;
  }
  // A point at the spine is inside; one 40 cm in front is not.
  PoseBuilder pb(rig);
  pb.finalize();
  const Capsule& torso = body.trunk[0];
  EXPECT_LT(segment_distance(rig.bind_pos[rig.chest], torso.a, torso.b), torso.radius_m + 0.1f);
  EXPECT_GT(segment_distance(rig.bind_pos[rig.chest] + glm::vec3(0, 0, 0.4f), torso.a, torso.b), torso.radius_m);
}

TEST(SynthesisCollision, HandInsideTheChestIsDetected) {
  avatar::Avatar av = make_reference_humanoid();
  SynthContext ctx;
  std::string error;
  ASSERT_TRUE(make_context(av, SynthesisOptions{}, &ctx, &error));
  PoseBuilder pb(ctx.rig);
  pb.set_from_local(ctx.rest_locals.data());
  EXPECT_LT(hand_penetration(ctx.body, pb, kRight, true, true).depth_m, 0.005f);  // rest is clean
  // A synthesised sign with collision avoidance off and the hand pushed into the chest.
  notation::SignSpec s = sign_at(flat(), BodyLevel::Chest, Side::Centre, Contact::Touch);
  s.dominant.orientation.extended_finger = {0, 0, -1};  // fingers into the body
  s.dominant.orientation.palm = {0, -1, 0};
  // The palm (not the fingertips) on the chest: the fingers then lie inside it.
  s.dominant.location.contact_part = notation::HandPlace::Palm;
  SynthesisOptions off;
  off.avoid_collisions = false;  // else the hand turns out of the chest (arm_ik.h)
  SynthesisResult r = synthesize_sign(s, av, off);
  ASSERT_TRUE(r.ok());
  // Touch is intended contact: exempt. Without the exemption the same frames penetrate.
  int f = first_sign_frame(r.clip);
  PoseBuilder p2 = frame_pose(ctx.rig, r.clip, f);
  EXPECT_GT(hand_penetration(ctx.body, p2, kRight, true, false).depth_m, 0.005f);
  EXPECT_NE(r.report.intended_contact[f] & exempt_bit(kRight, false), 0);
}

TEST(SynthesisCollision, NoPenetrationInAnAlphabetSequence) {
  avatar::Avatar av = make_reference_humanoid();
  SynthesisResult r = synthesize_phrase(items_of(constructed_alphabet()), av);
  ASSERT_TRUE(r.ok());
  EXPECT_LE(r.report.max_penetration_m, 0.005f)
      << (r.report.warnings.empty() ? "" : r.report.warnings.back());
}

TEST(SynthesisCollision, NoPenetrationInAnyTransitionBetweenTwoLetters) {
  avatar::Avatar av = make_reference_humanoid();
  auto alphabet = constructed_alphabet();
  SynthesisOptions opt;
  opt.start_from_rest = false;
  float worst = 0.0f;
  int vias = 0;
  for (size_t a = 0; a < alphabet.size(); ++a)
    for (size_t b = 0; b < alphabet.size(); ++b) {
      if (a == b) continue;
      SynthesisResult r = synthesize_phrase(items_of({alphabet[a], alphabet[b]}), av, opt);
      ASSERT_TRUE(r.ok());
      EXPECT_LE(r.report.max_penetration_m, 0.005f) << a << " -> " << b << ": "
          << (r.report.warnings.empty() ? "" : r.report.warnings.back());
      worst = std::max(worst, r.report.max_penetration_m);
      vias += r.report.via_points_inserted;
    }
  RecordProperty("max_penetration_mm", std::to_string(worst * 1000.0f));
  RecordProperty("via_points", std::to_string(vias));
}

TEST(SynthesisCollision, CrossBodyTransitionIsRoutedThroughAViaPose) {
  // From touching the left chest to far right beside the body and back, with the hand's path
  // straight through the torso if interpolated naively; the routed clip stays outside.
  avatar::Avatar av = make_reference_humanoid();
  notation::SignSpec a = sign_at(fist(), BodyLevel::Stomach, Side::Left, Contact::Close);
  a.dominant.orientation.extended_finger = {1, 0, 0};
  a.dominant.orientation.palm = {0, 0, -1};
  notation::SignSpec b = sign_at(flat(), BodyLevel::Chest, Side::RightBeside, Contact::None);
  SynthesisResult routed = synthesize_phrase(items_of({a, b, a}), av);
  ASSERT_TRUE(routed.ok());
  EXPECT_LE(routed.report.max_penetration_m, 0.005f);
}

}  // namespace
}  // namespace sw::synthesis
