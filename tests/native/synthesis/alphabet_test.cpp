// The data alphabets (data/<lang>/alphabet.jsonl, ASL and Ukrainian) through the whole pipeline on
// the project's avatar: every letter parses and synthesises, the alphabet sequence and every
// transition between two letters stay free of penetration (> 5 mm outside intended contact), and
// thumb-contact letters really touch. The ASL starter lexicon (data/ase/lexicon.jsonl) the same
// way for the arms: no frame puts an upper arm or forearm in the trunk, or a forearm through the
// other, by more than 5 mm outside intended contact.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "synthesis/collision.h"
#include "synthesis/orientation.h"
#include "synthesis/phrase_text.h"
#include "synthesis/sign_motion.h"
#include "synthesis/signing_avatar.h"
#include "synthesis/synthesize.h"
#include "arm_depths.h"
#include "synthesis_fixture.h"

namespace sw::synthesis {
namespace {

const std::string kRoot = SIGNWEAVE_SOURCE_DIR;


class SynthesisAlphabet : public ::testing::TestWithParam<const char*> {
 protected:
  void SetUp() override {
    std::string text, error;
    if (!testing::read_text_file(kRoot + "/data/" + GetParam() + "/alphabet.jsonl", &text)) GTEST_SKIP() << "no data alphabet";
    ASSERT_TRUE(parse_alphabet_jsonl(text, &alphabet_, &error)) << error;
    avatar_ = load_signing_avatar_file(kRoot + "/models/signweave-avatar.glb");
    if (!avatar_.ok()) GTEST_SKIP() << "models/signweave-avatar.glb: " << avatar_.error;
    for (const auto& e : alphabet_) {
      PhraseText t = phrase_from_text(e.notation, {});
      ASSERT_TRUE(t.ok()) << e.letter << ": " << (t.errors.empty() ? "" : t.errors[0].message);
      PhraseItem it = t.items[0];
      it.kind = PhraseItem::Kind::Letter;
      it.label = e.letter;
      letters_.push_back(it);
    }
  }
  std::vector<AlphabetEntry> alphabet_;
  SigningAvatar avatar_;
  std::vector<PhraseItem> letters_;
};

TEST_P(SynthesisAlphabet, WholeAlphabetSequenceDoesNotPenetrate) {
  Synthesizer synth(avatar_.avatar);
  ASSERT_TRUE(synth.ok()) << synth.error();
  SynthesisResult r = synth.phrase(letters_, SynthesisOptions{});
  ASSERT_TRUE(r.ok()) << r.errors[0].where << ": " << r.errors[0].message;
  EXPECT_LE(r.report.max_penetration_m, 0.005f) << (r.report.warnings.empty() ? "" : r.report.warnings.back());
  int letters = 0;
  for (const auto& s : r.clip.segments) letters += s.kind == ClipSegment::Kind::Letter;
  EXPECT_EQ(letters, static_cast<int>(letters_.size()));
  RecordProperty("max_penetration_mm", std::to_string(r.report.max_penetration_m * 1000.0f));
}

TEST_P(SynthesisAlphabet, EveryTransitionBetweenTwoLettersIsFreeOfPenetration) {
  Synthesizer synth(avatar_.avatar);
  SynthesisOptions opt;
  opt.start_from_rest = false;
  float worst = 0.0f;
  std::string worst_pair;
  for (size_t a = 0; a < letters_.size(); ++a)
    for (size_t b = 0; b < letters_.size(); ++b) {
      if (a == b) continue;
      SynthesisResult r = synth.phrase({letters_[a], letters_[b]}, opt);
      ASSERT_TRUE(r.ok());
      if (r.report.max_penetration_m > worst) {
        worst = r.report.max_penetration_m;
        worst_pair = letters_[a].label + " -> " + letters_[b].label + ": " +
                     (r.report.warnings.empty() ? "" : r.report.warnings.back());
      }
    }
  EXPECT_LE(worst, 0.005f) << worst_pair;
  RecordProperty("max_penetration_mm", std::to_string(worst * 1000.0f));
}

INSTANTIATE_TEST_SUITE_P(Data, SynthesisAlphabet, ::testing::Values("ase", "ukl"));

// Issue 4's acceptance, per letter: the palm normal within 10 degrees of the requested direction.
// Every letter of both alphabets and every digit, on the reference humanoid and the project
// avatar, at its key pose (the first frame of the letter): the requested hand frame
// (orientation_frame) against the posed one. A letter held off a body place (the Ukrainian
// letters at the chest, no contact) also stays in the 3-10 cm no-contact band. Before the
// no-contact band search and the ASL letters' move from the shoulder to neutral space, the ASL
// letters were 28 degrees off on the reference humanoid and 34 on the project avatar, the
// Ukrainian letters up to 14.5 and 19.2 (docs/SYNTHESIS.md, Orientation of the letters). The
// extended fingers' direction the same way, within 10 degrees: before that stop the ASL P and Q
// pointed 41.7 degrees off.
TEST(SynthesisAlphabetOrientation, EveryLetterAndDigitHoldsItsPalmAndFingersWithin10DegreesOnBothRigs) {
  std::string error;
  testing::NamedRigs rigs = testing::reference_and_project_avatar(&error);
  ASSERT_TRUE(error.empty()) << error;
  // Letters that truly cannot meet the bound, with the figure they are held to and why: none.
  const std::map<std::string, float> known_palm_deg = {};
  // The extended finger direction, as much a part of the letter to a reader, with the same
  // bound. Known: the Ukrainian Л, М, П, Т (fingers down, palm to the signer) at seed 004's L1(0),
  // the chest right held off 3-10 cm (the data keeps the seed's place). Fingers down with the
  // palm in need the forearm pointing forward from an elbow at the side and the wrist flexed
  // 58-75 degrees (limit 75): the wrist 5-10 cm outside the shoulder joint, 20-40 cm below it
  // (solved exactly there on both rigs). Beside the chest's right anchor, 10-12 cm inside the
  // shoulder joint, the forearm points inwards and the ulnar deviation (35) cannot make up the
  // rest: searched over the band (9 cm off, up to 8 cm below and 9 cm out) with the swivel
  // searched at each, the best hand rotation is 15.8 degrees off (reference) / 10.7 (avatar),
  // the elbow at the top of its swivel range; the band search's pick (9 cm off, 6 cm below the
  // anchor) leaves the fingers 18.6 / 14.3 degrees off, with the palm 8.1 / 7.2
  // (docs/SYNTHESIS.md, Orientation of the letters). Held to those.
  const std::map<std::string, float> fingers_down_deg = {{"reference", 19.0f}, {"avatar", 15.0f}};
  const std::map<std::string, std::map<std::string, float>> known_finger_deg = {
      {"Л", fingers_down_deg}, {"М", fingers_down_deg}, {"П", fingers_down_deg}, {"Т", fingers_down_deg}};
  float worst_finger = 0.0f;
  int checked = 0;
  for (const char* file : {"ase/alphabet", "ase/digits", "ukl/alphabet"}) {
    std::string text;
    std::vector<AlphabetEntry> entries;
    if (!testing::read_text_file(kRoot + "/data/" + file + ".jsonl", &text))
      GTEST_SKIP() << "no data " << file;
    ASSERT_TRUE(parse_alphabet_jsonl(text, &entries, &error)) << error;
    for (const auto& rg : rigs) {
      Rig rig;
      ASSERT_TRUE(build_rig(rg.second, &rig, &error)) << error;
      Synthesizer synth(rg.second);
      ASSERT_TRUE(synth.ok()) << synth.error();
      float worst = 0.0f;
      for (const auto& e : entries) {
        PhraseText t = phrase_from_text(e.notation, {});
        ASSERT_TRUE(t.ok()) << e.letter;
        const notation::SignSpec& sign = t.items[0].sign;
        SynthesisResult r = synth.sign(sign, SynthesisOptions{});
        ASSERT_TRUE(r.ok()) << e.letter << ": " << r.errors[0].message;
        PoseBuilder pose = testing::frame_pose(rig, r.clip, testing::first_sign_frame(r.clip));
        const HandFrame requested =
            orientation_frame(rig, sign.dominant.orientation, kRight, false);
        const HandFrame posed = posed_hand_frame(rig, kRight, pose.delta(rig.arms[kRight].hand));
        const float palm_deg = testing::angle_deg(requested.palm, posed.palm);
        const float finger_deg = testing::angle_deg(requested.finger, posed.finger);
        const std::string key = std::string(file) + " " + rg.first + " " + e.letter;
        auto known = known_palm_deg.find(key);
        EXPECT_LE(palm_deg, known == known_palm_deg.end() ? 10.0f : known->second)
            << key << ": the palm is off its direction";
        auto known_finger = known_finger_deg.find(e.letter);
        EXPECT_LE(finger_deg, known_finger == known_finger_deg.end() ? 10.0f : known_finger->second.at(rg.first))
            << key << ": the extended fingers are off their direction";
        if (sign.dominant.location.kind == notation::Location::Kind::Body &&
            sign.dominant.location.contact == notation::Contact::None) {
          ASSERT_FALSE(r.report.contact_distances_m.empty()) << key;
          EXPECT_GE(r.report.contact_distances_m[0], 0.03f) << key << ": held off, too near";
          EXPECT_LE(r.report.contact_distances_m[0], 0.10f) << key << ": held off, too far from it";
        }
        worst = std::max(worst, palm_deg);
        if (known_finger == known_finger_deg.end()) worst_finger = std::max(worst_finger, finger_deg);
        ++checked;
      }
      RecordProperty(std::string(file) + " " + rg.first + " worst_palm_deg", std::to_string(worst));
    }
  }
  EXPECT_GE(checked, 26 + 11 + 33);
  RecordProperty("worst_finger_deg_outside_known", std::to_string(worst_finger));
}

// Issue 4's acceptance for the ASL starter lexicon (data/ase/lexicon.jsonl), as for the letters
// above: at each sign's key pose (its first frame), on the reference humanoid and the project
// avatar, the dominant hand's palm normal within 10 degrees of the written direction, and the
// non-dominant hand's where the sign writes it its own orientation (a mirrored hand is the
// dominant's pose mirrored). The finger direction is reported beside it (RecordProperty), not
// bounded: the bound is the palm's. Signs that truly cannot meet the bound are held to
// their measured figure (plus 1 degree), each with the reason (docs/SYNTHESIS.md, Orientation of
// the lexicon's key poses).
TEST(SynthesisLexiconOrientation, EverySignHoldsItsPalmWithin10DegreesAtItsKeyPoseOnBothRigs) {
  std::string text, error;
  if (!testing::read_text_file(kRoot + "/data/ase/lexicon.jsonl", &text)) GTEST_SKIP() << "no data lexicon";
  testing::NamedRigs rigs = testing::reference_and_project_avatar(&error);
  ASSERT_TRUE(error.empty()) << error;
  // "<rig> <gloss> <dominant|nondominant>" -> the palm error (degrees) it is held to: its
  // measured figure + 1 so it cannot grow unnoticed. These are NOT shown impossible; they are the
  // gaps left at this stop, by cause (docs/SYNTHESIS.md, Orientation of the lexicon's key poses).
  const std::map<std::string, float> known_palm_deg = {
      // A touch on the face or chest: none. ME, WE, OLD, BROTHER, SISTER, DEAF, HELLO, FINE and
      // WRONG were written in poses no arm takes (the wrist beyond its limits or the arm in the
      // body at every elbow swivel, or the wrist inside the folded arm's reach); the lexicon now
      // writes them as signers make them (each entry's description says why). DOG's palm on the
      // thigh (10.9 degrees on the avatar) is 0.3: the touch's acceptance search (arm_ik.cpp
      // solve_arm, SynthesisArmIk.AKeyPoseOver10DegreesOffTakesTheSwivelThatRealisesIt).
      // A place on the other hand, or the hand that is the place (seed 004: one hand as the place
      // of the other). Both hands meet where both hold their orientations
      // (sign_motion.cpp, meet_where_both_hands_hold: the place hand in neutral space moves
      // within a bounded search, mostly 6-12 cm forward, the placed hand's elbow swivels; LATER,
      // NICE, WORK, BUY, MONEY, LEARN, STUDENT, WHEN, SCHOOL's place hand now within 10
      // degrees, NEW's and WRITE's data corrected; FRIEND's and NUMBER's place hands, palm up
      // across the body, found nearer the body and lower by the neutral search). Left: NEW on the reference
      // humanoid (the search holds both arms out of the trunk; the brush's frames still turn
      // the hand, 15.1 in the clip's first frame);
      // HOSPITAL (its place the other arm's upper arm) was written fingers up, palm left: the
      // tips reach the far upper arm only past two wrist limits; now fingers left and back, palm
      // in (22-24 -> 0 degrees). DAY is not searched (an elbow contact led by its wrist: moved, the frames' clearing turned the
      // swivel and the elbow missed the back of the hand by 39 mm).
      {"avatar DAY dominant", 31.7f},
      {"reference DAY dominant", 32.6f},
      {"reference NEW dominant", 16.1f},
      // Held off: none left. The arm in the trunk or the elbow behind the body no longer turns
      // the hand (TEACH, TEACHER, CHILD, PERSON, HAVE and the avatar's SEE were one 15-degree
      // step of turn_hand_out_of_body): the hand moves within the 3-10 cm band first
      // (sign_motion.cpp, hold_off_clear). LOOK, DRINK, GOODBYE and CANT were written in poses
      // signers do not make, a wrist or elbow at or past its limit; their descriptions say why.
      // BABY's cradling hands are found by the neutral search's nearer, lower rings.
  };
  const std::vector<testing::LexiconSign> signs = testing::lexicon_signs(text);
  const bool verbose = std::getenv("SIGNWEAVE_PALM_REPORT") != nullptr;
  int checked = 0;
  for (const auto& rg : rigs) {
    Rig rig;
    ASSERT_TRUE(build_rig(rg.second, &rig, &error)) << error;
    Synthesizer synth(rg.second);
    ASSERT_TRUE(synth.ok()) << synth.error();
    float worst_palm = 0.0f, worst_finger = 0.0f;
    int over = 0;
    for (const testing::LexiconSign& ls : signs) {
      ASSERT_TRUE(ls.text.ok() && !ls.text.items.empty()) << ls.gloss;
      const notation::SignSpec& sign = ls.text.items[0].sign;
      SynthesisResult r = synth.sign(sign, SynthesisOptions{});
      ASSERT_TRUE(r.ok()) << ls.gloss << ": " << r.errors[0].message;
      PoseBuilder pose = testing::frame_pose(rig, r.clip, testing::first_sign_frame(r.clip));
      struct Hand {
        const char* name;
        Side side;
        const notation::HandSpec* spec;
      };
      std::vector<Hand> hands = {{"dominant", kRight, &sign.dominant}};
      if (sign.nondominant) hands.push_back({"nondominant", kLeft, &*sign.nondominant});
      for (const Hand& h : hands) {
        const HandFrame requested = orientation_frame(rig, h.spec->orientation, h.side, false);
        const HandFrame posed = posed_hand_frame(rig, h.side, pose.delta(rig.arms[h.side].hand));
        const float palm_deg =
            testing::angle_deg(requested.palm, posed.palm);
        const float finger_deg =
            testing::angle_deg(requested.finger, posed.finger);
        const std::string key = rg.first + " " + ls.gloss + " " + h.name;
        auto known = known_palm_deg.find(key);
        EXPECT_LE(palm_deg, known == known_palm_deg.end() ? 10.0f : known->second)
            << key << ": the palm is off its direction (finger " << finger_deg << " deg)";
        if (verbose)
          std::printf("PALM %s palm %.1f finger %.1f\n", key.c_str(), palm_deg, finger_deg);
        over += palm_deg > 10.0f;
        worst_palm = std::max(worst_palm, palm_deg);
        worst_finger = std::max(worst_finger, finger_deg);
        ++checked;
      }
    }
    RecordProperty(rg.first + " worst_palm_deg", std::to_string(worst_palm));
    RecordProperty(rg.first + " worst_finger_deg", std::to_string(worst_finger));
    RecordProperty(rg.first + " palms_over_10_deg", std::to_string(over));
  }
  EXPECT_GE(checked, 141);
}

TEST(SynthesisLexicon, ArmsStayOutOfTheBodyAndOfEachOther) {
  std::string text;
  if (!testing::read_text_file(kRoot + "/data/ase/lexicon.jsonl", &text)) GTEST_SKIP() << "no data lexicon";
  SigningAvatar avatar = load_signing_avatar_file(kRoot + "/models/signweave-avatar.glb");
  if (!avatar.ok()) GTEST_SKIP() << "models/signweave-avatar.glb: " << avatar.error;
  Synthesizer synth(avatar.avatar);
  ASSERT_TRUE(synth.ok()) << synth.error();
  SynthContext ctx;
  std::string error;
  ASSERT_TRUE(make_context(avatar.avatar, SynthesisOptions{}, &ctx, &error)) << error;
  // Known gaps (measured on this avatar, docs/SYNTHESIS.md), each held to its own bound so it
  // cannot grow unnoticed. None now: LOVE's crossed fists are laid one in front of the other at
  // the key pose (sign_motion.cpp, separate_crossed_hands: forearms 74 mm through each other
  // before, 13.9 after), and its arriving transition brings the front arm in front all the way
  // (transition.cpp; 13.9 mm, then 2.5 mm by chance of the state count, now 1.0 mm).
  const std::map<std::string, float> known_trunk_mm = {};
  const std::map<std::string, float> known_forearms_mm = {};
  int signs = 0;
  float worst_trunk = 0.0f, worst_forearms = 0.0f;
  for (const testing::LexiconSign& sign : testing::lexicon_signs(text)) {
    const std::string& gloss = sign.gloss;
    const PhraseText& t = sign.text;
    ASSERT_TRUE(t.ok()) << gloss;
    SynthesisResult r = synth.phrase(t.items, SynthesisOptions{});
    ASSERT_TRUE(r.ok()) << gloss << ": " << r.errors[0].message;
    ++signs;
    testing::ArmDepths d = testing::arm_depths(ctx, r);
    auto kt = known_trunk_mm.find(gloss);
    auto kf = known_forearms_mm.find(gloss);
    EXPECT_LE(d.trunk_m * 1000.0f, kt == known_trunk_mm.end() ? 5.0f : kt->second) << gloss << ": " << d.trunk_what;
    EXPECT_LE(d.forearms_m * 1000.0f, kf == known_forearms_mm.end() ? 5.0f : kf->second)
        << gloss << ": " << d.forearms_what;
    if (kt == known_trunk_mm.end()) worst_trunk = std::max(worst_trunk, d.trunk_m);
    if (kf == known_forearms_mm.end()) worst_forearms = std::max(worst_forearms, d.forearms_m);
  }
  EXPECT_GE(signs, 110);
  RecordProperty("worst_arm_trunk_mm", std::to_string(worst_trunk * 1000.0f));
  RecordProperty("worst_forearms_mm", std::to_string(worst_forearms * 1000.0f));
}

// LOVE (fists rising from the rest to cross at the chest) at any speed and frame rate, on the
// project avatar and the reference humanoid: the forearms never pass through each other. The
// routing used to push both arms along their own escapes (one forward, the other back into the
// chest), and whether a via-pose cleared the crossing depended on the transition's state count:
// 2-41 mm on the project avatar and 1.4-36 mm on the reference over these speeds and rates
// (13.9 mm at the default once). Now the arm that ends in front is held in front: 1.0 / 1.4 mm.
TEST(SynthesisLexicon, LovesCrossingForearmsStayClearAtAnySpeedAndFrameRate) {
  std::string text;
  if (!testing::read_text_file(kRoot + "/data/ase/lexicon.jsonl", &text)) GTEST_SKIP() << "no data lexicon";
  const PhraseText* love = nullptr;
  const std::vector<testing::LexiconSign> signs = testing::lexicon_signs(text);
  for (const testing::LexiconSign& sign : signs)
    if (sign.gloss == "LOVE") love = &sign.text;
  ASSERT_NE(love, nullptr) << "LOVE is not in the lexicon";
  ASSERT_TRUE(love->ok());
  std::string rig_error;
  const testing::NamedRigs rigs = testing::reference_and_project_avatar(&rig_error);
  ASSERT_TRUE(rig_error.empty()) << rig_error;
  float worst = 0.0f;
  for (const auto& rg : rigs) {
    Synthesizer synth(rg.second);
    ASSERT_TRUE(synth.ok()) << synth.error();
    SynthContext ctx;
    std::string error;
    ASSERT_TRUE(make_context(rg.second, SynthesisOptions{}, &ctx, &error)) << error;
    for (float fps : {25.0f, 30.0f, 60.0f})
      for (float speed : {0.7f, 0.9f, 1.0f, 1.2f, 1.5f}) {
        SynthesisOptions opt;
        opt.fps = fps;
        opt.speed = speed;
        SynthesisResult r = synth.phrase(love->items, opt);
        ASSERT_TRUE(r.ok()) << r.errors[0].message;
        testing::ArmDepths d = testing::arm_depths(ctx, r);
        EXPECT_LE(d.forearms_m * 1000.0f, 5.0f) << rg.first << " fps " << fps << " speed " << speed << ": "
                                                << d.forearms_what;
        EXPECT_LE(d.trunk_m * 1000.0f, 5.0f) << rg.first << " fps " << fps << " speed " << speed << ": "
                                             << d.trunk_what;
        // The hands too (a hand in the other forearm): the crossing route held the front arm
        // forward by the forearms' depth + 4-12 cm, and where a hand went deeper than the
        // forearms that fell short (the project avatar at 4 of 9 lexicon settings: 7.6-8.4 mm).
        EXPECT_LE(r.report.max_penetration_m * 1000.0f, 5.0f) << rg.first << " fps " << fps << " speed " << speed;
        if (std::getenv("SIGNWEAVE_LEXICON_REPORT"))
          std::printf("love %s %.0f %.1f hands+arms %.1f\n", rg.first.c_str(), fps, speed, r.report.max_penetration_m * 1000.0f);
        worst = std::max({worst, d.forearms_m, d.trunk_m});
      }
  }
  RecordProperty("worst_arm_depth_mm", std::to_string(worst * 1000.0f));
}


// Every lexicon sign at the default settings, on the reference humanoid and the project avatar,
// as the synthesis report gives it: a touch reaches its place (issue 4: reach error < 1 cm with
// contact, measured at the sign's first frame) and no hand goes more than 5 mm into the trunk or
// the other hand outside intended contact. Known gaps are held to their measured figures
// (docs/SYNTHESIS.md, Known issues) so they cannot grow unnoticed.
TEST(SynthesisLexicon, EveryTouchReachesAndNoHandGoesIntoTheBodyOnBothRigs) {
  std::string text;
  if (!testing::read_text_file(kRoot + "/data/ase/lexicon.jsonl", &text)) GTEST_SKIP() << "no data lexicon";
  const std::vector<testing::LexiconSign> signs = testing::lexicon_signs(text);
  std::string rig_error;
  const testing::NamedRigs rigs = testing::reference_and_project_avatar(&rig_error);
  ASSERT_TRUE(rig_error.empty()) << rig_error;
  // Known gaps (docs/SYNTHESIS.md, Known issues): none now on either rig. They were, on the
  // reference humanoid: reach DEAF 21.6 mm and CAT 9.8 (the written orientation put the wrist
  // inside the folded arm's reach; the hand now tilts about the tip, arm_ik.h turn_hand_to_reach);
  // depth HAPPY 8.9 (circle into the chest), DAY 5.6 (upper arm across the chest), DIFFERENT 34.4
  // (right hand in the left forearm). DAY's elbow on the back of the left hand (written in
  // neutral space, beyond the upper arm's reach: it missed by 116/78 mm) touches since the place
  // comes to it (5.7 mm on the reference humanoid, 5.2 on the avatar). HAVE's, SAD's and FAMILY's
  // hands in each other on the way back to the rest are parted by the hands-apart route
  // (transition.cpp).
  const std::map<std::string, float> known_reach_mm = {};
  const std::map<std::string, float> known_depth_mm = {};
  float worst_reach = 0.0f, worst_depth = 0.0f;
  for (const auto& rg : rigs) {
    Synthesizer synth(rg.second);
    ASSERT_TRUE(synth.ok()) << synth.error();
    for (const testing::LexiconSign& sign : signs) {
      ASSERT_TRUE(sign.text.ok()) << sign.gloss;
      SynthesisResult r = synth.phrase(sign.text.items, SynthesisOptions{});
      ASSERT_TRUE(r.ok()) << sign.gloss << ": " << r.errors[0].message;
      const std::string key = rg.first + " " + sign.gloss;
      const float reach_mm = r.report.max_reach_error_m * 1000.0f, depth_mm = r.report.max_penetration_m * 1000.0f;
      if (std::getenv("SIGNWEAVE_LEXICON_REPORT")) std::printf("lexicon %s reach %.1f depth %.1f\n", key.c_str(), reach_mm, depth_mm);
      auto kr = known_reach_mm.find(key);
      auto kd = known_depth_mm.find(key);
      EXPECT_LE(reach_mm, kr == known_reach_mm.end() ? 10.0f : kr->second) << key << ": the touch misses its place";
      EXPECT_LE(depth_mm, kd == known_depth_mm.end() ? 5.0f : kd->second) << key << ": a hand in the body or the other hand";
      if (kr == known_reach_mm.end()) worst_reach = std::max(worst_reach, reach_mm);
      if (kd == known_depth_mm.end()) worst_depth = std::max(worst_depth, depth_mm);
    }
  }
  RecordProperty("worst_reach_error_mm", std::to_string(worst_reach));
  RecordProperty("worst_hand_depth_mm", std::to_string(worst_depth));
}

}  // namespace
}  // namespace sw::synthesis
