// Face regions; see face_regions.h.
#include "face_regions.h"

#include <cmath>

#include "implicit_body.h"

namespace sw::avatar_generator {

namespace {
float smoothstep(float e0, float e1, float x) {
  const float t = glm::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}
}  // namespace

float below_lip_line(glm::vec3 p) {
  const float lateral = std::max(0.0f, std::fabs(p.x) - 0.024f);  // beyond the mouth corners
  const float line_y = kMouthY + 0.9f * lateral;
  const float half_width = 0.0006f + 0.5f * lateral;
  return smoothstep(line_y + half_width, line_y - half_width, p.y);
}

float jaw_mask(glm::vec3 p) {
  const float front = smoothstep(-0.012f, 0.020f, p.z);      // the ramus ends below the ear
  const float above_neck = smoothstep(1.455f, 1.488f, p.y);  // the neck stays put
  // The lip corners are shared by both lips: they follow the jaw about halfway, and the upper
  // lip next to them a little, so the opening mouth is an oval, not a box.
  const float corner_x = (std::fabs(p.x) - 0.0245f) / 0.009f, corner_y = (p.y - kMouthY) / 0.008f;
  const float corner = std::exp(-(corner_x * corner_x + corner_y * corner_y));
  const float below = below_lip_line(p);
  return (below * (1.0f - 0.5f * corner) + (1.0f - below) * 0.3f * corner) * front * above_neck;
}

bool in_face_region(glm::vec3 p) {
  return std::fabs(p.x) < 0.10f && p.y > 1.452f && p.z > -0.014f && p.y < 1.75f;
}

}  // namespace sw::avatar_generator
