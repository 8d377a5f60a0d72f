#include "text/utf8.h"

#include <gtest/gtest.h>

#include <string>

#include "notation/text_position.h"

namespace {

std::string encoded(char32_t cp) {
  std::string s;
  sw::text::append_utf8(&s, cp);
  return s;
}

// RFC 3629's table: the last code point of each length and the first of the next.
TEST(TextUtf8, EncodesEachSequenceLengthAtItsBoundaries) {
  EXPECT_EQ(encoded(0x00), std::string(1, '\0'));
  EXPECT_EQ(encoded(0x7F), "\x7F");
  EXPECT_EQ(encoded(0x80), "\xC2\x80");
  EXPECT_EQ(encoded(0x7FF), "\xDF\xBF");
  EXPECT_EQ(encoded(0x800), "\xE0\xA0\x80");
  EXPECT_EQ(encoded(0x0416), "\xD0\x96");      // Ж
  EXPECT_EQ(encoded(0xE000), "\xEE\x80\x80");  // HamNoSys private use
  EXPECT_EQ(encoded(0xFFFF), "\xEF\xBF\xBF");
  EXPECT_EQ(encoded(0x10000), "\xF0\x90\x80\x80");
  EXPECT_EQ(encoded(0x10FFFF), "\xF4\x8F\xBF\xBF");
}

// The encoder writes what it is given; notation's append_utf8 replaces non-scalar values.
TEST(TextUtf8, SurrogatesAreEncodedAsGivenAndNotationReplacesThem) {
  EXPECT_EQ(encoded(0xD800), "\xED\xA0\x80");
  std::string s;
  sw::notation::append_utf8(&s, 0xD800);
  sw::notation::append_utf8(&s, 0x110000);
  EXPECT_EQ(s, "\xEF\xBF\xBD\xEF\xBF\xBD");
}

TEST(TextUtf8, EveryScalarValueRoundTripsThroughTheNotationDecoder) {
  for (char32_t cp = 0; cp <= 0x10FFFF; cp += (cp < 0x1000 ? 1 : 97)) {
    if (cp >= 0xD800 && cp <= 0xDFFF) continue;
    const std::string s = encoded(cp);
    std::size_t offset = 0;
    ASSERT_EQ(sw::notation::decode_utf8(s, &offset), cp);
    ASSERT_EQ(offset, s.size());
  }
}

}  // namespace
