#include "face/head_gesture.h"

#include <algorithm>
#include <cmath>

#include "face/easing.h"

namespace sw::face {

HeadGesture head_gesture_from_name(std::string_view name) {
  if (name == "nod") return HeadGesture::Nod;
  if (name == "shake") return HeadGesture::Shake;
  if (name == "tilt_l" || name == "tilt_left" || name == "tiltl") return HeadGesture::TiltLeft;
  if (name == "tilt_r" || name == "tilt_right" || name == "tiltr") return HeadGesture::TiltRight;
  if (name == "forward" || name == "pushforward") return HeadGesture::Forward;
  if (name == "back" || name == "tiltback") return HeadGesture::Back;
  return HeadGesture::None;
}

glm::quat head_gesture_rotation(HeadGesture gesture, float u) {
  const float c = std::clamp(u, 0.0f, 1.0f);
  const float envelope = std::sin(3.14159265f * c);             // 0 at both ends
  const float swing = std::sin(2.0f * 2.0f * 3.14159265f * c);  // two cycles
  const float hold =
      ease_cosine(std::min(1.0f, 3.0f * c)) * ease_cosine(std::min(1.0f, 3.0f * (1.0f - c)));
  switch (gesture) {
    case HeadGesture::Nod:  // pitch about +X: positive bows the face down towards +Y->-Y
      return glm::angleAxis(0.22f * envelope * std::fabs(swing), glm::vec3(1, 0, 0));
    case HeadGesture::Shake:
      return glm::angleAxis(0.30f * envelope * swing, glm::vec3(0, 1, 0));
    case HeadGesture::TiltLeft:  // ear towards the signer's left shoulder (+X): roll about +Z
      return glm::angleAxis(-0.25f * hold, glm::vec3(0, 0, 1));
    case HeadGesture::TiltRight:
      return glm::angleAxis(0.25f * hold, glm::vec3(0, 0, 1));
    case HeadGesture::Forward:
      return glm::angleAxis(0.15f * hold, glm::vec3(1, 0, 0));
    case HeadGesture::Back:
      return glm::angleAxis(-0.15f * hold, glm::vec3(1, 0, 0));
    case HeadGesture::None:
      break;
  }
  return glm::quat(1, 0, 0, 0);
}

glm::quat gaze_rotation(const glm::quat& head_world, const glm::vec3& look_dir,
                        float max_angle_rad) {
  // The eye's rest direction is the face's forward (+Z) carried by the head; we want the eye to
  // point along look_dir: the rotation, in the head's frame, from +Z to look_dir expressed there.
  const glm::vec3 target_in_head =
      glm::normalize(glm::inverse(head_world) * glm::normalize(look_dir));
  const glm::vec3 forward(0, 0, 1);
  float angle = std::acos(std::clamp(glm::dot(forward, target_in_head), -1.0f, 1.0f));
  glm::vec3 axis = glm::cross(forward, target_in_head);
  if (glm::length(axis) < 1e-6f) return glm::quat(1, 0, 0, 0);
  axis = glm::normalize(axis);
  angle = std::min(angle, max_angle_rad);  // eyeballs turn about 35 degrees at most
  return glm::angleAxis(angle, axis);
}

glm::vec3 gaze_direction(std::string_view name) {
  if (name == "up") return glm::normalize(glm::vec3(0, 0.5f, 1));
  if (name == "down") return glm::normalize(glm::vec3(0, -0.5f, 1));
  if (name == "left") return glm::normalize(glm::vec3(0.6f, 0, 1));
  if (name == "right") return glm::normalize(glm::vec3(-0.6f, 0, 1));
  return glm::vec3(0, 0, 1);  // the addressee stands in front of the signer
}

}  // namespace sw::face
