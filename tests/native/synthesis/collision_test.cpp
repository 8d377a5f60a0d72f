// Collisions (issue 4): no frame of an alphabet-like sequence, nor of a transition between any
// two letters, lets a hand penetrate the body or the other hand by more than 5 mm except at an
// intended contact; a transition that would pass through the body is routed via a pulled-out pose.
// The letters are handshape x orientation x location combinations built here (the data
// alphabets are exercised through the notation parser in the CLI/data tests once merged).
// The arms too: capsule-capsule distance against brute force, upper arm and forearm against the
// trunk and forearm against forearm, hands at the places across the body.
#include "synthesis/collision.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>

#include "notation/hamnosys.h"
#include "synthesis/transition.h"
#include "synthesis_fixture.h"

namespace sw::synthesis {
namespace {

using namespace testing;
using notation::BodyLevel;
using notation::Contact;
using notation::Direction;
using notation::Side;
using Side_ = sw::synthesis::Side;

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

// Deepest arm penetration over a clip's frames, with the exemptions synthesis uses (a hand's
// intended touch lets the forearm's wrist end rest on the body; hands in contact exempt the
// forearm pair).
float worst_arm_depth(const SynthContext& ctx, const SynthesisResult& r, std::string* what) {
  PoseBuilder pb(ctx.rig);
  float worst = 0.0f;
  const auto& ex = r.report.intended_contact;
  for (int f = 0; f < r.clip.frame_count; ++f) {
    pb.set_from_local(&r.clip.rotations[static_cast<size_t>(f) * ctx.rig.joint_count]);
    for (Side_ s : {kLeft, kRight}) {
      bool contact = ex[f] & exempt_bit(s, false);
      bool hands = !(ex[f] & exempt_bit(s, true)) && !(ex[f] & exempt_bit(other(s), true));
      Penetration p = arm_penetration(ctx.body, pb, s, true, contact, hands);
      if (p.depth_m > worst) {
        worst = p.depth_m;
        *what = p.what + " at frame " + std::to_string(f);
      }
    }
  }
  return worst;
}

TEST(SynthesisCollision, SegmentSegmentDistanceMatchesBruteForce) {
  // Deterministic pseudo-random segments in a 20 cm box, plus the awkward cases: parallel,
  // collinear overlapping, crossing, and degenerate (point) segments.
  std::uint32_t state = 12345u;
  auto rnd = [&]() {
    state = state * 1664525u + 1013904223u;
    return static_cast<float>(state >> 8) / static_cast<float>(1u << 24) * 0.2f - 0.1f;
  };
  struct Pair { glm::vec3 p1, q1, p2, q2; };
  std::vector<Pair> pairs = {
      {{0, 0, 0}, {0.1f, 0, 0}, {0, 0.05f, 0}, {0.1f, 0.05f, 0}},        // parallel
      {{0, 0, 0}, {0.1f, 0, 0}, {0.05f, 0, 0}, {0.15f, 0, 0}},           // collinear overlap
      {{0, 0, 0}, {0.1f, 0, 0}, {0.05f, -0.05f, 0.02f}, {0.05f, 0.05f, 0.02f}},  // crossing
      {{0, 0, 0}, {0, 0, 0}, {0.03f, 0.04f, 0}, {0.03f, 0.04f, 0}},      // two points
      {{0.02f, 0.01f, 0}, {0.02f, 0.01f, 0}, {-0.1f, 0, 0}, {0.1f, 0, 0}},  // point and segment
  };
  for (int i = 0; i < 300; ++i)
    pairs.push_back({{rnd(), rnd(), rnd()}, {rnd(), rnd(), rnd()}, {rnd(), rnd(), rnd()}, {rnd(), rnd(), rnd()}});
  for (size_t i = 0; i < pairs.size(); ++i) {
    const Pair& c = pairs[i];
    glm::vec3 on1, on2;
    float d = segment_segment_distance(c.p1, c.q1, c.p2, c.q2, &on1, &on2);
    // Brute force: 2001 points along the first segment, each against the second exactly.
    float brute = 1e9f;
    for (int k = 0; k <= 2000; ++k) {
      glm::vec3 p = c.p1 + (static_cast<float>(k) / 2000.0f) * (c.q1 - c.p1);
      brute = std::min(brute, segment_distance(p, c.p2, c.q2));
    }
    // The sampling step (<= 0.35 mm here) bounds how far brute force can be above the truth.
    float step = glm::length(c.q1 - c.p1) / 2000.0f;
    EXPECT_LE(d, brute + 1e-5f) << "pair " << i;
    EXPECT_GE(d, brute - step - 1e-5f) << "pair " << i;
    // The closest points lie on their segments and realise the distance.
    EXPECT_NEAR(glm::length(on1 - on2), d, 1e-5f) << "pair " << i;
    EXPECT_NEAR(segment_distance(on1, c.p1, c.q1), 0.0f, 1e-5f) << "pair " << i;
    EXPECT_NEAR(segment_distance(on2, c.p2, c.q2), 0.0f, 1e-5f) << "pair " << i;
    // Symmetric in its arguments.
    EXPECT_NEAR(segment_segment_distance(c.p2, c.q2, c.p1, c.q1), d, 1e-5f) << "pair " << i;
  }
}

TEST(SynthesisCollision, ArmInsideTheTorsoIsDetectedAndTheRestPoseIsClean) {
  avatar::Avatar av = make_reference_humanoid();
  SynthContext ctx;
  std::string error;
  ASSERT_TRUE(make_context(av, SynthesisOptions{}, &ctx, &error));
  const Rig& rig = ctx.rig;
  PoseBuilder rest(rig);
  rest.set_from_local(ctx.rest_locals.data());
  for (Side_ s : {kLeft, kRight}) {
    EXPECT_LE(arm_penetration(ctx.body, rest, s, true, false, true).depth_m, 0.0f) << s;
    // The IK-side query agrees with the pose-side one on an unposed trunk.
    EXPECT_LE(arm_trunk_depth(ctx.body, s, posed_arm(rest, s), false), 0.0f) << s;
  }
  // Swing the right arm's elbow into the chest: the upper arm straight across the body (a delta
  // rotation taking the bind arm direction, -X, to +X through the front would be the elbow in
  // front; taking it to point at the spine puts it inside).
  const ArmRig& a = rig.arms[kRight];
  glm::vec3 arm_dir = glm::normalize(rig.bind_pos[a.lower] - rig.bind_pos[a.upper]);
  glm::vec3 to_spine = glm::normalize(rig.bind_pos[rig.chest] - rig.bind_pos[a.upper]);
  PoseBuilder pb(rig);
  pb.set(a.upper, frame_to_frame(arm_dir, rig.up, to_spine, rig.up));
  pb.finalize();
  Penetration p = arm_penetration(ctx.body, pb, kRight, true, false, false);
  EXPECT_GT(p.depth_m, 0.05f);
  EXPECT_NE(p.what.find("right upper arm in torso"), std::string::npos) << p.what;
  EXPECT_GT(glm::dot(p.push_dir, p.push_dir), 0.99f);  // a unit way out
  // Without the trunk check nothing else is touched (the other forearm hangs far away).
  EXPECT_LE(arm_penetration(ctx.body, pb, kRight, false, false, true).depth_m, 0.0f);
  // Forearm against forearm: both forearms swung in across the body at the same height cross
  // at the midline (the trunk check off: only the pair is measured).
  PoseBuilder crossed(rig);
  crossed.set_from_local(ctx.rest_locals.data());
  for (Side_ s : {kLeft, kRight}) {
    const ArmRig& arm = rig.arms[s];
    glm::vec3 fore = glm::normalize(rig.bind_pos[arm.hand] - rig.bind_pos[arm.lower]);
    glm::vec3 medial = s == kLeft ? -rig.left : rig.left;
    crossed.set(arm.lower, frame_to_frame(fore, rig.up, glm::normalize(medial + 0.3f * rig.forward), rig.up));
  }
  crossed.finalize();
  Penetration fp = arm_penetration(ctx.body, crossed, kLeft, false, false, true);
  EXPECT_GT(fp.depth_m, 0.03f);
  EXPECT_NE(fp.what.find("left forearm in right forearm"), std::string::npos) << fp.what;
}

// Hands at the places across the body (the non-dominant side), where the forearm crosses the
// chest and the elbow could sink into the torso: the arm stays out of the trunk by 5 mm, with
// touch and close contact, three hand configurations, on the reference humanoid, the re-rigged
// variant and the project's avatar (all places; the project avatar's known gaps, each held to
// its measured depth rounded up, are in docs/SYNTHESIS.md). The `left_beside` places:
// HandBesideTheFarSide... below.
TEST(SynthesisCollision, HandsAcrossTheBodyKeepTheArmOutOfTheTrunk) {
  struct Place { BodyLevel level; Side side; };
  const std::vector<Place> all_places = {
      {BodyLevel::Shoulders, Side::Left}, {BodyLevel::ShoulderTop, Side::Left},
      {BodyLevel::Cheeks, Side::Left},    {BodyLevel::Ears, Side::Left},
      {BodyLevel::Chin, Side::Left},      {BodyLevel::Neck, Side::Left},
      {BodyLevel::Chest, Side::Left},     {BodyLevel::Stomach, Side::Left},
      {BodyLevel::Waist, Side::Left},
  };
  // The project avatar, worst of the three hands and two contacts: the shoulder top 13.0 mm (a
  // fist held off; 102-116 mm before its held-off direction was searched, sign_motion.cpp); the
  // shoulders 8.5 mm (the fist across the body touching; before the anchor fix and the routing:
  // 96 mm). The ears and the neck are within 5 mm since a hand held off the far side's own place
  // there is held off between the place's normal and forward (sign_motion.cpp body_target):
  // before, the ears' forearm in the head 30.8 mm (the fist across the body held off; 41.5 mm,
  // the pointing hand, before the head turned towards the hand at the far ear), the neck 5.7 mm,
  // and the shoulders' pointing hand held off 7.5 mm.
  const std::map<BodyLevel, float> project_known_mm = {{BodyLevel::ShoulderTop, 13.5f}, {BodyLevel::Shoulders, 9.0f}};
  const std::map<BodyLevel, float> none;
  struct Rig_ { avatar::Avatar avatar; const std::map<BodyLevel, float>* known; };
  std::vector<Rig_> rigs;
  rigs.push_back({make_reference_humanoid(), &none});
  rigs.push_back({make_rotated_variant(0.9f), &none});
  ProjectAvatar project = load_project_avatar();
  ASSERT_TRUE(project.error.empty()) << project.error;
  if (project.present) rigs.push_back({std::move(project.avatar), &project_known_mm});
  struct Hand { notation::HandShape shape; Direction finger, palm; };
  const Hand hands[] = {
      {flat(), {0, 1, 0}, {0, 0, -1}},   // flat, palm on the body
      {fist(), {1, 0, 0}, {0, 0, -1}},   // fist across the body
      {index_point(), {1, 1, 0}, {0, 0, -1}},
  };
  float worst = 0.0f;
  for (size_t v = 0; v < rigs.size(); ++v) {
    Synthesizer synth(rigs[v].avatar);
    ASSERT_TRUE(synth.ok()) << synth.error();
    SynthContext ctx;
    std::string error;
    ASSERT_TRUE(make_context(rigs[v].avatar, SynthesisOptions{}, &ctx, &error)) << error;
    for (const Place& pl : all_places)
      for (Contact c : {Contact::Touch, Contact::Close})
        for (const Hand& h : hands) {
          notation::SignSpec s = sign_at(h.shape, pl.level, pl.side, c);
          s.dominant.orientation.extended_finger = h.finger;
          s.dominant.orientation.palm = h.palm;
          SynthesisResult r = synth.sign(s, SynthesisOptions{});
          ASSERT_TRUE(r.ok()) << r.errors[0].message;
          std::string what;
          float d = worst_arm_depth(ctx, r, &what);
          const auto k = rigs[v].known->find(pl.level);
          const float bound_m = k == rigs[v].known->end() ? 0.005f : 0.001f * k->second;
          EXPECT_LE(d, bound_m) << "avatar " << v << " level " << int(pl.level) << " side " << int(pl.side)
                               << " contact " << int(c) << ": " << what;
          // The synthesis report counts the arms too.
          EXPECT_GE(r.report.max_penetration_m + 1e-6f, d);
          worst = std::max(worst, d);
          // Held off in whichever direction keeps the arm out, the hand is still 3-10 cm away.
          // Known gap: on the project avatar the fist held off the far side of the neck is pushed
          // out to 11.1 cm (the flat hand 10.8, the pointing hand 9.5; before the held-off
          // direction turned forward and the head turned towards the hand there, 10.8-11.3 cm;
          // docs/SYNTHESIS.md).
          if (c == Contact::Close) {
            ASSERT_EQ(r.report.contact_distances_m.size(), 1u);
            const bool neck_gap = rigs[v].known == &project_known_mm && pl.level == BodyLevel::Neck;
            EXPECT_GE(r.report.contact_distances_m[0], 0.03f) << "avatar " << v << " level " << int(pl.level);
            EXPECT_LE(r.report.contact_distances_m[0], neck_gap ? 0.112f : 0.10f) << "avatar " << v << " level "
                                                                                  << int(pl.level);
          }
        }
  }
  RecordProperty("worst_arm_depth_mm", std::to_string(worst * 1000.0f));
}

// The deepest `side` arm in the trunk over the frames of the clip's Sign segment (the key pose
// held) and over the whole clip (with the transitions from and back to rest).
void crossing_arm_depths(const SynthContext& ctx, const SynthesisResult& r, Side_ side, float* key_m,
                         float* clip_m) {
  int first = 0, last = -1;
  for (const auto& s : r.clip.segments)
    if (s.kind == ClipSegment::Kind::Sign) {
      first = static_cast<int>(std::lround(s.start_s * r.clip.fps));
      last = static_cast<int>(std::lround(s.end_s * r.clip.fps));
    }
  *key_m = *clip_m = 0.0f;
  PoseBuilder pb(ctx.rig);
  for (int f = 0; f < r.clip.frame_count; ++f) {
    pb.set_from_local(&r.clip.rotations[static_cast<size_t>(f) * ctx.rig.joint_count]);
    const bool contact = r.report.intended_contact[f] & exempt_bit(side, false);
    const float d = arm_penetration(ctx.body, pb, side, true, contact, false).depth_m;
    *clip_m = std::max(*clip_m, d);
    if (f >= first && f <= last) *key_m = std::max(*key_m, d);
  }
}

// The far side's beside places the far-side tests sweep, from the forehead to below the waist.
const BodyLevel kFarSideLevels[] = {BodyLevel::Forehead, BodyLevel::Ears,        BodyLevel::Mouth,
                                   BodyLevel::Chin,     BodyLevel::Neck,        BodyLevel::Shoulders,
                                   BodyLevel::ShoulderTop, BodyLevel::Chest,    BodyLevel::Stomach,
                                   BodyLevel::Belly,    BodyLevel::Waist,       BodyLevel::BelowWaist};

// The five hands they sweep there, palm towards the body: 0 flat, 1 fist, 2 pointing index (all
// three with the fingers up); 3 fist across the body (fingers to the left); 4 index pointing
// up-left (the earliest measurements' hands).
constexpr int kFarSideHands = 5;

// A one-handed sign: the dominant hand `hand` (above) beside the far side of the body at `level`.
notation::SignSpec far_side_sign(int hand, BodyLevel level, Contact contact) {
  const notation::HandShape shapes[kFarSideHands] = {flat(), fist(), index_point(), fist(), index_point()};
  const Direction fingers[kFarSideHands] = {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}};
  notation::SignSpec s = sign_at(shapes[hand], level, Side::LeftBeside, contact);
  s.dominant.orientation.extended_finger = fingers[hand];
  s.dominant.orientation.palm = {0, 0, -1};
  return s;
}

// The dominant hand beside the FAR side of the body (`left_beside` from the forehead to below the
// waist; touch, close and no contact; a flat hand, fingers up, palm in): the arm reaches round
// the front of the chest (the place held off in front, the shoulder girdle protracted) instead
// of through the torso. Before that, in the key poses, the upper arm was 22-83 mm in the torso
// at the shoulders to the belly on the reference humanoid (8-24 mm at the face and neck) and
// 13-22 mm on the project avatar, and the transitions from and back to rest cut through by
// 95-131 mm (now each clip's worst frame is its key pose's). From the belly down a hand held off
// the place is searched round it within the contact band (sign_motion.cpp key_state): before,
// the reference humanoid's belly 7.1 / 7.4 mm (close / none), waist 25.7 / 10.2 mm (its clip
// 31.3 / 19.2), below the waist 26.6 / 17.5 mm; the project avatar's below the waist 56.6 /
// 57.3 mm. From the stomach down the thorax now turns towards the far side (thorax_turn.h):
// before it, the reference humanoid's waist 9.7 mm (close, none), the project avatar below the
// waist 8.0 mm (touch) and its touch beside the waist 14.5 mm short; now 1.0 / 0.0 mm and 1.4 mm.
// Bounds: 5 mm (the rule) except where measured deeper, rounded up, per rig.
TEST(SynthesisCollision, HandBesideTheFarSideReachesRoundTheFrontOfTheChest) {
  struct Bounds { float touch_mm, close_mm, none_mm; };  // key pose and clip
  struct Rig_ {
    std::string name;
    avatar::Avatar avatar;
    std::map<BodyLevel, Bounds> known;
  };
  std::vector<Rig_> rigs;
  rigs.push_back({"reference", make_reference_humanoid(), {}});
  ProjectAvatar project = load_project_avatar();
  ASSERT_TRUE(project.error.empty()) << project.error;
  // Project avatar below the waist: within 5 mm since the place came in to 4 cm off the hips'
  // silhouette (body_anchors.cpp kBesideLegsClearMax_m); before, 28 cm out from the midline, the
  // arm at full stretch across the hips, close and none 12.9 mm (now 0.2).
  if (project.present) rigs.push_back({"avatar", std::move(project.avatar), {}});
  float worst_key = 0.0f;
  for (const Rig_& rg : rigs) {
    Synthesizer synth(rg.avatar);
    ASSERT_TRUE(synth.ok()) << synth.error();
    SynthContext ctx;
    std::string error;
    ASSERT_TRUE(make_context(rg.avatar, SynthesisOptions{}, &ctx, &error)) << error;
    for (BodyLevel level : kFarSideLevels)
      for (Contact c : {Contact::Touch, Contact::Close, Contact::None}) {
        SynthesisResult r = synth.sign(far_side_sign(0, level, c), SynthesisOptions{});
        ASSERT_TRUE(r.ok()) << r.errors[0].message;
        const std::string where = rg.name + " level " + std::to_string(static_cast<int>(level)) +
                                  " contact " + std::to_string(static_cast<int>(c));
        float key = 0.0f, clip = 0.0f;
        crossing_arm_depths(ctx, r, kRight, &key, &clip);
        float bound_mm = 5.0f;
        auto k = rg.known.find(level);
        if (k != rg.known.end())
          bound_mm = c == Contact::Touch ? k->second.touch_mm : c == Contact::Close ? k->second.close_mm : k->second.none_mm;
        EXPECT_LE(key * 1000.0f, bound_mm) << where << " (key pose)";
        EXPECT_LE(clip * 1000.0f, bound_mm) << where << " (whole clip)";
        worst_key = std::max(worst_key, key);
        // Still at the place: a touch touches, a hand held off stays 3-10 cm from it.
        ASSERT_EQ(r.report.contact_distances_m.size(), 1u);
        const float reach = r.report.contact_distances_m[0];
        if (c == Contact::Touch) {
          EXPECT_LT(reach, 0.01f) << where;
        } else {
          EXPECT_GE(reach, 0.03f) << where;
          EXPECT_LE(reach, 0.10f) << where;
        }
      }
  }
  // A left-handed signer mirrors it: the left arm reaches round the front to the right side.
  {
    avatar::Avatar av = make_reference_humanoid();
    SynthesisOptions lh;
    lh.left_handed = true;
    SynthContext ctx;
    std::string error;
    ASSERT_TRUE(make_context(av, lh, &ctx, &error)) << error;
    for (Contact c : {Contact::Close, Contact::None}) {
      SynthesisResult r = synthesize_sign(far_side_sign(0, BodyLevel::Chest, c), av, lh);
      ASSERT_TRUE(r.ok()) << r.errors[0].message;
      float key = 0.0f, clip = 0.0f;
      crossing_arm_depths(ctx, r, kLeft, &key, &clip);
      EXPECT_LE(key * 1000.0f, 5.0f) << "left-handed, contact " << static_cast<int>(c);
      EXPECT_LE(clip * 1000.0f, 5.0f) << "left-handed, contact " << static_cast<int>(c);
    }
  }
  RecordProperty("worst_key_pose_arm_depth_mm", std::to_string(worst_key * 1000.0f));
}

// The transitions from and back to the rest pose of a hand at the FAR side's beside places (fist,
// pointing and flat hands, touch, close and no contact, from the forehead to below the waist): the
// arm comes forward first and only then across (transition.cpp's waypoint chain), so no frame of
// the clip is deeper in the trunk than the key pose itself, or 5 mm. Before the chain, with the
// clavicle protraction and the arm slerped apart and one blended via-pose, the project avatar's
// fist at shoulder_top (touch) cut through by 120 mm in its rest transition (key pose 7.6 mm);
// with the fist across the body at shoulder_top by 105/119/107 mm (touch/close/none; now 18/8.7/5.9,
// the key poses') and at the shoulders by 105/77 mm (touch/close; now 6.0/3.9);
// the reference humanoid's flat hand at the waist (touch) by 91 mm (key 0.5 mm) and below the
// waist by 75 / 64 mm (close / none; key poses 27 / 18 mm); fists and pointing hands below the
// waist by 32-129 mm on both rigs (now each is its key pose's depth). The key poses below the
// chest stay deep (known gaps, docs/SYNTHESIS.md); this test bounds only what the transitions add.
// Exceptions, measured after the chain and rounded up, where a transition is still deeper than
// the key pose (from the stomach down): listed in `known` with what it was
// before.
TEST(SynthesisCollision, FarSideRestTransitionsAreNoDeeperThanTheKeyPose) {
  struct Case { std::string rig; int shape; BodyLevel level; Contact contact; };
  struct Known { Case c; float clip_mm; };
  // shape: 0 flat, 1 fist, 2 pointing index (fingers up, palm in); 3 fist across the body
  // (fingers to the left), 4 pointing up-left (the previous measurements' hands).
  // clip_mm: measured now, rounded up (before the chain, in brackets: arm depth in the clip; the
  // plan minimises the report's depth, hand included, which no case made worse).
  // Since the held-off places from the belly down are searched round the anchor (key_state)
  // and a routed path is judged by what it adds beyond its end poses (transition.cpp), every
  // other case stays within its key pose + 0.5 mm (before: 16 cases 8-32 mm beyond the bound,
  // among them the reference humanoid's fist across the body at the belly, touch, 29.4 mm for a
  // key pose of 21.3, and the project avatar's fist across the body at the waist, 13.9 mm for 1.2);
  // the last, the reference humanoid's fist across the body at the waist, touch (37.0 mm for a key
  // pose of 35.4), since the resting arm gives way. None is left.
  const std::vector<Known> known = {};

  std::string rig_error;
  const NamedRigs rigs = reference_and_project_avatar(&rig_error);
  ASSERT_TRUE(rig_error.empty()) << rig_error;
  float worst_added = 0.0f;
  for (const auto& [rig_name, av] : rigs) {
    Synthesizer synth(av);
    ASSERT_TRUE(synth.ok()) << synth.error();
    SynthContext ctx;
    std::string error;
    ASSERT_TRUE(make_context(av, SynthesisOptions{}, &ctx, &error)) << error;
    for (int shape = 0; shape < kFarSideHands; ++shape)
      for (BodyLevel level : kFarSideLevels)
        for (Contact c : {Contact::Touch, Contact::Close, Contact::None}) {
          SynthesisResult r = synth.sign(far_side_sign(shape, level, c), SynthesisOptions{});
          ASSERT_TRUE(r.ok()) << r.errors[0].message;
          float key = 0.0f, clip = 0.0f;
          crossing_arm_depths(ctx, r, kRight, &key, &clip);
          float bound_mm = std::max(key * 1000.0f, 5.0f) + 0.5f;  // 0.5 mm: sampling of the key pose's hold
          for (const Known& k : known)
            if (k.c.rig == rig_name && k.c.shape == shape && k.c.level == level && k.c.contact == c)
              bound_mm = k.clip_mm;
          const std::string where = rig_name + " shape " + std::to_string(shape) + " level " +
                                    std::to_string(static_cast<int>(level)) + " contact " +
                                    std::to_string(static_cast<int>(c));
          EXPECT_LE(clip * 1000.0f, bound_mm) << where << " (key pose " << key * 1000.0f << " mm)";
          worst_added = std::max(worst_added, clip - key);
        }
  }
  RecordProperty("worst_depth_added_by_a_transition_mm", std::to_string(worst_added * 1000.0f));
}

// The far side's rest transitions (the hands of FarSideRestTransitionsAreNoDeeperThanTheKeyPose: 5
// hands x 12 levels x 3 contacts, both rigs, from the rest and back) bring the hand across in
// front of the body: the wrist never goes further out to the dominant side than the rest pose's
// wrist by more than 4 cm, and they take a signer's time. Before (plan_transition fell back to
// the direct slerp or to via-poses whose IK lifted the elbow out to the side) the wrist went
// 10.6 / 11.4 cm out (reference / project avatar; the lead's fist to the left hip, below, 20.8
// cm out at chest height, the upper arm abducted 54 deg, 1.90 s each way), and the transitions
// took 1.33 / 1.17 s at the median, 1.80 / 1.73 s at the 90th percentile. Measured now: 2.0 /
// 2.9 cm out; median 0.87 / 0.83 s, 90th percentile 1.07 / 1.07 s. Bounds: 4 cm (the wrist's
// sway as the arm turns across); median 0.95 s and 90th percentile 1.2 s (the hand's path at
// its tempo, 2-4 frames of margin; the few touches still routed round, at the far neck and
// shoulders, up to 3.8 s, are what the 10% leaves). Those routed touches were timed by their
// fingertips' path (the reference humanoid's pointing hand touching the far neck 3.63 s, the
// shoulder top 3.80 s); timed by the arm as the hand's path is (transition.cpp
// time_rest_path_by_arm) 3.10 / 3.07 s. Bound on the slowest: 3.3 s on the reference humanoid
// (the old timing fails it), 1.8 s on the project avatar (its slowest, the fist across the body
// at the far shoulders, 1.70 s on the hand's path, unchanged).
TEST(SynthesisCollision, FarSideRestTransitionsBringTheHandAcrossInFront) {
  std::string rig_error;
  const NamedRigs rigs = reference_and_project_avatar(&rig_error);
  ASSERT_TRUE(rig_error.empty()) << rig_error;
  // The lead's case as written in the page: the right fist touching beside the left hip.
  const PhraseText fist_at_hip = phrase_from_text("R(H(fist), E(l), P(i), Loc(below_waist, left_beside, touch))", {});
  ASSERT_TRUE(fist_at_hip.ok());
  for (const auto& [rig_name, av] : rigs) {
    Synthesizer synth(av);
    ASSERT_TRUE(synth.ok()) << synth.error();
    SynthContext ctx;
    std::string error;
    ASSERT_TRUE(make_context(av, SynthesisOptions{}, &ctx, &error)) << error;
    const ArmRig& arm = ctx.rig.arms[kRight];
    PoseBuilder rest(ctx.rig);
    rest.set_from_local(ctx.rest_locals.data());
    const glm::vec3 rest_wrist = rest.position(arm.hand);
    // The wrist's furthest excursion out to the right of the rest pose's, over a clip's
    // transitions; their durations.
    auto measure = [&](const SynthesisResult& r, float* out_m, std::vector<double>* durations_s) {
      *out_m = 0.0f;
      for (const ClipSegment& sg : r.clip.segments) {
        if (sg.kind != ClipSegment::Kind::Transition) continue;
        durations_s->push_back(sg.end_s - sg.start_s);
        const int f0 = static_cast<int>(std::lround(sg.start_s * r.clip.fps));
        const int f1 = std::min(r.clip.frame_count - 1, static_cast<int>(std::lround(sg.end_s * r.clip.fps)));
        for (int f = f0; f <= f1; ++f) {
          const PoseBuilder pb = frame_pose(ctx.rig, r.clip, f);
          *out_m = std::max(*out_m, glm::dot(pb.position(arm.hand) - rest_wrist, -ctx.rig.left));
        }
      }
    };
    std::vector<double> durations_s;
    float worst_out_m = 0.0f;
    for (int shape = 0; shape < kFarSideHands; ++shape)
      for (BodyLevel level : kFarSideLevels)
        for (Contact c : {Contact::Touch, Contact::Close, Contact::None}) {
          SynthesisResult r = synth.sign(far_side_sign(shape, level, c), SynthesisOptions{});
          ASSERT_TRUE(r.ok()) << r.errors[0].message;
          float out_m = 0.0f;
          measure(r, &out_m, &durations_s);
          EXPECT_LE(out_m * 100.0f, 4.0f) << rig_name << " shape " << shape << " level " << static_cast<int>(level)
                                          << " contact " << static_cast<int>(c) << ": wrist out to the right, cm";
          worst_out_m = std::max(worst_out_m, out_m);
        }
    ASSERT_EQ(durations_s.size(), 360u);
    std::sort(durations_s.begin(), durations_s.end());
    const double median_s = durations_s[durations_s.size() / 2];
    const double p90_s = durations_s[durations_s.size() * 9 / 10];
    EXPECT_LE(median_s, 0.95) << rig_name;
    EXPECT_LE(p90_s, 1.2) << rig_name;
    EXPECT_LE(durations_s.back(), rig_name == "avatar" ? 1.8 : 3.3) << rig_name << ": slowest far-side rest transition";
    // The fist to the hip: measured 0.43 s (reference) / 0.90 s (avatar) each way, the wrist
    // 0.0 cm out of the rest's line.
    SynthesisResult r = synth.phrase(fist_at_hip.items, SynthesisOptions{});
    ASSERT_TRUE(r.ok()) << r.errors[0].message;
    float out_m = 0.0f;
    std::vector<double> fist_s;
    measure(r, &out_m, &fist_s);
    EXPECT_LE(out_m * 100.0f, 4.0f) << rig_name << ": the fist to the hip, wrist out to the right, cm";
    for (double d : fist_s) EXPECT_LE(d, 1.1) << rig_name << ": the fist to the hip";
    RecordProperty(rig_name + "_worst_wrist_out_cm", std::to_string(worst_out_m * 100.0f));
    RecordProperty(rig_name + "_median_s", std::to_string(median_s));
    RecordProperty(rig_name + "_p90_s", std::to_string(p90_s));
  }
}

// Fists TOUCHING beside the far side of the body (the right fist at `left_beside`, fingers up or
// across the body, palm in; the forehead to below the waist; both rigs): the key pose's arm depth
// in the trunk (FarSideRestTransitions... above bounds only what the transitions add to it). A
// touch's place is fixed (the held-off searches of key_state do not apply): the fist's palm
// centre goes to the point beside the body at its mid-depth, and the arm wraps round the front
// of the chest to get there, the upper arm across its own side of the chest ("right upper arm in
// torso right" in most) or the forearm across the far side. The flat hand touches with its middle
// fingertip, the wrist a hand's length lower, and stays within 5 mm (HandBesideTheFarSide...);
// the fist touches with the palm. From the stomach down the thorax turns towards the far side
// (thorax_turn.h), and below the waist also leans forward, which brings the place forward of
// (and nearer to) the reaching shoulder; before (fingers up / across) the reference humanoid's
// stomach 18.6 / 14.9 mm, belly 29.9 / 21.3, waist 41.2 / 35.4, below the waist 61.5 / 63.1; the
// project avatar's belly 4.2 / 5.7, waist 11.1 / 13.2, below the waist 72.0 / 79.3 mm. Higher up
// a turn would carry the place with the chest (those anchors are on the upper chest) and change
// nothing. Each case over 5 mm is held to its depth as measured, rounded up to the next half
// millimetre; the others to 5 mm. Below the waist the project avatar's fist also stopped short of
// the place (44.8 / 31.2 mm, then 18.1 / 17.0 mm: the arm at full stretch 28 cm across the hips);
// with the place 4 cm off the hips' silhouette (21.3 cm out, body_anchors.cpp) it touches (0.2 /
// 0.1 mm) and is 22.8 / 20.4 mm deep (was 42.1 / 44.2).
TEST(SynthesisCollision, FistsTouchingBesideTheFarSideAreHeldToTheirMeasuredDepth) {
  struct Gap { float fingers_up_mm, across_mm; };
  struct Rig_ { std::string name; avatar::Avatar avatar; std::map<BodyLevel, Gap> known; float below_waist_short_mm; };
  std::vector<Rig_> rigs;
  // Reference humanoid (measured, fingers up / across): neck 13.4 / 3.8, shoulders 17.3 / 7.4,
  // shoulder top 14.2 / 4.4, chest 16.2 / 13.0, stomach 4.3 / 3.7, belly 4.6 / 4.4,
  // waist 14.1 / 12.4, below the waist 7.6 / 3.3 mm.
  rigs.push_back({"reference", make_reference_humanoid(),
                  {{BodyLevel::Neck, {13.5f, 5.0f}},
                   {BodyLevel::Shoulders, {17.5f, 7.5f}},
                   {BodyLevel::ShoulderTop, {14.5f, 5.0f}},
                   {BodyLevel::Chest, {16.5f, 13.5f}},
                   {BodyLevel::Waist, {14.5f, 12.5f}},
                   {BodyLevel::BelowWaist, {8.0f, 5.0f}}},
                  0.0f});
  ProjectAvatar project = load_project_avatar();
  ASSERT_TRUE(project.error.empty()) << project.error;
  // Project avatar (fingers up / across): neck 1.9 / 2.0 (2.8 / 12.7, the forearm in the head,
  // before the head turned towards the hand at the far neck, sign_motion.cpp far_side_turns),
  // shoulders 14.9 / 13.2, shoulder top 7.6 / 18.1, chest 8.1 / 4.5, belly 1.8 / 0.4, waist
  // 1.0 / 1.0, below the waist 22.8 / 20.4 mm (42.1 / 44.2 and 18.1 / 17.0 mm short before the
  // place came in, body_anchors.cpp kBesideLegsClearMax_m).
  if (project.present)
    rigs.push_back({"avatar", std::move(project.avatar),
                    {{BodyLevel::Shoulders, {15.0f, 13.5f}},
                     {BodyLevel::ShoulderTop, {8.0f, 18.5f}},
                     {BodyLevel::Chest, {8.5f, 5.0f}},
                     {BodyLevel::BelowWaist, {23.0f, 20.5f}}},
                    0.0f});
  float worst = 0.0f;
  for (const Rig_& rg : rigs) {
    Synthesizer synth(rg.avatar);
    ASSERT_TRUE(synth.ok()) << synth.error();
    SynthContext ctx;
    std::string error;
    ASSERT_TRUE(make_context(rg.avatar, SynthesisOptions{}, &ctx, &error)) << error;
    for (int across = 0; across < 2; ++across)
      for (BodyLevel level : kFarSideLevels) {
        // The fist with the fingers up (far_side_sign's hand 1) and across the body (hand 3).
        SynthesisResult r = synth.sign(far_side_sign(across ? 3 : 1, level, Contact::Touch), SynthesisOptions{});
        ASSERT_TRUE(r.ok()) << r.errors[0].message;
        float key = 0.0f, clip = 0.0f;
        crossing_arm_depths(ctx, r, kRight, &key, &clip);
        float bound_mm = 5.0f;
        const auto k = rg.known.find(level);
        if (k != rg.known.end()) bound_mm = across ? k->second.across_mm : k->second.fingers_up_mm;
        const std::string where = rg.name + (across ? " across" : " fingers up") + " level " +
                                  std::to_string(static_cast<int>(level));
        EXPECT_LE(key * 1000.0f, bound_mm) << where;
        worst = std::max(worst, key);
        ASSERT_EQ(r.report.contact_distances_m.size(), 1u);
        const bool short_touch = level == BodyLevel::BelowWaist && rg.below_waist_short_mm > 0.0f;
        EXPECT_LT(r.report.contact_distances_m[0] * 1000.0f, short_touch ? rg.below_waist_short_mm : 10.0f) << where;
      }
  }
  RecordProperty("worst_key_pose_arm_depth_mm", std::to_string(worst * 1000.0f));
}

// Sign to sign across the body: from a far-side beside place (flat, fist, pointing hand; touch
// and close; the shoulder top, chest, stomach and waist) to the dominant side's place or beside
// it (shoulders to waist) and back, 192 phrases a rig: the transitions route round the front like
// the rest transitions, and no transition frame puts the arm deeper in the trunk than the deeper
// of the signs' own depth and 5 mm (0.5 mm for sampling). Before the waypoint chain they added up
// to 127 / 126 mm (reference / project avatar) in 68 / 49 phrases; after it still 7.3 / 11 mm in
// 16 / 13: a routed path was judged by its deepest frame of any kind, and at the far side's waist
// the key pose's hand in the other, hanging forearm (21.6 mm) hid what the arm did on the way
// (9 mm beyond its key pose). Now each kind is judged by what it adds beyond the end poses.
TEST(SynthesisCollision, CrossBodySignToSignTransitionsRouteRoundTheFront) {
  std::string rig_error;
  const NamedRigs rigs = reference_and_project_avatar(&rig_error);
  ASSERT_TRUE(rig_error.empty()) << rig_error;
  const notation::HandShape shapes[] = {flat(), fist(), index_point()};
  SynthesisOptions opt;
  opt.start_from_rest = false;
  for (const auto& [rig_name, av] : rigs) {
    SynthContext ctx;
    std::string error;
    ASSERT_TRUE(make_context(av, opt, &ctx, &error)) << error;
    Synthesizer synth(av);
    ASSERT_TRUE(synth.ok()) << synth.error();
    float worst_excess = 0.0f;
    int phrases = 0;
    for (int shape = 0; shape < 3; ++shape)
      for (BodyLevel far : {BodyLevel::ShoulderTop, BodyLevel::Chest, BodyLevel::Stomach, BodyLevel::Waist})
        for (BodyLevel near : {BodyLevel::Shoulders, BodyLevel::Chest, BodyLevel::Stomach, BodyLevel::Waist})
          for (Side near_side : {Side::Right, Side::RightBeside})
            for (Contact c : {Contact::Touch, Contact::Close}) {
            notation::SignSpec a = sign_at(shapes[shape], far, Side::LeftBeside, c);
            a.dominant.orientation.extended_finger = {0, 1, 0};
            a.dominant.orientation.palm = {0, 0, -1};
            notation::SignSpec b = sign_at(shapes[shape], near, near_side, Contact::None);
            SynthesisResult r = synthesize_phrase(items_of({a, b, a}), av, opt);
            ASSERT_TRUE(r.ok()) << r.errors[0].message;
            float in_transitions = 0.0f, in_signs = 0.0f;
            PoseBuilder pb(ctx.rig);
            for (const auto& sg : r.clip.segments) {
              const int f0 = static_cast<int>(std::lround(sg.start_s * r.clip.fps));
              const int f1 = std::min(r.clip.frame_count - 1, static_cast<int>(std::lround(sg.end_s * r.clip.fps)));
              for (int f = f0; f <= f1; ++f) {
                pb.set_from_local(&r.clip.rotations[static_cast<size_t>(f) * ctx.rig.joint_count]);
                const bool contact = r.report.intended_contact[f] & exempt_bit(kRight, false);
                const float d = arm_penetration(ctx.body, pb, kRight, true, contact, false).depth_m;
                float& into = sg.kind == ClipSegment::Kind::Transition ? in_transitions : in_signs;
                into = std::max(into, d);
              }
            }
            const float excess = in_transitions - std::max(in_signs, 0.005f);
            EXPECT_LE(excess * 1000.0f, 0.5f)
                << rig_name << " shape " << shape << " far level " << static_cast<int>(far)
                << " near level " << static_cast<int>(near) << " side "
                << static_cast<int>(near_side) << " contact " << static_cast<int>(c);
            worst_excess = std::max(worst_excess, excess);
            ++phrases;
          }
    EXPECT_EQ(phrases, 192);
    RecordProperty(rig_name + "_worst_transition_excess_mm",
                   std::to_string(worst_excess * 1000.0f));
  }
}

// A one-handed sign with the hand beside the far side of the body (5 hands x the shoulders to
// below the waist x touch, close, none; both rigs) puts the hand where the other arm hangs at
// rest: the resting arm gives way (sign_motion.cpp, resting_arm_gives_way). Before, the hand was
// in the other forearm by more than 5 mm in 48 of the 210 key poses, up to 43 mm (a flat hand
// held off beside the waist: reference 26.3 / 38.4 mm close / none, the project avatar below the
// waist 32.8 mm close). Then one key pose was left over 5 mm, the project avatar's fist touching
// beside the far side of the belly (6.3 mm); with the thorax turned towards that side
// (thorax_turn.h) none is (worst 4.9 mm). (The swing was first chosen on a pose started from
// the whole rest pose, whose finger metacarpals and tips kept their rest rotations under the
// solved hand: 19 key poses stayed in the arm, up to 28.5 mm.)
TEST(SynthesisCollision, TheRestingArmGivesWayToAHandAtTheFarSide) {
  std::string rig_error;
  const NamedRigs rigs = reference_and_project_avatar(&rig_error);
  ASSERT_TRUE(rig_error.empty()) << rig_error;
  const BodyLevel levels[] = {BodyLevel::Shoulders, BodyLevel::ShoulderTop, BodyLevel::Chest, BodyLevel::Stomach,
                              BodyLevel::Belly,     BodyLevel::Waist,       BodyLevel::BelowWaist};
  int over = 0;
  float worst = 0.0f;
  for (const auto& [rig_name, av] : rigs) {
    Synthesizer synth(av);
    ASSERT_TRUE(synth.ok()) << synth.error();
    SynthContext ctx;
    std::string error;
    ASSERT_TRUE(make_context(av, SynthesisOptions{}, &ctx, &error)) << error;
    for (int shape = 0; shape < kFarSideHands; ++shape)
      for (BodyLevel level : levels)
        for (Contact c : {Contact::Touch, Contact::Close, Contact::None}) {
          SynthesisResult r = synth.sign(far_side_sign(shape, level, c), SynthesisOptions{});
          ASSERT_TRUE(r.ok()) << r.errors[0].message;
          float in_other = 0.0f;
          PoseBuilder pb(ctx.rig);
          for (const auto& sg : r.clip.segments) {
            if (sg.kind != ClipSegment::Kind::Sign) continue;
            const int f0 = static_cast<int>(std::lround(sg.start_s * r.clip.fps));
            const int f1 = std::min(r.clip.frame_count - 1, static_cast<int>(std::lround(sg.end_s * r.clip.fps)));
            for (int f = f0; f <= f1; ++f) {
              pb.set_from_local(&r.clip.rotations[static_cast<size_t>(f) * ctx.rig.joint_count]);
              in_other = std::max(in_other, hand_penetration(ctx.body, pb, kRight, false, true).depth_m);
            }
          }
          const std::string where = rig_name + " shape " + std::to_string(shape) + " level " +
                                    std::to_string(static_cast<int>(level)) + " contact " +
                                    std::to_string(static_cast<int>(c));
          EXPECT_LE(in_other * 1000.0f, 5.0f) << where;
          if (in_other > 0.005f) ++over;
          worst = std::max(worst, in_other);
        }
  }
  EXPECT_EQ(over, 0);
  RecordProperty("hand_in_the_resting_arm_worst_mm", std::to_string(worst * 1000.0f));
  RecordProperty("hand_in_the_resting_arm_over_5mm", std::to_string(over));
}

// A one-handed sign has no other hand to go to. HamNoSys writes the parts of the hand that touch
// in brackets after the place (an earring: earlobe [touch thumb, index nail]), which the reader
// gave as a movement to a place on "the other hand". Followed, it took the hand from the ear
// down to the resting left hand by the hip and the forearm through the torso on the way (the
// project avatar's forearm 55 mm in it); make_plans dropped such targets of one-handed signs.
// The reader now reads the bracket as the contact part (hamnosys_parser.cpp,
// read_contact_bracket) and make_plans has no such exception: the sign as read stays at the ear.
TEST(SynthesisCollision, AOneHandedSignDoesNotReachForTheRestingHand) {
  std::string error;
  const NamedRigs rigs = reference_and_project_avatar(&error);
  ASSERT_TRUE(error.empty()) << error;
  notation::SignSpec s;
  ASSERT_TRUE(
      read_one_hamnosys("hamfinger2,hamextfingeru,hampalml,hamear,hamlrat,hamseqbegin,hamtouch,"
                        "hamindexfinger,hamfingerpad,hamseqend",
                        &s));
  for (const auto& [name, av] : rigs) {
    Synthesizer synth(av);
    ASSERT_TRUE(synth.ok()) << synth.error();
    const SynthesisResult r = synth.sign(s, SynthesisOptions{});
    ASSERT_TRUE(r.ok()) << name << ": " << r.errors[0].message;
    Rig rig;
    ASSERT_TRUE(build_rig(av, &rig, &error)) << error;
    const int first = first_sign_frame(r.clip);
    const int hand = rig.arms[kRight].hand;
    const glm::vec3 at_key = frame_pose(rig, r.clip, first).position(hand);
    float farthest = 0.0f;
    for (const ClipSegment& seg : r.clip.segments) {
      if (seg.kind != ClipSegment::Kind::Sign) continue;
      const int last = static_cast<int>(std::lround(seg.end_s * r.clip.fps));
      for (int f = first; f <= last; ++f)
        farthest = std::max(farthest, glm::length(frame_pose(rig, r.clip, f).position(hand) - at_key));
    }
    EXPECT_LT(farthest, 0.03f) << name << ": the wrist left the ear by " << farthest * 1000.0f << " mm";
    // No deeper than the same hand held at the ear without the bracket (the reference humanoid's
    // index at its ear has its own depth, not this test's concern).
    notation::SignSpec still = s;
    still.dominant.location.contact_part.reset();
    still.dominant.location.contact_finger = -1;
    const float still_m = synth.sign(still, SynthesisOptions{}).report.max_penetration_m;
    EXPECT_LE(r.report.max_penetration_m, still_m + 0.001f)
        << name << ": " << r.report.max_penetration_m * 1000.0f << " mm against " << still_m * 1000.0f << " mm";
  }
}

// Mirrored hands at the centre of neutral space (hamsymmlr with no place: wrists 8-12 cm apart on
// the project avatar) circling or stroking: the dominant hand is solved first and the other arm
// was pushed only out of what ITS hand touched, so the dominant hand went through the other
// forearm unchecked (the corpus: 216 signs, 37 mm median). The other arm now gives way to it too.
TEST(SynthesisCollision, MirroredHandsAtTheCentreKeepOutOfEachOthersForearm) {
  std::string error;
  const NamedRigs rigs = reference_and_project_avatar(&error);
  ASSERT_TRUE(error.empty()) << error;
  struct Variant { const char* name; Direction finger, palm; notation::MovementKind kind; Direction dir; };
  const Variant variants[] = {
      {"index up, palm down-left, circle out", {0, 1, 0}, {1, -1, 0}, notation::MovementKind::Circle, {0, 0, 1}},
      {"index up-forward, palm left, circle out", {0, 1, 1}, {1, 0, 0}, notation::MovementKind::Circle, {0, 0, 1}},
      {"index left, palm down, straight down", {1, 0, 0}, {0, -1, 0}, notation::MovementKind::Straight, {0, -1, 0}},
      {"index up, palm left, straight left", {0, 1, 0}, {1, 0, 0}, notation::MovementKind::Straight, {1, 0, 0}},
  };
  for (const auto& [name, av] : rigs) {
    Synthesizer synth(av);
    ASSERT_TRUE(synth.ok()) << synth.error();
    Rig rig;
    ASSERT_TRUE(build_rig(av, &rig, &error)) << error;
    SynthContext ctx;
    ASSERT_TRUE(make_context(av, SynthesisOptions{}, &ctx, &error)) << error;
    for (const Variant& v : variants) {
      notation::SignSpec s = sign_at(index_point(), BodyLevel::NeutralSpace, Side::Centre, Contact::None);
      s.symmetry = notation::Symmetry::MirrorLR;
      s.dominant.orientation.extended_finger = v.finger;
      s.dominant.orientation.palm = v.palm;
      notation::Movement m;
      m.kind = v.kind;
      if (v.kind == notation::MovementKind::Circle) m.circle_axis = v.dir;
      else m.direction = v.dir;
      s.movements.push_back(notation::MovementStep{{m}, {}});
      const SynthesisResult r = synth.sign(s, SynthesisOptions{});
      ASSERT_TRUE(r.ok()) << name << " " << v.name << ": " << r.errors[0].message;
      float deepest = 0.0f;
      for (int f = 0; f < r.clip.frame_count; ++f) {
        const PoseBuilder pb = frame_pose(rig, r.clip, f);
        deepest = std::max(deepest, hand_penetration(ctx.body, pb, kRight, false, true).depth_m);
      }
      EXPECT_LE(deepest, 0.005f) << name << ", " << v.name << ": the right hand " << deepest * 1000.0f
                                 << " mm in the left hand or forearm";
    }
  }
}

// collision.h trunk_crossing: a line from in front of the chest straight back stops at the chest
// and goes through the body; one in front of the body is left as it is; one from the side of the
// head round to the front of the face (DEAF's ear to the mouth) cuts the head's chord without going
// through it.
TEST(SynthesisCollision, TrunkCrossingStopsALineThatGoesThroughTheBody) {
  avatar::Avatar av = make_reference_humanoid();
  SynthContext ctx;
  std::string error;
  ASSERT_TRUE(make_context(av, SynthesisOptions{}, &ctx, &error)) << error;
  PoseBuilder rest(ctx.rig);
  rest.set_from_local(ctx.rest_locals.data());
  const Capsule* torso = nullptr;
  const Capsule* head = nullptr;
  for (const Capsule& c : ctx.body.trunk) {
    if (!torso && c.name.rfind("torso", 0) == 0) torso = &c;
    if (c.name == "head") head = &c;
  }
  ASSERT_TRUE(torso && head);
  const glm::vec3 fwd = ctx.rig.forward, left = ctx.rig.left;
  // The chest: the torso capsule's middle, on the body's centre line.
  glm::vec3 chest = 0.5f * (torso->a + torso->b);
  chest -= glm::dot(chest, left) * left;
  const float torso_front = 0.2f;  // beyond any torso's radius
  const glm::vec3 in_front = chest + fwd * torso_front, behind = chest - fwd * torso_front;
  const TrunkCrossing through = trunk_crossing(ctx.body, rest, in_front, behind, 0.01f);
  EXPECT_TRUE(through.through);
  // Stopped at the chest's front: no deeper than 1 cm into any trunk capsule, and in front of the
  // chest's centre.
  float deepest = -1.0f;
  for (const Capsule& c : ctx.body.trunk)
    deepest = std::max(deepest, c.radius_m - segment_distance(through.stop, c.a, c.b));
  EXPECT_LE(deepest, 0.0105f);
  EXPECT_GT(glm::dot(through.stop - chest, fwd), 0.05f);
  // Across the front of the body, 20 cm ahead of it: untouched.
  const glm::vec3 across = in_front + 0.3f * left;
  const TrunkCrossing clear = trunk_crossing(ctx.body, rest, in_front - 0.3f * left, across, 0.01f);
  EXPECT_FALSE(clear.through);
  EXPECT_EQ(clear.stop, across);
  // The side of the head to the front of the face, both on the head's surface: a chord, not
  // through (it stops, but sign_motion.cpp stops only hands whose lines go through or that move
  // by directions alone).
  const glm::vec3 head_mid = 0.5f * (head->a + head->b);
  const glm::vec3 ear = head_mid - left * head->radius_m, mouth = head_mid + fwd * head->radius_m;
  EXPECT_FALSE(trunk_crossing(ctx.body, rest, ear, mouth, 0.01f).through);
}

// A hand held close in front of the far side's shoulders moving in to touch them (the corpus's
// BIRTHDAY5^, SUCCESS2^, CHANCE1^, PARTY-POLITICAL1^ are of this family: 13.7-14.0 mm on the
// project avatar): the upper arm crosses the front of the chest, and its first stretch, 4-12 cm
// from the shoulder joint, went through the round top of the torso capsule on its own side
// (docs/SYNTHESIS.md arm-side). No swivel clears it (the elbow's whole circle measured: its best
// within a few mm of the pick); the shoulder girdle does, protracted as it is for wrists across
// the body nearer the chest, which the usual zone withholds beyond 27% of the reach in front of
// the shoulder. Such a sign is solved again with the wider zones (synthesize.cpp
// choose_wide_protraction) and keeps the shallower clip. Notations written for the test; before,
// the project avatar 13.7 / 6.5 mm, now 3.5 / 1.2 mm (the reference humanoid 0.0 / 0.2 mm both
// ways: it is not solved again).
TEST(SynthesisCollision, AnUpperArmCrossingTheChestTakesTheShoulderGirdleForward) {
  std::string error;
  const NamedRigs rigs = reference_and_project_avatar(&error);
  ASSERT_TRUE(error.empty()) << error;
  const char* const signs[] = {
      "hamfinger23,hamextfingerul,hampalmd,hamlrat,hamshoulders,hamclose,hammovei,hamtouch",
      "hamfist,hamextfingeru,hampalml,hamlrat,hamshoulders,hamclose,hammovei,hamtouch",
  };
  for (const auto& [name, av] : rigs) {
    Synthesizer synth(av);
    ASSERT_TRUE(synth.ok()) << synth.error();
    for (const char* names : signs) {
      notation::SignSpec s;
      ASSERT_TRUE(read_one_hamnosys(names, &s));
      const SynthesisResult r = synth.sign(s, SynthesisOptions{});
      ASSERT_TRUE(r.ok()) << name << ": " << r.errors[0].message;
      std::printf("%s %s: %.1f mm, touch %.1f mm\n", name.c_str(), names, r.report.max_penetration_m * 1000.0f,
                  r.report.max_reach_error_m * 1000.0f);
      EXPECT_LE(r.report.max_penetration_m, 0.005f)
          << name << " " << names << ": " << r.report.max_penetration_m * 1000.0f << " mm";
      EXPECT_LT(r.report.max_reach_error_m, 0.01f) << name << " " << names;
    }
  }
}

}  // namespace
}  // namespace sw::synthesis

