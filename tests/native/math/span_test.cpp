// Span (math/span.h): a view, never a copy.
#include "math/span.h"

#include <gtest/gtest.h>

namespace sw::math {
namespace {

TEST(Span, ViewsAVectorWithoutCopying) {
  std::vector<int> values = {1, 2, 3};
  Span<int> view = values;
  ASSERT_EQ(view.size, 3u);
  view[1] = 20;
  EXPECT_EQ(values[1], 20);
  int sum = 0;
  for (int v : view) sum += v;
  EXPECT_EQ(sum, 24);
}

TEST(Span, ConstViewOfConstVectorAndDefaultIsEmpty) {
  const std::vector<float> values = {0.5f};
  const Span<const float> view = values;
  EXPECT_EQ(view.data, values.data());
  EXPECT_TRUE(Span<const float>{}.empty());
  EXPECT_FALSE(view.empty());
}

}  // namespace
}  // namespace sw::math
