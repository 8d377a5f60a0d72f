// server/store/edit_distance.h: optimal string alignment distance with its early-exit bound.
#include "store/edit_distance.h"

#include <gtest/gtest.h>

#include "store/utf8_text.h"

namespace sw::store {
namespace {

int distance(const char* a, const char* b, int bound = 5) {
  return bounded_osa_distance(decode_utf8(a), decode_utf8(b), bound);
}

TEST(EditDistance, EditsOfEachKind) {
  EXPECT_EQ(distance("hello", "hello"), 0);
  EXPECT_EQ(distance("helo", "hello"), 1);    // insertion
  EXPECT_EQ(distance("helllo", "hello"), 1);  // deletion
  EXPECT_EQ(distance("hellp", "hello"), 1);   // substitution
  EXPECT_EQ(distance("hlelo", "hello"), 1);   // adjacent transposition (Damerau)
  EXPECT_EQ(distance("", "abc"), 3);
  EXPECT_EQ(distance("kitten", "sitting"), 3);
}

TEST(EditDistance, CountsCodePointsNotBytes) {
  EXPECT_EQ(distance("привіт", "привет"), 1);  // і -> е: one letter, two bytes each
  EXPECT_EQ(distance("ї", "і"), 1);
}

TEST(EditDistance, StopsAtTheBound) {
  EXPECT_EQ(distance("abcdef", "uvwxyz", 2), 3);  // bound + 1
  EXPECT_EQ(distance("a", "abcdefgh", 2), 3);     // length difference alone exceeds it
  EXPECT_EQ(distance("hello", "hellp", 1), 1);
}

}  // namespace
}  // namespace sw::store
