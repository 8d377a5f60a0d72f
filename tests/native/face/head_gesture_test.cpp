#include "face/head_gesture.h"

#include <gtest/gtest.h>

namespace sw::face {
namespace {

float angle_of(const glm::quat& q) { return 2.0f * std::acos(std::min(1.0f, std::fabs(q.w))); }

TEST(HeadGesture, GesturesStartAndEndAtRest) {
  for (HeadGesture g : {HeadGesture::Nod, HeadGesture::Shake, HeadGesture::TiltLeft,
                        HeadGesture::TiltRight, HeadGesture::Forward, HeadGesture::Back}) {
    EXPECT_LT(angle_of(head_gesture_rotation(g, 0.0f)), 1e-4f);
    EXPECT_LT(angle_of(head_gesture_rotation(g, 1.0f)), 1e-4f);
    float largest = 0.0f;
    for (float u = 0; u <= 1.0f; u += 0.01f)
      largest = std::max(largest, angle_of(head_gesture_rotation(g, u)));
    EXPECT_GT(largest, 0.1f);   // visible
    EXPECT_LT(largest, 0.45f);  // within a comfortable neck range (~25 degrees)
  }
}

TEST(HeadGesture, ShakeTurnsAboutTheVerticalAndNodAboutTheSideways) {
  const glm::quat shake = head_gesture_rotation(HeadGesture::Shake, 0.12f);
  const glm::vec3 shake_axis = glm::normalize(glm::vec3(shake.x, shake.y, shake.z));
  EXPECT_GT(std::fabs(shake_axis.y), 0.99f);
  const glm::quat nod = head_gesture_rotation(HeadGesture::Nod, 0.12f);
  const glm::vec3 nod_axis = glm::normalize(glm::vec3(nod.x, nod.y, nod.z));
  EXPECT_GT(std::fabs(nod_axis.x), 0.99f);
  EXPECT_EQ(head_gesture_from_name("shake"), HeadGesture::Shake);
  EXPECT_EQ(head_gesture_from_name("wobble"), HeadGesture::None);
}

TEST(Gaze, EyesCounterRotateTheHeadToKeepEyeContact) {
  // seed 002: the head turns 20 degrees to the left; the eyes must still look at +Z.
  const glm::quat head = glm::angleAxis(0.35f, glm::vec3(0, 1, 0));
  const glm::quat eye_in_head = gaze_rotation(head, glm::vec3(0, 0, 1));
  const glm::vec3 looking = head * eye_in_head * glm::vec3(0, 0, 1);
  EXPECT_NEAR(looking.z, 1.0f, 1e-4f);
  EXPECT_NEAR(looking.x, 0.0f, 1e-4f);
}

TEST(Gaze, EyeballRangeIsClamped) {
  const glm::quat head = glm::angleAxis(1.4f, glm::vec3(0, 1, 0));  // 80 degrees: out of range
  const glm::quat eye = gaze_rotation(head, glm::vec3(0, 0, 1), 0.6f);
  EXPECT_NEAR(angle_of(eye), 0.6f, 1e-3f);
}

}  // namespace
}  // namespace sw::face
