// Transitions (seed 004 eqs 8-10): state counts follow k = coef * L_max, rotations interpolate on
// the shortest path without flips, velocities are continuous across every join, and a transition
// that would pass through the body is routed through a via-pose.
#include "synthesis/transition.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "notation/parse.h"
#include "synthesis/collision.h"
#include "synthesis/sign_motion.h"
#include "synthesis_fixture.h"

namespace sw::synthesis {
namespace {

using namespace testing;
using notation::BodyLevel;
using notation::Contact;
using notation::Side;

std::vector<PhraseItem> letters(const std::vector<notation::SignSpec>& signs) {
  std::vector<PhraseItem> items;
  for (size_t i = 0; i < signs.size(); ++i) {
    PhraseItem it;
    it.kind = PhraseItem::Kind::Letter;
    it.sign = signs[i];
    it.label = std::string(1, static_cast<char>('A' + i));
    it.word_index = 0;
    items.push_back(it);
  }
  return items;
}

TEST(SynthesisTransition, StateCountFollowsEquation10) {
  EXPECT_EQ(transition_states(0.0f, 30.0f, 1.0f), kMinTransitionStates);
  EXPECT_EQ(transition_states(0.5f, 30.0f, 1.0f), 15);   // 30 states/m * 0.5 m
  EXPECT_EQ(transition_states(0.5f, 60.0f, 1.0f), 30);   // same duration at 60 fps
  EXPECT_EQ(transition_states(0.5f, 30.0f, 2.0f), 8);    // twice the speed: ceil(7.5)
}

TEST(SynthesisTransition, PhraseTransitionsHaveTheStateCountOfEquation10) {
  avatar::Avatar av = make_reference_humanoid();
  SynthContext ctx;
  std::string error;
  ASSERT_TRUE(make_context(av, SynthesisOptions{}, &ctx, &error));
  SynthesisOptions opt;
  opt.avoid_collisions = false;  // routing lengthens L_max on purpose; test the plain equation
  SynthesisResult r = synthesize_phrase(
      letters({sign_at(fist(), BodyLevel::NeutralSpace, Side::Right, Contact::None),
               sign_at(flat(), BodyLevel::Chin, Side::Centre, Contact::Close),
               sign_at(index_point(), BodyLevel::Chest, Side::Left, Contact::Close)}),
      av, opt);
  ASSERT_TRUE(r.ok());
  const Clip& c = r.clip;
  const int J = c.joint_count();
  int checked = 0;
  for (const auto& seg : c.segments) {
    if (seg.kind != ClipSegment::Kind::Transition) continue;
    int a = static_cast<int>(std::lround(seg.start_s * c.fps)), b = static_cast<int>(std::lround(seg.end_s * c.fps));
    // L_max along the path the joints travel (transition.h), which is never shorter than the
    // straight distance of the seed's formula.
    const glm::quat* from = &c.rotations[static_cast<size_t>(a) * J];
    const glm::quat* to = &c.rotations[static_cast<size_t>(b) * J];
    float lmax = transition_path_m(ctx.rig, from, to);
    EXPECT_GE(lmax + 1e-4f, transition_lmax(ctx.rig, from, to)) << "transition at " << seg.start_s;
    EXPECT_EQ(b - a, transition_states(lmax, c.fps, 1.0f)) << "transition at " << seg.start_s;
    ++checked;
  }
  EXPECT_EQ(checked, 4);  // rest -> A -> B -> C -> rest
}

// Angular speed of every joint between consecutive frames; the change of that speed from one
// frame to the next is bounded (no velocity jump anywhere, joins included).
float max_velocity_jump(const Clip& c) {
  const int J = c.joint_count();
  float worst = 0.0f;
  for (int f = 1; f + 1 < c.frame_count; ++f)
    for (int j = 0; j < J; ++j) {
      const glm::quat& q0 = c.rotations[static_cast<size_t>(f - 1) * J + j];
      const glm::quat& q1 = c.rotations[static_cast<size_t>(f) * J + j];
      const glm::quat& q2 = c.rotations[static_cast<size_t>(f + 1) * J + j];
      // Angular velocity vectors (axis * angle) in the joint's frame.
      auto omega = [](const glm::quat& a, const glm::quat& b) {
        glm::quat d = glm::conjugate(a) * b;
        if (d.w < 0) d = -d;
        float ang = rotation_angle(d);
        glm::vec3 v(d.x, d.y, d.z);
        float len = glm::length(v);
        return len > 1e-9f ? v / len * ang : glm::vec3(0.0f);
      };
      worst = std::max(worst, glm::length(omega(q1, q2) - omega(q0, q1)));
    }
  return worst;
}

TEST(SynthesisTransition, VelocitiesAreContinuousAcrossJoins) {
  avatar::Avatar av = make_reference_humanoid();
  SynthesisResult r = synthesize_phrase(
      letters({sign_at(fist(), BodyLevel::NeutralSpace, Side::Right, Contact::None),
               sign_at(flat(), BodyLevel::Forehead, Side::Right, Contact::Touch),
               sign_at(index_point(), BodyLevel::Chest, Side::Centre, Contact::Touch),
               sign_at(fist(), BodyLevel::NeutralSpace, Side::Centre, Contact::None)}),
      av);
  ASSERT_TRUE(r.ok());
  const Clip& c = r.clip;
  // Peak angular speed per frame for scale.
  float peak = 0.0f;
  const int J = c.joint_count();
  for (int f = 1; f < c.frame_count; ++f)
    for (int j = 0; j < J; ++j)
      peak = std::max(peak, rotation_angle(glm::conjugate(c.rotations[static_cast<size_t>(f - 1) * J + j]) *
                                           c.rotations[static_cast<size_t>(f) * J + j]));
  ASSERT_GT(peak, 0.05f);
  // A velocity jump (a linear blend starting at full speed) would be about the peak itself; with
  // eased joins the change per frame stays well below it.
  EXPECT_LT(max_velocity_jump(c), 0.6f * peak);
  // And exactly at each join the velocity is (nearly) zero on both sides.
  for (const auto& seg : c.segments) {
    if (seg.kind != ClipSegment::Kind::Transition) continue;
    for (double t : {seg.start_s, seg.end_s}) {
      int f = static_cast<int>(std::lround(t * c.fps));
      if (f <= 0 || f + 1 >= c.frame_count) continue;
      for (int j = 0; j < J; ++j) {
        float before = rotation_angle(glm::conjugate(c.rotations[static_cast<size_t>(f - 1) * J + j]) * c.rotations[static_cast<size_t>(f) * J + j]);
        float after = rotation_angle(glm::conjugate(c.rotations[static_cast<size_t>(f) * J + j]) * c.rotations[static_cast<size_t>(f + 1) * J + j]);
        EXPECT_LT(std::fabs(after - before), 0.25f * peak) << "joint " << c.joint_names[j] << " at " << t;
      }
    }
  }
}

TEST(SynthesisTransition, ShortestPathNeverFlips) {
  // Two rotations 170 degrees apart the long way and 190 the short way: every interpolated state
  // must lie on the short arc (angle to either end <= the short distance).
  glm::quat a = axis_angle(glm::vec3(0, 1, 0), 0.0f);
  glm::quat b = -axis_angle(glm::vec3(0, 1, 0), 3.3f);  // same rotation, negated quaternion
  float total = rotation_angle(glm::conjugate(a) * b);
  for (int i = 0; i <= 10; ++i) {
    glm::quat q = slerp_shortest(a, b, i / 10.0f);
    EXPECT_LE(rotation_angle(glm::conjugate(a) * q), total + 1e-4f);
    EXPECT_LE(rotation_angle(glm::conjugate(q) * b), total + 1e-4f);
  }
}

// The transitions from the rest pose to a lexicon sign's first key pose and back (every dictionary
// lookup starts and ends with them) take the hand's own path where it is clear of the body
// (plan_hand_path): slerped arm joints swung the wrist along an arc and tumbled the hand, so ME's
// index tip travelled 1.53 m for 0.58 m straight and the raise took 1.53 s on the project avatar,
// 1.70 s on the reference humanoid; the lexicon's median rest transition 1.07 s on both. The
// hand's path made them 1.00 / 1.10 s (ME) and 0.90 / 0.93 s (median): eq. (10)'s L_max was
// still the index tip's path, 2.2 times the wrist's as the hand turns from hanging to its sign.
// With L_max the arm's path (coef's 1 m/s is a hand speed) and the fingers held to 2.5 m/s at
// their peak: ME 0.73 / 0.83 s, median 0.70 / 0.73 s, where a signer raises the hand to the chest
// in about 0.6-0.8 s. Bounds, with two frames of margin: ME's raise and lowering within 0.9 s
// and the median of all within 0.8 s on both rigs (the direct slerped path fails both, and so
// does the hand's path timed by its fingertips). The slowest: where the hand's first path was
// not clear of the body, it fell back to the direct path (40 of the 564); tried again with the
// swivel searched and bowed further forward, 26 are left and the project avatar's slowest went
// 1.47 -> 1.27 s (DEAF); on the reference humanoid MORNING stays 2.13 s (its left arm carries
// the right elbow; routed, docs/SYNTHESIS.md Known issues). Since the arm IK's swivel change
// (merged) MORNING and DEAF take the hand's path (0.73-0.90 s), and the slowest were the direct
// paths left, timed by their fingertips: DAY's hands leaving each other for the rest, 1.43 s
// (reference) / 1.27 s (avatar). Those fallbacks (direct path, via-poses) are now timed by the
// arm as the hand's path is (transition.cpp time_rest_path_by_arm): DAY 1.07 / 0.93 s, the
// slowest of all 1.10 s on both rigs (TEACH's and TEACHER's raise, their hand's path stretched
// for the arm's 40 m/s^2). Bound: 1.2 s on both rigs (three frames of margin; the old timing
// fails it on both).

TEST(SynthesisTransition, RestTransitionsTakeTheHandsShortPath) {
  std::string text;
  if (!read_text_file(std::string(SIGNWEAVE_SOURCE_DIR) + "/data/ase/lexicon.jsonl", &text))
    GTEST_SKIP() << "no data/ase/lexicon.jsonl";
  std::string rig_error;
  const NamedRigs rigs = reference_and_project_avatar(&rig_error);
  ASSERT_TRUE(rig_error.empty()) << rig_error;
  const std::vector<LexiconSign> signs = lexicon_signs(text);
  for (const auto& [rig_name, av] : rigs) {
    Synthesizer synth(av);
    ASSERT_TRUE(synth.ok()) << synth.error();
    std::vector<double> durations_s;
    bool saw_me = false;
    for (const LexiconSign& sign : signs) {
      ASSERT_TRUE(sign.text.ok()) << sign.gloss;
      SynthesisResult r = synth.phrase(sign.text.items, SynthesisOptions{});
      ASSERT_TRUE(r.ok()) << sign.gloss;
      std::vector<const ClipSegment*> moves;
      for (const ClipSegment& seg : r.clip.segments)
        if (seg.kind == ClipSegment::Kind::Transition) moves.push_back(&seg);
      ASSERT_GE(moves.size(), 2u) << sign.gloss;
      for (const ClipSegment* seg : {moves.front(), moves.back()}) {
        const double duration_s = seg->end_s - seg->start_s;
        durations_s.push_back(duration_s);
        if (sign.gloss == "ME") {
          saw_me = true;
          EXPECT_LE(duration_s, 0.9) << rig_name << ": ME " << (seg == moves.front() ? "from" : "back to") << " rest";
        }
      }
    }
    EXPECT_TRUE(saw_me) << "ME is not in the lexicon";
    ASSERT_GE(durations_s.size(), 220u);
    std::sort(durations_s.begin(), durations_s.end());
    const double median_s = durations_s[durations_s.size() / 2];
    EXPECT_LE(median_s, 0.8) << rig_name << ": median rest transition";
    EXPECT_LE(durations_s.back(), 1.2) << rig_name << ": slowest rest transition";
    RecordProperty(rig_name + "_slowest_rest_transition_s", std::to_string(durations_s.back()));
    RecordProperty(rig_name + "_median_rest_transition_s", std::to_string(median_s));
  }
}

// Hands that would go into each other on the way are parted (plan_transition: each wrist held out
// to its own side and forward). HAVE's and FAMILY's hands leave their contact for the rest pose,
// SAD's spread hands leave the face: their escape pushes point each hand along the other and
// cancel, and the hands passed 8-16 mm into each other. Over the transition back to the rest, outside the intended
// contact, no hand is more than 5 mm in the other hand or forearm.
TEST(SynthesisTransition, HandsLeavingEachOtherForTheRestArePartedNotPassedThrough) {
  std::string text;
  if (!read_text_file(std::string(SIGNWEAVE_SOURCE_DIR) + "/data/ase/lexicon.jsonl", &text))
    GTEST_SKIP() << "no data/ase/lexicon.jsonl";
  std::string rig_error;
  const NamedRigs rigs = reference_and_project_avatar(&rig_error);
  ASSERT_TRUE(rig_error.empty()) << rig_error;
  const std::vector<LexiconSign> signs = lexicon_signs(text);
  int checked = 0;
  for (const auto& [rig_name, av] : rigs) {
    Synthesizer synth(av);
    ASSERT_TRUE(synth.ok()) << synth.error();
    SynthContext ctx;
    std::string error;
    ASSERT_TRUE(make_context(av, SynthesisOptions{}, &ctx, &error)) << error;
    const int J = ctx.rig.joint_count;
    for (const LexiconSign& sign : signs) {
      if (sign.gloss != "HAVE" && sign.gloss != "FAMILY" && sign.gloss != "SAD") continue;
      ASSERT_TRUE(sign.text.ok()) << sign.gloss;
      SynthesisResult r = synth.phrase(sign.text.items, SynthesisOptions{});
      ASSERT_TRUE(r.ok()) << sign.gloss;
      ASSERT_EQ(r.clip.joint_count(), J);
      const ClipSegment& back = r.clip.segments.back();
      ASSERT_EQ(back.kind, ClipSegment::Kind::Transition) << sign.gloss;
      const int first = static_cast<int>(std::lround(back.start_s * r.clip.fps));
      const int last = std::min(r.clip.frame_count - 1, static_cast<int>(std::lround(back.end_s * r.clip.fps)));
      float depth_m = 0.0f;
      PoseBuilder pb(ctx.rig);
      for (int f = first; f <= last; ++f) {
        const std::uint8_t ex = r.report.intended_contact[static_cast<size_t>(f)];
        if ((ex & exempt_bit(kLeft, true)) || (ex & exempt_bit(kRight, true))) continue;
        pb.set_from_local(&r.clip.rotations[static_cast<size_t>(f) * J]);
        for (synthesis::Side s : {kLeft, kRight}) depth_m = std::max(depth_m, hand_penetration(ctx.body, pb, s, false, true).depth_m);
      }
      EXPECT_LE(depth_m, 0.005f) << rig_name << " " << sign.gloss << ": hands through each other on the way to the rest";
      ++checked;
    }
  }
  EXPECT_EQ(checked, 3 * static_cast<int>(rigs.size())) << "HAVE, FAMILY or SAD is not in the lexicon";
}

// The final check of a phrase takes the frames the transitions already checked from the memo
// (transition.h): what it reports must be what checking them again reports — the same depth, the
// same name, the same frame — also when the face layer has turned only the eyes, and a frame it
// has not seen (or the same frame with other exemptions) must be checked, not looked up.
TEST(SynthesisTransition, PenetrationMemoGivesWhatTheChecksGive) {
  avatar::Avatar av = make_reference_humanoid();
  SynthContext ctx;
  std::string error;
  ASSERT_TRUE(make_context(av, SynthesisOptions{}, &ctx, &error)) << error;
  const int J = ctx.rig.joint_count;
  // The palm on the chest with the fingers pointing into it (SynthesisCollision's case): without
  // the exemption of the intended contact, its frames penetrate.
  notation::SignSpec s = sign_at(flat(), BodyLevel::Chest, Side::Centre, Contact::Touch);
  s.dominant.orientation.extended_finger = {0, 0, -1};
  s.dominant.orientation.palm = {0, -1, 0};
  s.dominant.location.contact_part = notation::HandPlace::Palm;
  SynthesisOptions off;
  off.avoid_collisions = false;
  SynthesisResult r = synthesize_sign(s, av, off);
  ASSERT_TRUE(r.ok());
  std::vector<glm::quat> frames = r.clip.rotations;
  const int n = r.clip.frame_count;
  const std::vector<std::uint8_t> none(static_cast<size_t>(n), 0);
  const std::vector<std::uint8_t>& intended = r.report.intended_contact;
  auto check = [&](const SynthContext& c, const std::vector<glm::quat>& f, const std::vector<std::uint8_t>& ex) {
    std::string what;
    int frame = -1;
    float depth = max_penetration(c, f.data(), n, ex.data(), &what, &frame);
    return std::make_tuple(depth, what, frame);
  };
  const auto plain = check(ctx, frames, none);
  ASSERT_GT(std::get<0>(plain), 0.005f);
  ASSERT_FALSE(std::get<1>(plain).empty());

  SynthContext with_memo = ctx;
  PenetrationMemo memo(with_memo);
  with_memo.penetration_memo = &memo;
  EXPECT_EQ(check(with_memo, frames, none), plain);  // fills the memo
  EXPECT_EQ(check(with_memo, frames, none), plain);  // every frame from the memo

  // Other exemptions: the intended contact is exempt, so the depth is smaller.
  const auto exempt_plain = check(ctx, frames, intended);
  EXPECT_LT(std::get<0>(exempt_plain), std::get<0>(plain));
  EXPECT_EQ(check(with_memo, frames, intended), exempt_plain);

  // The eyes turned on every frame: not part of what the checks read.
  std::vector<glm::quat> eyes = frames;
  int turned = 0;
  for (int j = 0; j < J; ++j) {
    if (ctx.rig.names[j] != "leftEye" && ctx.rig.names[j] != "rightEye") continue;
    for (int f = 0; f < n; ++f) eyes[static_cast<size_t>(f) * J + j] *= axis_angle(glm::vec3(0, 1, 0), 0.01f * (f + 1));
    ++turned;
  }
  EXPECT_EQ(turned, 2);
  EXPECT_EQ(check(with_memo, eyes, none), plain);

  // The right hand turned on the deepest frame: a new frame, checked (the memo would give the old
  // frame's depth).
  std::vector<glm::quat> moved = frames;
  const int worst = std::get<2>(plain);
  const int hand = ctx.rig.arms[kRight].hand;
  moved[static_cast<size_t>(worst) * J + hand] *= axis_angle(glm::vec3(1, 0, 0), 0.4f);
  const auto moved_plain = check(ctx, moved, none);
  EXPECT_EQ(check(with_memo, moved, none), moved_plain);
}

// A rest transition that neither the hand's path (adding nothing beyond its end poses) nor any
// via-pose or waypoint chain clears took the best route (transition.cpp): the hand's path tries,
// rejected at the first state deeper than the ends + 0.5 mm, were never measured against it.
// plan_hand_path_least_deep takes the try that adds least where it beats the route. Hand-written
// minimal HamNoSys of the corpus's form (its GROUP1D: 5.3 mm routed, 2.7 mm along the hand's path):
// mirrored C hands, fingers out-left, palms left, moving left to touch, on the project avatar.
TEST(SynthesisTransition, ARestTransitionNoRouteClearsTakesTheHandsPathThatAddsLeast) {
  ProjectAvatar project = load_project_avatar();
  if (!project.present) GTEST_SKIP() << "models/signweave-avatar.glb not found";
  ASSERT_TRUE(project.error.empty()) << project.error;
  // hamsymmlr hamcee12 [hamthumbopenmod] hamextfingerol hampalml hammovel hamtouch
  const std::string cee = "\xee\x83\xa9\xee\x80\x89", thumb_open = "\xee\x80\x8e";
  const std::string rest_of_it = "\xee\x80\xa8\xee\x80\xbe\xee\x82\x86\xee\x83\x91";
  for (const std::string& hns : {cee + thumb_open + rest_of_it, cee + rest_of_it}) {
    const std::vector<notation::SignParse> parsed = notation::parse_signs(hns, notation::NotationFormat::HamNoSys);
    ASSERT_FALSE(parsed.empty());
    ASSERT_TRUE(parsed[0].ok() && parsed[0].spec);
    const SynthesisResult r = synthesize_sign(*parsed[0].spec, project.avatar, SynthesisOptions{});
    ASSERT_TRUE(r.ok());
    EXPECT_LE(r.report.max_penetration_m, 0.005f) << (hns.size() > cee.size() + rest_of_it.size() ? "thumb open" : "");
  }
}

// hands-meet: a rest transition into a sign whose hands touch or nearly touch each other ran
// both wrists straight to their places, and the hands met part way (on the corpus 44 of the 56
// rest transitions over 5 mm were a hand 7-16 mm in the other hand, their frames carrying no
// hand-contact exemption). The hand's path now has tries that hold the wrists apart along the
// line between the hands, turned as at the sign, until the last quarter (transition.cpp
// hands_meet_at_sign). Hand-written minimal HamNoSys of the corpus's form: symmetric C hands,
// fingers up, palms down-left, touching, moving down; on the project avatar 6.8 mm before (the
// hands into each other on the way up from the rest), 5.5 mm with the wrists apart but the hands
// still turning as they closed, 4.4 mm now. Still open: the flat hands' roof (HOUSE1B's form,
// 13.6 mm).
TEST(SynthesisTransition, HandsThatTouchAtTheSignMeetOnlyAtTheEndOfTheRestTransition) {
  ProjectAvatar project = load_project_avatar();
  if (!project.present) GTEST_SKIP() << "models/signweave-avatar.glb not found";
  ASSERT_TRUE(project.error.empty()) << project.error;
  // hamsymmlr hamceeall hamextfingeru hampalmdl hamtouch hammoved
  const std::string hns = "\xee\x83\xa9\xee\x80\x8a\xee\x80\xa0\xee\x80\xbd\xee\x83\x91\xee\x82\x84";
  const std::vector<notation::SignParse> parsed = notation::parse_signs(hns, notation::NotationFormat::HamNoSys);
  ASSERT_FALSE(parsed.empty());
  ASSERT_TRUE(parsed[0].ok() && parsed[0].spec);
  const SynthesisResult r = synthesize_sign(*parsed[0].spec, project.avatar, SynthesisOptions{});
  ASSERT_TRUE(r.ok());
  EXPECT_LE(r.report.max_penetration_m, 0.005f);
}

// rest-meet: hands whose parts pass each other at the sign closed into each other in the rest
// transition's last states however they were held apart on the way: the hands-apart tries' last
// waypoint (three quarters of the way) still had the hands turning and the fingers forming, and
// the joint-space path from there to the key pose is no straight approach; and along the line
// between the palm centres no straight approach is clear at all where the hands' parts cross at
// the sign. The approach tries (transition.cpp approach_dirs, kApproachFractions) bring each hand
// in along a line the hands stay clear along, with the sign's orientation, elbow and handshape
// held, through waypoints 3 cm and 1 cm off. Hand-written minimal HamNoSys of the corpus's form
// (TO-TOUCH1A, SOFT1B, MONTH-CALENDAR2: 8.6 mm in the rest transition in): symmetric C hands,
// thumbs open, fingers straight, fingers up, palms down-left; the open thumbs cross under the
// palms. Before (the thumbs through each other in the approach's last frames): 9.1 mm on the
// reference humanoid, 7.4 mm on the project avatar; now 2.9 and 0.1 mm.
TEST(SynthesisTransition, HandsWhosePartsCrossAtTheSignCloseAlongALineTheyStayClearAlong) {
  // hamsymmlr hamceeall hamthumbopenmod hamfingerstraightmod hamextfingeru hampalmdl
  const std::string hns = "\xee\x83\xa9\xee\x80\x8a\xee\x80\x8e\xee\x80\x90\xee\x80\xa0\xee\x80\xbd";
  const std::vector<notation::SignParse> parsed = notation::parse_signs(hns, notation::NotationFormat::HamNoSys);
  ASSERT_FALSE(parsed.empty());
  ASSERT_TRUE(parsed[0].ok() && parsed[0].spec);
  const SynthesisResult reference = synthesize_sign(*parsed[0].spec, make_reference_humanoid(), SynthesisOptions{});
  ASSERT_TRUE(reference.ok());
  EXPECT_LE(reference.report.max_penetration_m, 0.005f) << "reference humanoid";
  ProjectAvatar project = load_project_avatar();
  if (!project.present) GTEST_SKIP() << "models/signweave-avatar.glb not found";
  ASSERT_TRUE(project.error.empty()) << project.error;
  const SynthesisResult r = synthesize_sign(*parsed[0].spec, project.avatar, SynthesisOptions{});
  ASSERT_TRUE(r.ok());
  EXPECT_LE(r.report.max_penetration_m, 0.005f) << "project avatar";
}
}  // namespace
}  // namespace sw::synthesis
