// Test support: comparing matrices element by element (used by the math and skeleton tests).
#pragma once

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

namespace sw::test {

// Largest absolute difference between corresponding elements of a and b.
inline float max_abs_diff(const glm::mat4& a, const glm::mat4& b) {
  float d = 0;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) d = std::max(d, std::fabs(a[c][r] - b[c][r]));
  return d;
}

}  // namespace sw::test
