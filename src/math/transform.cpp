// Transform <-> matrix (glTF 2.0 §5.25: a node's matrix is T * R * S).
#include "math/transform.h"

#include <cmath>

namespace sw::math {

glm::mat4 Transform::to_matrix() const {
  // Written out rather than composing three mat4 products: this runs once per joint per frame.
  const glm::mat3 r = glm::mat3_cast(rotation);
  glm::mat4 m(1.0f);
  m[0] = glm::vec4(r[0] * scale.x, 0.0f);
  m[1] = glm::vec4(r[1] * scale.y, 0.0f);
  m[2] = glm::vec4(r[2] * scale.z, 0.0f);
  m[3] = glm::vec4(translation, 1.0f);
  return m;
}

Transform decompose(const glm::mat4& matrix) {
  Transform t;
  t.translation = glm::vec3(matrix[3]);
  glm::vec3 axis[3] = {glm::vec3(matrix[0]), glm::vec3(matrix[1]), glm::vec3(matrix[2])};
  t.scale = glm::vec3(glm::length(axis[0]), glm::length(axis[1]), glm::length(axis[2]));
  // A mirroring matrix (negative determinant) cannot be a rotation times positive scales; put the
  // reflection into the x scale so that R stays a proper rotation and T*R*S still equals the input.
  if (glm::determinant(glm::mat3(matrix)) < 0.0f) t.scale.x = -t.scale.x;
  for (int i = 0; i < 3; ++i) {
    // A zero scale leaves that axis undefined; keep the identity axis so the quaternion is valid.
    if (t.scale[i] != 0.0f) {
      axis[i] /= t.scale[i];
    } else {
      axis[i] = glm::vec3(0.0f);
      axis[i][i] = 1.0f;
    }
  }
  t.rotation = glm::normalize(glm::quat_cast(glm::mat3(axis[0], axis[1], axis[2])));
  return t;
}

}  // namespace sw::math
