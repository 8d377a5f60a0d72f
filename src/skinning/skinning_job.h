// SkinningJob: linear blend skinning (glTF 2.0 §3.7.3.3) of positions and normals with exactly
// four influences per vertex (avatar.h kMaxInfluences; unused slots carry weight 0):
//   S = Σ_i w_i · M_{j_i}        p' = S · p        n' = S · n  (w = 0)
// written into caller-owned, tightly packed xyz float buffers (the page hands them to WebGL2 as
// typed-array views into WASM memory, so nothing is copied per frame).
//
// Two paths with the same arithmetic order, equal within 1e-5: a scalar loop, and a 4-wide SIMD
// loop (WebAssembly SIMD128 via wasm_simd128.h in the `simd` WASM flavour; SSE2 through GCC vector
// extensions natively). `simd_available()` says whether this build has the SIMD loop; a job asking
// for SIMD where it is absent runs the scalar loop.
//
// Contract (checked by validate(), except the joint indices and weights, which the loader
// guarantees — a per-frame check would cost as much as the skinning): weights >= 0 summing to 1
// (a vertex with w.x == 1 is skinned by one matrix, w.z == w.w == 0 by two), every joint index
// < joint_count; outputs do not overlap the inputs (the SIMD loop writes 4 floats per vertex,
// the 4th overwritten by the next vertex).
// Does NOT: normalise normals (shader does), use the inverse-transpose for non-uniform scale
// (joints of a humanoid rig are rigid or uniformly scaled), or skin tangents.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include <glm/glm.hpp>

namespace sw::skinning {

enum class SkinningPath { Scalar, Simd };

// True when this build has the SIMD loop (native x86-64/arm64, WASM built with -msimd128).
bool simd_available();

struct SkinningJob {
  int vertex_count = 0;
  const glm::mat4* skinning_matrices = nullptr;  // joint_count (SkinningMatrixJob)
  int joint_count = 0;
  const glm::vec3* in_positions = nullptr;               // vertex_count (after morphs)
  const glm::vec3* in_normals = nullptr;                 // vertex_count, or null: no normals
  const std::array<std::uint16_t, 4>* joints = nullptr;  // vertex_count
  const glm::vec4* weights = nullptr;                    // vertex_count, sum 1
  float* out_positions = nullptr;                        // 3 * vertex_count floats
  float* out_normals = nullptr;                          // 3 * vertex_count when in_normals set
  SkinningPath path = SkinningPath::Simd;

  std::string validate() const;
  bool run() const;
};

}  // namespace sw::skinning
