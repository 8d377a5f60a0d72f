// Motion continuity over the real data (issue 4: continuous positions and velocities): the ASL
// starter lexicon, both data alphabets as sequences, and every transition between two letters,
// on the project avatar and on the reference humanoid. No tracked joint (wrists, elbows,
// fingertips) may move further in one frame than a signing hand ever does, and its per-frame
// displacement may not change abruptly from one frame to the next (a correction that holds a
// joint and then lets it go shows up as a spike in this second difference even when the jump
// itself is under the speed bound). Wrists and elbows, which the arm IK and the collision
// corrections move, are held to both human bounds. Fingertips are held to the speed bound
// everywhere; their step change is held to the hand's bound in the lexicon's signs and the
// transitions from and back to the rest pose, and within fingerspelling to its measured worst (a
// known gap, see kLetterFingertipBound).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <initializer_list>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "arm_depths.h"
#include "notation/hamnosys.h"
#include "synthesis/arm_ik.h"
#include "synthesis/clip_steps.h"
#include "synthesis/collision.h"
#include "synthesis/phrase_text.h"
#include "synthesis/reference_humanoid.h"
#include "synthesis/rig.h"
#include "synthesis/sign_motion.h"
#include "synthesis/signing_avatar.h"
#include "synthesis/synthesize.h"
#include "synthesis_fixture.h"

