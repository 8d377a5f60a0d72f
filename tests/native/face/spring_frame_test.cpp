#include "face/spring_frame.h"

#include <gtest/gtest.h>

namespace sw::face {
namespace {

TEST(SpringFrame, SpringConstantIsTheInverseVarianceOfSeed003) {
  // 1/k = sum (L(n) - l_s)^2 / n: lengths 1.1 and 0.9 around 1.0 -> variance 0.01 -> k = 100.
  EXPECT_NEAR(spring_constant_from_lengths({1.1f, 0.9f}, 1.0f, 1000.0f), 100.0f, 1e-2f);
  // A spring no expression changes is bone-like: capped, never a division by zero.
  EXPECT_FLOAT_EQ(spring_constant_from_lengths({1.0f, 1.0f}, 1.0f, 50.0f), 50.0f);
  EXPECT_FLOAT_EQ(spring_constant_from_lengths({}, 1.0f, 50.0f), 50.0f);
}

TEST(SpringFrame, ExpressionNaturalLengthScalesByTheObservedRatio) {
  // seed 003: l_c = (L(n) / l_s) * l.
  EXPECT_FLOAT_EQ(expression_natural_length(0.8f, 1.0f, 2.0f), 1.6f);
}

TEST(SpringFrame, RelaxesToEquilibriumBetweenTwoFixedPoints) {
  // A moving point between two fixed points with equal springs settles in the middle.
  SpringFrame frame;
  const int left = frame.add_point({0.0f, 0.0f}, true);
  const int right = frame.add_point({2.0f, 0.0f}, true);
  const int mover = frame.add_point({1.7f, 0.3f}, false);
  frame.add_spring(left, mover, 1.0f, 0.5f);
  frame.add_spring(mover, right, 1.0f, 0.5f);
  const int steps = frame.relax(0.2f, 1e-5f, 10000);
  EXPECT_LT(steps, 10000);
  EXPECT_NEAR(frame.points()[std::size_t(mover)].position.x, 1.0f, 1e-3f);
  EXPECT_NEAR(frame.points()[std::size_t(mover)].position.y, 0.0f, 1e-3f);
  EXPECT_LT(glm::length(frame.net_force(mover)), 1e-4f);
  // Fixed points never move (seed 003: points on bone).
  EXPECT_EQ(frame.points()[std::size_t(left)].position, glm::vec2(0.0f, 0.0f));
}

TEST(SpringFrame, ShorteningASpringPullsThePointAndShowsIntermediateStates) {
  SpringFrame frame;
  const int anchor = frame.add_point({0.0f, 0.0f}, true);
  const int lip = frame.add_point({1.0f, 0.0f}, false);
  const int s = frame.add_spring(anchor, lip, 2.0f, 1.0f);
  frame.springs()[std::size_t(s)].natural_length = expression_natural_length(0.6f, 1.0f, 1.0f);
  std::vector<float> xs;
  for (int i = 0; i < 20; ++i) {
    frame.step(0.1f);
    xs.push_back(frame.points()[std::size_t(lip)].position.x);
  }
  for (std::size_t i = 1; i < xs.size(); ++i) EXPECT_LT(xs[i], xs[i - 1]);  // monotone, no overshoot
  EXPECT_GT(xs.front(), 0.6f + 0.05f);  // an intermediate state, not a jump to the end
  EXPECT_NEAR(xs.back(), 0.6f, 0.02f);
}

TEST(SpringFrame, LargeStepIsCappedAndStaysStable) {
  SpringFrame frame;
  const int a = frame.add_point({0, 0}, true);
  const int b = frame.add_point({3, 0}, false);
  frame.add_spring(a, b, 50.0f, 1.0f);
  frame.relax(10.0f, 1e-4f, 1000);  // alpha * k = 500 would explode without the cap
  EXPECT_NEAR(frame.points()[std::size_t(b)].position.x, 1.0f, 1e-3f);
}

}  // namespace
}  // namespace sw::face
