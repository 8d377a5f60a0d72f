// HamNoSys 4 / SiGML constructs the dev corpus rarely writes and the definition allows:
// sequential parts with their own symmetry, hamnondominant, numeric bends, doubled direction
// letters, split_location with one location, cumulative posture changes, the H-SiGML spelling
// hamUpperarm. Each is read clean and, where a printer exists, printed back to the same SignSpec.
#include <gtest/gtest.h>

#include <string>

#include "notation/hamnosys.h"
#include "notation/hamnosys_symbols.h"
#include "notation/sigml.h"
#include "notation/sign_spec_json.h"

namespace sw::notation {
namespace {

SignSpec clean_hamnosys(const std::string& text) {
  const std::vector<SignParse> signs = parse_hamnosys_text(text);
  EXPECT_EQ(signs.size(), 1u);
  if (signs.empty()) return {};
  for (const Diagnostic& d : signs[0].diagnostics)
    EXPECT_NE(d.severity, Severity::Error) << text << ": " << d.symbol << ": " << d.message;
  EXPECT_TRUE(signs[0].spec.has_value()) << text;
  return signs[0].spec ? *signs[0].spec : SignSpec{};
}

SignSpec clean_sigml(const std::string& body) {
  const std::vector<SignParse> signs = parse_sigml_text("<sigml>" + body + "</sigml>");
  EXPECT_EQ(signs.size(), 1u);
  if (signs.empty()) return {};
  for (const Diagnostic& d : signs[0].diagnostics)
    EXPECT_NE(d.severity, Severity::Error) << body << ": " << d.symbol << ": " << d.message;
  EXPECT_TRUE(signs[0].spec.has_value()) << body;
  return signs[0].spec ? *signs[0].spec : SignSpec{};
}

// Printed as HamNoSys (both spellings) and G-SiGML and read back: the same SignSpec.
void expect_round_trip(const SignSpec& sign) {
  const std::string json = sign_to_json_text(sign);
  SignSpec no_gloss = sign;  // a HamNoSys string carries no gloss
  no_gloss.gloss.clear();
  for (HamNoSysSpelling spelling : {HamNoSysSpelling::Unicode, HamNoSysSpelling::Names}) {
    const std::string printed = print_hamnosys(sign, spelling);
    EXPECT_EQ(sign_to_json_text(clean_hamnosys(printed)), sign_to_json_text(no_gloss)) << printed;
  }
  const std::string g = print_gsigml({sign});
  const std::vector<SignParse> again = parse_sigml_text(g);
  ASSERT_EQ(again.size(), 1u);
  ASSERT_TRUE(again[0].spec.has_value()) << g;
  EXPECT_EQ(sign_to_json_text(*again[0].spec), json) << g;
}

TEST(HamNoSys4Grammar, SequentialPartWithItsOwnSymmetryParses) {
  // A one-handed part, then hamplus and a symmetric part with its own configuration and place.
  const SignSpec s = clean_hamnosys(
      "hamfinger2 hamextfingerul hampalml hamchest hamclose hammovei hamplus hamsymmlr hamflathand "
      "hamextfingeruo hampalmdl hamshoulders hammoved");
  ASSERT_GE(s.movements.size(), 3u);
  // The second part starts with a change to its handshape and place, then its movement.
  const Movement& change = s.movements[1].dominant.at(0);
  EXPECT_EQ(change.kind, MovementKind::Replace);
  ASSERT_TRUE(change.to_shape.has_value());
  EXPECT_NE(change.to_shape->hamnosys_base.find("hamflathand"), std::string::npos);
  ASSERT_TRUE(change.to_location.has_value());
  EXPECT_EQ(change.to_location->level, BodyLevel::Shoulders);
  EXPECT_EQ(s.movements.back().dominant.at(0).direction, (Direction{0, -1, 0}));
}

TEST(HamNoSys4Grammar, SequentialPartWithAnOrientationPair) {
  const SignSpec s = clean_hamnosys(
      "hamflathand hamextfingerui hampalmdr hamforehead hamtouch hamplus hamsymmlr hamflathand "
      "hamparbegin hamextfingerul hampalml hamplus hamextfingerr hampalmr hamparend hamchest "
      "hammoveo");
  ASSERT_GE(s.movements.size(), 2u);
  const MovementStep& part = s.movements[0];
  ASSERT_EQ(part.nondominant.size(), 1u);
  ASSERT_TRUE(part.nondominant[0].to_orientation.has_value());
  EXPECT_EQ(part.nondominant[0].to_orientation->palm, (Direction{-1, 0, 0}));
  ASSERT_TRUE(part.dominant.at(0).to_orientation.has_value());
  EXPECT_EQ(part.dominant[0].to_orientation->palm, (Direction{1, 0, 0}));
}

TEST(HamNoSys4Grammar, ContactAlongAPathInABracketAfterAPlace) {
  const SignSpec s = clean_hamnosys(
      "hamceeall hamextfingerol hampalmd hamlowerarm hamseqbegin hamtouch hammovedo hambetween "
      "hammoveor hamseqend");
  EXPECT_FALSE(s.movements.empty());
}

TEST(HamNoSys4Grammar, MalformedStaysRejectedWithPositionAndSymbol) {
  const std::vector<SignParse> a = parse_hamnosys_text("hamflathand hamchest hamparbegin hammoveo");
  ASSERT_EQ(a.size(), 1u);
  EXPECT_FALSE(a[0].ok());
  const std::vector<SignParse> b = parse_hamnosys_text("hamflathand hamchest hamnosuchsymbol");
  ASSERT_EQ(b.size(), 1u);
  ASSERT_FALSE(b[0].diagnostics.empty());
  EXPECT_EQ(b[0].diagnostics[0].symbol, "hamnosuchsymbol");
  EXPECT_EQ(b[0].diagnostics[0].column, 22);
}

TEST(HamNoSys4Grammar, NondominantOneHandedSignIsKeptAndPrinted) {
  const SignSpec h =
      clean_hamnosys("hamnondominant hamfinger2 hamextfingeru hampalml hamchest hammoveo");
  EXPECT_TRUE(h.one_hand_is_nondominant);
  EXPECT_FALSE(h.nondominant.has_value());
  expect_round_trip(h);
  const SignSpec g = clean_sigml(
      "<hamgestural_sign gloss=\"X\"><sign_manual nondominant=\"true\"><handconfig "
      "handshape=\"flat\" "
      "extfidir=\"o\" palmor=\"d\"/><location_bodyarm location=\"chest\"/><directedmotion "
      "direction=\"do\"/>"
      "</sign_manual></hamgestural_sign>");
  EXPECT_TRUE(g.one_hand_is_nondominant);
  expect_round_trip(g);
  // Inside a pair (the non-dominant hand's configuration) it is no mark of the sign.
  const SignSpec pair = clean_hamnosys(
      "hamparbegin hamfinger2 hamextfingerl hampalmd hamplus hamnondominant hamflathand "
      "hamextfingeror hampalmu hamparend hamchest");
  EXPECT_FALSE(pair.one_hand_is_nondominant);
}

TEST(HamNoSys4Grammar, HSiGMLSpellingHamUpperarm) {
  const HamSymbolInfo* a = ham_symbol_by_name("hamUpperarm");
  const HamSymbolInfo* b = ham_symbol_by_name("hamupperarm");
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(a, b);
  const SignSpec s = clean_sigml(
      "<hns_sign gloss=\"ARM\"><hamnosys_manual><hamflathand/><hamextfingerol/><hampalmd/>"
      "<hamUpperarm/><hamtouch/></hamnosys_manual></hns_sign>");
  EXPECT_EQ(s.dominant.location.kind, Location::Kind::OtherHand);
  EXPECT_EQ(s.dominant.location.hand_place, HandPlace::UpperArm);
}

const char* kGesturalHead = "<hamgestural_sign gloss=\"X\"><sign_manual>";
const char* kGesturalTail = "</sign_manual></hamgestural_sign>";

TEST(HamNoSys4Grammar, GSiGMLDoubledDirectionLetters) {
  const SignSpec s = clean_sigml(std::string(kGesturalHead) +
                                 "<handconfig handshape=\"flat\" extfidir=\"uuo\" palmor=\"ddl\"/>"
                                 "<location_bodyarm location=\"chest\"/>" +
                                 kGesturalTail);
  EXPECT_EQ(s.dominant.orientation.extended_finger, (Direction{0, 1, 1}));
  EXPECT_EQ(s.dominant.orientation.palm, (Direction{1, -1, 0}));
  // Both letters of one axis are still no direction.
  const std::vector<SignParse> bad = parse_sigml_text(
      std::string("<sigml>") + kGesturalHead + "<handconfig handshape=\"flat\" extfidir=\"ud\"/>" +
      kGesturalTail + "</sigml>");
  ASSERT_EQ(bad.size(), 1u);
  EXPECT_FALSE(bad[0].ok());
}

TEST(HamNoSys4Grammar, GSiGMLNumericBendCodes) {
  const SignSpec bent = clean_sigml(
      std::string(kGesturalHead) +
      "<handconfig handshape=\"finger2345\" mainbend=\"400\" extfidir=\"u\" palmor=\"l\"/>" +
      kGesturalTail);
  const SignSpec named = clean_sigml(
      std::string(kGesturalHead) +
      "<handconfig handshape=\"finger2345\" mainbend=\"bent\" extfidir=\"u\" palmor=\"l\"/>" +
      kGesturalTail);
  EXPECT_EQ(sign_to_json_text(bent), sign_to_json_text(named));
  const SignSpec hooked = clean_sigml(
      std::string(kGesturalHead) +
      "<handconfig handshape=\"finger2345\" mainbend=\"044\" extfidir=\"u\" palmor=\"l\"/>" +
      kGesturalTail);
  const SignSpec hooked_named = clean_sigml(
      std::string(kGesturalHead) +
      "<handconfig handshape=\"finger2345\" mainbend=\"hooked\" extfidir=\"u\" palmor=\"l\"/>" +
      kGesturalTail);
  EXPECT_EQ(sign_to_json_text(hooked), sign_to_json_text(hooked_named));
  const std::vector<SignParse> bad = parse_sigml_text(
      std::string("<sigml>") + kGesturalHead + "<handconfig handshape=\"flat\" mainbend=\"59\"/>" +
      kGesturalTail + "</sigml>");
  ASSERT_EQ(bad.size(), 1u);
  EXPECT_FALSE(bad[0].ok());
}

TEST(HamNoSys4Grammar, GSiGMLSplitLocationWithOneLocation) {
  const SignSpec s =
      clean_sigml(std::string(kGesturalHead) +
                  "<handconfig handshape=\"flat\" extfidir=\"u\" palmor=\"l\"/>"
                  "<split_location><location_bodyarm location=\"chin\"/></split_location>" +
                  kGesturalTail);
  EXPECT_EQ(s.dominant.location.level, BodyLevel::Chin);
}

TEST(HamNoSys4Grammar, GSiGMLPostureChangesAreCumulative) {
  // A change of handshape alone, then of orientation alone: the second keeps the changed shape;
  // the first keeps the start's orientation (no change of it).
  const SignSpec s = clean_sigml(
      std::string(kGesturalHead) +
      "<handconfig handshape=\"flat\" extfidir=\"u\" palmor=\"l\"/><location_bodyarm "
      "location=\"chest\"/>"
      "<tgt_motion><changeposture/><handconfig handshape=\"fist\"/></tgt_motion>"
      "<tgt_motion><changeposture/><handconfig extfidir=\"o\" palmor=\"d\"/></tgt_motion>"
      "<tgt_motion><changeposture/><handconfig handshape=\"finger2\"/></tgt_motion>" +
      kGesturalTail);
  ASSERT_EQ(s.movements.size(), 3u);
  const Movement& a = s.movements[0].dominant.at(0);
  const Movement& b = s.movements[1].dominant.at(0);
  const Movement& c = s.movements[2].dominant.at(0);
  EXPECT_FALSE(a.to_orientation.has_value());
  ASSERT_TRUE(b.to_shape.has_value());
  ASSERT_TRUE(a.to_shape.has_value());
  EXPECT_EQ(b.to_shape->hamnosys_base, a.to_shape->hamnosys_base);
  ASSERT_TRUE(c.to_orientation.has_value());
  EXPECT_EQ(c.to_orientation->extended_finger, (Direction{0, 0, 1}));
  EXPECT_EQ(c.to_orientation->palm, (Direction{0, -1, 0}));
}

TEST(HamNoSys4Grammar, SpecialFingerTakesTheIndexsPlace) {
  // G-SiGML specialfingers / HamNoSys digits after a one-finger base: the middle finger extended
  // in the index's place, the index closed (not both straight).
  const SignSpec g = clean_sigml(
      std::string(kGesturalHead) +
      "<handconfig handshape=\"finger2\" specialfingers=\"3\" extfidir=\"u\" palmor=\"l\"/>" +
      kGesturalTail);
  const SignSpec h = clean_hamnosys("hamfinger2 hammiddlefinger hamextfingeru hampalml");
  for (const SignSpec* s : {&g, &h}) {
    const FingerConfig& index = s->dominant.shape.fingers[static_cast<int>(Finger::Index)];
    const FingerConfig& middle = s->dominant.shape.fingers[static_cast<int>(Finger::Middle)];
    EXPECT_EQ(index.id, kFingerPressedToStraight);
    EXPECT_LE(index.t, 0.0f) << "the index must close";
    EXPECT_EQ(middle.id, kFingerPressedToStraight);
    EXPECT_GE(middle.t, 1.0f) << "the middle finger must be straight";
  }
  expect_round_trip(h);
}

}  // namespace
}  // namespace sw::notation