namespace sw::synthesis {
namespace {

const std::string kRoot = SIGNWEAVE_SOURCE_DIR;

// Peak hand speeds in fluent signing are about 2-3 m/s (motion-capture studies of ASL/DGS
// signers; fingerspelling is slower). At the clip's 30 fps, 3 m/s is 10 cm per frame: no wrist,
// elbow or fingertip of a natural clip moves further than that between two frames.
constexpr float kMaxStepM = 0.10f;
// Hand accelerations in signing peak at a few tens of m/s^2 (a fast stop or a tap); 50 m/s^2 at
// 30 fps is a change of 5.6 cm/frame in the per-frame displacement (a * dt^2). A joint held and
// then released (GOOD's 17 cm jump) changes its displacement by the whole jump in one frame.
constexpr float kMaxStepChangeM = 0.056f;


// The sign's own motion, without the transitions from and back to the rest pose (held by their
// own test below, RestTransitionsMoveAtHumanSpeed).
SynthesisOptions from_key_pose() {
  SynthesisOptions o;
  o.start_from_rest = false;
  return o;
}

// The per-frame steps of the tracked points (synthesis/clip_steps.h).
using Worst = FrameSteps;
using Track = StepTrack;
Worst measure(const Rig& rig, const Clip& clip, int first = 0, int last = -1, Track track = Track::Arms) {
  return measure_frame_steps(rig, clip, first, last, track);
}

// The wrist joint within its limits in every frame of `clip`: the hand's local rotation (flexion
// and deviation; the forearm carries the twist) bent from its bind at most as far as the largest
// flexion and deviation together allow (+0.01 rad for rounding).
void expect_wrists_within_their_bend(const Rig& rig, const Clip& clip, const std::string& label,
                                     std::initializer_list<Side> sides = {kLeft, kRight}) {
  const ArmLimits& lim = arm_limits();
  const float flex = std::max(lim.wrist_flex, lim.wrist_ext);
  const float dev = std::max(lim.radial_dev, lim.ulnar_dev);
  const float max_bend = 2.0f * std::acos(std::cos(0.5f * flex) * std::cos(0.5f * dev));
  for (Side s : sides) {
    const int hand = rig.arms[s].hand;
    for (int f = 0; f < clip.frame_count; ++f) {
      const glm::quat rel =
          glm::conjugate(rig.bind_local_rot[hand]) * clip.rotations[static_cast<size_t>(f) * rig.joint_count + hand];
      const float bend = 2.0f * std::acos(std::min(1.0f, std::fabs(rel.w)));
      EXPECT_LE(bend, max_bend + 0.01f) << label << (s == kLeft ? " left" : " right") << " wrist at frame " << f;
    }
  }
}

// Bounds in millimetres: per-frame step, change of the step.
struct Bound {
  float step_mm = kMaxStepM * 1000.0f, change_mm = kMaxStepChangeM * 1000.0f;
};

// Fingertips within the lexicon's signs: the hand's own bounds. The worst step change was
// 67 mm (PLAY; NUMBER 65 mm), wrist twists whose forearm rotation ran into its limit, where the
// clamped wrist angles moved faster than the request and the twist's minimum-jerk middle ran
// the hand to and fro; with the twist turning the key pose's wrist and refitted at the limits
// (arm_ik.h ArmTarget::wrist_motion) and timed at a constant rate, PLAY 67 -> 28 mm (avatar) /
// 61 -> 34 (reference), NUMBER 65 -> 27 (reference); the worst sign now is PLEASE, 52 mm
// (reference; LOOK 46 on the avatar), and the worst step 69 mm (MAN).
const Bound kFingertipBound{};
// Fingertips within fingerspelling: the speed bound of the hand (the worst step is 80 mm a
// frame, the ring tip on the way from ASL J to W) and the step change held to its measured
// worst, 64.4 mm (Ukrainian Ґ's pairs: Ґ -> Р on the avatar; Ґ -> Я 63.3 mm on the reference),
// rounded up: over the hand's 56 mm, a fingertip 18 cm from the wrist sweeps an arc as the hand
// turns between two letters. Was 70 mm for signs and letters alike (PLAY's 67 mm). Й's twist
// came off its pairs' worst (46 -> 18 mm, reference). Whether a signer's fingertips accelerate
// that hard is not measured here (no motion-capture data in the sources); the bound keeps it from
// growing.
const Bound kLetterFingertipBound{kMaxStepM * 1000.0f, 65.0f};

class MotionSmoothness : public ::testing::TestWithParam<const char*> {
 protected:
  void SetUp() override {
    if (std::string(GetParam()) == "avatar") {
      SigningAvatar sa = load_signing_avatar_file(kRoot + "/models/signweave-avatar.glb");
      if (!sa.ok()) GTEST_SKIP() << "models/signweave-avatar.glb: " << sa.error;
      avatar_ = sa.avatar;
    } else {
      avatar_ = make_reference_humanoid();
    }
    std::string error;
    ASSERT_TRUE(build_rig(avatar_, &rig_, &error)) << error;
  }
  void expect_smooth(const std::string& label, const Worst& w, const Bound& b) {
    EXPECT_LE(w.step_m * 1000.0f, b.step_mm) << label << ": " << w.step_what;
    EXPECT_LE(w.change_m * 1000.0f, b.change_mm) << label << ": " << w.change_what;
  }
  avatar::Avatar avatar_;
  Rig rig_;
};

TEST_P(MotionSmoothness, EveryLexiconSignMovesContinuously) {
  std::string text;
  if (!testing::read_text_file(kRoot + "/data/ase/lexicon.jsonl", &text)) GTEST_SKIP() << "no data lexicon";
  Synthesizer synth(avatar_);
  ASSERT_TRUE(synth.ok()) << synth.error();
  // Known gaps, measured (the worse of the two rigs, rounded up by a few mm) and held to their
  // own bounds so they cannot grow unnoticed; every other sign meets the human bounds above.
  // None now. STUDENT was the last (98 mm step on the avatar, 66 mm change on the reference):
  // its two 180-degree hand turns went the way the rounding of a dot product chose, through
  // orientations out of the wrist's reach, the second in a 0.35 s replace; the turn's way is now
  // chosen by what the arm reaches and no step turns the hand faster than 5 rad/s on average
  // (sign_motion.cpp, kMeanHandTurnRadPerS): 40/32 mm (avatar), 41/30 mm (reference).
  // What fixed the others (BAD, DAY, DEAF, HOSPITAL, LEARN, MORNING came off this list with
  // swivel continuity and the forearm-carried elbow contact; BOOK, 86 mm change on the avatar,
  // with hands parted at a movement's goal; TELL and THANK-YOU, 78 mm elbow steps and 71/94 mm
  // changes on the reference, with swivel fixes kept to one side from frame to frame, no swivel
  // fix on a path for a gain under 1 mm, and turns ramped without a kink; LOOK, 61 mm on the
  // avatar, with pushes ramped in a blended direction): CHANGELOG.md; docs/SYNTHESIS.md, known
  // issues.
  const std::map<std::string, Bound> known = {};
  int signs = 0, smooth = 0;
  for (const testing::LexiconSign& sign : testing::lexicon_signs(text)) {
    const std::string& gloss = sign.gloss;
    const PhraseText& t = sign.text;
    ASSERT_TRUE(t.ok()) << gloss;
    SynthesisResult r = synth.phrase(t.items, from_key_pose());
    ASSERT_TRUE(r.ok()) << gloss;
    Worst w = measure(rig_, r.clip);
    // SIGNWEAVE_SMOOTHNESS_REPORT=1 prints every sign's figures (the per-frame clearing is
    // sensitive: a change is judged on all signs of both rigs, not only the exempted ones).
    const Worst tips = measure(rig_, r.clip, 0, -1, Track::Fingertips);
    if (std::getenv("SIGNWEAVE_SMOOTHNESS_REPORT"))
      std::printf("smoothness %s %s %.1f %.1f (%s | %s) fingertips %.1f %.1f (%s | %s)\n", GetParam(), gloss.c_str(),
                  w.step_m * 1000.0f, w.change_m * 1000.0f, w.step_what.c_str(), w.change_what.c_str(),
                  tips.step_m * 1000.0f, tips.change_m * 1000.0f, tips.step_what.c_str(), tips.change_what.c_str());
    auto k = known.find(gloss);
    expect_smooth(gloss, w, k == known.end() ? Bound{} : k->second);
    expect_smooth(gloss + " fingertips", tips, kFingertipBound);
    smooth += w.step_m <= kMaxStepM && w.change_m <= kMaxStepChangeM;
    ++signs;
  }
  EXPECT_GE(signs, 110);
  RecordProperty("signs_within_human_bounds", std::to_string(smooth) + "/" + std::to_string(signs));
}

// The transitions from the rest pose to each lexicon sign and back: eq. (10)'s k over the
// distance the joints travel along the interpolated path (transition.h) keeps them at a signer's
// speed. Before, k followed the straight distance while the fingertip swung along an arc up to
// 2.7 times longer (ME: 16.6 cm/frame at the index tip, 8.5 cm/frame at the wrist). Wrists,
// elbows and fingertips are held to the human bounds, both joins included.
TEST_P(MotionSmoothness, RestTransitionsMoveAtHumanSpeed) {
  std::string text;
  if (!testing::read_text_file(kRoot + "/data/ase/lexicon.jsonl", &text)) GTEST_SKIP() << "no data lexicon";
  Synthesizer synth(avatar_);
  ASSERT_TRUE(synth.ok()) << synth.error();
  SynthesisOptions from_rest;
  from_rest.start_from_rest = true;
  Worst worst;
  int transitions = 0;
  for (const testing::LexiconSign& sign : testing::lexicon_signs(text)) {
    ASSERT_TRUE(sign.text.ok()) << sign.gloss;
    SynthesisResult r = synth.phrase(sign.text.items, from_rest);
    ASSERT_TRUE(r.ok()) << sign.gloss;
    const Clip& c = r.clip;
    std::vector<const ClipSegment*> moves;
    for (const ClipSegment& seg : c.segments)
      if (seg.kind == ClipSegment::Kind::Transition) moves.push_back(&seg);
    ASSERT_GE(moves.size(), 2u) << sign.gloss << ": no transition from or back to rest";
    for (const ClipSegment* seg : {moves.front(), moves.back()}) {
      int first = static_cast<int>(std::lround(seg->start_s * c.fps));
      int last = static_cast<int>(std::lround(seg->end_s * c.fps));
      Worst w = measure(rig_, c, first, last, Track::ArmsAndFingertips);
      const std::string where = sign.gloss + (seg == moves.front() ? " from rest" : " back to rest");
      expect_smooth(where, w, Bound{});
      if (w.step_m > worst.step_m) worst.step_m = w.step_m, worst.step_what = where + ": " + w.step_what;
      if (w.change_m > worst.change_m) worst.change_m = w.change_m, worst.change_what = where + ": " + w.change_what;
      ++transitions;
    }
  }
  EXPECT_GE(transitions, 220);
  RecordProperty("worst_step_mm", std::to_string(worst.step_m * 1000.0f) + " " + worst.step_what);
  RecordProperty("worst_change_mm", std::to_string(worst.change_m * 1000.0f) + " " + worst.change_what);
}

// A one-handed sign low on the far side of the body turns the thorax towards it (thorax_turn.h):
// the whole clip, from the rest pose and back, with the turn eased in and out by the transitions,
// keeps the wrists and elbows within the human bounds (5 hands x the stomach to below the waist x
// touch, close, none: 60 clips a rig, most of them turned).
TEST_P(MotionSmoothness, FarSideReachesWithTheTurnedThoraxMoveContinuously) {
  Synthesizer synth(avatar_);
  ASSERT_TRUE(synth.ok()) << synth.error();
  const notation::HandShape shapes[] = {testing::flat(), testing::fist(), testing::index_point(), testing::fist(),
                                        testing::index_point()};
  const notation::Direction fingers[] = {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}};
  Worst worst;
  for (int shape = 0; shape < 5; ++shape)
    for (notation::BodyLevel level : {notation::BodyLevel::Stomach, notation::BodyLevel::Belly,
                                      notation::BodyLevel::Waist, notation::BodyLevel::BelowWaist})
      for (notation::Contact c : {notation::Contact::Touch, notation::Contact::Close, notation::Contact::None}) {
        notation::SignSpec s = testing::sign_at(shapes[shape], level, notation::Side::LeftBeside, c);
        s.dominant.orientation.extended_finger = fingers[shape];
        s.dominant.orientation.palm = {0, 0, -1};
        SynthesisResult r = synth.sign(s, SynthesisOptions{});
        ASSERT_TRUE(r.ok()) << r.errors[0].message;
        const Worst w = measure(rig_, r.clip);
        const std::string where = "shape " + std::to_string(shape) + " level " + std::to_string(static_cast<int>(level)) +
                                  " contact " + std::to_string(static_cast<int>(c));
        expect_smooth(where, w, Bound{});
        if (w.step_m > worst.step_m) worst.step_m = w.step_m, worst.step_what = where + ": " + w.step_what;
        if (w.change_m > worst.change_m) worst.change_m = w.change_m, worst.change_what = where + ": " + w.change_what;
      }
  RecordProperty("worst_step_mm", std::to_string(worst.step_m * 1000.0f) + " " + worst.step_what);
  RecordProperty("worst_change_mm", std::to_string(worst.change_m * 1000.0f) + " " + worst.change_what);
}

TEST_P(MotionSmoothness, AlphabetsAndLetterPairsMoveContinuously) {
  Synthesizer synth(avatar_);
  ASSERT_TRUE(synth.ok()) << synth.error();
  // Every letter and pair within the human bounds. Й, held to its own 72 mm bound before,
  // measures under 26 mm on both rigs (already so on the main line this bound was tightened
  // on); the worst step change of all is 51 mm (the avatar's A -> Z).
  const Bound letters_bound{};
  for (const char* lang : {"ase", "ukl"}) {
    std::string text, error;
    if (!testing::read_text_file(kRoot + "/data/" + lang + "/alphabet.jsonl", &text)) GTEST_SKIP() << "no data alphabet " << lang;
    std::vector<AlphabetEntry> alphabet;
    ASSERT_TRUE(parse_alphabet_jsonl(text, &alphabet, &error)) << error;
    std::vector<PhraseItem> letters;
    for (const auto& e : alphabet) {
      PhraseText t = phrase_from_text(e.notation, {});
      ASSERT_TRUE(t.ok()) << e.letter;
      PhraseItem it = t.items[0];
      it.kind = PhraseItem::Kind::Letter;
      it.label = e.letter;
      letters.push_back(it);
    }
    SynthesisResult seq = synth.phrase(letters, from_key_pose());
    ASSERT_TRUE(seq.ok());
    const Worst seq_arms = measure(rig_, seq.clip), seq_tips = measure(rig_, seq.clip, 0, -1, Track::Fingertips);
    if (std::getenv("SIGNWEAVE_SMOOTHNESS_REPORT"))
      std::printf("smoothness %s %s sequence %.1f %.1f fingertips %.1f %.1f (%s | %s)\n", GetParam(), lang,
                  seq_arms.step_m * 1000.0f, seq_arms.change_m * 1000.0f, seq_tips.step_m * 1000.0f,
                  seq_tips.change_m * 1000.0f, seq_tips.step_what.c_str(), seq_tips.change_what.c_str());
    expect_smooth(std::string(lang) + " sequence", seq_arms, letters_bound);
    expect_smooth(std::string(lang) + " sequence fingertips", seq_tips, kLetterFingertipBound);
    const SynthesisOptions opt = from_key_pose();
    for (size_t a = 0; a < letters.size(); ++a)
      for (size_t b = 0; b < letters.size(); ++b) {
        if (a == b) continue;
        SynthesisResult r = synth.phrase({letters[a], letters[b]}, opt);
        ASSERT_TRUE(r.ok());
        const std::string pair = std::string(lang) + " " + letters[a].label + " -> " + letters[b].label;
        const Worst w = measure(rig_, r.clip), tips = measure(rig_, r.clip, 0, -1, Track::Fingertips);
        // SIGNWEAVE_SMOOTHNESS_REPORT=1 prints every pair's figures, as for the lexicon above.
        if (std::getenv("SIGNWEAVE_SMOOTHNESS_REPORT"))
          std::printf("smoothness %s %s %.1f %.1f fingertips %.1f %.1f (%s | %s)\n", GetParam(), pair.c_str(),
                      w.step_m * 1000.0f, w.change_m * 1000.0f, tips.step_m * 1000.0f, tips.change_m * 1000.0f,
                      tips.step_what.c_str(), tips.change_what.c_str());
        expect_smooth(pair, w, letters_bound);
        expect_smooth(pair + " fingertips", tips, kLetterFingertipBound);
      }
  }
}


// The frame rates and speed factors the page offers (clips are synthesised at the page's fps):
// the motion in seconds must keep to the same human bounds at each of them, the frame rate only
// sampling it. Measured in physical units over a fixed window of kWindowS = 1/30 s (a whole
// number of frames: 1 at 25 and 30 fps, 2 at 60): speed |p(t) - p(t-W)| / W and acceleration
// |p(t) - 2 p(t-W) + p(t-2W)| / W^2. Per frame at 60 fps, a velocity step dv shows as dv * 60
// m/s^2, twice what the same step gives at 30 fps, and the sampling noise of a smooth path
// grows with fps^2: a fixed window judges the same motion by the same figure at every rate, and
// at 30 fps it is exactly the per-frame measure above (10 cm/frame = 3 m/s, 5.6 cm change of
// step = 50.4 m/s^2).
constexpr float kWindowS = 1.0f / 30.0f;
constexpr float kMaxSpeedMPerS = kMaxStepM * 30.0f;
constexpr float kMaxAccelMPerS2 = kMaxStepChangeM * 30.0f * 30.0f;

struct PhysicalWorst {
  float speed = 0.0f, accel = 0.0f;  // m/s, m/s^2
  std::string speed_what, accel_what;
};

const char* segment_kind_name(ClipSegment::Kind k) {
  switch (k) {
    case ClipSegment::Kind::Sign: return "sign";
    case ClipSegment::Kind::Letter: return "letter";
    case ClipSegment::Kind::Transition: return "transition";
    case ClipSegment::Kind::Hold: return "hold";
    case ClipSegment::Kind::Pause: return "pause";
  }
  return "?";
}

// Where frame f lies: the segment's kind and label and the time into it (s).
std::string where_in(const Clip& c, int f) {
  const double t = f / double(c.fps);
  char buf[96];
  for (const ClipSegment& s : c.segments)
    if (t >= s.start_s - 1e-6 && t <= s.end_s + 1e-6) {
      std::snprintf(buf, sizeof buf, " (%s%s%s, %.3f of %.3f s)", segment_kind_name(s.kind), s.label.empty() ? "" : " ",
                    s.label.c_str(), t - s.start_s, s.end_s - s.start_s);
      return "frame " + std::to_string(f) + buf;
    }
  return "frame " + std::to_string(f);
}

// The wrists' and elbows' (or, with `fingertips`, the ten fingertips') worst speed and
// acceleration over the clip.
PhysicalWorst measure_physical(const Rig& rig, const Clip& clip, bool fingertips = false) {
  PhysicalWorst w;
  PoseBuilder pb(rig);
  const int J = rig.joint_count;
  const int W = std::max(1, static_cast<int>(std::lround(kWindowS * clip.fps)));
  const float win_s = static_cast<float>(W) / clip.fps;
  const char* side_names[2] = {"left", "right"};
  const char* finger_names[5] = {"thumb", "index", "middle", "ring", "little"};
  std::vector<std::string> names;
  for (Side s : {kLeft, kRight}) {
    if (fingertips) {
      for (const char* finger : finger_names) names.push_back(std::string(side_names[s]) + " " + finger + " tip");
    } else {
      names.push_back(std::string(side_names[s]) + " wrist");
      names.push_back(std::string(side_names[s]) + " elbow");
    }
  }
  const size_t n = names.size();
  std::vector<glm::vec3> pos(static_cast<size_t>(clip.frame_count) * n);
  for (int f = 0; f < clip.frame_count; ++f) {
    pb.set_from_local(&clip.rotations[static_cast<size_t>(f) * J]);
    size_t k = 0;
    for (Side s : {kLeft, kRight}) {
      if (fingertips) {
        for (int finger = 0; finger < 5; ++finger) pos[static_cast<size_t>(f) * n + k++] = pb.tip(s, finger);
      } else {
        pos[static_cast<size_t>(f) * n + k++] = pb.position(rig.arms[s].hand);
        pos[static_cast<size_t>(f) * n + k++] = pb.position(rig.arms[s].lower);
      }
    }
  }
  auto at = [&](int f, size_t k) { return pos[static_cast<size_t>(f) * n + k]; };
  for (int f = W; f < clip.frame_count; ++f)
    for (size_t k = 0; k < n; ++k) {
      const float v = glm::length(at(f, k) - at(f - W, k)) / win_s;
      if (v > w.speed) w.speed = v, w.speed_what = names[k] + " at " + where_in(clip, f);
      if (f < 2 * W) continue;
      const float a = glm::length(at(f, k) - 2.0f * at(f - W, k) + at(f - 2 * W, k)) / (win_s * win_s);
      if (a > w.accel) w.accel = a, w.accel_what = names[k] + " at " + where_in(clip, f - W);
    }
  return w;
}

// Every lexicon sign, from the rest pose and back as the page plays it, at 25/30/60 fps x speed
// 0.8/1.0/1.25: wrists and elbows within 3 m/s and 50 m/s^2 (the bounds above, in seconds), the
// fingertips too (their known gaps below), and the arms out of the trunk and out of each other
// within 5 mm outside intended contact. The frame rate and speed change the transitions' state
// count k, so a path judged on its own frames could be clear at one setting and not at another.
// 141 signs x 9 settings a rig: one pass measures both on the same clips (they were two tests
// synthesising the same 2,538 phrases).
TEST_P(MotionSmoothness, EveryLexiconSignMovesHumanlyAndKeepsItsArmsOutAtEveryFrameRateAndSpeed) {
  std::string text;
  if (!testing::read_text_file(kRoot + "/data/ase/lexicon.jsonl", &text)) GTEST_SKIP() << "no data lexicon";
  Synthesizer synth(avatar_);
  ASSERT_TRUE(synth.ok()) << synth.error();
  SynthContext ctx;
  std::string ctx_error;
  ASSERT_TRUE(make_context(avatar_, SynthesisOptions{}, &ctx, &ctx_error)) << ctx_error;
  // Arm depth: no known gaps on either rig. The reference humanoid's were, at their worst setting:
  // DAY 5.6 mm (the upper arm across the chest as the wrist-led arc went beyond the arm's reach;
  // the wrist now goes round the elbow), MORNING 7.0 (the left arm across the torso to the crook
  // of the right elbow; that place now comes forward), HAPPY 9.9 (the brushing circle ran into
  // the chest; it now starts at the chest), DIFFERENT 13.4 (crossed hands laid apart by
  // alternating pushes; the pair is now laid clear of both hands and forearms), all in
  // sign_motion.cpp / movement.cpp. SAD and HAVE (forearms through each other in the arriving
  // transition at some state counts: 7.2/10.4 mm on the reference, 5.5 mm on the project avatar)
  // are clear since a route's excess over its end poses adds the kinds (transition.cpp).
  constexpr float kMaxArmDepthM = 0.005f;
  float worst_depth_m = 0.0f;
  struct Limit {
    float speed = kMaxSpeedMPerS, accel = kMaxAccelMPerS2;
  };
  // Known gaps: "rig GLOSS" -> the worst over the 9 settings as measured (m/s, m/s^2, rounded
  // up), each with its reason (docs/SYNTHESIS.md, Known issues).
  // Before the ramps spanned a fixed time (frame_corrections' ramps counted 8 frames) and the
  // last ramp round stopped adding one-frame fixes, 24 of the 2,538 sign-settings were over,
  // worst THANK-YOU 4.3 m/s and 144 m/s^2 (reference, 60 fps x 1.25); now 20.
  // OLD (reference humanoid, 60 fps only: 2.7 m/s, 153 m/s^2 at 0.52 of 0.65 s) is within the
  // bounds (22-32 m/s^2 at 60 fps): the forearm lies in the torso while the hand is at the chin,
  // the swivel fixes that clear it (up to 1.5 rad) do not settle in the ramp rounds, and the
  // last round cleared a frame 4.x mm deep at once (+0.3 rad for one frame, the elbow 8.7 cm
  // up and back); that net now acts only beyond 4.9 mm, the lexicon's 5 mm bound
  // (sign_motion.cpp kRampOnlyClearM, AnArmWithinTheDepthBoundIsNotJerkedOutOfIt; the arm 4.6 ->
  // 4.7 mm deep). Its cause, the key pose (the wrist 9 cm in front of the shoulder), is left.
  // THANK-YOU (3.1 m/s, 94 m/s^2) and GOOD (3.3 m/s, 123 m/s^2) are off the list: their hands
  // turned about the fingertips at the chin, the wrist into the neck
  // (AHandLeavingATouchWhileItTurnsCarriesItsWristAlongThePath).
  // KEY (both rigs, 60 fps: the wrist twist turned round with a kink, 66-69 m/s^2) is within the
  // bounds (22 m/s^2) since twists are refitted at the wrist's limits and timed at a constant
  // rate (arm_ik.cpp fit_clamped_wrist, movement.cpp). 8 sign-settings are over now.
  // - TEACHER (reference; 0.8 and 60 fps, the left elbow in the sign's last movement, up to
  //   78 m/s^2; 35 at 30 fps x 1): the elbow speeds up over the movement's last 0.1 s while
  //   the wrist slows, and stops within a frame: the wrist turns through a flip there (6 rad/s
  //   x speed) and the arm meets the free solution where that ends. Traced further: the folded
  //   arm at the elbow's and all three wrist angles' limits beside the forehead, the contact
  //   2 -> 45 mm short, the clavicle elevation wobbling frame by frame (docs/SYNTHESIS.md).
  //   With the swivel's zero leaning forward over the shoulder (arm_ik.cpp, merged from main):
  //   58.1 m/s^2 at 0.8 (30 and 60 fps), 52.9-53.0 at 1.25, 43.2 at 60 fps x 1 (was 77.5).
  //   Off the list: the data asked for what no arm reaches. The written TEACHER opened to the
  //   flat hands, fingers forward, palms facing, AT the temples (close beside the forehead):
  //   the wrist must then sit behind the fingertips at the side of the head, beyond the folded
  //   arm (the elbow at 150 degrees, the wrist 1.5 rad beyond its limits). A signer opens the
  //   hands as they come down and forward from the temples (PERSON is signed in front of the
  //   body): data/ase/lexicon.jsonl now writes the opening with a step down and out. Worst
  //   setting 31.4 m/s^2 (reference, 30 fps x 1.25), fingertips 27.3.
  // UNDERSTAND (both rigs, 30 fps x 1.25, the elbow in the rest transitions: 50.4 / 53.0 m/s^2,
  // 31-35 at speed 1; the speed factor divides every duration, so accelerations grow with its
  // square) is within the bounds (39.5 / 39.9 m/s^2) since a transition's k is stretched until no
  // arm joint accelerates beyond 40 m/s^2 (transition.cpp kArmPeakAccelMPerS2,
  // RestTransitionsKeepTheArmWithinHumanAccelerationAtAFasterSpeed). With OLD, 4 sign-settings were
  // over (TEACHER's); with TEACHER's data corrected (above), none.
  const std::map<std::string, Limit> known = {};
  // Fingertips, over the same window: the hand's bounds (3 m/s; 50.4 m/s^2, the hand's 56 mm
  // change of a 30 fps step). Before the hand path's fingertip peak stopped scaling with the
  // speed factor above 1 (transition.cpp kHandPathFingerPeakMPerS: 2.5 m/s x 1.25), 605 of the
  // 846 sign-settings at speed 1.25 had a fingertip over 3 m/s in a rest transition (MAN 3.48
  // m/s); now none (worst 2.96 m/s, IMPORTANT's sign on the reference at 25 fps x 1.25; 2.74
  // since the signs' steps are stretched above speed 1, WE and WOMAN's rest transitions on the
  // avatar). Their
  // accelerations at speeds 0.8 and 1 keep to 50.4 m/s^2 but for TEACHER on the reference (its
  // arm above); at 1.25 the speed factor's square on the signs' own movements and on the
  // transitions' hands (the transitions' acceleration rule counts the arm joints) takes a few
  // over, held to their measured worst over the 9 settings (m/s^2, rounded up). Off the list:
  // PLEASE (reference 65.0 -> 46.4, avatar 50.7 -> 43.6) and LOOK (avatar 53.1 -> 49.8): the
  // speed factor's square on the signs' own steps; above speed 1 a step is now stretched until
  // its hand keeps within 45 m/s^2 and 2.7 m/s, never beyond its speed-1 time (sign_motion.cpp,
  // ASignsOwnMovementKeepsTheHandWithinHumanAccelerationAtAFasterSpeed). TEACHER on the
  // reference (63 -> 27.3): its data (above). TEACH and TEACHER on the avatar (51.6 -> 48.8,
  // the middle fingertip in the rest transition at 1.25): the transitions' acceleration rule
  // now counts the fingertips (transition.cpp kFingertipPeakAccelMPerS2,
  // RestTransitionsKeepTheFingertipsWithinHumanAccelerationAtAFasterSpeed). None left.
  const std::map<std::string, float> known_tips = {};
  PhysicalWorst worst_tips;
  int over = 0, settings = 0;
  PhysicalWorst worst;
  for (const testing::LexiconSign& sign : testing::lexicon_signs(text)) {
    ASSERT_TRUE(sign.text.ok()) << sign.gloss;
    PhysicalWorst sw, sign_tips;
    for (float fps : {25.0f, 30.0f, 60.0f})
      for (float speed : {0.8f, 1.0f, 1.25f}) {
        SynthesisOptions o;
        o.fps = fps;
        o.speed = speed;
        SynthesisResult r = synth.phrase(sign.text.items, o);
        ASSERT_TRUE(r.ok()) << sign.gloss;
        const PhysicalWorst w = measure_physical(rig_, r.clip);
        char setting[48];
        std::snprintf(setting, sizeof setting, "%g fps x %g: ", fps, speed);
        const testing::ArmDepths d = testing::arm_depths(ctx, r);
        const float depth_m = std::max(d.trunk_m, d.forearms_m);
        EXPECT_LE(depth_m, kMaxArmDepthM) << GetParam() << " " << sign.gloss << " " << setting
                                          << (d.trunk_m >= d.forearms_m ? d.trunk_what : d.forearms_what);
        worst_depth_m = std::max(worst_depth_m, depth_m);
        if (std::getenv("SIGNWEAVE_LEXICON_REPORT"))
          std::printf("sweep %s %s %g %g %.1f mm %s\n", GetParam(), sign.gloss.c_str(), fps, speed, depth_m * 1000.0f,
                      (d.trunk_m >= d.forearms_m ? d.trunk_what : d.forearms_what).c_str());
        const PhysicalWorst tips = measure_physical(rig_, r.clip, true);
        if (std::getenv("SIGNWEAVE_SMOOTHNESS_REPORT")) {
          std::printf("smoothness-settings %s %s %g %g %.2f m/s (%s) %.1f m/s^2 (%s)\n", GetParam(), sign.gloss.c_str(), fps,
                      speed, w.speed, w.speed_what.c_str(), w.accel, w.accel_what.c_str());
          std::printf("smoothness-tips %s %s %g %g %.2f m/s (%s) %.1f m/s^2 (%s)\n", GetParam(), sign.gloss.c_str(), fps,
                      speed, tips.speed, tips.speed_what.c_str(), tips.accel, tips.accel_what.c_str());
        }
        over += w.speed > kMaxSpeedMPerS || w.accel > kMaxAccelMPerS2;
        ++settings;
        if (w.speed > sw.speed) sw.speed = w.speed, sw.speed_what = setting + w.speed_what;
        if (w.accel > sw.accel) sw.accel = w.accel, sw.accel_what = setting + w.accel_what;
        if (tips.speed > sign_tips.speed)
          sign_tips.speed = tips.speed, sign_tips.speed_what = setting + tips.speed_what;
        if (tips.accel > sign_tips.accel)
          sign_tips.accel = tips.accel, sign_tips.accel_what = setting + tips.accel_what;
      }
    const std::string key = std::string(GetParam()) + " " + sign.gloss;
    auto kt = known_tips.find(key);
    EXPECT_LE(sign_tips.speed, kMaxSpeedMPerS) << key << " fingertips: " << sign_tips.speed_what;
    EXPECT_LE(sign_tips.accel, kt == known_tips.end() ? kMaxAccelMPerS2 : kt->second)
        << key << " fingertips: " << sign_tips.accel_what;
    if (sign_tips.speed > worst_tips.speed)
      worst_tips.speed = sign_tips.speed, worst_tips.speed_what = key + " " + sign_tips.speed_what;
    if (kt == known_tips.end() && sign_tips.accel > worst_tips.accel)
      worst_tips.accel = sign_tips.accel, worst_tips.accel_what = key + " " + sign_tips.accel_what;
    auto k = known.find(key);
    const Limit lim = k == known.end() ? Limit{} : k->second;
    EXPECT_LE(sw.speed, lim.speed) << key << ": " << sw.speed_what;
    EXPECT_LE(sw.accel, lim.accel) << key << ": " << sw.accel_what;
    if (k != known.end()) continue;
    if (sw.speed > worst.speed) worst.speed = sw.speed, worst.speed_what = key + " " + sw.speed_what;
    if (sw.accel > worst.accel) worst.accel = sw.accel, worst.accel_what = key + " " + sw.accel_what;
  }
  EXPECT_GE(settings, 9 * 110);
  RecordProperty("sign_settings_over_human_bounds", std::to_string(over) + "/" + std::to_string(settings));
  RecordProperty("worst_speed_m_per_s", std::to_string(worst.speed) + " " + worst.speed_what);
  RecordProperty("worst_fingertip_speed_m_per_s", std::to_string(worst_tips.speed) + " " + worst_tips.speed_what);
  RecordProperty("worst_fingertip_accel_m_per_s2", std::to_string(worst_tips.accel) + " " + worst_tips.accel_what);
  RecordProperty("worst_accel_m_per_s2", std::to_string(worst.accel) + " " + worst.accel_what);
  RecordProperty("worst_arm_depth_mm", std::to_string(worst_depth_m * 1000.0f));
}

// A faster signer still has a human arm. The speed factor divides every duration, so along the
// same path every acceleration grows with its square: UNDERSTAND's raise to the forehead (its
// elbow swinging from behind the arm to in front of it between two of the hand path's
// waypoints) measured 31-35 m/s^2 at speed 1 and 50.4 (project avatar) / 53.0 (reference) at
// 30 fps x 1.25. A transition's states now keep every arm joint within 40 m/s^2 (transition.cpp,
// kArmPeakAccelMPerS2): at 1.25 and 1.5 (30 and 60 fps) every rest transition of the lexicon
// keeps its wrists and elbows within that, +2 m/s^2 for the windows straddling the sign's first
// or last frame (measured 41.5, SISTER on the reference humanoid at 60 fps x 1.5; before, 64.8 /
// 68.2, YESTERDAY / TEACH at 1.5), measured as the lexicon test measures.
TEST_P(MotionSmoothness, RestTransitionsKeepTheArmWithinHumanAccelerationAtAFasterSpeed) {
  std::string text;
  if (!testing::read_text_file(kRoot + "/data/ase/lexicon.jsonl", &text)) GTEST_SKIP() << "no data lexicon";
  Synthesizer synth(avatar_);
  ASSERT_TRUE(synth.ok()) << synth.error();
  PoseBuilder pb(rig_);
  const int J = rig_.joint_count;
  float worst = 0.0f;
  std::string worst_what;
  int checked = 0;
  bool saw_understand = false;
  for (const testing::LexiconSign& sign : testing::lexicon_signs(text)) {
    ASSERT_TRUE(sign.text.ok()) << sign.gloss;
    saw_understand |= sign.gloss == "UNDERSTAND";
    for (float fps : {30.0f, 60.0f})
      for (float speed : {1.25f, 1.5f}) {
        SynthesisOptions o;
        o.fps = fps;
        o.speed = speed;
        SynthesisResult r = synth.phrase(sign.text.items, o);
        ASSERT_TRUE(r.ok()) << sign.gloss;
        const Clip& c = r.clip;
        const int W = std::max(1, static_cast<int>(std::lround(kWindowS * c.fps)));
        const float win_s = static_cast<float>(W) / c.fps;
        for (const ClipSegment& seg : c.segments) {
          if (seg.kind != ClipSegment::Kind::Transition) continue;
          const int first = static_cast<int>(std::lround(seg.start_s * c.fps));
          const int last = std::min(c.frame_count - 1, static_cast<int>(std::lround(seg.end_s * c.fps)));
          std::vector<std::array<glm::vec3, 4>> pos;
          for (int f = std::max(0, first - W); f <= std::min(c.frame_count - 1, last + W); ++f) {
            pb.set_from_local(&c.rotations[static_cast<size_t>(f) * J]);
            pos.push_back({pb.position(rig_.arms[kLeft].hand), pb.position(rig_.arms[kLeft].lower),
                           pb.position(rig_.arms[kRight].hand), pb.position(rig_.arms[kRight].lower)});
          }
          const int offset = std::max(0, first - W);
          for (int f = first; f <= last; ++f) {
            const int i = f - offset;
            if (i - W < 0 || i + W >= static_cast<int>(pos.size())) continue;
            for (int k = 0; k < 4; ++k) {
              const float a = glm::length(pos[i + W][k] - 2.0f * pos[i][k] + pos[i - W][k]) / (win_s * win_s);
              if (a > worst) {
                worst = a;
                char buf[64];
                std::snprintf(buf, sizeof buf, " at %g fps x %g: ", fps, speed);
                worst_what = sign.gloss + buf + where_in(c, f);
              }
            }
          }
          ++checked;
        }
      }
  }
  EXPECT_TRUE(saw_understand) << "UNDERSTAND is not in the lexicon";
  EXPECT_GE(checked, 4 * 2 * 110);
  EXPECT_LE(worst, 42.0f) << worst_what;
  RecordProperty("worst_rest_transition_accel_m_per_s2", std::to_string(worst) + " " + worst_what);
}

// A faster signer still has a human hand. A sign's own steps took the speed factor as a divisor
// of their time, so along the same path their accelerations grew with its square: PLEASE's flat
// hand circling on the chest, 46.4 m/s^2 at a fingertip at 30 fps x 1 on the reference
// humanoid, 65.0 at 60 fps x 1.25 (the project avatar 50.7). Above speed 1 a step whose hand
// passes 45 m/s^2 in the solved frames is stretched, never beyond its time at speed 1
// (sign_motion.cpp kStepHandPeakAccelMPerS2): 45.5 / within 45. A step within bounds keeps
// the speed factor's timing: a small push forward takes its speed-1 time over 1.25.
TEST_P(MotionSmoothness, ASignsOwnMovementKeepsTheHandWithinHumanAccelerationAtAFasterSpeed) {
  Synthesizer synth(avatar_);
  ASSERT_TRUE(synth.ok()) << synth.error();
  auto sign_s = [](const Clip& c) {
    for (const ClipSegment& seg : c.segments)
      if (seg.kind == ClipSegment::Kind::Sign) return seg.end_s - seg.start_s;
    return 0.0;
  };
  const PhraseText please = phrase_from_text(
      "R(H(flat), E(u), P(i), Loc(chest, centre, touch), C(palm), M(circle, axis=o, cw))", {});
  const PhraseText push =
      phrase_from_text("R(H(flat), E(u), P(o), Loc(chest, centre), M(straight, o, small))", {});
  ASSERT_TRUE(please.ok() && push.ok());
  for (float fps : {30.0f, 60.0f}) {
    SynthesisOptions o;
    o.fps = fps;
    SynthesisResult at_1 = synth.phrase(please.items, o);
    o.speed = 1.25f;
    SynthesisResult faster = synth.phrase(please.items, o);
    ASSERT_TRUE(at_1.ok() && faster.ok());
    const PhysicalWorst tips = measure_physical(rig_, faster.clip, true);
    EXPECT_LE(tips.accel, kMaxAccelMPerS2)
        << "PLEASE at " << fps << " fps x 1.25: " << tips.accel_what;
    EXPECT_LE(sign_s(faster.clip), sign_s(at_1.clip) + 1e-6) << "PLEASE at " << fps << " fps";
    o.speed = 1.0f;
    at_1 = synth.phrase(push.items, o);
    o.speed = 1.25f;
    faster = synth.phrase(push.items, o);
    ASSERT_TRUE(at_1.ok() && faster.ok());
    EXPECT_LE(measure_physical(rig_, faster.clip, true).accel, 45.0f);
    EXPECT_NEAR(sign_s(faster.clip), sign_s(at_1.clip) / 1.25, 2.0 / fps)
        << "a push at " << fps << " fps";
  }
}

// The transitions' acceleration rule counted the arm joints only: from the rest pose, TEACH's
// hand turns to fingers up beside the temple and on the project avatar its middle fingertip
// reached 51.6 m/s^2 at 60 fps x 1.25 (50.6 at 25 fps), beyond the hand's 50.4. The fingertips
// now count at 50 m/s^2 (transition.cpp kFingertipPeakAccelMPerS2): 48.8.
TEST_P(MotionSmoothness, RestTransitionsKeepTheFingertipsWithinHumanAccelerationAtAFasterSpeed) {
  Synthesizer synth(avatar_);
  ASSERT_TRUE(synth.ok()) << synth.error();
  const PhraseText teach = phrase_from_text(
      "R(H(pinchall, bent), E(u), P(o), Loc(forehead, right_beside, close), M(straight, o, small), "
      "Rep(fromstart, 1)) "
      "Sym(lr)",
      {});
  ASSERT_TRUE(teach.ok());
  for (float fps : {25.0f, 30.0f, 60.0f}) {
    SynthesisOptions o;
    o.fps = fps;
    o.speed = 1.25f;
    SynthesisResult r = synth.phrase(teach.items, o);
    ASSERT_TRUE(r.ok());
    const PhysicalWorst tips = measure_physical(rig_, r.clip, true);
    EXPECT_LE(tips.accel, kMaxAccelMPerS2)
        << "TEACH at " << fps << " fps x 1.25: " << tips.accel_what;
  }
}

// A frame whose arm is within the lexicon's depth bound is not jerked out of it. OLD's C hand
// grasps under the chin on the reference humanoid; at 60 fps the swivel each frame needs changes
// faster than the correction ramps can follow, and the last ramp round cleared a frame whose
// forearm was 4.x mm in the torso at once (a net at 4 mm): +0.3 rad for that frame alone, the
// elbow 8.7 cm up and back, 153 m/s^2 at 0.8, 1 and 1.25. The net now acts only from 4.9 mm
// (sign_motion.cpp kRampOnlyClearM): within the human bounds at every speed, and the arm no
// more than 5 mm in the trunk (the lexicon's bound; measured 4.7 mm).
TEST_P(MotionSmoothness, AnArmWithinTheDepthBoundIsNotJerkedOutOfIt) {
  Synthesizer synth(avatar_);
  ASSERT_TRUE(synth.ok()) << synth.error();
  SynthContext ctx;
  std::string error;
  ASSERT_TRUE(make_context(avatar_, SynthesisOptions{}, &ctx, &error)) << error;
  const PhraseText t = phrase_from_text(
      "R(H(ceeall), E(o), P(l), Loc(chin, centre, touch), C(palm), Par(M(straight, d), M(replace, H(fist, "
      "thumbacross))))",
      {});
  ASSERT_TRUE(t.ok());
  for (float speed : {0.8f, 1.0f, 1.25f}) {
    SCOPED_TRACE("OLD at 60 fps x " + std::to_string(speed));
    SynthesisOptions o;
    o.fps = 60.0f;
    o.speed = speed;
    SynthesisResult r = synth.phrase(t.items, o);
    ASSERT_TRUE(r.ok());
    const PhysicalWorst w = measure_physical(rig_, r.clip);
    EXPECT_LE(w.speed, kMaxSpeedMPerS) << w.speed_what;
    EXPECT_LE(w.accel, kMaxAccelMPerS2) << w.accel_what;
    float depth_m = 0.0f;
    PoseBuilder pb(rig_);
    for (int f = 0; f < r.clip.frame_count; ++f) {
      pb.set_from_local(&r.clip.rotations[static_cast<size_t>(f) * rig_.joint_count]);
      const bool contact = r.report.intended_contact[static_cast<size_t>(f)] & exempt_bit(kRight, false);
      depth_m = std::max(depth_m, arm_penetration(ctx.body, pb, kRight, true, contact, false).depth_m);
    }
    EXPECT_LE(depth_m, 0.005f);
  }
}

// A hand that leaves its touch while it turns (THANK-YOU: the fingertips at the chin, fingers up,
// then out and down, turning to fingers forward, palm up) travels the path with its wrist: the
// written contact part belongs to the place it leaves. Turned about the fingertips, fingers
// forward put the goal's wrist 18 cm behind the chin (in the neck) and the wrist went back
// along the path instead of out; the reference humanoid's forearm lay 86 mm in the torso and
// the frames' swivel fixes (up to 1.5 rad) moved the wrist at 3.1 m/s, 93 m/s^2 (60 fps).
TEST_P(MotionSmoothness, AHandLeavingATouchWhileItTurnsCarriesItsWristAlongThePath) {
  Synthesizer synth(avatar_);
  ASSERT_TRUE(synth.ok()) << synth.error();
  // THANK-YOU (out and down) and GOOD (to the left palm: the contact point travels there).
  for (const char* text :
       {"R(H(flat), E(u), P(i), Loc(chin, centre, touch), C(tip, 2), Par(M(straight, do), M(replace, E(o), P(u))))",
        "R(H(flat), E(u), P(i), Loc(chin, centre, touch), C(tip, 2), Par(M(to, Loc(hand, palm, touch)), M(replace, "
        "E(o), P(u)))) L(H(flat), E(o), P(u), Loc(neutral, centre))"})
  for (float fps : {25.0f, 30.0f, 60.0f})
  for (float speed : {1.0f, 1.25f}) {
    const PhraseText t = phrase_from_text(text, {});
    ASSERT_TRUE(t.ok()) << text;
    SCOPED_TRACE(std::string(text) + " at " + std::to_string(fps) + " fps x " + std::to_string(speed));
    SynthesisOptions o = from_key_pose();
    o.fps = fps;
    o.speed = speed;
    SynthesisResult r = synth.phrase(t.items, o);
    ASSERT_TRUE(r.ok());
    PoseBuilder pb(rig_);
    const int J = rig_.joint_count;
    pb.set_from_local(&r.clip.rotations[0]);
    const glm::vec3 start = pb.position(rig_.arms[kRight].hand);
    float least_forward = 0.0f;
    glm::vec3 wrist = start;
    for (int f = 0; f < r.clip.frame_count; ++f) {
      pb.set_from_local(&r.clip.rotations[static_cast<size_t>(f) * J]);
      wrist = pb.position(rig_.arms[kRight].hand);
      least_forward = std::min(least_forward, glm::dot(wrist - start, rig_.forward));
    }
    // Out and down: the wrist ends in front of where it started and never goes back towards the body.
    EXPECT_GT(glm::dot(wrist - start, rig_.forward), 0.03f);
    EXPECT_GT(least_forward, -0.01f);
    const PhysicalWorst w = measure_physical(rig_, r.clip);
    EXPECT_LE(w.speed, kMaxSpeedMPerS) << w.speed_what;
    EXPECT_LE(w.accel, kMaxAccelMPerS2) << w.accel_what;
  }
}

// A hand turned half round in place above the shoulder (not in the lexicon): the pinched hand at
// the forehead, fingers in, replaced by a flat hand pointing forward. Its wrist passes straight
// over the shoulder joint, where the swivel's zero (the elbow "down", arm_ik.cpp solve_chain)
// turned half round: the project avatar's elbow jumped 194 mm in a frame (243 mm change of step),
// the reference humanoid's 90 mm. Both now within the hand's bounds (measured 84 / 41 mm on the
// avatar, 89 / 46 mm on the reference: what is left is the elbow's sweep from the key pose's
// swivel to the goal's over the replace, not a jump).
TEST_P(MotionSmoothness, AHandTurnedHalfRoundInPlaceOverTheShoulderMovesItsElbowSmoothly) {
  Synthesizer synth(avatar_);
  ASSERT_TRUE(synth.ok()) << synth.error();
  const PhraseText t =
      phrase_from_text("R(H(pinchall, bent), E(i), P(d), Loc(forehead, centre, touch), M(replace, H(flat), E(o), P(d)))", {});
  ASSERT_TRUE(t.ok());
  SynthesisResult r = synth.phrase(t.items, from_key_pose());
  ASSERT_TRUE(r.ok());
  const Worst w = measure(rig_, r.clip);
  expect_smooth(GetParam(), w, Bound{});
  RecordProperty("worst_step_mm", std::to_string(w.step_m * 1000.0f) + " " + w.step_what);
  RecordProperty("worst_change_mm", std::to_string(w.change_m * 1000.0f) + " " + w.change_what);
}

// A bent index at the ear, pointing up and out, that arcs down while it turns in and up (the
// HamNoSys corpus's HEARING-AID1^, whole, from the rest pose and back). At the turn the wrist sits
// at the shoulder joint's coronal plane, where the swivel's zero (arm_ik.cpp solve_chain) turns
// half round: the frames' swivel numbers put the project avatar's right elbow on the other side of
// its circle in one frame, 486 mm (a change of step of 524 mm). The elbow is now carried round its
// circle over several frames (elbow_path.h), the wrist's path unchanged: 70 / 51 mm.
TEST_P(MotionSmoothness, AFingerAtTheEarArcingDownWhileItTurnsCarriesTheElbowRoundItsCircle) {
  const std::vector<notation::SignParse> read = notation::parse_hamnosys_text(
      "hamfinger2,hamfingerbendmod,hamextfingeruo,hampalmdl,hamear,hamlrat,hamclose,hamparbegin,hammoved,hamsmallmod,"
      "hamarcd,hamsmallmod,hamreplace,hamextfingerui,hampalmul,hamparend");
  ASSERT_EQ(read.size(), 1u);
  ASSERT_TRUE(read[0].ok() && read[0].spec);
  const SynthesisResult r = synthesize_sign(*read[0].spec, avatar_, SynthesisOptions{});
  ASSERT_TRUE(r.ok());
  const Worst w = measure(rig_, r.clip);
  expect_smooth(GetParam(), w, Bound{});
  RecordProperty("worst_step_mm", std::to_string(w.step_m * 1000.0f) + " " + w.step_what);
  RecordProperty("worst_change_mm", std::to_string(w.change_m * 1000.0f) + " " + w.change_what);
  // ... and the wrist joint within its limits in every frame, the swing too: the hand's local
  // rotation (flexion and deviation; the forearm carries the twist) bent from its bind at most
  // as far as the largest flexion and deviation together allow. Carrying the elbow round with
  // the hand's orientation kept in space bent this wrist 2.8 rad (project avatar).
  expect_wrists_within_their_bend(rig_, r.clip, GetParam(), {kRight});
}

// Both flat hands at the shoulders, fingertips touching them, that turn down and arc down and
// out (the HamNoSys corpus's nie chcieć, whole, from the rest pose and back). No swivel offset
// clears the right arm over the arc, and the best offset's side, chosen frame by frame, flipped
// between neighbouring frames; the ramp followed the larger neighbour, and the ramped swivels
// swung the project avatar's right elbow 530 mm in one frame (a change of step of 550 mm), the
// arm 16.1 mm deep, the right wrist bent 1.46 rad. With one side for the whole run of fixes
// (sign_motion.cpp, kept where the arms are no deeper): 102 mm, 0.8 mm, 1.18 rad (the
// reference: 59 mm, clear, either way).
TEST_P(MotionSmoothness, ShoulderTouchArcingDownKeepsItsElbowOnOneSideOfTheBody) {
  const std::vector<notation::SignParse> read = notation::parse_hamnosys_text(
      "hamsymmlr,hamfingerstraightmod,hamflathand,hamextfingerul,hampalml,hamshoulders,hamlrat,hamseqbegin,"
      "hamtouch,hamfingertip,hamseqend,hamparbegin,hamreplace,hamextfingeruo,hampalmd,hammovedo,hamarcd,hamfast,"
      "hamparend");
  ASSERT_EQ(read.size(), 1u);
  ASSERT_TRUE(read[0].ok() && read[0].spec);
  const SynthesisResult r = synthesize_sign(*read[0].spec, avatar_, SynthesisOptions{});
  ASSERT_TRUE(r.ok());
  const Worst w = measure(rig_, r.clip);
  EXPECT_LE(w.step_m, 0.15f) << GetParam() << ": " << w.step_what;
  EXPECT_LE(r.report.max_penetration_m, 0.005f) << GetParam();
  RecordProperty("worst_step_mm", std::to_string(w.step_m * 1000.0f) + " " + w.step_what);
  RecordProperty("worst_change_mm", std::to_string(w.change_m * 1000.0f) + " " + w.change_what);
  // Both wrists within the joint's limits in every frame (as the test above).
  expect_wrists_within_their_bend(rig_, r.clip, GetParam());
}

// Hands whose wrist flips and then turns through (sign_motion.cpp `continued`): with the wrist
// angles held, the arm solve's iteration has an answer on either side of the contact point, and
// the usual start picked one or the other from frame to frame. The HamNoSys corpus's TO-LEARN2B^
// (the pinched hand circling at the cheek, touching) and GROIN1B^ (the flat hand at the stomach,
// moving up-right), whole, from the rest pose and back. The sign is also solved with each
// continued frame's branch chosen on the finished frame, and that solve kept where it is no
// deeper and steps less. Measured on the project avatar, the largest step of a wrist in a frame:
// TO-LEARN2B^ 107 -> 74 mm, GROIN1B^ 106 -> 57 mm; the wrists stay within their bend (as
// AFingerAtTheEarArcingDown... above) and the arms out of the body. The reference humanoid is
// held to the same bounds.
TEST_P(MotionSmoothness, AWristTurningThroughAFlipAtAContactKeepsItsSideOfTheContact) {
  for (const char* names :
       {"hampinchall,hamfingerstraightmod,hamextfingeru,hampalml,hamcheek,hamlrat,hamclose,hamcircleui,hamtouch,"
        "hamrepeatfromstart",
        "hamflathand,hamextfingerdl,hampalmu,hamstomach,hamlrat,hamtouch,hammoveur"}) {
    SCOPED_TRACE(names);
    const std::vector<notation::SignParse> read = notation::parse_hamnosys_text(names);
    ASSERT_EQ(read.size(), 1u);
    ASSERT_TRUE(read[0].ok() && read[0].spec);
    const SynthesisResult r = synthesize_sign(*read[0].spec, avatar_, SynthesisOptions{});
    ASSERT_TRUE(r.ok());
    PoseBuilder pb(rig_);
    const int J = rig_.joint_count;
    float step = 0.0f;
    std::array<glm::vec3, 2> before{};
    for (int f = 0; f < r.clip.frame_count; ++f) {
      pb.set_from_local(&r.clip.rotations[static_cast<size_t>(f) * J]);
      for (Side s : {kLeft, kRight}) {
        const glm::vec3 wrist = pb.position(rig_.arms[s].hand);
        if (f > 0) step = std::max(step, glm::length(wrist - before[s]));
        before[s] = wrist;
      }
    }
    RecordProperty("largest_wrist_step_mm", std::to_string(step * 1000.0f));
    EXPECT_LT(step, 0.090f);
    EXPECT_LE(r.report.max_penetration_m, 0.005f);
    expect_wrists_within_their_bend(rig_, r.clip, GetParam());
  }
}

// Both hands at the shoulders moving in to the top of the shoulder (the HamNoSys corpus's
// siedem tygodni temu, whole, from the rest pose and back). On the way the hands' targets lie in
// the pocket between the chin, the neck and the top of the torso: a push out of the deepest
// capsule went into the next, and the way the hand finally left by flipped between neighbouring
// frames (sideways, then back, then the other side), so the ramped pushes alternated. Measured
// on the project avatar without the jam rule (sign_motion.cpp `jam_rule`): the left elbow 397 mm
// in one frame, the arms 25.5 mm deep; with it, 110 mm and 8.0 mm. The reference humanoid's
// largest step is elsewhere (337 mm); chosen on the sign alone the rule's clip was 4.4 mm deep in
// the rest transitions, judged with them (synthesize.cpp) the clip without the rule stays (337.4
// mm, as without the rule): held to the lexicon's 5 mm arm bound and to its step, not improved.
TEST_P(MotionSmoothness, HandsCaughtBetweenTheChinAndTheTorsoLeaveByOneWay) {
  const std::vector<notation::SignParse> read = notation::parse_hamnosys_text(
      "hamsymmpar,hamparbegin,hamfinger2,hamthumboutmod,hamextfingeru,hampalmd,hamplus,hamfinger2345,"
      "hamthumboutmod,hamextfingeru,hampalmd,hamparend,hamparbegin,hamshoulders,hamlrat,hamplus,hamshoulders,"
      "hamlrat,hamparend,hamparbegin,hammovei,hamlargemod,hamshouldertop,hamlrat,hamclose,hamreplace,"
      "hamextfingeri,hampalmd,hamparend");
  ASSERT_EQ(read.size(), 1u);
  ASSERT_TRUE(read[0].ok() && read[0].spec);
  const SynthesisResult r = synthesize_sign(*read[0].spec, avatar_, SynthesisOptions{});
  ASSERT_TRUE(r.ok());
  const Worst w = measure(rig_, r.clip);
  RecordProperty("worst_step_mm", std::to_string(w.step_m * 1000.0f) + " " + w.step_what);
  const bool avatar = std::string(GetParam()) == "avatar";
  EXPECT_LE(w.step_m, avatar ? 0.15f : 0.34f) << GetParam() << ": " << w.step_what;
  EXPECT_LE(r.report.max_penetration_m, avatar ? 0.01f : 0.005f) << GetParam();
}

// Wrists that cross the shoulder joint's coronal plane (docs/SYNTHESIS.md elbow-leap,
// swivel-pref): the HamNoSys corpus's gołąb (fists hanging at the plane below the stomach, the
// wrist within a centimetre of it and straight under the joint) and szkoła (pjm_276: a flat hand
// across the body at the far shoulder turning palm up, the wrist passing 1-3 cm behind the
// plane), whole, from the rest pose and back. The swivel's old zero turned half round at that
// plane (and under the joint), so the same swivel number put the elbow on the other side: on
// main the project avatar's right elbow leapt 465 mm (gołąb) and 464 mm (szkoła) in a frame,
// szkoła 118.8 mm deep. With the zero of fixed handedness and the way down leaned back under the
// joint: the largest arm step held to 150 mm; gołąb to the 5 mm depth bound, szkoła to 15 mm
// (measured 12.4 mm on the project avatar: its palm-up goal at the far shoulder is deep on every
// swivel, elbow-flip).
TEST_P(MotionSmoothness, AWristCrossingTheShouldersCoronalPlaneKeepsItsElbowOnOneSide) {
  struct Case {
    const char* names;
    float depth_m;
  };
  for (const Case& c :
       {Case{"hamsymmlr,hamfist,hamthumbacrossmod,hamextfingerd,hampalml,hambelowstomach,hamlrbeside,hamclose,"
             "hammoveil,hamlargemod,hamrepeatfromstart",
             0.005f},
        Case{"hamflathand,hamfingerbendmod,hamextfingerl,hampalml,hamlrat,hamshouldertop,hambetween,hamshoulders,"
             "hamtouch,hamreplace,hampalmu,hamfast,hamrepeatfromstart",
             0.015f}}) {
    SCOPED_TRACE(c.names);
    const std::vector<notation::SignParse> read = notation::parse_hamnosys_text(c.names);
    ASSERT_EQ(read.size(), 1u);
    ASSERT_TRUE(read[0].ok() && read[0].spec);
    const SynthesisResult r = synthesize_sign(*read[0].spec, avatar_, SynthesisOptions{});
    ASSERT_TRUE(r.ok());
    const Worst w = measure(rig_, r.clip);
    RecordProperty("worst_step_mm", std::to_string(w.step_m * 1000.0f) + " " + w.step_what);
    EXPECT_LE(w.step_m, 0.15f) << GetParam() << ": " << w.step_what;
    EXPECT_LE(r.report.max_penetration_m, c.depth_m) << GetParam();
  }
}

// The same two signs as one phrase (docs/SYNTHESIS.md swivel-choice): each may be solved in the
// swivel zero of fixed handedness while the phrase's transitions plan in the usual one
// (transition.cpp pose_swivel reads the posed elbows in the phrase's zero), so the joins between
// signs of either zero must not leap either: the largest arm step of the whole phrase, both
// transitions between the signs included, held to the single signs' 150 mm.
TEST_P(MotionSmoothness, SignsSolvedInEitherSwivelZeroJoinWithoutALeap) {
  const char* szkola =
      "hamflathand,hamfingerbendmod,hamextfingerl,hampalml,hamlrat,hamshouldertop,hambetween,hamshoulders,"
      "hamtouch,hamreplace,hampalmu,hamfast,hamrepeatfromstart";
  const char* golab =
      "hamsymmlr,hamfist,hamthumbacrossmod,hamextfingerd,hampalml,hambelowstomach,hamlrbeside,hamclose,"
      "hammoveil,hamlargemod,hamrepeatfromstart";
  std::vector<notation::SignParse> read;
  for (const char* names : {szkola, golab, szkola}) {
    std::vector<notation::SignParse> one = notation::parse_hamnosys_text(names);
    ASSERT_EQ(one.size(), 1u) << names;
    read.push_back(std::move(one[0]));
  }
  Synthesizer synth(avatar_);
  ASSERT_TRUE(synth.ok()) << synth.error();
  std::vector<PhraseItem> items;
  for (const notation::SignParse& p : read) {
    ASSERT_TRUE(p.ok() && p.spec);
    PhraseItem item;
    item.sign = *p.spec;
    items.push_back(item);
  }
  SynthesisOptions opt;
  opt.start_from_rest = true;
  const SynthesisResult r = synth.phrase(items, opt);
  ASSERT_TRUE(r.ok());
  const Worst w = measure(rig_, r.clip);
  RecordProperty("worst_step_mm", std::to_string(w.step_m * 1000.0f) + " " + w.step_what);
  EXPECT_LE(w.step_m, 0.15f) << GetParam() << ": " << w.step_what;
  EXPECT_LE(r.report.max_penetration_m, 0.015f) << GetParam();
}

// A leap that is not in the sign's own clip (docs/SYNTHESIS.md leap): the HamNoSys corpus's
// kelner (a flat hand palm up at the top of the shoulder, moving out in a zigzag), whole, from the
// rest pose and back. Its own frames step under 150 mm, so the sign alone never tried the other
// swivel zero (swivel-choice); with the rest transitions the clip's elbow goes up and behind the
// shoulder on the way in and comes back in front in the sign, and the whole clip's elbow path
// could not carry it: on main the project avatar's right elbow leapt 551 mm in a frame (4.2 mm
// deep). The phrase now judges the other zero with the transitions where its clip still leaps
// (synthesize.cpp choose_zero_with_transitions): 82 mm, nothing deep. Held to the 150 mm of the
// choice's threshold and the 5 mm depth bound, both rigs.
TEST_P(MotionSmoothness, AHandAtTheShoulderTopKeepsItsElbowOnOneSideWithItsRestTransitions) {
  const std::vector<notation::SignParse> read =
      notation::parse_hamnosys_text("hamflathand,hamextfingerr,hampalmu,hamshouldertop,hamlrat,hammoveo,hamzigzag");
  ASSERT_EQ(read.size(), 1u);
  ASSERT_TRUE(read[0].ok() && read[0].spec);
  const SynthesisResult r = synthesize_sign(*read[0].spec, avatar_, SynthesisOptions{});
  ASSERT_TRUE(r.ok());
  const Worst w = measure(rig_, r.clip);
  RecordProperty("worst_step_mm", std::to_string(w.step_m * 1000.0f) + " " + w.step_what);
  EXPECT_LE(w.step_m, 0.15f) << GetParam() << ": " << w.step_what;
  EXPECT_LE(r.report.max_penetration_m, 0.005f) << GetParam();
}

// Both hands at the thighs drawing up to the stomach (the HamNoSys corpus's rajstopy, tights,
// writes the thigh as "hambelowstomach [hamupperarm hamlrat]"; this notation is written for the
// test). Read as a part of each hand, the upper arm was the hands' contact point, 35 cm from the
// wrist, and the hand swung round it as the target rose: on main a wrist leapt 325 mm in a frame
// (the project avatar's right; the reference humanoid's left 266 mm; rajstopy itself 466 mm and
// 34.7 mm deep). Read as a place on the leg (hamnosys_parser.cpp: below the stomach, no contact
// part), the hands simply rise. Held to the 150 mm of the swivel choice's threshold and the 5 mm
// depth bound, both rigs.
TEST_P(MotionSmoothness, HandsDrawnUpFromTheThighsDoNotSwingRoundTheirUpperArms) {
  const std::vector<notation::SignParse> read = notation::parse_hamnosys_text(
      "hamsymmpar,hamfinger2345,hamextfingerd,hampalmd,hamlrat,hambelowstomach,hamseqbegin,hamupperarm,"
      "hamlrat,hamseqend,hamclose,hammoveu,hamstomach,hamclose");
  ASSERT_EQ(read.size(), 1u);
  ASSERT_TRUE(read[0].ok() && read[0].spec);
  const SynthesisResult r = synthesize_sign(*read[0].spec, avatar_, SynthesisOptions{});
  ASSERT_TRUE(r.ok());
  const Worst w = measure(rig_, r.clip);
  RecordProperty("worst_step_mm", std::to_string(w.step_m * 1000.0f) + " " + w.step_what);
  EXPECT_LE(w.step_m, 0.15f) << GetParam() << ": " << w.step_what;
  EXPECT_LE(r.report.max_penetration_m, 0.005f)
      << GetParam() << ": " << (r.report.warnings.empty() ? "" : r.report.warnings.back());
}

// A swivel fix the last ramp round adds comes on at once (docs/SYNTHESIS.md leap): mirrored
// spread hands drawn in on an arc, closing to fists turned out (the HamNoSys corpus's kraść
// family; this notation is written for the test), from the rest pose and back. The last of the
// three ramp rounds corrects what is still deep and nothing ramps those corrections: on main the
// project avatar's left elbow leapt 266 mm in a frame (10.5 mm deep). Where they jump and the
// phrase leaps, more last rounds ramp them in (sign_motion.cpp ramp_rounds, asked for by
// synthesize.cpp choose_zero_with_transitions): 67 mm, 4.7 mm deep. Held to the 150 mm of the
// threshold and the 5 mm depth bound, both rigs.
TEST_P(MotionSmoothness, ALastRoundsSwivelFixIsRampedInWhereItLeaps) {
  const std::vector<notation::SignParse> read = notation::parse_hamnosys_text(
      "hamsymmlr,hamfinger2345,hamthumboutmod,hamextfingerdr,hampalmu,hamparbegin,hammovei,hamarcr,hamreplace,"
      "hamfist,hamthumbacrossmod,hamextfingerol,hampalml,hamparend");
  ASSERT_EQ(read.size(), 1u);
  ASSERT_TRUE(read[0].ok() && read[0].spec);
  const SynthesisResult r = synthesize_sign(*read[0].spec, avatar_, SynthesisOptions{});
  ASSERT_TRUE(r.ok());
  const Worst w = measure(rig_, r.clip);
  RecordProperty("worst_step_mm", std::to_string(w.step_m * 1000.0f) + " " + w.step_what);
  EXPECT_LE(w.step_m, 0.15f) << GetParam() << ": " << w.step_what;
  EXPECT_LE(r.report.max_penetration_m, 0.005f)
      << GetParam() << ": " << (r.report.warnings.empty() ? "" : r.report.warnings.back());
}

// The same extra rounds in the zero the sign did not keep (docs/SYNTHESIS.md leap): a fist at
// the top of the shoulder reaching behind to touch, repeated (the HamNoSys corpus's UPPER-BACK1A^
// family; this notation is written for the test), from the rest pose and back. The sign keeps
// the fixed-handed zero (swivel-choice: 538 -> 179 mm), whose extra rounds do not help; the usual
// zero's with them do: on main the project avatar's right elbow 179 mm in a frame, now 102 mm.
// The far reach behind the shoulder is deep on every solve (37.1 -> 30.8 mm): the step held to
// the 150 mm threshold, the depth to what was measured with a margin.
TEST_P(MotionSmoothness, AFistReachingBehindTheShoulderTriesTheExtraRoundsInBothZeros) {
  const std::vector<notation::SignParse> read = notation::parse_hamnosys_text(
      "hamfist,hamextfingeril,hampalml,hamshouldertop,hamlrat,hambehind,hamtouch,hamrepeatfromstart");
  ASSERT_EQ(read.size(), 1u);
  ASSERT_TRUE(read[0].ok() && read[0].spec);
  const SynthesisResult r = synthesize_sign(*read[0].spec, avatar_, SynthesisOptions{});
  ASSERT_TRUE(r.ok());
  const Worst w = measure(rig_, r.clip);
  RecordProperty("worst_step_mm", std::to_string(w.step_m * 1000.0f) + " " + w.step_what);
  RecordProperty("depth_mm", std::to_string(r.report.max_penetration_m * 1000.0f));
  EXPECT_LE(w.step_m, 0.15f) << GetParam() << ": " << w.step_what;
  EXPECT_LE(r.report.max_penetration_m, 0.035f) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(Rigs, MotionSmoothness, ::testing::Values("avatar", "reference"));

}  // namespace
}  // namespace sw::synthesis
