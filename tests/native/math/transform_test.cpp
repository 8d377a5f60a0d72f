// Transform <-> matrix (math/transform.h).
#include "math/transform.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <random>

#include "../support/matrix_compare.h"

namespace sw::math {
namespace {

using test::max_abs_diff;

TEST(Transform, ToMatrixIsTranslateRotateScale) {
  Transform t;
  t.translation = {1, 2, 3};
  t.rotation = glm::angleAxis(0.7f, glm::normalize(glm::vec3(1, 2, -1)));
  t.scale = {2, 0.5f, 3};
  const glm::mat4 expected = glm::translate(glm::mat4(1), t.translation) *
                             glm::mat4_cast(t.rotation) * glm::scale(glm::mat4(1), t.scale);
  EXPECT_LT(max_abs_diff(t.to_matrix(), expected), 1e-6f);
}

TEST(Transform, DefaultIsIdentity) { EXPECT_EQ(Transform{}.to_matrix(), glm::mat4(1.0f)); }

TEST(Transform, DecomposeInvertsToMatrix) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-1, 1), s(0.2f, 3.0f);
  for (int i = 0; i < 500; ++i) {
    Transform t;
    t.translation = {u(rng) * 5, u(rng) * 5, u(rng) * 5};
    t.rotation = glm::normalize(glm::quat(u(rng), u(rng), u(rng), u(rng)));
    t.scale = {s(rng), s(rng), s(rng)};
    const Transform back = decompose(t.to_matrix());
    EXPECT_LT(glm::length(back.translation - t.translation), 1e-5f);
    EXPECT_LT(glm::length(back.scale - t.scale), 1e-5f);
    EXPECT_LT(max_abs_diff(back.to_matrix(), t.to_matrix()), 1e-5f);
  }
}

TEST(Transform, DecomposeMirrorKeepsAProperRotation) {
  const glm::mat4 mirror = glm::scale(glm::mat4(1), glm::vec3(-1, 1, 1));
  const Transform t = decompose(mirror);
  EXPECT_LT(max_abs_diff(t.to_matrix(), mirror), 1e-6f);
  EXPECT_NEAR(glm::length(t.rotation), 1.0f, 1e-6f);
}

TEST(Transform, DecomposeZeroScaleGivesValidRotation) {
  const glm::mat4 flat = glm::scale(glm::mat4(1), glm::vec3(1, 0, 1));
  const Transform t = decompose(flat);
  EXPECT_NEAR(glm::length(t.rotation), 1.0f, 1e-6f);
  EXPECT_EQ(t.scale.y, 0.0f);
  EXPECT_LT(max_abs_diff(t.to_matrix(), flat), 1e-6f);
}

}  // namespace
}  // namespace sw::math
