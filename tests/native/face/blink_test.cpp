#include "face/blink.h"

#include <gtest/gtest.h>

namespace sw::face {
namespace {

TEST(Blink, DeterministicRhythmWithinHumanIntervals) {
  const auto a = schedule_blinks(30.0, {}, 7);
  const auto b = schedule_blinks(30.0, {}, 7);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, schedule_blinks(30.0, {}, 8));
  ASSERT_GE(a.size(), 5u);  // 30 s at one blink per 2.4..4.8 s
  ASSERT_LE(a.size(), 13u);
  for (std::size_t i = 1; i < a.size(); ++i) {
    EXPECT_GE(a[i] - a[i - 1], 2.4 - 1e-9);
    EXPECT_LE(a[i] - a[i - 1], 4.8 + 1e-9);
  }
}

TEST(Blink, BlinksAtProsodicBoundaries) {
  const auto s = schedule_blinks(10.0, {1.0, 5.5}, 3);
  auto has_near = [&](double t) {
    for (double x : s)
      if (std::abs(x - t) < 0.5) return true;
    return false;
  };
  EXPECT_TRUE(has_near(1.0));
  EXPECT_TRUE(has_near(5.5));
}

TEST(Blink, LidClosesFullyThenReopens) {
  const std::vector<double> starts{1.0};
  EXPECT_FLOAT_EQ(blink_weight(starts, 0.5), 0.0f);
  EXPECT_FLOAT_EQ(blink_weight(starts, 1.0 + 0.08 + 0.02), 1.0f);
  EXPECT_GT(blink_weight(starts, 1.04), 0.0f);
  EXPECT_LT(blink_weight(starts, 1.04), 1.0f);
  EXPECT_FLOAT_EQ(blink_weight(starts, 1.5), 0.0f);
}

}  // namespace
}  // namespace sw::face
