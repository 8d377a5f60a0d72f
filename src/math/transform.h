// Transform: a joint's local translation / rotation / scale (glTF 2.0 §5.25 node TRS).
// Units: metres and radians; right-handed, +Y up, the avatar faces +Z (ARCHITECTURE.md).
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace sw::math {

struct Transform {
  glm::vec3 translation{0.0f};
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  // w, x, y, z
  glm::vec3 scale{1.0f};

  // M = T * R * S, the glTF node matrix.
  glm::mat4 to_matrix() const;
};

// Inverse of to_matrix for matrices without shear; scale is taken per axis.
Transform decompose(const glm::mat4& matrix);

}  // namespace sw::math
