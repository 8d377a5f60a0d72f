// Dual-quaternion skinning. See dual_quaternion_job.h.
#include "skinning/dual_quaternion_job.h"

#include <cmath>
#include <vector>

#include <glm/gtc/quaternion.hpp>

namespace sw::skinning {
namespace {

struct DualQuat {
  glm::quat real;
  glm::quat dual;
};

DualQuat from_rigid(const glm::mat4& m) {
  const glm::quat r = glm::normalize(glm::quat_cast(glm::mat3(m)));
  const glm::quat t(0.0f, m[3].x, m[3].y, m[3].z);
  return {r, (t * r) * 0.5f};
}

float quat_dot(const glm::quat& a, const glm::quat& b) {
  return a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
}

}  // namespace

std::string DualQuaternionSkinningJob::validate() const {
  if (vertex_count < 0) return "DualQuaternionSkinningJob: negative vertex count";
  if (vertex_count == 0) return {};
  if (!skinning_matrices || joint_count <= 0)
    return "DualQuaternionSkinningJob: no skinning matrices";
  if (!in_positions || !joints || !weights || !out_positions)
    return "DualQuaternionSkinningJob: missing buffers";
  if (in_normals && !out_normals)
    return "DualQuaternionSkinningJob: normals given without an output";
  for (int j = 0; j < joint_count; ++j) {
    const glm::mat3 r(skinning_matrices[j]);
    const glm::mat3 should_be_identity = glm::transpose(r) * r;
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k)
        if (std::abs(should_be_identity[c][k] - (c == k ? 1.0f : 0.0f)) > 1e-3f)
          return "DualQuaternionSkinningJob: matrix " + std::to_string(j) +
                 " is not rigid (scale or shear)";
  }
  for (int v = 0; v < vertex_count; ++v)
    for (std::uint16_t j : joints[v])
      if (j >= joint_count)
        return "DualQuaternionSkinningJob: vertex " + std::to_string(v) +
               " joint index out of range";
  return {};
}

bool DualQuaternionSkinningJob::run() const {
  if (!validate().empty()) return false;
  std::vector<DualQuat> dqs(static_cast<std::size_t>(joint_count));
  for (int j = 0; j < joint_count; ++j)
    dqs[static_cast<std::size_t>(j)] = from_rigid(skinning_matrices[j]);
  for (int v = 0; v < vertex_count; ++v) {
    const auto& j = joints[v];
    const glm::vec4 w = weights[v];
    const DualQuat& first = dqs[j[0]];
    glm::quat real(0.0f, 0.0f, 0.0f, 0.0f), dual(0.0f, 0.0f, 0.0f, 0.0f);
    for (int k = 0; k < 4; ++k) {
      if (w[k] == 0.0f) continue;
      const DualQuat& dq = dqs[j[static_cast<std::size_t>(k)]];
      // q and -q are the same rotation: blend in the first influence's hemisphere (Kavan §4).
      const float s = quat_dot(first.real, dq.real) < 0.0f ? -w[k] : w[k];
      real = real + dq.real * s;
      dual = dual + dq.dual * s;
    }
    const float len = std::sqrt(quat_dot(real, real));
    real = real * (1.0f / len);
    dual = dual * (1.0f / len);
    // Translation of a unit dual quaternion: t = 2 · dual · conj(real).
    const glm::quat t = (dual * glm::conjugate(real)) * 2.0f;
    const glm::vec3 p = real * in_positions[v] + glm::vec3(t.x, t.y, t.z);
    float* op = out_positions + 3 * v;
    op[0] = p.x;
    op[1] = p.y;
    op[2] = p.z;
    if (in_normals) {
      const glm::vec3 n = real * in_normals[v];
      float* on = out_normals + 3 * v;
      on[0] = n.x;
      on[1] = n.y;
      on[2] = n.z;
    }
  }
  return true;
}

}  // namespace sw::skinning
