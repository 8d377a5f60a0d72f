// Tests of the HamNoSys reader's locations (src/notation/hamnosys.h) on hand-written signs: the
// bracketed part of the hand that makes a contact, symmetric pairs whose hands touch each other,
// and a hand constellation placed at a body location. Each was a fault the real-sign corpus
// showed (docs/NOTATION.md, "Locations as real corpora write them").
#include "notation/hamnosys.h"

#include <gtest/gtest.h>

#include "notation/sigml.h"
#include "notation/sign_spec_json.h"
#include "notation/text_position.h"

namespace sw::notation {
namespace {

SignSpec read_clean(const std::string& text) {
  std::vector<SignParse> v = parse_hamnosys_text(text);
  EXPECT_EQ(v.size(), 1u);
  if (v.empty()) return {};
  EXPECT_TRUE(v[0].ok()) << (v[0].diagnostics.empty() ? "no sign" : format_diagnostic(v[0].diagnostics[0]));
  return v[0].spec ? *v[0].spec : SignSpec{};
}

// Printed (both spellings, and as H-SiGML and G-SiGML) and read again: the same SignSpec.
// `gsigml` false: a sign G-SiGML cannot say exactly (below).
void expect_round_trip(const SignSpec& s, bool gsigml = true) {
  for (HamNoSysSpelling spelling : {HamNoSysSpelling::Unicode, HamNoSysSpelling::Names}) {
    const std::string printed = print_hamnosys(s, spelling);
    const std::vector<SignParse> again = parse_hamnosys_text(printed);
    ASSERT_EQ(again.size(), 1u);
    ASSERT_TRUE(again[0].ok()) << printed;
    EXPECT_EQ(sign_to_json_text(*again[0].spec), sign_to_json_text(s)) << printed;
  }
  // And through both SiGML printers (H-SiGML is read by this reader; G-SiGML by its own, which
  // writes the bracket as a location_bodyarm's location_hand and the constellation's place as a
  // handconstellation's location_bodyarm).
  std::vector<std::string> sigml = {print_hsigml({s})};
  if (gsigml) sigml.push_back(print_gsigml({s}));
  for (const std::string& printed : sigml) {
    const std::vector<SignParse> again = parse_sigml_text(printed);
    ASSERT_EQ(again.size(), 1u);
    ASSERT_TRUE(again[0].ok()) << printed;
    SignSpec back = *again[0].spec;
    back.gloss = s.gloss;
    EXPECT_EQ(sign_to_json_text(back), sign_to_json_text(s)) << printed;
  }
}

bool any_target_on_the_other_hand(const SignSpec& s) {
  for (const MovementStep& step : s.movements)
    for (const Movement& m : step.dominant)
      if (m.to_location && m.to_location->kind == Location::Kind::OtherHand) return true;
  return false;
}

// HamNoSys 4 writes the part of the hand that makes the contact in brackets after the place
// (hamseqbegin contact digits part hamseqend); SiGML writes it as a location_bodyarm with a
// location_hand child. It was read as a movement to the other hand: a one-handed sign reached
// for the resting hand by the hip.
TEST(HamNoSysLocations, ABracketAfterThePlaceNamesThePartOfTheHandThatTouches) {
  const SignSpec s = read_clean(
      "hamfinger2,hamextfingeru,hampalml,hamcheek,hamlrat,"
      "hamseqbegin,hamtouch,hamindexfinger,hamfingernail,hamseqend");
  EXPECT_FALSE(s.nondominant.has_value());
  EXPECT_FALSE(s.nondominant_is_place);
  const Location& l = s.dominant.location;
  EXPECT_EQ(l.kind, Location::Kind::Body);
  EXPECT_EQ(l.level, BodyLevel::Cheeks);
  EXPECT_EQ(l.side, Side::Right);
  EXPECT_EQ(l.contact, Contact::Touch);
  ASSERT_TRUE(l.contact_part.has_value());
  EXPECT_EQ(*l.contact_part, HandPlace::FingerNail);
  EXPECT_EQ(l.contact_finger, static_cast<int>(Finger::Index));
  EXPECT_TRUE(s.movements.empty()) << "the bracket was read as a movement";
  expect_round_trip(s);
}

// Two digits (the thumb and index together) keep the first; a part after the finger part is
// the side of it (hampalm: palmar, SiGML side="palmar") and does not replace it; a movement
// after the bracket keeps the written place.
TEST(HamNoSysLocations, ABracketWithTwoDigitsAndASideThenAMovement) {
  const SignSpec s = read_clean(
      "hampinch12,hamextfingeru,hampalml,hamchin,"
      "hamseqbegin,hamclose,hamthumb,hamindexfinger,hamfingertip,hampalm,hamseqend,hammoved,hamsmallmod");
  const Location& l = s.dominant.location;
  EXPECT_EQ(l.level, BodyLevel::Chin);
  EXPECT_EQ(l.contact, Contact::Close);
  ASSERT_TRUE(l.contact_part.has_value());
  EXPECT_EQ(*l.contact_part, HandPlace::Fingertip);
  EXPECT_EQ(l.contact_finger, static_cast<int>(Finger::Thumb));
  ASSERT_EQ(s.movements.size(), 1u);
  EXPECT_EQ(s.movements[0].dominant[0].kind, MovementKind::Straight);
  EXPECT_FALSE(any_target_on_the_other_hand(s));
  expect_round_trip(s);
}

// A bracket whose inside is a path (a contact on the way at a body place) is not a hand part:
// it stays what it was, a move to that place after the movement before it.
TEST(HamNoSysLocations, ABracketWithABodyPlaceInsideIsStillAPath) {
  const SignSpec s = read_clean(
      "hamfinger2,hamextfingerul,hampalmd,hamcheek,hamlrat,hamclose,"
      "hammoved,hamseqbegin,hambrushing,hamchin,hamtouch,hamseqend");
  EXPECT_FALSE(s.dominant.location.contact_part.has_value());
  EXPECT_EQ(s.dominant.location.contact, Contact::Close);
  ASSERT_EQ(s.movements.size(), 2u);
  EXPECT_EQ(s.movements[0].dominant[0].kind, MovementKind::Straight);
  ASSERT_TRUE(s.movements[1].dominant[0].to_location.has_value());
  EXPECT_EQ(s.movements[1].dominant[0].to_location->level, BodyLevel::Chin);
  EXPECT_FALSE(any_target_on_the_other_hand(s));
}

// After hambelowstomach the corpus writes places on the legs with the arm's symbols in a sequence
// of places (tights and stockings: "hambelowstomach [hamupperarm hamlrat]", the thigh; a knee:
// "[hamelbowinside]"). Read as a part of this hand, the hand put its own upper arm (or the inside
// of its elbow) at the belly (docs/SYNTHESIS.md leap): the same place as hambelowstomach alone,
// no contact part.
TEST(HamNoSysLocations, AnArmPlaceInASequenceBelowTheStomachIsOnTheLegNotThisHandsPart) {
  const SignSpec plain = read_clean("hamflathand,hamextfingerd,hampalml,hambelowstomach,hamlrat,hamtouch,hammoveu");
  for (const char* text :
       {"hamflathand,hamextfingerd,hampalml,hambelowstomach,hamseqbegin,hamupperarm,hamlrat,hamseqend,hamtouch,"
        "hammoveu",
        "hamflathand,hamextfingerd,hampalml,hambelowstomach,hamlrat,hamseqbegin,hamelbowinside,hamseqend,hamtouch,"
        "hammoveu"}) {
    SCOPED_TRACE(text);
    const SignSpec s = read_clean(text);
    const Location& l = s.dominant.location;
    EXPECT_FALSE(l.contact_part.has_value());
    EXPECT_EQ(l.kind, Location::Kind::Body);
    EXPECT_EQ(l.level, plain.dominant.location.level);
    EXPECT_EQ(l.side, Side::Right);
    EXPECT_EQ(l.contact, Contact::Touch);
    ASSERT_EQ(s.movements.size(), 1u);
    EXPECT_EQ(s.movements[0].dominant[0].kind, MovementKind::Straight);
    expect_round_trip(s);
  }
}

// A symmetric pair whose hands touch each other (hamsymmlr, the dominant hand's back on the other
// palm, circling): both hands make the movement, the non-dominant one mirrored. It was read with
// nondominant_is_place, so one hand circled on a still one.
TEST(HamNoSysLocations, ASymmetricPairOnEachOtherMovesBothHands) {
  const SignSpec s = read_clean("hamsymmlr,hamflathand,hamextfingero,hampalmd,hamhandback,hamtouch,hamcirclei");
  EXPECT_EQ(s.symmetry, Symmetry::MirrorLR);
  EXPECT_EQ(s.dominant.location.kind, Location::Kind::OtherHand);
  EXPECT_EQ(s.dominant.location.hand_place, HandPlace::BackOfHand);
  EXPECT_FALSE(s.nondominant_is_place);
  ASSERT_EQ(s.movements.size(), 1u);
  EXPECT_EQ(s.movements[0].dominant[0].kind, MovementKind::Circle);
  EXPECT_TRUE(s.movements[0].nondominant.empty());  // follows the symmetry
  expect_round_trip(s);
}

// One handshape for both hands and their orientations paired after it (147 signs of the
// real-sign corpus, PJM Peugeot: "hamfinger2345 hamthumboutmod hamparbegin hamextfingeru hampalmdl
// hamplus hamextfingeru hampalmd hamparend"): the two hands' configurations. It was read as a
// change of the hand after the start (a warning), the dominant orientation left unwritten and the
// places after it read as the target of that change, the hands starting in neutral space.
TEST(HamNoSysLocations, OneHandshapeWithPairedOrientationsConfiguresBothHands) {
  const std::vector<SignParse> v = parse_hamnosys_text(
      "hamsymmlr,hamfinger2345,hamthumboutmod,hamparbegin,hamextfingeru,hampalmdl,hamplus,"
      "hamextfingeru,hampalmd,hamparend,hamparbegin,hamshoulders,hamlrat,hamplus,hamlrat,"
      "hamshoulders,"
      "hamparend,hammovei");
  ASSERT_EQ(v.size(), 1u);
  ASSERT_TRUE(v[0].ok() && v[0].spec);
  EXPECT_TRUE(v[0].diagnostics.empty()) << format_diagnostic(v[0].diagnostics[0]);
  const SignSpec& s = *v[0].spec;
  EXPECT_EQ(s.dominant.orientation.extended_finger, (Direction{0, 1, 0}));
  EXPECT_EQ(s.dominant.orientation.palm, (Direction{1, -1, 0}));
  ASSERT_TRUE(s.nondominant.has_value());
  EXPECT_EQ(s.nondominant->shape.hamnosys_base, s.dominant.shape.hamnosys_base);
  EXPECT_EQ(s.nondominant->orientation.extended_finger, (Direction{0, 1, 0}));
  EXPECT_EQ(s.nondominant->orientation.palm, (Direction{0, -1, 0}));
  EXPECT_EQ(s.dominant.location.level, BodyLevel::Shoulders);
  EXPECT_EQ(s.dominant.location.side, Side::Right);
  EXPECT_EQ(s.nondominant->location.level, BodyLevel::Shoulders);
  EXPECT_EQ(s.nondominant->location.side, Side::Left);
  ASSERT_EQ(s.movements.size(), 1u);
  EXPECT_EQ(s.movements[0].dominant[0].kind, MovementKind::Straight);
  expect_round_trip(s);
}

// Without a symmetry operator the other hand given as the place stays still: the dominant
// index tip on the other palm, the non-dominant hand configured with hamplus.
TEST(HamNoSysLocations, WithoutSymmetryTheOtherHandIsAStillPlace) {
  const SignSpec s = read_clean(
      "hamparbegin,hamfinger2,hamextfingerol,hampalmd,hamplus,hamflathand,hamextfingeror,hampalmu,hamparend,"
      "hampalm,hamtouch,hammoveo");
  EXPECT_EQ(s.symmetry, Symmetry::None);
  EXPECT_EQ(s.dominant.location.kind, Location::Kind::OtherHand);
  EXPECT_TRUE(s.nondominant_is_place);
  expect_round_trip(s);
}

// A hand constellation made at a body location: "(palm + back of hand) close, at the chest".
// The body location is where the pair is (SiGML: a handconstellation with a location_bodyarm
// child), given to the non-dominant hand, the place; it was read as a first movement there.
TEST(HamNoSysLocations, AConstellationAtABodyLocationIsThePairsPlaceNotAMovement) {
  const SignSpec s = read_clean(
      "hamsymmlr,hamflathand,hamextfingerol,hampalmd,"
      "hamparbegin,hampalm,hamplus,hamhandback,hamparend,hamclose,hamchest,hamcircleo");
  EXPECT_EQ(s.dominant.location.kind, Location::Kind::OtherHand);
  EXPECT_EQ(s.dominant.location.hand_place, HandPlace::BackOfHand);
  ASSERT_TRUE(s.dominant.location.contact_part.has_value());
  EXPECT_EQ(*s.dominant.location.contact_part, HandPlace::Palm);
  EXPECT_EQ(s.dominant.location.contact, Contact::Close);
  ASSERT_TRUE(s.nondominant.has_value());
  EXPECT_EQ(s.nondominant->location.kind, Location::Kind::Body);
  EXPECT_EQ(s.nondominant->location.level, BodyLevel::Chest);
  // Under hamsymmlr the non-dominant hand is the dominant one mirrored left-right.
  EXPECT_EQ(s.nondominant->orientation.extended_finger, (Direction{-1, 0, 1}));
  EXPECT_EQ(s.nondominant->orientation.palm, (Direction{0, -1, 0}));
  ASSERT_EQ(s.movements.size(), 1u) << "the body location was read as a movement";
  EXPECT_EQ(s.movements[0].dominant[0].kind, MovementKind::Circle);
  expect_round_trip(s);

  // A single place on the other hand with its contact, then the body location and its contact.
  const SignSpec t = read_clean(
      "hamsymmlr,hamfinger2,hamextfingerl,hampalmd,hamfingertip,hamtouch,hamlrat,hamchest,hamtouch,hammoved");
  EXPECT_EQ(t.dominant.location.kind, Location::Kind::OtherHand);
  ASSERT_TRUE(t.nondominant.has_value());
  EXPECT_EQ(t.nondominant->location.level, BodyLevel::Chest);
  EXPECT_EQ(t.nondominant->location.side, Side::Left);
  EXPECT_EQ(t.nondominant->location.contact, Contact::Touch);
  ASSERT_EQ(t.movements.size(), 1u);
  EXPECT_FALSE(t.movements[0].dominant[0].to_location.has_value());
  // G-SiGML's handconstellation names a part of each hand: a place with no part of this hand is
  // printed with the palm (gsigml_printer.cpp), so only HamNoSys and H-SiGML give it back exactly.
  expect_round_trip(t, false);
}

}  // namespace
}  // namespace sw::notation
