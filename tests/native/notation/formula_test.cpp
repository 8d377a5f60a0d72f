// Tests of the formula notation reader and printer (src/notation/formula.h): the seed's letters,
// every extension of docs/NOTATION.md, errors with positions, and parse(print(x)) == x.
#include "notation/formula.h"

#include <gtest/gtest.h>

#include "notation/parse.h"

namespace sw::notation {
namespace {

SignSpec parse_one(const std::string& text) {
  const std::vector<SignParse> signs = parse_formula_text(text);
  EXPECT_EQ(signs.size(), 1u) << text;
  if (signs.empty()) return {};
  for (const Diagnostic& d : signs[0].diagnostics) ADD_FAILURE() << format_diagnostic(d) << " in " << text;
  EXPECT_TRUE(signs[0].spec.has_value()) << text;
  return signs[0].spec.value_or(SignSpec{});
}

Diagnostic first_error(const std::string& text) {
  const std::vector<SignParse> signs = parse_formula_text(text);
  for (const SignParse& s : signs) {
    for (const Diagnostic& d : s.diagnostics) {
      if (d.severity == Severity::Error) return d;
    }
  }
  ADD_FAILURE() << "no error for " << text;
  return {};
}

TEST(Formula, SeedLetterVe) {
  // Seed 004 Table 2, letter В.
  const SignSpec s = parse_one("R(L1(0), D1, F_0^1(0.5), F_0^2(1), F_0^3(1), F_0^4(1), F_0^5(1))");
  EXPECT_EQ(s.dominant.location.seed_id, 1);
  EXPECT_EQ(s.dominant.location.level, BodyLevel::Chest);
  EXPECT_EQ(s.dominant.location.side, Side::Right);
  EXPECT_EQ(s.dominant.location.contact, Contact::None);
  EXPECT_EQ(s.dominant.orientation.seed_palm, SeedPalm::D1);
  EXPECT_TRUE(s.dominant.shape.fingers[0].has_t);
  EXPECT_FLOAT_EQ(s.dominant.shape.fingers[0].t, 0.5f);
  for (int k = 1; k < kFingerCount; ++k) {
    EXPECT_EQ(s.dominant.shape.fingers[k].id, kFingerPressedToStraight);
    EXPECT_FLOAT_EQ(s.dominant.shape.fingers[k].t, 1.0f);
  }
  EXPECT_FALSE(s.nondominant.has_value());
  EXPECT_TRUE(s.movements.empty());
}

TEST(Formula, SeedLetterGheWithGlossAndComment) {
  const std::string text =
      "# Ukrainian dactyl alphabet, seed 004 Table 2\n"
      "\n"
      "Г = R(L1(0), D5, F_0^1(1), F_0^2(1), F_0^3(0), F_0^4(0), F_0^5(0))  # palm to the side\n";
  const std::vector<SignParse> signs = parse_formula_text(text);
  ASSERT_EQ(signs.size(), 1u);
  ASSERT_TRUE(signs[0].ok());
  EXPECT_EQ(signs[0].gloss, "Г");
  EXPECT_EQ(signs[0].spec->gloss, "Г");
  EXPECT_EQ(signs[0].line, 3);
  EXPECT_EQ(signs[0].spec->dominant.orientation.seed_palm, SeedPalm::D5);
  EXPECT_FLOAT_EQ(signs[0].spec->dominant.shape.fingers[2].t, 0.0f);
}

TEST(Formula, HandshapeByNameWithOverrides) {
  const SignSpec s = parse_one("R(H(finger2, thumbacross), F_1^3, E(uo), P(dl), Loc(chin, centre, touch), C(tip, 2))");
  EXPECT_EQ(s.dominant.shape.hamnosys_base, "hamfinger2,hamthumbacrossmod");
  EXPECT_EQ(s.dominant.shape.fingers[0].id, kThumbAcross);
  EXPECT_FLOAT_EQ(s.dominant.shape.fingers[1].t, 1.0f);   // index straight
  EXPECT_EQ(s.dominant.shape.fingers[2].id, kFingerHorizontal);  // override
  EXPECT_EQ(s.dominant.orientation.extended_finger, (Direction{0, 1, 1}));
  EXPECT_EQ(s.dominant.orientation.palm, (Direction{1, -1, 0}));  // l = +X = signer's left
  EXPECT_EQ(s.dominant.location.kind, Location::Kind::Body);
  EXPECT_EQ(s.dominant.location.contact, Contact::Touch);
  ASSERT_TRUE(s.dominant.location.contact_part.has_value());
  EXPECT_EQ(*s.dominant.location.contact_part, HandPlace::Fingertip);
  EXPECT_EQ(s.dominant.location.contact_finger, 1);
}

TEST(Formula, TwoHandsMovementsSymmetryRepetitionNonManual) {
  const SignSpec s = parse_one(
      "R(H(flat), Loc(chest, centre), M(straight, o, small, fast), Par(M(circle, axis=i, cw), "
      "M(nod)), M(replace, H(fist), E(u), P(l))) "
      "L(H(flat), Loc(hand, palm, close), M(arc, u, bulge=l, alt)) Sym(lr) Rep(fromstart_several, 2) "
      "N(mouth=\"hallo welt\", brows=up, expression=happy:0.6, head=nod)");
  ASSERT_TRUE(s.nondominant.has_value());
  EXPECT_EQ(s.nondominant->location.kind, Location::Kind::OtherHand);
  EXPECT_EQ(s.symmetry, Symmetry::MirrorLR);
  EXPECT_EQ(s.repetition.kind, RepeatKind::FromStartSeveral);
  EXPECT_EQ(s.repetition.count, 2);
  ASSERT_EQ(s.movements.size(), 3u);
  EXPECT_EQ(s.movements[0].dominant[0].kind, MovementKind::Straight);
  EXPECT_EQ(s.movements[0].dominant[0].direction, (Direction{0, 0, 1}));
  EXPECT_EQ(s.movements[0].dominant[0].size, Size::Small);
  EXPECT_EQ(s.movements[0].dominant[0].manner, Manner::Fast);
  ASSERT_EQ(s.movements[0].nondominant.size(), 1u);
  EXPECT_EQ(s.movements[0].nondominant[0].kind, MovementKind::Arc);
  EXPECT_EQ(s.movements[0].nondominant[0].arc_bulge, (Direction{1, 0, 0}));
  EXPECT_TRUE(s.movements[0].nondominant[0].alternating);
  ASSERT_EQ(s.movements[1].dominant.size(), 2u);
  EXPECT_TRUE(s.movements[1].dominant[0].clockwise);
  EXPECT_EQ(s.movements[1].dominant[1].kind, MovementKind::WristNod);
  ASSERT_TRUE(s.movements[2].dominant[0].to_shape.has_value());
  EXPECT_EQ(s.movements[2].dominant[0].to_shape->fingers[1].t, 0.0f);
  EXPECT_EQ(s.nonmanual.mouthing, "hallo welt");
  EXPECT_FLOAT_EQ(s.nonmanual.expression_intensity, 0.6f);
}

// A movement's target orientation keeps what it does not write. Before this, an unwritten part
// fell back to the defaults (E uo, P i): `M(replace, P(d))` on a hand pointing left also swung
// its fingers up and out.
TEST(Formula, MovementOrientationKeepsWhatItDoesNotWrite) {
  const SignSpec s = parse_one("R(H(flat), E(l), P(u), M(replace, P(d)), M(straight, o, E(o)), M(replace, P(r)))");
  ASSERT_EQ(s.movements.size(), 3u);
  const auto& m = s.movements;
  ASSERT_TRUE(m[0].dominant[0].to_orientation.has_value());
  EXPECT_EQ(m[0].dominant[0].to_orientation->extended_finger, (Direction{1, 0, 0}));  // kept: left
  EXPECT_EQ(m[0].dominant[0].to_orientation->palm, (Direction{0, -1, 0}));
  ASSERT_TRUE(m[1].dominant[0].to_orientation.has_value());
  EXPECT_EQ(m[1].dominant[0].to_orientation->extended_finger, (Direction{0, 0, 1}));
  EXPECT_EQ(m[1].dominant[0].to_orientation->palm, (Direction{0, -1, 0}));  // from the movement before
  // Written in any order: the movement may come before the hand's own E(...).
  const SignSpec t = parse_one("R(M(replace, P(d)), H(flat), E(r), P(u))");
  ASSERT_TRUE(t.movements[0].dominant[0].to_orientation.has_value());
  EXPECT_EQ(t.movements[0].dominant[0].to_orientation->extended_finger, (Direction{-1, 0, 0}));
  // The other hand's movements inherit from the other hand.
  const SignSpec u = parse_one("R(H(flat), E(o), P(d)) L(H(flat), E(u), P(r), M(replace, E(o)))");
  ASSERT_EQ(u.movements.size(), 1u);
  ASSERT_EQ(u.movements[0].nondominant.size(), 1u);
  ASSERT_TRUE(u.movements[0].nondominant[0].to_orientation.has_value());
  EXPECT_EQ(u.movements[0].nondominant[0].to_orientation->palm, (Direction{-1, 0, 0}));
  // A D<i> hand has no separate E and P to keep: changing one of them alone is reported there.
  const Diagnostic d = first_error("R(D2, M(replace, P(d)))");
  EXPECT_EQ(d.symbol, "P");
  EXPECT_EQ(d.column, 18);
  EXPECT_NE(d.message.find("D2"), std::string::npos) << d.message;
  EXPECT_TRUE(parse_one("R(D2, M(replace, E(o), P(d)), M(replace, D3))").movements.size() == 2u);
}

TEST(Formula, RoundTripPrintThenParse) {
  const char* formulas[] = {
      "R(L1(0), D1, F_0^1(0.5), F_0^2(1), F_0^3(1), F_0^4(1), F_0^5(1))",
      "R(H(ceeall, thumbopen), F_2^3(1, 0.25), F_3^4(s=0.5), E(dol), Loc(hand, tip, 3, left, touch), C(pad, 1))",
      "R(H(flat), M(to, L9(1)), M(ellipse, axis=o, ellipse=ul, large, slow)) L(place, M(wavy, r)) Sym(par)",
      "R(F_0^1, F_0^2, F_0^3, F_0^4, F_0^5, M(zigzag, d, tense)) L(M(fingerplay)) N(gaze=hands, intensity=0.3)",
      "R(H(hamfinger2, hambetween, hamflathand), Loc(neutral, left_beside, close))",
  };
  for (const char* f : formulas) {
    const SignSpec a = parse_one(f);
    const std::string printed = print_formula(a);
    const SignSpec b = parse_one(printed);
    EXPECT_EQ(print_formula(b), printed) << f;
  }
}

TEST(Formula, ErrorsSayExpectedAndFoundWithPosition) {
  Diagnostic d = first_error("R(L1(0), D7)");
  EXPECT_EQ(d.line, 1);
  EXPECT_EQ(d.column, 10);
  EXPECT_EQ(d.symbol, "D7");
  EXPECT_NE(d.message.find("expected"), std::string::npos);
  EXPECT_NE(d.message.find("found 'D7'"), std::string::npos);

  d = first_error("ok = R(F_0^1(1))\nВ = R(F_0^1(1.5))");
  EXPECT_EQ(d.line, 2);
  EXPECT_EQ(d.column, 13);  // columns count code points: 'В' is one
  EXPECT_NE(d.message.find("[0, 1]"), std::string::npos);

  d = first_error("R(E(ud))");
  EXPECT_NE(d.message.find("letters u/d"), std::string::npos);
  d = first_error("R(F_0^1(1)");
  EXPECT_NE(d.message.find("found the end of the line"), std::string::npos);
  d = first_error("L(F_0^1(1))");
  EXPECT_NE(d.message.find("R(...)"), std::string::npos);
  d = first_error("R(H(flat, zzz))");
  EXPECT_EQ(d.symbol, "zzz");
  d = first_error("R(M(circle, axis=q))");
  EXPECT_EQ(d.symbol, "q");
  d = first_error("R(D1) N(mouth=\"open)");
  EXPECT_NE(d.message.find("unterminated"), std::string::npos);
}

TEST(Formula, OneBadLineDoesNotStopTheOthers) {
  const std::vector<SignParse> signs = parse_formula_text("A = R(F_0^1(1))\nB = R(oops)\nC = R(D2)\n");
  ASSERT_EQ(signs.size(), 3u);
  EXPECT_TRUE(signs[0].ok());
  EXPECT_FALSE(signs[1].ok());
  EXPECT_TRUE(signs[2].ok());
  EXPECT_EQ(signs[1].diagnostics[0].line, 2);
}

}  // namespace
}  // namespace sw::notation
