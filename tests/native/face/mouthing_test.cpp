#include "face/mouthing.h"

#include <gtest/gtest.h>

namespace sw::face {
namespace {

std::vector<std::string> names(const std::vector<int>& v) {
  std::vector<std::string> out;
  for (int c : v) out.emplace_back(channel_name(c));
  return out;
}

TEST(Mouthing, EnglishSpellingGivesBilabialClosureAndVowels) {
  EXPECT_EQ(names(visemes_of_word("mama")),
            (std::vector<std::string>{"viseme_PP", "viseme_aa", "viseme_PP", "viseme_aa"}));
  EXPECT_EQ(names(visemes_of_word("thank")),
            (std::vector<std::string>{"viseme_TH", "viseme_aa", "viseme_nn", "viseme_kk"}));
  EXPECT_EQ(names(visemes_of_word("food")),
            (std::vector<std::string>{"viseme_FF", "viseme_O", "viseme_DD"}));  // "oo" one key
}

TEST(Mouthing, SampaFromSigmlMouthPictures) {
  // NGT corpus mouth pictures look like "tIn", "zEstin", "@lf".
  EXPECT_EQ(names(visemes_of_word("tIn")),
            (std::vector<std::string>{"viseme_DD", "viseme_I", "viseme_nn"}));
  EXPECT_EQ(names(visemes_of_word("@lf")),
            (std::vector<std::string>{"viseme_E", "viseme_nn", "viseme_FF"}));
  EXPECT_EQ(names(visemes_of_word("tSa")), (std::vector<std::string>{"viseme_CH", "viseme_aa"}));
}

TEST(Mouthing, CyrillicUkrainian) {
  // "мама" and "так"
  EXPECT_EQ(names(visemes_of_word("\xD0\xBC\xD0\xB0\xD0\xBC\xD0\xB0")),
            (std::vector<std::string>{"viseme_PP", "viseme_aa", "viseme_PP", "viseme_aa"}));
  EXPECT_EQ(names(visemes_of_word("\xD0\xA2\xD0\xB0\xD0\xBA")),
            (std::vector<std::string>{"viseme_DD", "viseme_aa", "viseme_kk"}));
}

TEST(Mouthing, InvalidUtf8AndEmptyAreHarmless) {
  EXPECT_TRUE(visemes_of_word("").empty());
  EXPECT_NO_FATAL_FAILURE(visemes_of_word("\xFF\xC3"));
  EXPECT_NO_FATAL_FAILURE(visemes_of_word("\xE2\x82"));      // truncated 3-byte sequence
  EXPECT_TRUE(schedule_mouthing("mama", 1.0, 1.0).empty());  // no time to say it
}

TEST(Mouthing, ThreePhasesRestPeakRestWithLinearInBetweens) {
  // seed 000: before motion, maximum, back at rest; linear in-betweens (3.3).
  const auto keys = schedule_mouthing("a", 0.0, 0.6);
  ASSERT_EQ(keys.size(), 3u);
  const int aa = channel_index("viseme_aa");
  EXPECT_FLOAT_EQ(sample_mouthing(keys, 0.3)[aa], 1.0f);      // peak in the middle
  EXPECT_NEAR(sample_mouthing(keys, 0.15)[aa], 0.5f, 1e-5f);  // half way up
  EXPECT_FLOAT_EQ(sample_mouthing(keys, 0.0)[aa], 0.0f);      // at rest
  EXPECT_FLOAT_EQ(sample_mouthing(keys, 0.6)[aa], 0.0f);
  EXPECT_FLOAT_EQ(sample_mouthing(keys, 2.0)[aa], 0.0f);
}

}  // namespace
}  // namespace sw::face
