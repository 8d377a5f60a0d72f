// server/store/utf8_text.h: validation (overlongs, surrogates, truncation), lower-casing across
// the alphabets of data/, normalisation, character classes for the phrase tokeniser.
#include "store/utf8_text.h"

#include <gtest/gtest.h>

#include <string>

namespace sw::store {
namespace {

TEST(Utf8Text, ValidationFindsTheFirstBadByte) {
  EXPECT_TRUE(is_valid_utf8("plain ASCII"));
  EXPECT_TRUE(is_valid_utf8("Привіт, Ґанок! 😀"));
  EXPECT_EQ(find_invalid_utf8(std::string("ab\xff", 3)), 2u);
  EXPECT_EQ(find_invalid_utf8(std::string("\xc0\xaf", 2)), 0u);          // overlong '/'
  EXPECT_EQ(find_invalid_utf8(std::string("x\xed\xa0\x80", 4)), 1u);      // surrogate U+D800
  EXPECT_EQ(find_invalid_utf8(std::string("\xf4\x90\x80\x80", 4)), 0u);  // above U+10FFFF
  EXPECT_EQ(find_invalid_utf8(std::string("ok\xe2\x82", 4)), 2u);         // truncated
}

TEST(Utf8Text, LowerCasesLatinGreekCyrillic) {
  EXPECT_EQ(normalize_for_match("HELLO World"), "hello world");
  EXPECT_EQ(normalize_for_match("ÀÉÎÕÜ ĞŁŽ"), "àéîõü ğłž");
  EXPECT_EQ(normalize_for_match("ΑΒΓ Ω"), "αβγ ω");
  EXPECT_EQ(normalize_for_match("ПРИВІТ ЇЖАК ҐАНОК Є"), "привіт їжак ґанок є");
  EXPECT_EQ(normalize_for_match("  thank \t  you  "), "thank you");
}

TEST(Utf8Text, RoundTripsCodePoints) {
  std::string text = "aЖ€😀";
  EXPECT_EQ(decode_utf8(text).size(), 4u);
  EXPECT_EQ(encode_utf8(decode_utf8(text)), text);
}

TEST(Utf8Text, CharacterClasses) {
  EXPECT_TRUE(is_word_char(U'a'));
  EXPECT_TRUE(is_word_char(U'Ї'));
  EXPECT_TRUE(is_word_char(U'7'));
  EXPECT_FALSE(is_word_char(U','));
  EXPECT_FALSE(is_word_char(U'\uE000'));  // HamNoSys private-use symbol
  EXPECT_FALSE(is_word_char(U'\u2014'));  // em dash
  EXPECT_TRUE(is_word_joiner(U'\u02BC'));  // Ukrainian apostrophe
  EXPECT_GT(pause_after_punctuation_s(U'.'), pause_after_punctuation_s(U','));
  EXPECT_EQ(pause_after_punctuation_s(U'a'), 0.0);
}

}  // namespace
}  // namespace sw::store
