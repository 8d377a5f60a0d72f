// DualQuaternionSkinningJob: dual-quaternion skinning (Kavan et al. 2007, "Skinning with dual
// quaternions") of positions and normals, 4 influences, into caller-owned packed xyz buffers —
// the alternative to linear blend skinning where LBS collapses: a forearm twisted 90-180° keeps
// its radius instead of pinching into a candy wrapper.
//
//   dq_i = (r_i, ½ (0, t_i) r_i) from each skinning matrix (rotation r_i, translation t_i)
//   b = Σ w_i · s_i · dq_i   with s_i = ±1 so every r_i lies in r_0's hemisphere
//   p' = rotate(b̂, p) + translation(b̂),   n' = rotate(b̂, n)      (b̂ = b / |b.real|)
//
// Scalar only: it is the optional path for the twist-prone vertices; LBS (skinning_job.h) stays the
// hot loop. Does NOT: handle scaled joints (validate() rejects non-rigid matrices: a dual
// quaternion has no scale), or compute skinning matrices (skinning_matrix_job.h).
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include <glm/glm.hpp>

namespace sw::skinning {

struct DualQuaternionSkinningJob {
  int vertex_count = 0;
  const glm::mat4* skinning_matrices = nullptr;  // joint_count, rigid
  int joint_count = 0;
  const glm::vec3* in_positions = nullptr;
  const glm::vec3* in_normals = nullptr;  // or null: no normals
  const std::array<std::uint16_t, 4>* joints = nullptr;
  const glm::vec4* weights = nullptr;
  float* out_positions = nullptr;  // 3 * vertex_count
  float* out_normals = nullptr;    // 3 * vertex_count when in_normals set

  // Empty when usable; lists the first problem, including a non-rigid matrix (scale or shear
  // beyond 1e-3) and joint indices out of range (checked here: this path is not the hot loop).
  std::string validate() const;
  bool run() const;
};

}  // namespace sw::skinning
