#include "face/spring_frame.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

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
  for (std::size_t i = 1; i < xs.size(); ++i)
    EXPECT_LT(xs[i], xs[i - 1]);        // monotone, no overshoot
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

TEST(SpringFrame, StepMovesEveryPointByItsNetForce) {
  // step() gathers the forces in one pass over the springs (the face layer steps 67 springs per
  // frame); every moving point must still move by exactly what net_force and its springs' total
  // stiffness give, for points with several springs, springs in both directions and a
  // zero-length spring.
  SpringFrame frame;
  const int f0 = frame.add_point({0.0f, 0.0f}, true);
  const int f1 = frame.add_point({2.0f, 1.0f}, true);
  const int m0 = frame.add_point({0.7f, 0.4f}, false);
  const int m1 = frame.add_point({1.3f, -0.2f}, false);
  const int m2 = frame.add_point({1.3f, -0.2f}, false);
  frame.add_spring(f0, m0, 2.0f, 0.5f);
  frame.add_spring(m0, m1, 3.0f, 0.4f);
  frame.add_spring(m1, f1, 1.5f, 0.0f);
  frame.add_spring(m2, m1, 0.5f, 0.3f);  // coincident ends: pushed apart along +x
  frame.add_spring(f1, m0, 4.0f, 1.0f);
  const float alpha = 0.1f;
  std::vector<glm::vec2> expected;
  for (int p = 0; p < 5; ++p) {
    const SpringPoint& pt = frame.points()[std::size_t(p)];
    float stiffness = 0.0f;
    for (const Spring& s : frame.springs())
      if (s.a == p || s.b == p) stiffness += s.k;
    const float a = std::min(alpha, 0.9f * pt.mass / stiffness);
    expected.push_back(pt.fixed ? pt.position : pt.position + a * frame.net_force(p) / pt.mass);
  }
  frame.step(alpha);
  for (int p = 0; p < 5; ++p) {
    EXPECT_EQ(frame.points()[std::size_t(p)].position.x, expected[std::size_t(p)].x)
        << "point " << p;
    EXPECT_EQ(frame.points()[std::size_t(p)].position.y, expected[std::size_t(p)].y)
        << "point " << p;
  }
}

}  // namespace
}  // namespace sw::face
