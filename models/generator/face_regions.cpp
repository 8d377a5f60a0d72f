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

float jaw_mask(glm::vec3 p) {
  const float lateral = std::max(0.0f, std::fabs(p.x) - 0.024f);  // beyond the mouth corners
  // The dividing line follows the lip line, then rises along the mandible's ramus to the hinge.
  const float line_y = kMouthY + 0.9f * lateral;
  const float half_width = 0.0006f + 0.5f * lateral;
  const float below = smoothstep(line_y + half_width, line_y - half_width, p.y);
  const float front = smoothstep(-0.015f, 0.020f, p.z);     // the ramus ends below the ear
  const float above_neck = smoothstep(1.452f, 1.488f, p.y);  // the neck stays put
  return below * front * above_neck;
}

}  // namespace sw::avatar_generator
