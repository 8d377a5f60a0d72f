// Tests of handshape descriptions -> per-finger configurations (src/notation/handshape.h): the
// twelve bases, thumb and bending modifiers, named fingers, between, errors, and printing words.
#include "notation/handshape.h"

#include <gtest/gtest.h>

#include "notation/hamnosys_symbols.h"

namespace sw::notation {
namespace {

HandShape build(std::vector<char32_t> words) {
  HandShape s;
  ShapeError e;
  EXPECT_TRUE(build_handshape(words, &s, &e)) << e.message;
  return s;
}
bool straight(const FingerConfig& c) { return c.id == kFingerPressedToStraight && c.has_t && c.t == 1.0f; }
bool pressed(const FingerConfig& c) { return c.id == kFingerPressedToStraight && c.has_t && c.t == 0.0f; }

TEST(Handshape, BasesSelectTheirFingers) {
  const HandShape fist = build({hamfist});
  for (int k = 1; k < kFingerCount; ++k) EXPECT_TRUE(pressed(fist.fingers[k]));
  const HandShape flat = build({hamflathand});
  for (int k = 1; k < kFingerCount; ++k) EXPECT_TRUE(straight(flat.fingers[k]));
  const HandShape v = build({hamfinger23spread});
  EXPECT_TRUE(straight(v.fingers[1]));
  EXPECT_EQ(v.fingers[2].id, kFingerSpread);
  EXPECT_TRUE(pressed(v.fingers[3]));
  const HandShape o = build({hampinchall});
  EXPECT_EQ(o.fingers[0].id, kThumbPadOnIndex);
  for (int k = 1; k < kFingerCount; ++k) EXPECT_EQ(o.fingers[k].id, kFingerRound);
  const HandShape c = build({hamceeall});
  EXPECT_EQ(c.fingers[0].id, kThumbOpposed);
  const HandShape f = build({hampinch12open});
  EXPECT_EQ(f.fingers[1].id, kFingerRound);
  EXPECT_TRUE(straight(f.fingers[4]));
  for (char32_t base = hamfist; base <= hamceeopen; ++base) EXPECT_EQ(build({base}).hamnosys_base, ham_symbol_name(base));
}

TEST(Handshape, ModifiersChangeThumbAndSelectedFingers) {
  const HandShape s = build({hamfist, hamthumbacrossmod});
  EXPECT_EQ(s.fingers[0].id, kThumbAcross);
  const HandShape bent = build({hamflathand, hamthumboutmod, hamfingerbendmod});
  EXPECT_EQ(bent.fingers[0].id, kThumbOut);
  for (int k = 1; k < kFingerCount; ++k) EXPECT_EQ(bent.fingers[k].id, kFingerHorizontal);
  // Only the selected finger of finger2 is hooked; the closed ones stay closed.
  const HandShape hook = build({hamfinger2, hamfingerhookmod});
  EXPECT_EQ(hook.fingers[1].id, kFingerHooked);
  EXPECT_TRUE(pressed(hook.fingers[2]));
  // A named finger: the bending applies to it alone, and a closed one is extended first.
  const HandShape named = build({hamfinger2345, hamringfinger, hamdoublehooked});
  EXPECT_EQ(named.fingers[3].id, kFingerDoubleHooked);
  EXPECT_EQ(named.fingers[2].id, kFingerSpread);
  const HandShape little = build({hamfinger2, hampinky});
  EXPECT_TRUE(straight(little.fingers[4]));
  // Thumb contact: a finger followed by a part.
  EXPECT_EQ(build({hamfinger23spread, hammiddlefinger, hamfingerpad}).fingers[0].id, kThumbOnMiddle);
  // Formula-only extras.
  EXPECT_EQ(build({hamflathand, kShapeSpread}).fingers[3].id, kFingerSpread);
  EXPECT_EQ(build({hamfinger23, kShapeCrossed}).fingers[2].id, kFingerCrossed);
  EXPECT_EQ(build({hamfist, kShapeThumbOn4}).fingers[0].id, kThumbOnRing);
}

TEST(Handshape, BetweenTwoShapesTakesTheMeanOfSeedStates) {
  const HandShape s = build({hamfist, hambetween, hamflathand});
  for (int k = 1; k < kFingerCount; ++k) EXPECT_FLOAT_EQ(s.fingers[k].t, 0.5f);
}

TEST(Handshape, ErrorsNameTheWord) {
  HandShape s;
  ShapeError e;
  EXPECT_FALSE(build_handshape({hamthumboutmod}, &s, &e));
  EXPECT_EQ(e.word_index, 0u);
  EXPECT_NE(e.message.find("expected a handshape base"), std::string::npos);
  EXPECT_NE(e.message.find("found 'hamthumboutmod'"), std::string::npos);
  EXPECT_FALSE(build_handshape({hamflathand, hambetween}, &s, &e));
  EXPECT_EQ(e.word_index, 2u);
  EXPECT_NE(e.message.find("the end of the handshape"), std::string::npos);
  EXPECT_FALSE(build_handshape({}, &s, &e));
}

TEST(Handshape, WordsForPrintingRebuildTheFingers) {
  // From its own words, and from fingers alone (formula F items): the closest combination.
  const HandShape a = build({hamfinger2, hamthumbacrossmod, hamfingerbendmod});
  EXPECT_EQ(join_shape_words(handshape_words(a)), "hamfinger2,hamthumbacrossmod,hamfingerbendmod");
  HandShape bare = a;
  bare.hamnosys_base.clear();
  const HandShape rebuilt = build(handshape_words(bare));
  for (int k = 0; k < kFingerCount; ++k) EXPECT_EQ(rebuilt.fingers[k].id, a.fingers[k].id) << k;
  std::vector<char32_t> words;
  ASSERT_TRUE(split_shape_words("flat,thumbout,round", &words));
  EXPECT_EQ(join_shape_words(words), "hamflathand,hamthumboutmod,round");
  EXPECT_FALSE(split_shape_words("flat,banana", &words));
}

}  // namespace
}  // namespace sw::notation
