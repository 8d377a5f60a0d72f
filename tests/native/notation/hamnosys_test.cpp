// Tests of the HamNoSys reader and printer (src/notation/hamnosys.h) on hand-written signs:
// the mapping into SignSpec, both spellings, and diagnostics with positions and recovery.
#include "notation/hamnosys.h"

#include <gtest/gtest.h>

#include "notation/hamnosys_symbols.h"
#include "notation/sign_spec_json.h"
#include "notation/text_position.h"

namespace sw::notation {
namespace {

SignParse one(const std::string& text) {
  std::vector<SignParse> v = parse_hamnosys_text(text);
  EXPECT_EQ(v.size(), 1u);
  return v.empty() ? SignParse{} : v[0];
}

std::string unicode(std::initializer_list<char32_t> codes) {
  std::string s;
  for (char32_t c : codes) append_utf8(&s, c);
  return s;
}

TEST(HamNoSys, NamesAndCodePointsGiveTheSameSign) {
  const SignParse a = one("hamflathand,hamthumboutmod,hamextfingeru,hampalml,hamchest,hamlrat,hamtouch,hammoveo,hamsmallmod,hamrepeatfromstart");
  const SignParse b = one(unicode({hamflathand, hamthumboutmod, hamextfingeru, hampalml, hamchest, hamlrat,
                                   hamtouch, hammoveo, hamsmallmod, hamrepeatfromstart}));
  ASSERT_TRUE(a.ok());
  ASSERT_TRUE(b.ok());
  EXPECT_EQ(sign_to_json(*a.spec), sign_to_json(*b.spec));
  const SignSpec& s = *a.spec;
  EXPECT_EQ(s.dominant.shape.fingers[0].id, kThumbOut);
  for (int k = 1; k < kFingerCount; ++k) EXPECT_FLOAT_EQ(s.dominant.shape.fingers[k].t, 1.0f);
  EXPECT_EQ(s.dominant.orientation.extended_finger, (Direction{0, 1, 0}));
  EXPECT_EQ(s.dominant.orientation.palm, (Direction{1, 0, 0}));  // l: +X, the signer's left
  EXPECT_EQ(s.dominant.location.level, BodyLevel::Chest);
  EXPECT_EQ(s.dominant.location.side, Side::Right);  // hamlrat after the level: dominant side
  EXPECT_EQ(s.dominant.location.contact, Contact::Touch);
  ASSERT_EQ(s.movements.size(), 1u);
  EXPECT_EQ(s.movements[0].dominant[0].direction, (Direction{0, 0, 1}));
  EXPECT_EQ(s.movements[0].dominant[0].size, Size::Small);
  EXPECT_EQ(s.repetition.kind, RepeatKind::FromStart);
}

TEST(HamNoSys, TwoHandsSymmetryGroupsAndReplacement) {
  const SignParse p = one(
      "hamsymmlr,hamparbegin,hamfist,hamextfingero,hampalmd,hamplus,hamflathand,hamextfingerr,hampalmu,"
      "hamparend,hamparbegin,hamfingertip,hamplus,hampalm,hamparend,hamtouch,"
      "hamseqbegin,hamcircleo,hamellipsev,hamlargemod,hamarcu,hammoveu,hamwavy,hamseqend,"
      "hamparbegin,hammoved,hamreplace,hamfinger2,hamthumbacrossmod,hamextfingerdi,hamplus,hamnodding,hamparend");
  ASSERT_TRUE(p.ok()) << (p.diagnostics.empty() ? "" : format_diagnostic(p.diagnostics[0]));
  const SignSpec& s = *p.spec;
  EXPECT_EQ(s.symmetry, Symmetry::MirrorLR);
  ASSERT_TRUE(s.nondominant.has_value());
  EXPECT_EQ(s.nondominant->shape.hamnosys_base, "hamflathand");
  EXPECT_EQ(s.dominant.location.kind, Location::Kind::OtherHand);
  EXPECT_EQ(s.dominant.location.hand_place, HandPlace::Palm);
  EXPECT_EQ(*s.dominant.location.contact_part, HandPlace::Fingertip);
  // A symmetry operator: both hands move, the contact between them (not a still place).
  EXPECT_FALSE(s.nondominant_is_place);
  ASSERT_EQ(s.movements.size(), 3u);
  EXPECT_EQ(s.movements[0].dominant[0].kind, MovementKind::Ellipse);
  EXPECT_EQ(s.movements[0].dominant[0].size, Size::Large);
  EXPECT_EQ(s.movements[1].dominant[0].kind, MovementKind::Wavy);
  ASSERT_EQ(s.movements[2].dominant.size(), 2u);
  EXPECT_EQ(s.movements[2].dominant[1].kind, MovementKind::Replace);
  EXPECT_EQ(s.movements[2].dominant[1].to_orientation->extended_finger, (Direction{0, -1, -1}));
  ASSERT_EQ(s.movements[2].nondominant.size(), 1u);
  EXPECT_EQ(s.movements[2].nondominant[0].kind, MovementKind::WristNod);
  // Printed and read again: the same sign, in both spellings.
  for (HamNoSysSpelling spelling : {HamNoSysSpelling::Unicode, HamNoSysSpelling::Names}) {
    const SignParse again = one(print_hamnosys(s, spelling));
    ASSERT_TRUE(again.ok());
    EXPECT_EQ(sign_to_json(*again.spec), sign_to_json(s));
  }
}

// "hamparbegin MOTION hamplus hamnomotion hamparend" under a symmetry: only the dominant hand
// moves in that step. The reader kept no mark of the other hand's "no motion" (an empty list
// follows the symmetry), so the synthesis moved both hands; printed back it lost the hamnomotion.
TEST(HamNoSys, NoMotionForTheOtherHandInASplitStepIsKept) {
  const SignParse p = one("hamsymmlr,hamflathand,hamextfingero,hampalmd,hamchest,"
                          "hamparbegin,hammoveu,hamplus,hamnomotion,hamparend,hammoved");
  ASSERT_TRUE(p.ok()) << (p.diagnostics.empty() ? "" : format_diagnostic(p.diagnostics[0]));
  const SignSpec& s = *p.spec;
  ASSERT_EQ(s.movements.size(), 2u);
  ASSERT_EQ(s.movements[0].dominant.size(), 1u);
  EXPECT_TRUE(s.movements[0].nondominant.empty());
  EXPECT_TRUE(s.movements[0].nondominant_stays);
  EXPECT_FALSE(s.movements[1].nondominant_stays);  // a plain step still follows the symmetry
  // The dominant hand written still, the other moving: an empty dominant list, no mark.
  const SignParse other = one("hamsymmlr,hamflathand,hamextfingero,hampalmd,hamchest,"
                              "hamparbegin,hamnomotion,hamplus,hammoveu,hamparend");
  ASSERT_TRUE(other.ok());
  ASSERT_EQ(other.spec->movements.size(), 1u);
  EXPECT_TRUE(other.spec->movements[0].dominant.empty());
  EXPECT_EQ(other.spec->movements[0].nondominant.size(), 1u);
  EXPECT_FALSE(other.spec->movements[0].nondominant_stays);
  // A change of the dominant hand alone (the corpus's WHY3B): read, not an error.
  const SignParse change = one("hamsymmlr,hamfinger2,hamextfingeruo,hampalmdl,hamchest,"
                               "hamreplace,hamparbegin,hampalml,hamplus,hamnomotion,hamparend");
  ASSERT_TRUE(change.ok()) << (change.diagnostics.empty() ? "" : format_diagnostic(change.diagnostics[0]));
  ASSERT_EQ(change.spec->movements.size(), 1u);
  EXPECT_EQ(change.spec->movements[0].dominant[0].kind, MovementKind::Replace);
  EXPECT_TRUE(change.spec->movements[0].nondominant_stays);
  // Printed and read again: the same signs, in both spellings.
  for (const SignSpec* sign : {&s, &*other.spec, &*change.spec}) {
    for (HamNoSysSpelling spelling : {HamNoSysSpelling::Unicode, HamNoSysSpelling::Names}) {
      const std::string printed = print_hamnosys(*sign, spelling);
      const SignParse again = one(printed);
      ASSERT_TRUE(again.ok()) << printed;
      EXPECT_EQ(sign_to_json(*again.spec), sign_to_json(*sign)) << print_hamnosys(*sign, HamNoSysSpelling::Names);
    }
  }
  // A hand-written malformed group keeps its error.
  EXPECT_FALSE(one("hamsymmlr,hamflathand,hamextfingero,hampalmd,hamchest,"
                   "hamreplace,hamparbegin,hampalml,hamplus,hamnomotion,hammoveu,hamparend").ok());
}

TEST(HamNoSys, UnknownSymbolIsReportedWithPositionAndSkipped) {
  const SignParse p = one("hamflathand,hamfoo,hamextfingeru");
  ASSERT_EQ(p.diagnostics.size(), 1u);
  EXPECT_EQ(p.diagnostics[0].symbol, "hamfoo");
  EXPECT_EQ(p.diagnostics[0].column, 13);
  EXPECT_EQ(p.diagnostics[0].offset, 12u);
  ASSERT_TRUE(p.spec.has_value());  // recovered: the rest was read
  EXPECT_EQ(p.spec->dominant.orientation.extended_finger, (Direction{0, 1, 0}));

  const std::string text = unicode({hamflathand}) + "\xEE\x83\xBF" + unicode({hamextfingeru});  // U+E0FF
  const SignParse q = one(text);
  ASSERT_FALSE(q.diagnostics.empty());
  EXPECT_EQ(q.diagnostics[0].symbol, "U+E0FF");
  EXPECT_EQ(q.diagnostics[0].column, 2);
}

TEST(HamNoSys, UnbalancedBracketsAreReportedAndReadingGoesOn) {
  SignParse p = one("hamflathand,hamextfingeru,hamparbegin,hammoveu,hammoved");
  ASSERT_FALSE(p.diagnostics.empty());
  EXPECT_EQ(p.diagnostics[0].symbol, "hamparbegin");
  EXPECT_NE(p.diagnostics[0].message.find("never closed"), std::string::npos);
  ASSERT_TRUE(p.spec.has_value());
  EXPECT_EQ(p.spec->movements.size(), 1u);  // the open group runs to the end

  p = one("hamflathand,hamextfingeru,hammoveu,hamseqend,hammoved");
  ASSERT_FALSE(p.diagnostics.empty());
  EXPECT_EQ(p.diagnostics[0].symbol, "hamseqend");
  EXPECT_NE(p.diagnostics[0].message.find("closes nothing"), std::string::npos);
  ASSERT_TRUE(p.spec.has_value());
  EXPECT_EQ(p.spec->movements.size(), 2u);
}

TEST(HamNoSys, MissingHandshapeSaysWhatWasExpected) {
  const SignParse p = one("hamextfingeru,hampalmd,hamchest");
  EXPECT_FALSE(p.spec.has_value());
  ASSERT_FALSE(p.diagnostics.empty());
  EXPECT_NE(p.diagnostics[0].message.find("expected a handshape"), std::string::npos);
  EXPECT_NE(p.diagnostics[0].message.find("found 'hamextfingeru'"), std::string::npos);
}

TEST(HamNoSys, FileFormWithGlossesAndComments) {
  const std::vector<SignParse> v = parse_hamnosys_text(
      "# two signs\nHOUSE = hamflathand,hamextfingerul,hampalmdr,hamparbegin,hammovedr,hamplus,hammovedl,hamparend\n\n"
      "BAD = hamfist,hamzzz\n");
  ASSERT_EQ(v.size(), 2u);
  EXPECT_EQ(v[0].gloss, "HOUSE");
  EXPECT_TRUE(v[0].ok());
  EXPECT_EQ(v[1].gloss, "BAD");
  EXPECT_FALSE(v[1].ok());
  EXPECT_EQ(v[1].diagnostics[0].line, 4);
}

}  // namespace
}  // namespace sw::notation
