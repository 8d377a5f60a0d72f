#include "face/easing.h"

#include <algorithm>
#include <cmath>

namespace sw::face {

float ease_linear(float t) { return std::clamp(t, 0.0f, 1.0f); }

float ease_cosine(float t) {
  const float c = std::clamp(t, 0.0f, 1.0f);
  return 0.5f * (1.0f - std::cos(3.14159265358979f * c));
}

float lerp(float a, float b, float mu) { return (1.0f - mu) * a + mu * b; }

}  // namespace sw::face
