// Tests of the SiGML readers and printers (src/notation/sigml.h) on hand-written documents.
#include "notation/sigml.h"

#include <gtest/gtest.h>

#include "notation/hamnosys.h"
#include "notation/sign_spec_json.h"

namespace sw::notation {
namespace {

const char* kGestural = R"(<?xml version="1.0" encoding="UTF-8"?>
<sigml>
<hamgestural_sign gloss="DRIEENTWINTIG_23">
  <sign_nonmanual>
    <mouthing_tier><mouth_picture picture="dRi@ntvInt@x"/></mouthing_tier>
    <facialexpr_tier><eye_brows movement="RB"/></facialexpr_tier>
  </sign_nonmanual>
  <sign_manual both_hands="true" lr_symm="true" outofphase="true">
    <handconfig bend5="dblhooked" handshape="finger2345" thumbpos="across"/>
    <handconfig extfidir="u"/>
    <handconfig palmor="u"/>
    <location_bodyarm location="shoulders" side="right_at" contact="close">
      <location_hand digits="2" location="tip"/>
    </location_bodyarm>
    <tgt_motion>
      <changeposture/>
      <handconfig handshape="finger23spread" thumbpos="across"/>
      <handconfig extfidir="ul" palmor="l"/>
    </tgt_motion>
    <rpt_motion repetition="fromstart_several">
      <par_motion>
        <directedmotion direction="r" curve="u" size="small" fast="true"/>
        <circularmotion axis="l"/>
      </par_motion>
    </rpt_motion>
  </sign_manual>
</hamgestural_sign>
</sigml>
)";

TEST(SiGML, GesturalSignMapsOntoSignSpec) {
  const std::vector<SignParse> v = parse_sigml_text(kGestural);
  ASSERT_EQ(v.size(), 1u);
  ASSERT_TRUE(v[0].ok()) << (v[0].diagnostics.empty() ? "" : format_diagnostic(v[0].diagnostics[0]));
  const SignSpec& s = *v[0].spec;
  EXPECT_EQ(s.gloss, "DRIEENTWINTIG_23");
  EXPECT_EQ(s.nonmanual.mouthing, "dRi@ntvInt@x");
  EXPECT_EQ(s.nonmanual.eyebrows, "up");
  EXPECT_EQ(s.symmetry, Symmetry::MirrorLR);
  EXPECT_EQ(s.dominant.shape.fingers[0].id, kThumbAcross);
  EXPECT_EQ(s.dominant.shape.fingers[4].id, kFingerDoubleHooked);
  EXPECT_EQ(s.dominant.orientation.extended_finger, (Direction{0, 1, 0}));
  EXPECT_EQ(s.dominant.location.level, BodyLevel::Shoulders);
  EXPECT_EQ(s.dominant.location.side, Side::Right);
  EXPECT_EQ(s.dominant.location.contact, Contact::Close);
  EXPECT_EQ(*s.dominant.location.contact_part, HandPlace::Fingertip);
  EXPECT_EQ(s.dominant.location.contact_finger, 1);
  ASSERT_EQ(s.movements.size(), 2u);
  EXPECT_EQ(s.movements[0].dominant[0].kind, MovementKind::Replace);
  EXPECT_EQ(s.movements[0].dominant[0].to_orientation->palm, (Direction{1, 0, 0}));
  ASSERT_EQ(s.movements[1].dominant.size(), 2u);
  EXPECT_EQ(s.movements[1].dominant[0].kind, MovementKind::Arc);
  EXPECT_EQ(s.movements[1].dominant[0].manner, Manner::Fast);
  EXPECT_TRUE(s.movements[1].dominant[1].alternating);
  EXPECT_EQ(s.repetition.kind, RepeatKind::FromStartSeveral);
  // Printed back (both SiGML kinds) and read again: the same sign.
  for (const std::string& printed : {print_gsigml({s}), print_hsigml({s})}) {
    const std::vector<SignParse> again = parse_sigml_text(printed);
    ASSERT_EQ(again.size(), 1u);
    ASSERT_TRUE(again[0].ok()) << printed;
    if (printed.find("hamgestural_sign") != std::string::npos) {
      EXPECT_EQ(sign_to_json(*again[0].spec), sign_to_json(s)) << printed;
    } else {
      EXPECT_EQ(again[0].spec->dominant.shape.fingers[4].id, kFingerDoubleHooked);
    }
  }
}

TEST(SiGML, BadValuesAndSymbolsArePositioned) {
  const std::vector<SignParse> v = parse_sigml_text(
      "<sigml>\n<hamgestural_sign gloss=\"A\"><sign_manual>\n  <handconfig handshape=\"flat\" extfidir=\"udo\"/>\n"
      "</sign_manual></hamgestural_sign>\n<hns_sign gloss=\"B\"><hamnosys_manual>\n  <hamflathand/><hamUpperArm/>\n"
      "</hamnosys_manual></hns_sign>\n</sigml>");
  ASSERT_EQ(v.size(), 2u);
  ASSERT_FALSE(v[0].diagnostics.empty());
  EXPECT_EQ(v[0].diagnostics[0].line, 3);
  EXPECT_EQ(v[0].diagnostics[0].column, 3);
  EXPECT_EQ(v[0].diagnostics[0].symbol, "extfidir=\"udo\"");
  ASSERT_FALSE(v[1].diagnostics.empty());
  EXPECT_EQ(v[1].diagnostics[0].symbol, "hamUpperArm");
  EXPECT_EQ(v[1].diagnostics[0].line, 6);
  EXPECT_EQ(v[1].diagnostics[0].column, 17);
  ASSERT_TRUE(v[1].spec.has_value());  // recovered
}

TEST(SiGML, BrokenDocumentKeepsItsCompleteSigns) {
  const std::vector<SignParse> v = parse_sigml_text(
      "<sigml><hns_sign gloss=\"OK\"><hamnosys_manual><hamfist/></hamnosys_manual></hns_sign>"
      "<hns_sign gloss=\"CUT\"><hamnosys_manual><hamfist/>");
  ASSERT_EQ(v.size(), 2u);
  EXPECT_TRUE(v[0].ok());
  EXPECT_EQ(v[0].gloss, "OK");
  EXPECT_FALSE(v[1].ok());  // the document-level error
  EXPECT_NE(v[1].diagnostics[0].message.find("expected the end tag"), std::string::npos);
}

// A hand on the other hand: under a symmetry (lr_symm) both hands make the motion, the contact
// between them, as the HamNoSys reader has it (hamsymmlr ... hamhandback hamtouch hamcirclei);
// without one the other hand is the still place. The G-SiGML reader made the other hand a
// still place in both, so such a pair did not round-trip through G-SiGML.
TEST(SiGML, ASymmetricPairOnEachOtherMovesBothHandsAsInHamNoSys) {
  auto read = [](const std::string& sign_manual) {
    const std::vector<SignParse> v =
        parse_sigml_text("<sigml><hamgestural_sign gloss=\"PAIR\">" + sign_manual +
                         "<handconfig handshape=\"flat\" extfidir=\"o\" palmor=\"d\"/>"
                         "<location_hand location=\"handback\" contact=\"touch\"/>"
                         "<circularmotion axis=\"i\"/>"
                         "</sign_manual></hamgestural_sign></sigml>");
    EXPECT_EQ(v.size(), 1u);
    EXPECT_TRUE(!v.empty() && v[0].ok() && v[0].spec);
    return v.empty() || !v[0].spec ? SignSpec{} : *v[0].spec;
  };
  const SignSpec pair = read("<sign_manual both_hands=\"true\" lr_symm=\"true\">");
  EXPECT_EQ(pair.symmetry, Symmetry::MirrorLR);
  EXPECT_EQ(pair.dominant.location.kind, Location::Kind::OtherHand);
  EXPECT_EQ(pair.dominant.location.hand_place, HandPlace::BackOfHand);
  EXPECT_FALSE(pair.nondominant_is_place);
  const std::vector<SignParse> hns = parse_hamnosys_text(
      "hamsymmlr,hamflathand,hamextfingero,hampalmd,hamhandback,hamtouch,hamcirclei");
  ASSERT_EQ(hns.size(), 1u);
  ASSERT_TRUE(hns[0].ok() && hns[0].spec);
  SignSpec same = *hns[0].spec;
  same.gloss = pair.gloss;
  EXPECT_EQ(sign_to_json_text(pair), sign_to_json_text(same));

  const SignSpec one_moving = read("<sign_manual>");
  EXPECT_EQ(one_moving.symmetry, Symmetry::None);
  EXPECT_TRUE(one_moving.nondominant_is_place);
}

// <split_motion> with <nomotion/> for the other hand under lr_symm: only the dominant hand moves
// in that step (the NGT HANDENARBEID). The reader kept no mark of it (an empty list follows the
// symmetry) and the printer wrote the step as the dominant's motion alone. The same SignSpec as
// the HamNoSys reader's for "hamparbegin hammoveu hamplus hamnomotion hamparend".
TEST(SiGML, NoMotionForTheOtherHandInASplitMotionIsKept) {
  const std::vector<SignParse> v = parse_sigml_text(
      "<sigml><hamgestural_sign gloss=\"STAYS\"><sign_manual both_hands=\"true\" lr_symm=\"true\">"
      "<handconfig handshape=\"flat\" extfidir=\"o\" palmor=\"d\"/><location_bodyarm location=\"chest\"/>"
      "<split_motion><directedmotion direction=\"u\"/><nomotion/></split_motion>"
      "<directedmotion direction=\"d\"/>"
      "</sign_manual></hamgestural_sign></sigml>");
  ASSERT_EQ(v.size(), 1u);
  ASSERT_TRUE(v[0].ok() && v[0].spec) << (v[0].diagnostics.empty() ? "" : format_diagnostic(v[0].diagnostics[0]));
  const SignSpec& s = *v[0].spec;
  ASSERT_EQ(s.movements.size(), 2u);
  EXPECT_TRUE(s.movements[0].nondominant.empty());
  EXPECT_TRUE(s.movements[0].nondominant_stays);
  EXPECT_FALSE(s.movements[1].nondominant_stays);
  const std::vector<SignParse> hns = parse_hamnosys_text(
      "hamsymmlr,hamflathand,hamextfingero,hampalmd,hamchest,hamparbegin,hammoveu,hamplus,hamnomotion,"
      "hamparend,hammoved");
  ASSERT_EQ(hns.size(), 1u);
  ASSERT_TRUE(hns[0].ok() && hns[0].spec);
  SignSpec same = *hns[0].spec;
  same.gloss = s.gloss;
  EXPECT_EQ(sign_to_json_text(s), sign_to_json_text(same));
  const std::string printed = print_gsigml({s});
  const std::vector<SignParse> again = parse_sigml_text(printed);
  ASSERT_EQ(again.size(), 1u);
  ASSERT_TRUE(again[0].ok() && again[0].spec) << printed;
  EXPECT_EQ(sign_to_json(*again[0].spec), sign_to_json(s)) << printed;
  // A split_motion without its second motion keeps its error.
  EXPECT_FALSE(parse_sigml_text("<sigml><hamgestural_sign gloss=\"BAD\"><sign_manual lr_symm=\"true\">"
                                "<handconfig handshape=\"flat\"/><split_motion><nomotion/></split_motion>"
                                "</sign_manual></hamgestural_sign></sigml>")[0].ok());
}

}  // namespace
}  // namespace sw::notation
