// SkinningJob: scalar and SIMD linear blend skinning loops. See skinning_job.h.
#include "skinning/skinning_job.h"

#include <cstring>

#if defined(__wasm_simd128__)
#include <wasm_simd128.h>
#define SW_SKINNING_SIMD 1
#elif defined(__GNUC__) && (defined(__SSE2__) || defined(__aarch64__)) && !defined(__EMSCRIPTEN__)
#define SW_SKINNING_SIMD 1
#endif

namespace sw::skinning {
namespace {

bool overlaps(const void* a, std::size_t a_bytes, const void* b, std::size_t b_bytes) {
  const auto* pa = static_cast<const unsigned char*>(a);
  const auto* pb = static_cast<const unsigned char*>(b);
  return a && b && pa < pb + b_bytes && pb < pa + a_bytes;
}

void skin_scalar(const SkinningJob& job) {
  // Locals, not job fields, in the loop: see SimdArrays below.
  const glm::mat4* m = job.skinning_matrices;
  const std::array<std::uint16_t, 4>* joints = job.joints;
  const glm::vec4* weights = job.weights;
  const glm::vec3* in_positions = job.in_positions;
  const glm::vec3* in_normals = job.in_normals;
  float* out_positions = job.out_positions;
  float* out_normals = job.out_normals;
  const int n = job.vertex_count;
  for (int v = 0; v < n; ++v) {
    const auto& j = joints[v];
    const glm::vec4 w = weights[v];
    // Blend the four matrices' columns in the same order as the SIMD loop.
    glm::vec4 c[4];
    // The same influence-count shortcuts as the SIMD loop (see skin_vertex_simd).
    if (w.x == 1.0f) {
      for (int k = 0; k < 4; ++k) c[k] = m[j[0]][k];
    } else if (w.z == 0.0f && w.w == 0.0f) {
      for (int k = 0; k < 4; ++k) c[k] = m[j[0]][k] * w.x + m[j[1]][k] * w.y;
    } else {
      for (int k = 0; k < 4; ++k)
        c[k] = m[j[0]][k] * w.x + m[j[1]][k] * w.y + m[j[2]][k] * w.z + m[j[3]][k] * w.w;
    }
    const glm::vec3 p = in_positions[v];
    const glm::vec4 sp = c[0] * p.x + c[1] * p.y + c[2] * p.z + c[3];
    float* op = out_positions + 3 * v;
    op[0] = sp.x;
    op[1] = sp.y;
    op[2] = sp.z;
    if (in_normals) {
      const glm::vec3 nv = in_normals[v];
      const glm::vec4 sn = c[0] * nv.x + c[1] * nv.y + c[2] * nv.z;
      float* on = out_normals + 3 * v;
      on[0] = sn.x;
      on[1] = sn.y;
      on[2] = sn.z;
    }
  }
}

#if defined(SW_SKINNING_SIMD)
// A minimal 4-lane float vector: WebAssembly SIMD128 intrinsics, or GCC vector extensions
// (SSE2 natively). Only what the skinning loop needs.
#if defined(__wasm_simd128__)
using F4 = v128_t;
inline F4 load4(const float* p) { return wasm_v128_load(p); }
inline F4 load_splat(const float* p) { return wasm_v128_load32_splat(p); }  // one instruction
inline F4 mul(F4 a, F4 b) { return wasm_f32x4_mul(a, b); }
inline F4 add(F4 a, F4 b) { return wasm_f32x4_add(a, b); }
inline void store4(float* p, F4 v) { wasm_v128_store(p, v); }
inline void store3(float* p, F4 v) {
  p[0] = wasm_f32x4_extract_lane(v, 0);
  p[1] = wasm_f32x4_extract_lane(v, 1);
  p[2] = wasm_f32x4_extract_lane(v, 2);
}
#else
typedef float F4 __attribute__((vector_size(16)));
inline F4 load4(const float* p) {
  F4 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
inline F4 splat(float x) { return F4{x, x, x, x}; }
inline F4 load_splat(const float* p) { return splat(*p); }
inline F4 mul(F4 a, F4 b) { return a * b; }
inline F4 add(F4 a, F4 b) { return a + b; }
inline void store4(float* p, F4 v) { std::memcpy(p, &v, sizeof v); }
inline void store3(float* p, F4 v) {
  p[0] = v[0];
  p[1] = v[1];
  p[2] = v[2];
}
#endif

// The job's arrays copied into locals: the output stores (memcpy natively, may_alias v128 stores
// in WASM) may alias anything in memory, so fields read through `job` would be reloaded after
// every store; locals whose address is never taken cannot be aliased.
struct SimdArrays {
  const float* matrices;
  const std::array<std::uint16_t, 4>* joints;
  const glm::vec4* weights;
  const glm::vec3* positions;
  const glm::vec3* normals;
  float* out_positions;
  float* out_normals;
};

// One vertex: blend four matrix columns by the weights, then transform point and normal.
// `kLast` vertices are stored lane by lane; the others with a 4-float store whose 4th float is
// overwritten by the next vertex (cheaper than three lane stores).
template <bool kNormals, bool kLast>
inline void skin_vertex_simd(const SimdArrays& a, std::size_t v) {
  const auto& j = a.joints[v];
  const float* m0 = a.matrices + 16 * j[0];
  const float* m1 = a.matrices + 16 * j[1];
  const float* m2 = a.matrices + 16 * j[2];
  const float* m3 = a.matrices + 16 * j[3];
  const glm::vec4 wv = a.weights[v];
  const float* wp = &a.weights[v].x;
  F4 c[4];
  // Most of a humanoid's vertices have one or two influences (rigid limbs, knuckle seams): skip
  // the zero-weight matrices. With weights >= 0 summing to 1 (the Avatar contract), w.x == 1 means
  // one influence, and 1·M + 0·M' == M bit for bit, so the result is the full blend's.
  if (wv.x == 1.0f) {
    for (int k = 0; k < 4; ++k) c[k] = load4(m0 + 4 * k);
  } else if (wv.z == 0.0f && wv.w == 0.0f) {
    const F4 w0 = load_splat(wp), w1 = load_splat(wp + 1);
    for (int k = 0; k < 4; ++k) c[k] = add(mul(load4(m0 + 4 * k), w0), mul(load4(m1 + 4 * k), w1));
  } else {
    const F4 w0 = load_splat(wp), w1 = load_splat(wp + 1), w2 = load_splat(wp + 2),
             w3 = load_splat(wp + 3);
    for (int k = 0; k < 4; ++k) {
      c[k] = add(add(add(mul(load4(m0 + 4 * k), w0), mul(load4(m1 + 4 * k), w1)),
                     mul(load4(m2 + 4 * k), w2)),
                 mul(load4(m3 + 4 * k), w3));
    }
  }
  const float* p = &a.positions[v].x;
  const F4 sp = add(add(add(mul(c[0], load_splat(p)), mul(c[1], load_splat(p + 1))),
                        mul(c[2], load_splat(p + 2))),
                    c[3]);
  float* op = a.out_positions + 3 * v;
  if (kLast)
    store3(op, sp);
  else
    store4(op, sp);
  if (kNormals) {
    const float* n = &a.normals[v].x;
    const F4 sn = add(add(mul(c[0], load_splat(n)), mul(c[1], load_splat(n + 1))),
                      mul(c[2], load_splat(n + 2)));
    float* on = a.out_normals + 3 * v;
    if (kLast)
      store3(on, sn);
    else
      store4(on, sn);
  }
}

template <bool kNormals>
void skin_simd(const SkinningJob& job) {
  const SimdArrays a{&job.skinning_matrices[0][0][0],
                     job.joints,
                     job.weights,
                     job.in_positions,
                     job.in_normals,
                     job.out_positions,
                     job.out_normals};
  const std::size_t n = static_cast<std::size_t>(job.vertex_count);
  for (std::size_t v = 0; v + 1 < n; ++v) skin_vertex_simd<kNormals, false>(a, v);
  if (n > 0) skin_vertex_simd<kNormals, true>(a, n - 1);
}
#endif

}  // namespace

bool simd_available() {
#if defined(SW_SKINNING_SIMD)
  return true;
#else
  return false;
#endif
}

std::string SkinningJob::validate() const {
  if (vertex_count < 0) return "SkinningJob: negative vertex count";
  if (vertex_count == 0) return {};
  if (!skinning_matrices || joint_count <= 0) return "SkinningJob: no skinning matrices";
  if (!in_positions || !joints || !weights) return "SkinningJob: missing vertex input";
  if (!out_positions) return "SkinningJob: no position output";
  if (in_normals && !out_normals) return "SkinningJob: normals given without an output";
  const std::size_t n = static_cast<std::size_t>(vertex_count);
  const std::size_t out_bytes = 3 * n * sizeof(float);
  const std::size_t in_bytes = n * sizeof(glm::vec3);
  if (overlaps(out_positions, out_bytes, in_positions, in_bytes) ||
      overlaps(out_positions, out_bytes, in_normals, in_bytes) ||
      overlaps(out_normals, out_bytes, in_positions, in_bytes) ||
      overlaps(out_normals, out_bytes, in_normals, in_bytes) ||
      overlaps(out_positions, out_bytes, out_normals, out_bytes))
    return "SkinningJob: output buffers overlap the inputs or each other";
  return {};
}

bool SkinningJob::run() const {
  if (!validate().empty()) return false;
#if defined(SW_SKINNING_SIMD)
  if (path == SkinningPath::Simd) {
    if (in_normals)
      skin_simd<true>(*this);
    else
      skin_simd<false>(*this);
    return true;
  }
#endif
  skin_scalar(*this);
  return true;
}

}  // namespace sw::skinning
